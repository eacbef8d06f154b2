// A number as text with a fixed count of decimals ("%.*f"), for reports, gates and tables.
#pragma once

#include <cstdio>
#include <string>

#include "util/c_number.h"

namespace plantsim::util {

inline std::string fixed(double v, int decimals = 3) {
  char text[64];
  util::c_snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

}  // namespace plantsim::util
