// The one rule for names (see the header).
#include "worlds/names.h"

#include <filesystem>

#include "util/unicode_text.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {

std::string name_problem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.size() > 100) return "is longer than 100 bytes";
  for (std::size_t i = 0; i < name.size();) {
    const std::int32_t cp = util::next_code_point(name, i);
    if (cp < 0) return "is not valid UTF-8";
    if (util::invisible_or_control(cp))
      return "holds a control, invisible or direction-changing character";
    if (cp == '|') return "holds '|', which separates the parts of an episode id";
  }
  if (name.front() == ' ' || name.back() == ' ') return "begins or ends with a space";
  if (name.find_first_not_of('.') == std::string::npos) return "is only dots";
  return "";
}

std::string name_from_file(const std::string& path, const std::string& remedy) {
  const std::string stem = std::filesystem::path(path).stem().string();
  if (const std::string problem = name_problem(stem); !problem.empty())
    throw WorldError(
        path, "name",
        "the world is named by its file's name, which " + problem + " (" + remedy + ")");
  return stem;
}

}  // namespace plantsim::worlds
