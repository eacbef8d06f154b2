// The YAML input's limits checked event by event.
#include "worlds/yaml_limits_check.h"

#include <algorithm>

#include "worlds/world_error.h"

namespace plantsim::worlds {

YamlLimitsCheck::YamlLimitsCheck(std::string source, YamlLimits limits)
    : source_(std::move(source)), limits_(limits) {}

void YamlLimitsCheck::OnDocumentStart(const YAML::Mark& mark) {
  // yaml-cpp's YAML::Load reads the first document and ignores the rest silently: a file
  // holding two has no single meaning.
  if (++documents_ > 1)
    refuse("", "holds a second YAML document (after '---' or '...'): one document per file", mark);
}

void YamlLimitsCheck::OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) {
  Extent e;
  count(e, mark);
  add(e, anchor, mark);
}

void YamlLimitsCheck::OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) {
  const auto it = anchors_.find(anchor);
  // yaml-cpp knows the anchor from its node's start: an alias inside that node is a cycle.
  if (it == anchors_.end()) refuse(path(), "an alias inside the node it names (a cycle)", mark);
  const Extent e = it->second;  // a copy: `add` may record anchors
  count(e, mark);
  add(e, 0, mark);
}

void YamlLimitsCheck::OnScalar(const YAML::Mark& mark, const std::string& tag,
                               YAML::anchor_t anchor, const std::string& value) {
  check_tag(tag, mark);
  Extent e;
  e.scalar = true;
  e.text = value;
  e.bytes = value.size();
  count(e, mark);
  add(e, anchor, mark);
}

void YamlLimitsCheck::OnSequenceStart(const YAML::Mark& mark, const std::string& tag,
                                      YAML::anchor_t anchor, YAML::EmitterStyle::value) {
  open(mark, tag, anchor, false);
}

void YamlLimitsCheck::OnMapStart(const YAML::Mark& mark, const std::string& tag,
                                 YAML::anchor_t anchor, YAML::EmitterStyle::value) {
  open(mark, tag, anchor, true);
}

void YamlLimitsCheck::open(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                           bool is_map) {
  check_tag(tag, mark);
  Frame f;
  f.extent.levels = 1;
  f.anchor = anchor;
  f.is_map = is_map;
  count(f.extent, mark);
  frames_.push_back(std::move(f));
}

void YamlLimitsCheck::close() {
  const Frame f = std::move(frames_.back());
  frames_.pop_back();
  add(f.extent, f.anchor, YAML::Mark::null_mark());
}

// Counts a node about to join the tree: itself, or all an alias stands for. Text is counted
// too: one long scalar aliased at every use would make a converter's copies huge.
void YamlLimitsCheck::count(const Extent& e, const YAML::Mark& mark) {
  if (e.nodes > limits_.nodes - nodes_)
    refuse(path(),
           "expands to more than " + std::to_string(limits_.nodes) +
               " YAML nodes (aliases counted at every use; docs/world_format.md: limits)",
           mark);
  nodes_ += e.nodes;
  if (e.bytes > limits_.text_bytes - bytes_)
    refuse(path(),
           "expands to more than " + std::to_string(limits_.text_bytes) +
               " bytes of YAML text (aliases counted at every use; docs/world_format.md: limits)",
           mark);
  bytes_ += e.bytes;
  if (frames_.size() + static_cast<std::size_t>(e.levels) > static_cast<std::size_t>(limits_.depth))
    refuse(path(),
           "nests deeper than " + std::to_string(limits_.depth) +
               " levels of mappings and sequences (aliases expanded; docs/world_format.md: limits)",
           mark);
}

// A finished node into its parent: a sequence's element, a mapping's key or value.
void YamlLimitsCheck::add(const Extent& e, YAML::anchor_t anchor, const YAML::Mark& mark) {
  if (anchor != 0) anchors_[anchor] = e;
  if (frames_.empty()) return;
  Frame& p = frames_.back();
  // Bounded by the count: every node added here was counted first.
  p.extent.nodes += e.nodes;
  p.extent.bytes += e.bytes;
  p.extent.levels = std::max(p.extent.levels, 1 + e.levels);
  if (!p.is_map) {
    ++p.elements;
    return;
  }
  if (p.has_key) {
    p.has_key = false;
    return;
  }
  p.has_key = true;
  p.key = e.scalar ? e.text : "?";
  // yaml-cpp keeps the first copy silently; YAML itself says keys are unique.
  if (e.scalar && !p.keys.insert(e.text).second) refuse(path(), "given twice in one mapping", mark);
}

void YamlLimitsCheck::check_tag(const std::string& tag, const YAML::Mark& mark) const {
  // yaml-cpp gives "?" to a plain node and "!" to a quoted scalar; any other tag was written
  // (`!!str 010`, `!foo`) and yaml-cpp's conversions ignore it, so the file would not mean
  // what it says.
  if (tag.empty() || tag == "?" || tag == "!") return;
  const std::string core = "tag:yaml.org,2002:";
  const std::string shown = tag.rfind(core, 0) == 0 ? "!!" + tag.substr(core.size()) : tag;
  refuse(path(), "has the YAML tag '" + shown + "': tags are not read, write the value plainly",
         mark);
}

void YamlLimitsCheck::refuse(const std::string& field, const std::string& problem,
                             const YAML::Mark& mark) const {
  const std::string line = mark.is_null() ? "" : " (line " + std::to_string(mark.line + 1) + ")";
  throw WorldError(source_, field, problem + line);
}

// "faults.a.odometry[2]": each open collection's current member, spelled only for a message.
std::string YamlLimitsCheck::path() const {
  std::string p;
  for (const Frame& f : frames_) {
    // Appended piece by piece: GCC 12 misreads `"[" + std::to_string(n)` as an overlapping copy.
    if (f.is_map && f.has_key)
      p.append(p.empty() ? "" : ".").append(f.key);
    else if (!f.is_map)
      p.append(1, '[').append(std::to_string(f.elements)).append(1, ']');
  }
  return p;
}

}  // namespace plantsim::worlds
