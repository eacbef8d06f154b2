// Cividis control points (Nuñez et al. 2018, as matplotlib publishes it, at six points) and tick
// arithmetic.
#include "render/colormap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "util/c_number.h"

namespace plantsim::render {

Rgb cividis(double t) {
  static const double kPoints[6][3] = {{0, 34, 78},     {53, 69, 108},   {102, 105, 112},
                                       {148, 142, 119}, {200, 184, 102}, {254, 232, 56}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 5.0;
  const int i = std::min(static_cast<int>(t), 4);
  const double f = t - i;
  auto mix = [&](int c) {
    return static_cast<std::uint8_t>(
        std::lround(kPoints[i][c] + f * (kPoints[i + 1][c] - kPoints[i][c])));
  };
  return {mix(0), mix(1), mix(2)};
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> out;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
  const double raw = (hi - lo) / std::max(1, target);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
    out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  return out;
}

std::string tick_label(double value, double step) {
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  char buf[64];
  util::c_snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

}  // namespace plantsim::render
