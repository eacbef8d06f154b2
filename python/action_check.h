// The checks an action passes before any environment steps (plantsim.Env.step, VectorEnv.step),
// as a pure function of what the array holds: its shape, its element kind and its values. No
// pybind11 here, so that a libFuzzer harness (fuzz/fuzz_actions.cpp) drives it directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace plantsim::python {

/// What numpy's dtype.kind says of the elements ('f', 'i'/'u', 'b', 'c', 'U'/'S', 'O', ...).
enum class ElementKind { kReal, kInteger, kBool, kComplex, kText, kObject, kOther };
ElementKind element_kind(char numpy_kind);

/// An action argument as numpy holds it. `values` is read only when the kind and shape pass
/// (real or integer, converted to double by the caller), row-major.
struct ActionInput {
  std::vector<std::int64_t> shape;
  ElementKind kind = ElementKind::kReal;
  std::vector<double> values;
};

struct ActionProblem {
  enum class Kind { kNone, kType, kValue } kind = Kind::kNone;
  std::string message;  ///< names `argument` and the offending index
  explicit operator bool() const { return kind != Kind::kNone; }
};

/// Checks the action of one environment (`envs` 0: shape (2,)) or of `envs` environments
/// (shape (envs, 2)): real or whole numbers only (not bool, complex, text or objects: a type
/// problem), the exact shape and every value finite (a value problem). `argument` names the
/// argument in the message ("action", "actions").
ActionProblem action_problem(const ActionInput& a, std::size_t envs, const std::string& argument);

}  // namespace plantsim::python
