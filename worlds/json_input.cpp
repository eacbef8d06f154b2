// JSON parsing with the nesting depth bounded and the keys of every object checked for repeats
// while the text is read.
#include "worlds/json_input.h"

#include <set>
#include <vector>

#include "worlds/world_error.h"

namespace plantsim::worlds {
namespace {

// Where the parser is: one frame per open object or array. A frame holds only its own step
// (its current key or element count), never the path from the top: the path is spelled only
// for a message, so memory stays linear in the depth (a frame that copied its parent's path
// cost memory quadratic in it: 1.7 GB for 60 KB of brackets).
template <typename Json>
class KeyTracker {
 public:
  explicit KeyTracker(std::string source) : source_(std::move(source)) {}

  bool on_event(typename Json::parse_event_t event, const Json& parsed) {
    using Event = typename Json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        open(event == Event::object_start);
        break;
      case Event::key:
        key(parsed.template get<std::string>());
        break;
      case Event::object_end:
      case Event::array_end:
        frames_.pop_back();
        break;
      case Event::value:
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().elements;
        break;
    }
    return true;  // keep everything: the callback only checks
  }

 private:
  struct Frame {
    bool is_object = false;
    std::set<std::string> keys;
    std::string last_key;
    std::size_t elements = 0;  // of an array, counted as each one starts
  };

  void open(bool is_object) {
    if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().elements;
    if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth))
      throw WorldError(source_, path(),
                       "nests deeper than " + std::to_string(kMaxJsonDepth) +
                           " levels of arrays and objects (docs/world_format.md: limits)");
    Frame f;
    f.is_object = is_object;
    frames_.push_back(std::move(f));
  }

  void key(const std::string& k) {
    Frame& f = frames_.back();
    f.last_key = k;
    if (!f.keys.insert(k).second) throw WorldError(source_, path(), "given twice in one object");
  }

  // "robot.mass_kg", "faults[2].name": each open frame's current member, from the top.
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      // Appended piece by piece: GCC 12 misreads `"[" + std::to_string(n)` as an overlapping copy.
      if (!f.is_object)
        p.append(1, '[')
            .append(std::to_string(f.elements == 0 ? 0 : f.elements - 1))
            .append(1, ']');
      else
        p.append(p.empty() ? "" : ".").append(f.last_key);
    }
    return p;
  }

  std::string source_;
  std::vector<Frame> frames_;
};

template <typename Json>
Json parse_bounded(const std::string& text, const std::string& source) {
  KeyTracker<Json> tracker(source);
  try {
    return Json::parse(text, [&tracker](int, typename Json::parse_event_t event, Json& parsed) {
      return tracker.on_event(event, parsed);
    });
  } catch (const typename Json::exception& e) {
    throw WorldError(source, "", std::string("malformed JSON: ") + e.what());
  }
}

}  // namespace

nlohmann::json parse_json_input(const std::string& text, const std::string& source) {
  return parse_bounded<nlohmann::json>(text, source);
}

nlohmann::ordered_json parse_ordered_json_input(const std::string& text,
                                                const std::string& source) {
  return parse_bounded<nlohmann::ordered_json>(text, source);
}

}  // namespace plantsim::worlds
