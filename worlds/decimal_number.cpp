// Decimal numbers from text.
#include "worlds/decimal_number.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "util/c_number.h"

namespace plantsim::worlds {

bool is_decimal_number(const std::string& s) {
  std::size_t i = 0;
  auto digits = [&]() {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i > from;
  };
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  bool any = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    any = digits() || any;
  }
  if (!any) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    if (!digits()) return false;
  }
  return i == s.size();
}

std::optional<double> decimal_number(const std::string& text) {
  if (!is_decimal_number(text)) return std::nullopt;
  // strtod reads exactly the decimal forms the check let through (hexadecimal and inf/nan
  // were refused before it), in the "C" locale whatever a host process set (util/c_number.h).
  const double v = util::c_strtod(text.c_str(), nullptr);
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<std::uint64_t> decimal_whole_number(const std::string& text) {
  const std::size_t from = !text.empty() && text[0] == '+' ? 1 : 0;
  if (from == text.size()) return std::nullopt;
  std::uint64_t v = 0;
  const char* end = text.data() + text.size();
  // from_chars in base 10 takes digits only: no sign, no 0x, and "010" is ten.
  const auto [stop, error] = std::from_chars(text.data() + from, end, v, 10);
  if (error != std::errc() || stop != end) return std::nullopt;
  return v;
}

std::optional<double> decimal_number(const YAML::Node& node) {
  if (!node || !node.IsScalar()) return std::nullopt;
  return decimal_number(node.Scalar());
}

std::optional<std::uint64_t> decimal_whole_number(const YAML::Node& node) {
  if (!node || !node.IsScalar()) return std::nullopt;
  return decimal_whole_number(node.Scalar());
}

}  // namespace plantsim::worlds
