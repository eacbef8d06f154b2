// libFuzzer harness: plantsim world JSON (both schemas) through parse_world_json.
#include "fuzz/fuzz_input.h"
#include "worlds/world_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  plantsim::fuzz::expect_clean_refusal(
      [&] { plantsim::worlds::parse_world_json(text, "fuzz.json"); });
  return 0;
}
