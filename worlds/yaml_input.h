// Loading a YAML file as untrusted input: read through util::read_input_file (regular files,
// size limit), parsed, and its tree walked with aliases expanded up to a node limit, so that
// an alias bomb ("billion laughs") is refused at load instead of exhausting time or memory
// wherever the tree is later converted or cloned; the same walk refuses repeated keys.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

namespace plantsim::worlds {

/// Nodes a YAML input may expand to (aliases counted at every use); scenario and map files
/// hold a few thousand.
inline constexpr std::size_t kMaxYamlNodes = 200000;

/// Throws WorldError naming the file: unreadable, not a regular file, too large, malformed
/// YAML, more than kMaxYamlNodes nodes once aliases are expanded, or (naming the field) a
/// mapping that gives one key twice.
YAML::Node load_yaml_input(const std::string& path);

}  // namespace plantsim::worlds
