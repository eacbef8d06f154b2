// libFuzzer harness: the bounded readers every JSON and YAML input goes through
// (worlds/json_input.h, worlds/yaml_input.h), the same bytes as both: depth, node, alias and
// text limits, keys given twice, tags and documents, whatever loader later reads the tree.
#include "fuzz/fuzz_input.h"
#include "worlds/json_input.h"
#include "worlds/yaml_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::worlds::parse_json_input(text, "f.json"); });
  plantsim::fuzz::expect_clean_refusal(
      [&] { plantsim::worlds::parse_ordered_json_input(text, "f.json"); });
  const std::string path = plantsim::fuzz::write_scratch("f.yaml", text);
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::worlds::load_yaml_input(path); });
  return 0;
}
