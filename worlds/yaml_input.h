// Loading a YAML file as untrusted input: read through util::read_input_file (regular files,
// size limit), its parser's events checked against the limits below as they come (an alias
// bomb, "billion laughs", or a flood of nodes is refused while it is read, before any tree is
// built), then built into a tree of at most those nodes. Refused on the way as well: keys given
// twice, tags, a second document.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace plantsim::worlds {

/// Nodes a YAML input may expand to (aliases counted at every use); scenario and map files
/// hold a few thousand.
inline constexpr std::size_t kMaxYamlNodes = 200000;

/// Mappings and sequences nested in one another (aliases expanded); plantsim's deepest YAML (a
/// scenario's fault overrides) nests 4.
inline constexpr int kMaxYamlDepth = 64;

/// The largest YAML file, and the most scalar text it may expand to (aliases counted at every
/// use): scenario, map and Nav2 parameter files are a few kB.
inline constexpr std::uint64_t kMaxYamlBytes = 16u << 20;

/// Throws WorldError naming the file: unreadable, not a regular file, over kMaxYamlBytes,
/// malformed YAML, more than kMaxYamlNodes nodes or kMaxYamlBytes of text once aliases are
/// expanded, nested deeper than kMaxYamlDepth, a second document; and naming the field (and
/// the line): a mapping that gives one key twice, a tag (`!!str`, `!foo`).
YAML::Node load_yaml_input(const std::string& path);

}  // namespace plantsim::worlds
