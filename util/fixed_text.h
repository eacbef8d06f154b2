// A number as text with a fixed count of decimals ("%.*f"), for reports, gates and tables.
#pragma once

#include <cstdio>
#include <string>

namespace plantsim::util {

inline std::string fixed(double v, int decimals = 3) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

}  // namespace plantsim::util
