// Text drawn into images with FreeType and Debian's DejaVu Sans (package fonts-dejavu-core):
// anti-aliased glyphs alpha-blended onto an Image, with measuring and anchoring so that
// titles, tick labels and legends can be placed exactly.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/image.h"

namespace plantsim::render {

enum class Anchor { kLeft, kCenter, kRight };

struct TextBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixels the text covers (inclusive-exclusive)
};

class TextRenderer {
 public:
  /// Loads DejaVu Sans (regular and bold); throws std::runtime_error naming a missing font.
  TextRenderer();
  ~TextRenderer();
  TextRenderer(const TextRenderer&) = delete;
  TextRenderer& operator=(const TextRenderer&) = delete;

  /// Draws UTF-8 `text` with its baseline at row `baseline_y`; `x` is the left end, centre or
  /// right end per `anchor`. Returns the box it covers.
  TextBox draw(Image& image, const std::string& text, int x, int baseline_y, int size_px,
               Rgb colour, Anchor anchor = Anchor::kLeft, bool bold = false);
  /// Width in pixels and the box the text would cover, without drawing.
  TextBox measure(const std::string& text, int x, int baseline_y, int size_px,
                  Anchor anchor = Anchor::kLeft, bool bold = false);

  static std::string font_path(bool bold);

 private:
  struct Glyph {
    int width = 0, rows = 0, left = 0, top = 0, advance = 0;
    std::vector<std::uint8_t> alpha;
  };
  const Glyph& glyph(char32_t code, int size_px, bool bold);
  TextBox layout(const std::string& text, int x, int baseline_y, int size_px, Anchor anchor,
                 bool bold, Image* image, Rgb colour);

  struct Faces;
  std::unique_ptr<Faces> faces_;
  std::map<std::tuple<char32_t, int, bool>, Glyph> cache_;
};

}  // namespace plantsim::render
