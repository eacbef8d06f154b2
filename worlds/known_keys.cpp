// Edit distance for key suggestions, and names made safe for the file system.
#include "worlds/known_keys.h"

#include <algorithm>
#include <filesystem>

namespace plantsim::worlds {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string nearest_known_name(const std::string& key, const std::vector<std::string>& known) {
  if (key.size() > 200) return "";
  std::string best;
  std::size_t best_distance =
      std::min<std::size_t>(3, std::max<std::size_t>(1, key.size() / 3)) + 1;
  for (const std::string& k : known) {
    const std::size_t d = edit_distance(key, k);
    if (d < best_distance) best_distance = d, best = k;
  }
  return best;
}

std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& known) {
  const std::string near = nearest_known_name(key, known);
  return near.empty() ? "unknown key" : "unknown key, did you mean '" + near + "'?";
}

bool valid_utf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t n = c < 0x80           ? 1
                          : (c >> 5) == 0x6  ? 2
                          : (c >> 4) == 0xe  ? 3
                          : (c >> 3) == 0x1e ? 4
                                             : 0;
    if (n == 0 || i + n > text.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) return false;
    i += n;
  }
  return true;
}

std::string file_name_component(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    const bool unsafe = c < 0x20 || c == 0x7f || c == '/' || c == '\\' || c == ':' || c == '|' ||
                        c == ',' || c == '"' || c == '*' || c == '?' || c == '<' || c == '>' ||
                        c == ' ';
    out += unsafe ? '_' : static_cast<char>(c);
  }
  out.erase(0, out.find_first_not_of('.'));
  if (out.size() > 100) out.resize(100);
  return out.empty() ? "world" : out;
}

}  // namespace plantsim::worlds
