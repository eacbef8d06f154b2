// libFuzzer harness: batch scenario YAML through load_batch_spec (worlds it names resolve in the
// scratch folder, where a tiny world file waits).
#include "batch/batch_spec.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  plantsim::fuzz::ensure_scratch_world();
  const std::string path = plantsim::fuzz::write_scratch(
      "s.yaml", std::string(reinterpret_cast<const char*>(data), size));
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::batch::load_batch_spec(path); });
  return 0;
}
