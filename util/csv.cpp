// Quoting doubles quotes inside a quoted field; splitting undoes it.
#include "util/csv.h"

#include <cstdlib>

#include "util/c_number.h"

namespace plantsim::util {

namespace {

/// Text a spreadsheet would run as a formula (OWASP's CSV injection: a cell starting with
/// = + - @, a tab or a carriage return); a number such as -0.5 is a number.
bool formula_like(const std::string& s) {
  if (s.empty() || std::string("=+-@\t\r").find(s[0]) == std::string::npos) return false;
  char* end = nullptr;
  util::c_strtod(s.c_str(), &end);
  return end != s.c_str() + s.size();
}

}  // namespace

std::string csv_field(const std::string& text) {
  // A leading ' makes a spreadsheet show the cell as text (the name keeps every character).
  const std::string s = formula_like(text) ? "'" + text : text;
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<std::string> csv_split(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else if (c != '\r') {
      cells.back() += c;
    }
  }
  return cells;
}

}  // namespace plantsim::util
