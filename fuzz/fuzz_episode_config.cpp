// libFuzzer harness: episode configs (JSON) through parse_episode_config.
#include "episode/episode_config_json.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  plantsim::fuzz::expect_clean_refusal(
      [&] { plantsim::episode::parse_episode_config(text, "fuzz.json"); });
  return 0;
}
