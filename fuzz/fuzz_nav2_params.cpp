// libFuzzer harness: a Nav2 parameter file through import_nav2_params, as `plantsim nav2-import`
// and the Python module read it (the config it makes is checked by plantsim's own reader).
#include "app/nav2_import.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = plantsim::fuzz::write_scratch(
      "nav2.yaml", std::string(reinterpret_cast<const char*>(data), size));
  plantsim::fuzz::expect_clean_refusal([&] { plantsim::app::import_nav2_params(path); });
  return 0;
}
