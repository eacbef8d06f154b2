// JSON parsing with the keys of every object checked for repeats while the text is read.
#include "worlds/json_input.h"

#include <set>
#include <vector>

#include "worlds/world_error.h"

namespace plantsim::worlds {
namespace {

using nlohmann::json;

// Where the parser is: one frame per open object or array, each knowing its own field path.
class KeyTracker {
 public:
  explicit KeyTracker(std::string source) : source_(std::move(source)) {}

  bool on_event(json::parse_event_t event, const json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        open(event == json::parse_event_t::object_start);
        break;
      case json::parse_event_t::key:
        key(parsed.get<std::string>());
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        break;
      case json::parse_event_t::value:
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().elements;
        break;
    }
    return true;  // keep everything: the callback only checks
  }

 private:
  struct Frame {
    bool is_object = false;
    std::string path;  // "robot", "faults[2]"; empty at the top
    std::set<std::string> keys;
    std::string last_key;
    std::size_t elements = 0;
  };

  void open(bool is_object) {
    Frame f;
    f.is_object = is_object;
    if (!frames_.empty()) f.path = child_path(frames_.back());
    if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().elements;
    frames_.push_back(std::move(f));
  }

  void key(const std::string& k) {
    Frame& f = frames_.back();
    f.last_key = k;
    if (!f.keys.insert(k).second)
      throw WorldError(source_, child_path(f), "given twice in one object");
  }

  static std::string child_path(const Frame& f) {
    if (!f.is_object) return f.path + "[" + std::to_string(f.elements) + "]";
    return f.path.empty() ? f.last_key : f.path + "." + f.last_key;
  }

  std::string source_;
  std::vector<Frame> frames_;
};

}  // namespace

json parse_json_input(const std::string& text, const std::string& source) {
  KeyTracker tracker(source);
  try {
    return json::parse(text, [&tracker](int, json::parse_event_t event, json& parsed) {
      return tracker.on_event(event, parsed);
    });
  } catch (const json::exception& e) {
    throw WorldError(source, "", std::string("malformed JSON: ") + e.what());
  }
}

}  // namespace plantsim::worlds
