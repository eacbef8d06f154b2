// Action checks (see the header). Every check runs before any environment steps: a VectorEnv
// whose fourth action was NaN used to step the first three, then raise, and never report an
// episode that ended in that step.
#include "python/action_check.h"

#include <cmath>
#include <sstream>

namespace plantsim::python {
namespace {

const char* kind_name(ElementKind k) {
  switch (k) {
    case ElementKind::kReal:
      return "real";
    case ElementKind::kInteger:
      return "integer";
    case ElementKind::kBool:
      return "bool";
    case ElementKind::kComplex:
      return "complex";
    case ElementKind::kText:
      return "text";
    case ElementKind::kObject:
      return "object";
    case ElementKind::kOther:
      break;
  }
  return "non-numeric";
}

std::string shape_text(const std::vector<std::int64_t>& shape) {
  std::ostringstream s;
  s << "(";
  for (std::size_t i = 0; i < shape.size(); ++i) s << (i ? ", " : "") << shape[i];
  s << (shape.size() == 1 ? ",)" : ")");
  return s.str();
}

ActionProblem problem(ActionProblem::Kind kind, std::string message) {
  return {kind, std::move(message)};
}

}  // namespace

ElementKind element_kind(char numpy_kind) {
  switch (numpy_kind) {
    case 'f':
      return ElementKind::kReal;
    case 'i':
    case 'u':
      return ElementKind::kInteger;
    case 'b':
      return ElementKind::kBool;
    case 'c':
      return ElementKind::kComplex;
    case 'U':
    case 'S':
      return ElementKind::kText;
    case 'O':
      return ElementKind::kObject;
    default:
      return ElementKind::kOther;
  }
}

ActionProblem action_problem(const ActionInput& a, std::size_t envs, const std::string& argument) {
  using K = ActionProblem::Kind;
  const std::string expected = envs == 0 ? "(2,)" : "(" + std::to_string(envs) + ", 2)";
  const std::string unit = envs == 0 ? "(v, omega) or (left, right)" : "one (v, omega) per row";
  if (a.kind != ElementKind::kReal && a.kind != ElementKind::kInteger)
    return problem(K::kType, argument + " must hold real numbers (" + unit + "), got " +
                                 kind_name(a.kind) + " elements");
  const bool shape_ok =
      envs == 0 ? a.shape == std::vector<std::int64_t>{2}
                : a.shape == std::vector<std::int64_t>{static_cast<std::int64_t>(envs), 2};
  if (!shape_ok)
    return problem(K::kValue, argument + " must be two numbers" +
                                  (envs == 0 ? "" : " per environment") + ", shape " + expected +
                                  " (" + unit + "), got shape " + shape_text(a.shape));
  const std::size_t rows = envs == 0 ? 1 : envs;
  if (a.values.size() != 2 * rows)
    return problem(K::kValue, argument + ": " + std::to_string(a.values.size()) +
                                  " values for shape " + expected);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < 2; ++c) {
      const double v = a.values[2 * r + c];
      if (std::isfinite(v)) continue;
      std::ostringstream s;
      s << argument << "[";
      if (envs != 0) s << r << ", ";
      s << c << "] is " << v << ": a non-finite action";
      return problem(K::kValue, s.str());
    }
  }
  return {};
}

}  // namespace plantsim::python
