// Bounded YAML loading: the parser's events checked first, the tree built only from a file that
// passed.
#include "worlds/yaml_input.h"

#include <yaml-cpp/parser.h>

#include <sstream>

#include "util/input_file.h"
#include "worlds/world_error.h"
#include "worlds/yaml_limits_check.h"

namespace plantsim::worlds {

YAML::Node load_yaml_input(const std::string& path) {
  std::string text;
  try {
    text = util::read_input_file(path, kMaxYamlBytes);
  } catch (const util::InputFileError& e) {
    throw WorldError(path, "", e.what());
  }
  try {
    // Parsed twice: the events once, checked as they come (no tree), then YAML::Load on a text
    // now known to be small, which keeps yaml-cpp's own tree (shared aliases, marks). Building
    // the tree from the events instead would merge yaml-cpp's node stores at every level.
    std::istringstream in(text);
    YAML::Parser parser(in);
    YamlLimitsCheck check(path, {kMaxYamlNodes, kMaxYamlDepth, kMaxYamlBytes});
    while (parser.HandleNextDocument(check)) {
    }
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw WorldError(path, "", std::string("malformed YAML: ") + e.what());
  }
}

}  // namespace plantsim::worlds
