// Each kind recognises its own output by its first bytes, or (configs and worlds, which a user
// also writes by hand) by loading it as that kind of file.
#include "app/output_kinds.h"

#include "batch/batch_gate.h"
#include "episode/episode_config_json.h"
#include "util/input_file.h"
#include "worlds/world_loader.h"

namespace plantsim::app {
namespace {

bool loads_as_config(const std::string& path) {
  try {
    episode::parse_episode_config(util::read_input_file(path, 1 << 20), path);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

bool loads_as_world(const std::string& path) {
  try {
    worlds::parse_world_json(util::read_input_file(path), path);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

const util::OutputKind& junit_report_kind() {
  static const util::OutputKind kind{"a JUnit report", [](const std::string& path) {
                                       return batch::looks_like_junit_report(util::file_head(path));
                                     }};
  return kind;
}

const util::OutputKind& summary_markdown_kind() {
  static const util::OutputKind kind{"a results table", [](const std::string& path) {
                                       return util::file_head(path).rfind("# plantsim results",
                                                                          0) == 0;
                                     }};
  return kind;
}

const util::OutputKind& dashboard_kind() {
  static const util::OutputKind kind{"a results dashboard", [](const std::string& path) {
                                       const std::string head = util::file_head(path);
                                       return head.rfind("<!DOCTYPE html>", 0) == 0 &&
                                              head.find("<title>plantsim results</title>") !=
                                                  std::string::npos;
                                     }};
  return kind;
}

const util::OutputKind& config_file_kind() {
  static const util::OutputKind kind{"an episode config", loads_as_config};
  return kind;
}

const util::OutputKind& world_file_kind() {
  static const util::OutputKind kind{"a world file", loads_as_world};
  return kind;
}

}  // namespace plantsim::app
