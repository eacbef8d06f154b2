// PNG map images through libpng's low-level reader. The simplified API used before converted to
// 8-bit sRGB: 16-bit samples went through a linear-to-sRGB gamma curve (a grey of 0.75, unknown
// at map_server's thresholds, became 0.88 and free) and its alpha was dropped.
#include "worlds/map_image_png.h"

#include <png.h>

#include <csetjmp>
#include <cstring>

#include "worlds/world_error.h"

namespace plantsim::worlds {
namespace {

struct MemoryInput {
  const std::string* bytes;
  std::size_t at = 0;
};

void read_from_memory(png_structp png, png_bytep out, png_size_t n) {
  auto* in = static_cast<MemoryInput*>(png_get_io_ptr(png));
  if (n > in->bytes->size() - in->at) png_error(png, "the file ends before the image does");
  std::memcpy(out, in->bytes->data() + in->at, n);
  in->at += n;
}

// libpng reports an error by this callback and must not return to it: the message is kept for
// the WorldError thrown where setjmp lands.
void on_error(png_structp png, png_const_charp message) {
  auto* text = static_cast<std::string*>(png_get_error_ptr(png));
  *text = message;
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // e.g. a damaged ancillary chunk, skipped

// libpng's structures, freed however the decoding ends.
struct Reader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~Reader() { png_destroy_read_struct(&png, &info, nullptr); }
};

// The decoding's state, outside the frame that calls setjmp: only that frame's own automatic
// variables are indeterminate after libpng's longjmp.
struct Decoding {
  Reader r;
  MemoryInput in;
  std::string error;
  MapImage image;
  std::vector<png_byte> row;
  int channels = 0, bytes_per_sample = 1, passes = 1;
  bool too_large = false;
};

// One row of a pass into the image: every pixel of a progressive row, or those of an Adam7
// (interlaced) pass, whose row buffer holds the pass's pixels only.
void keep_row(Decoding& d, png_uint_32 y, int pass) {
  MapImage& m = d.image;
  if (d.passes > 1 && !PNG_ROW_IN_INTERLACE_PASS(y, pass)) return;
  const auto sample = [&](const png_byte* p, int k) -> std::uint32_t {
    return d.bytes_per_sample == 2 ? (p[2 * k] << 8) | p[2 * k + 1] : p[k];
  };
  const std::size_t stride = static_cast<std::size_t>(d.channels) * d.bytes_per_sample;
  for (png_uint_32 x = 0; x < static_cast<png_uint_32>(m.width); ++x) {
    if (d.passes > 1 && !PNG_COL_IN_INTERLACE_PASS(x, pass)) continue;
    const png_byte* p = d.row.data() + x * stride;
    const std::size_t i = static_cast<std::size_t>(y) * m.width + x;
    m.values[i] = m.colours == 1 ? sample(p, 0) : sample(p, 0) + sample(p, 1) + sample(p, 2);
    if (!m.alpha.empty()) m.alpha[i] = static_cast<std::uint16_t>(sample(p, d.channels - 1));
  }
}

// Reads the header, checks the size, then the rows. False when libpng failed (d.error says why).
bool decode(Decoding& d) {
  png_structp png = d.r.png;
  png_infop info = d.r.info;
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, &d.in, read_from_memory);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info),
                    height = png_get_image_height(png, info);
  if (static_cast<double>(width) * height > kMaxMapPixels) {
    d.too_large = true;
    return false;
  }
  // Palettes and grey below 8 bits expanded to 8, a tRNS colour to an alpha channel (as
  // map_server's image library reads it); 16-bit samples and the file's gamma left alone.
  const int colour_type = png_get_color_type(png, info);
  if (colour_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (colour_type == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8)
    png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  d.passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  d.channels = png_get_channels(png, info);
  d.bytes_per_sample = png_get_bit_depth(png, info) == 16 ? 2 : 1;
  MapImage& m = d.image;
  m.width = static_cast<int>(width);
  m.height = static_cast<int>(height);
  m.max_value = d.bytes_per_sample == 2 ? 65535 : 255;
  m.colours = d.channels >= 3 ? 3 : 1;
  m.values.assign(static_cast<std::size_t>(width) * height, 0);
  if (d.channels == 2 || d.channels == 4) m.alpha.assign(m.values.size(), 0);
  d.row.assign(png_get_rowbytes(png, info), 0);
  for (int pass = 0; pass < d.passes; ++pass)
    for (png_uint_32 y = 0; y < height; ++y) {
      png_read_row(png, d.row.data(), nullptr);
      keep_row(d, y, pass);
    }
  return true;
}

}  // namespace

MapImage decode_png_map(const std::string& bytes, const std::string& path) {
  Decoding d;
  d.in.bytes = &bytes;
  d.r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &d.error, on_error, on_warning);
  if (d.r.png) d.r.info = png_create_info_struct(d.r.png);
  if (!d.r.png || !d.r.info) throw WorldError(path, "", "no memory to decode a PNG image");
  if (!decode(d)) {
    if (d.too_large) throw WorldError(path, "", "image too large (over 64 Mpixel)");
    throw WorldError(path, "", "not a readable PNG image: " + d.error);
  }
  return std::move(d.image);
}

}  // namespace plantsim::worlds
