// Bounded YAML loading.
#include "worlds/yaml_input.h"

#include "util/input_file.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {
namespace {

// Counts nodes as a converter would visit them; stops as soon as the limit is passed.
bool within(const YAML::Node& node, std::size_t& budget, int depth) {
  if (budget == 0 || depth > 64) return false;
  --budget;
  if (node.IsSequence()) {
    for (const auto& item : node)
      if (!within(item, budget, depth + 1)) return false;
  } else if (node.IsMap()) {
    for (const auto& kv : node)
      if (!within(kv.first, budget, depth + 1) || !within(kv.second, budget, depth + 1))
        return false;
  }
  return true;
}

}  // namespace

YAML::Node load_yaml_input(const std::string& path) {
  std::string text;
  try {
    text = util::read_input_file(path);
  } catch (const util::InputFileError& e) {
    throw WorldError(path, "", e.what());
  }
  YAML::Node doc;
  try {
    doc = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw WorldError(path, "", std::string("malformed YAML: ") + e.what());
  }
  std::size_t budget = kMaxYamlNodes;
  if (!within(doc, budget, 0))
    throw WorldError(path, "",
                     "expands to more than " + std::to_string(kMaxYamlNodes) +
                         " YAML nodes or nests deeper than 64 (aliases?)");
  return doc;
}

}  // namespace plantsim::worlds
