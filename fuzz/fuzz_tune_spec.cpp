// libFuzzer harness: a tuning scenario (a batch scenario with its `tune:` section) through
// load_tune_spec, as `plantsim tune` reads it; the worlds it names resolve in the scratch folder,
// where a tiny world file waits.
#include "fuzz/fuzz_input.h"
#include "tune/tune_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  plantsim::fuzz::ensure_scratch_world();
  plantsim::tune::TuneRequest request;
  request.scenario = plantsim::fuzz::write_scratch(
      "t.yaml", std::string(reinterpret_cast<const char*>(data), size));
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::tune::load_tune_spec(request); });
  return 0;
}
