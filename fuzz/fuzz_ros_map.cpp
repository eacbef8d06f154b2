// libFuzzer harness: a ROS map_server YAML and its image (PGM or PNG), split by "\n--8<--\n".
#include "fuzz/fuzz_input.h"
#include "worlds/world_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto [yaml, image] = plantsim::fuzz::two_parts(data, size);
  plantsim::fuzz::write_scratch("map.pgm", image);
  const std::string path = plantsim::fuzz::write_scratch("map.yaml", yaml);
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::worlds::load_world(path); });
  return 0;
}
