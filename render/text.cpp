// FreeType glyph rendering with a cache per (code point, size, weight).
#include "render/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <tuple>

namespace plantsim::render {
namespace {

// Decodes UTF-8 leniently: a malformed byte becomes U+FFFD.
std::vector<char32_t> decode_utf8(const std::string& s) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int extra = c < 0x80           ? 0
                      : (c >> 5) == 0x6  ? 1
                      : (c >> 4) == 0xE  ? 2
                      : (c >> 3) == 0x1E ? 3
                                         : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >=
                         s.size() + (extra == 0 ? 1 : 0)) {  // bad or cut short
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t code = extra == 0 ? c : c & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k)
      code = (code << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    out.push_back(code);
    i += extra + 1;
  }
  return out;
}

}  // namespace

struct TextRenderer::Faces {
  FT_Library library = nullptr;
  FT_Face regular = nullptr;
  FT_Face bold = nullptr;
};

std::string TextRenderer::font_path(bool bold) {
  return bold ? "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"
              : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
}

TextRenderer::TextRenderer() : faces_(std::make_unique<Faces>()) {
  if (FT_Init_FreeType(&faces_->library)) throw std::runtime_error("FreeType: cannot initialise");
  for (bool bold : {false, true}) {
    FT_Face& face = bold ? faces_->bold : faces_->regular;
    if (FT_New_Face(faces_->library, font_path(bold).c_str(), 0, &face))
      throw std::runtime_error("font " + font_path(bold) +
                               " is missing: install the Debian package fonts-dejavu-core");
  }
}

TextRenderer::~TextRenderer() {
  if (faces_->regular) FT_Done_Face(faces_->regular);
  if (faces_->bold) FT_Done_Face(faces_->bold);
  if (faces_->library) FT_Done_FreeType(faces_->library);
}

const TextRenderer::Glyph& TextRenderer::glyph(char32_t code, int size_px, bool bold) {
  const auto key = std::make_tuple(code, size_px, bold);
  auto it = cache_.find(key);
  if (it != cache_.end()) return it->second;
  FT_Face face = bold ? faces_->bold : faces_->regular;
  FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px));
  Glyph g;
  if (FT_Load_Char(face, code, FT_LOAD_RENDER) == 0) {
    const FT_GlyphSlot slot = face->glyph;
    g.width = static_cast<int>(slot->bitmap.width);
    g.rows = static_cast<int>(slot->bitmap.rows);
    g.left = slot->bitmap_left;
    g.top = slot->bitmap_top;
    g.advance = static_cast<int>(slot->advance.x >> 6);
    g.alpha.resize(static_cast<std::size_t>(g.width) * g.rows);
    for (int r = 0; r < g.rows; ++r)
      std::copy_n(slot->bitmap.buffer + r * slot->bitmap.pitch, g.width,
                  g.alpha.begin() + static_cast<std::ptrdiff_t>(r) * g.width);
  }
  return cache_.emplace(key, std::move(g)).first->second;
}

TextBox TextRenderer::layout(const std::string& text, int x, int baseline_y, int size_px,
                             Anchor anchor, bool bold, Image* image, Rgb colour) {
  const auto codes = decode_utf8(text);
  int width = 0;
  for (char32_t c : codes) width += glyph(c, size_px, bold).advance;
  int pen = anchor == Anchor::kLeft ? x : anchor == Anchor::kCenter ? x - width / 2 : x - width;
  TextBox box{pen, baseline_y, pen, baseline_y};
  bool any = false;
  for (char32_t c : codes) {
    const Glyph& g = glyph(c, size_px, bold);
    const int gx = pen + g.left, gy = baseline_y - g.top;
    if (g.width > 0 && g.rows > 0) {
      box = any ? TextBox{std::min(box.x0, gx), std::min(box.y0, gy),
                          std::max(box.x1, gx + g.width), std::max(box.y1, gy + g.rows)}
                : TextBox{gx, gy, gx + g.width, gy + g.rows};
      any = true;
    }
    if (image) {
      for (int r = 0; r < g.rows; ++r)
        for (int col = 0; col < g.width; ++col) {
          const int px = gx + col, py = gy + r;
          if (px < 0 || py < 0 || px >= image->width || py >= image->height) continue;
          const int a = g.alpha[static_cast<std::size_t>(r) * g.width + col];
          if (a == 0) continue;
          std::uint8_t* d = &image->rgba[(static_cast<std::size_t>(py) * image->width + px) * 4];
          d[0] = static_cast<std::uint8_t>((colour.r * a + d[0] * (255 - a) + 127) / 255);
          d[1] = static_cast<std::uint8_t>((colour.g * a + d[1] * (255 - a) + 127) / 255);
          d[2] = static_cast<std::uint8_t>((colour.b * a + d[2] * (255 - a) + 127) / 255);
        }
    }
    pen += g.advance;
  }
  if (!any) box = {pen, baseline_y, pen, baseline_y};
  return box;
}

TextBox TextRenderer::draw(Image& image, const std::string& text, int x, int baseline_y,
                           int size_px, Rgb colour, Anchor anchor, bool bold) {
  return layout(text, x, baseline_y, size_px, anchor, bold, &image, colour);
}

TextBox TextRenderer::measure(const std::string& text, int x, int baseline_y, int size_px,
                              Anchor anchor, bool bold) {
  return layout(text, x, baseline_y, size_px, anchor, bold, nullptr, {});
}

}  // namespace plantsim::render
