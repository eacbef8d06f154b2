// libFuzzer harness: a MovingAI .map and .scen, split by "\n--8<--\n", loaded as a world from
// the scen's first query (the path `plantsim run x.map --scen x.scen` takes).
#include "fuzz/fuzz_input.h"
#include "worlds/world_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto [map, scen] = plantsim::fuzz::two_parts(data, size);
  plantsim::worlds::PoseOverrides poses;
  poses.movingai_scen = plantsim::fuzz::write_scratch("x.scen", scen);
  const std::string path = plantsim::fuzz::write_scratch("x.map", map);
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::worlds::load_world(path, poses); });
  return 0;
}
