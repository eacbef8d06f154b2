// Checks every figure type must pass: text inside the canvas and no two texts overlapping;
// every legend entry's colour drawn somewhere outside the legends (its layer is in the picture).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "render/figure.h"
#include "render/image.h"

namespace plantsim::test {

using render::FigureLayout;
using render::Image;
using render::LegendEntry;
using render::PixelBox;
using render::Rgb;
using render::TextBox;

inline bool inside(const PixelBox& b, int x, int y) {
  return x >= b.left && x < b.right && y >= b.top && y < b.bottom;
}

/// Pixels within `tolerance` (per channel) of colour c, outside every legend box and every text.
inline int pixels_of(const Image& img, Rgb c, const FigureLayout& layout, int tolerance = 8) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const Rgb p = img.at(x, y);
      if (std::abs(p.r - c.r) > tolerance || std::abs(p.g - c.g) > tolerance ||
          std::abs(p.b - c.b) > tolerance)
        continue;
      bool excluded = false;
      for (const PixelBox& b : layout.legend_boxes) excluded = excluded || inside(b, x, y);
      for (const TextBox& t : layout.text_boxes)
        excluded = excluded || (x >= t.x0 && x < t.x1 && y >= t.y0 && y < t.y1);
      n += !excluded;
    }
  return n;
}

inline bool has_legend(const FigureLayout& layout, const std::string& label) {
  for (const LegendEntry& e : layout.legend)
    if (e.label == label) return true;
  return false;
}

inline void expect_sound_layout(const Image& img, const FigureLayout& layout,
                                const std::string& figure) {
  ASSERT_EQ(layout.texts.size(), layout.text_boxes.size());
  for (std::size_t i = 0; i < layout.text_boxes.size(); ++i) {
    const TextBox& b = layout.text_boxes[i];
    EXPECT_TRUE(b.x0 >= 0 && b.y0 >= 0 && b.x1 <= img.width && b.y1 <= img.height)
        << figure << ": '" << layout.texts[i] << "' leaves the canvas (" << b.x0 << "," << b.y0
        << ")-(" << b.x1 << "," << b.y1 << ")";
    for (std::size_t j = i + 1; j < layout.text_boxes.size(); ++j)
      EXPECT_FALSE(render::overlaps(b, layout.text_boxes[j]))
          << figure << ": '" << layout.texts[i] << "' overlaps '" << layout.texts[j] << "'";
  }
  for (const LegendEntry& e : layout.legend)
    EXPECT_GT(pixels_of(img, e.colour, layout), 3)
        << figure << ": legend entry '" << e.label << "' is not drawn";
}

}  // namespace plantsim::test
