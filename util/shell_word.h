// A word as a POSIX shell reads it back, for every command line plantsim prints for a person to
// paste (the run's recorded command, a report's "re-run it alone" line): quoted with '...' when
// it holds anything but safe characters, a quote inside written '\''.
#pragma once

#include <string>

namespace plantsim::util {

inline std::string shell_word(const std::string& word) {
  const bool safe = !word.empty() && word.find_first_not_of(
                                         "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                         "0123456789_-./,:=+@%") == std::string::npos;
  if (safe) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace plantsim::util
