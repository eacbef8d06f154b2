// Colour-vision simulation and colour difference.
#include "render/colour_vision.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace plantsim::render {

namespace {

using Linear = std::array<double, 3>;

double to_linear(unsigned char c) {
  const double v = c / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

unsigned char from_linear(double v) {
  v = std::clamp(v, 0.0, 1.0);
  const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(255.0 * s));
}

Linear linear(Rgb c) { return {to_linear(c.r), to_linear(c.g), to_linear(c.b)}; }

Linear lab(const Linear& l) {
  const double x = (0.4124 * l[0] + 0.3576 * l[1] + 0.1805 * l[2]) / 0.95047;
  const double y = 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
  const double z = (0.0193 * l[0] + 0.1192 * l[1] + 0.9505 * l[2]) / 1.08883;
  auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

}  // namespace

Rgb simulate(Rgb colour, ColourVision vision) {
  static constexpr double kProtanopia[3][3] = {{0.152286, 1.052583, -0.204868},
                                               {0.114503, 0.786281, 0.099216},
                                               {-0.003882, -0.048116, 1.051998}};
  static constexpr double kDeuteranopia[3][3] = {{0.367322, 0.860646, -0.227968},
                                                 {0.280085, 0.672501, 0.047413},
                                                 {-0.011820, 0.042940, 0.968881}};
  static constexpr double kTritanopia[3][3] = {{1.255528, -0.076749, -0.178779},
                                               {-0.078411, 0.930809, 0.147602},
                                               {0.004733, 0.691367, 0.303900}};
  const double(*m)[3] = nullptr;
  switch (vision) {
    case ColourVision::kNormal:
      return colour;
    case ColourVision::kDeuteranopia:
      m = kDeuteranopia;
      break;
    case ColourVision::kProtanopia:
      m = kProtanopia;
      break;
    case ColourVision::kTritanopia:
      m = kTritanopia;
      break;
  }
  const Linear l = linear(colour);
  unsigned char out[3];
  for (int i = 0; i < 3; ++i)
    out[i] = from_linear(m[i][0] * l[0] + m[i][1] * l[1] + m[i][2] * l[2]);
  return {out[0], out[1], out[2]};
}

double colour_difference(Rgb a, Rgb b) {
  const Linear la = lab(linear(a)), lb = lab(linear(b));
  return std::hypot(la[0] - lb[0], la[1] - lb[1], la[2] - lb[2]);
}

}  // namespace plantsim::render
