// libFuzzer harness: the checks every action passes before an environment steps
// (python/action_check.h, plantsim.Env.step and VectorEnv.step). Any shape, element kind and
// values: an action accepted has the exact shape, real or whole elements and finite values; one
// refused says so naming the argument; nothing else happens (no crash, no read past the values).
//
// Input: byte 0 the environments (0: one Env), byte 1 the element kind, byte 2 the dimensions
// (0 to 4), one byte per dimension (its extent, 0 to 9), then the values, 8 bytes each.
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "python/action_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace plantsim::python;
  if (size < 3) return 0;
  const std::size_t envs = data[0] % 6;
  const char kinds[] = {'f', 'i', 'u', 'b', 'c', 'U', 'S', 'O', 'V', 'M'};
  ActionInput in;
  in.kind = element_kind(kinds[data[1] % sizeof kinds]);
  const std::size_t dims = data[2] % 5;
  std::size_t at = 3, count = 1;
  for (std::size_t d = 0; d < dims && at < size; ++d, ++at) {
    in.shape.push_back(data[at] % 10);
    count *= static_cast<std::size_t>(in.shape.back());
  }
  // As the binding fills them: the values only when the kind is numeric and the count fits.
  for (; at + 8 <= size && in.values.size() < count; at += 8) {
    double v = 0;
    std::memcpy(&v, data + at, 8);
    in.values.push_back(v);
  }
  const ActionProblem p = action_problem(in, envs, "actions");
  if (!p) {
    const std::size_t rows = envs == 0 ? 1 : envs;
    if (in.kind != ElementKind::kReal && in.kind != ElementKind::kInteger) std::abort();
    if (in.values.size() != 2 * rows) std::abort();
    for (double v : in.values)
      if (!std::isfinite(v)) std::abort();
    if (envs == 0 ? in.shape != std::vector<std::int64_t>{2}
                  : in.shape != std::vector<std::int64_t>{static_cast<std::int64_t>(envs), 2})
      std::abort();
  } else if (p.message.rfind("actions", 0) != 0) {
    std::abort();  // a refusal names its argument first
  }
  return 0;
}
