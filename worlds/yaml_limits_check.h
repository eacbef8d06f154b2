// The checks a YAML input passes while yaml-cpp's parser reads it, event by event, before any
// tree is built: nodes counted with aliases expanded at every use, nesting depth, keys given
// twice, tags and a second document refused, each as soon as it is met. Building the tree first
// (YAML::Load) and counting after cost 1.9 GB for 8 MB of YAML before the count could refuse it.
#pragma once

#include <yaml-cpp/anchor.h>
#include <yaml-cpp/emitterstyle.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/mark.h>

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace plantsim::worlds {

/// What one document may hold, aliases expanded at every use.
struct YamlLimits {
  std::size_t nodes = 0;       ///< scalars, nulls, mappings and sequences
  int depth = 0;               ///< mappings and sequences nested in one another
  std::size_t text_bytes = 0;  ///< the scalars' text
};

/// An event handler that builds nothing: it throws WorldError naming `source`, the field (as
/// "faults.a[2]") and the line at the first event past a limit.
class YamlLimitsCheck : public YAML::EventHandler {
 public:
  YamlLimitsCheck(std::string source, YamlLimits limits);

  void OnDocumentStart(const YAML::Mark& mark) override;
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override;
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override;
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override;
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value style) override;
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value style) override;
  void OnMapEnd() override { close(); }

 private:
  // A finished node as its parent and its aliases see it.
  struct Extent {
    std::size_t nodes = 1;  // with aliases expanded, itself included
    std::size_t bytes = 0;  // its scalars' text, aliases expanded
    int levels = 0;         // mappings and sequences nested in it, itself included
    bool scalar = false;
    std::string text;  // a scalar's value, for a key
  };
  // An open mapping or sequence.
  struct Frame {
    Extent extent;
    YAML::anchor_t anchor = 0;
    bool is_map = false;
    bool has_key = false;  // a mapping's key read, its value awaited
    std::string key;       // that key for paths ("?" when not a scalar)
    std::set<std::string> keys;
    std::size_t elements = 0;  // a sequence's children so far
  };

  void open(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor, bool is_map);
  void close();
  void add(const Extent& e, YAML::anchor_t anchor, const YAML::Mark& mark);
  void count(const Extent& e, const YAML::Mark& mark);
  void check_tag(const std::string& tag, const YAML::Mark& mark) const;
  [[noreturn]] void refuse(const std::string& field, const std::string& problem,
                           const YAML::Mark& mark) const;
  std::string path() const;

  std::string source_;
  YamlLimits limits_;
  std::size_t nodes_ = 0, bytes_ = 0;
  int documents_ = 0;
  std::vector<Frame> frames_;
  std::map<YAML::anchor_t, Extent> anchors_;
};

}  // namespace plantsim::worlds
