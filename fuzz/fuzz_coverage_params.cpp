// libFuzzer harness: seed 004's coverage parameters (JSON) through parse_coverage_params.
#include "fuzz/fuzz_input.h"
#include "planner/coverage/coverage_params_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  plantsim::fuzz::expect_clean_refusal(
      [&] { plantsim::planner::parse_coverage_params(text, "fuzz.json"); });
  return 0;
}
