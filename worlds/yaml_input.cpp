// Bounded YAML loading.
#include "worlds/yaml_input.h"

#include <set>

#include "util/input_file.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {
namespace {

// Walks the tree as a converter would (aliases expanded at every use), stopping as soon as the
// node limit or the depth limit is passed, and refuses a mapping that gives one key twice
// (yaml-cpp keeps the first copy silently; YAML itself says keys are unique).
class TreeCheck {
 public:
  explicit TreeCheck(std::string source) : source_(std::move(source)) {}

  bool within_limits(const YAML::Node& node, const std::string& path, int depth) {
    if (budget_ == 0 || depth > 64) return false;
    --budget_;
    if (node.IsSequence()) {
      std::size_t i = 0;
      for (const auto& item : node)
        if (!within_limits(item, path + "[" + std::to_string(i++) + "]", depth + 1)) return false;
    } else if (node.IsMap()) {
      std::set<std::string> keys;
      for (const auto& kv : node) {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
        const std::string child = path.empty() ? key : path + "." + key;
        if (kv.first.IsScalar() && !keys.insert(key).second)
          throw WorldError(source_, child, "given twice in one mapping");
        if (!within_limits(kv.first, child, depth + 1) ||
            !within_limits(kv.second, child, depth + 1))
          return false;
      }
    }
    return true;
  }

 private:
  std::string source_;
  std::size_t budget_ = kMaxYamlNodes;
};

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
  if (!TreeCheck(path).within_limits(doc, "", 0))
    throw WorldError(path, "",
                     "expands to more than " + std::to_string(kMaxYamlNodes) +
                         " YAML nodes or nests deeper than 64 (aliases?)");
  return doc;
}

}  // namespace plantsim::worlds
