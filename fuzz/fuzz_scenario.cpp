// libFuzzer harness: batch scenario YAML through load_batch_spec (worlds it names resolve in the
// scratch folder, where a tiny world file waits).
#include "batch/batch_spec.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool world_ready = [] {
    plantsim::fuzz::write_scratch(
        "w.json",
        R"({"W": 10, "H": 10, "rects": [[4, 4, 5, 5]], "start": [1, 1], "goal": [8, 8]})");
    return true;
  }();
  (void)world_ready;
  const std::string path = plantsim::fuzz::write_scratch(
      "s.yaml", std::string(reinterpret_cast<const char*>(data), size));
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::batch::load_batch_spec(path); });
  return 0;
}
