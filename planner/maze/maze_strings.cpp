// Turn-string simplification by the document's rewrite rules.
#include "planner/maze/maze_strings.h"

#include <stdexcept>

namespace plantsim::planner {

std::string simplify_turns(std::string_view turns, Hand hand) {
  for (char c : turns)
    if (c != 'L' && c != 'R' && c != 'S' && c != 'U')
      throw std::invalid_argument(std::string("turn string may hold only L, R, S and U, not '") +
                                  c + "'");
  struct Rule {
    const char* pattern;
    const char* replacement;
  };
  const Rule left[] = {{"SUL", "R"}, {"LUS", "R"}, {"LUL", "S"}};
  const Rule right[] = {{"SUR", "L"}, {"RUS", "L"}, {"RUR", "S"}};
  const Rule* rules = hand == Hand::kLeft ? left : right;
  std::string s(turns);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i + 3 <= s.size() && !changed; ++i)
      for (int r = 0; r < 3; ++r)
        if (s.compare(i, 3, rules[r].pattern) == 0) {
          s.replace(i, 3, rules[r].replacement);
          changed = true;
          break;
        }
  }
  return s;
}

}  // namespace plantsim::planner
