// libpng glue: memory-buffer write callbacks and the simplified read API.
#include "render/png_io.h"

#include <png.h>
#include <zlib.h>

#include <stdexcept>

#include "util/atomic_file.h"
#include "util/build_stamp.h"

namespace plantsim::render {
namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

void flush_nothing(png_structp) {}

}  // namespace

std::string encode_png(const Image& image, const PngSettings& settings) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) throw std::runtime_error("libpng: cannot create write struct");
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw std::runtime_error("libpng: cannot create info struct");
  }
  std::string out;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng: encoding failed");
  }
  png_set_write_fn(png, &out, append_bytes, flush_nothing);
  // Figures are opaque: RGB, a quarter less data to compress than RGBA.
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, settings.compression_level);
  if (settings.run_length) png_set_compression_strategy(png, Z_RLE);
  png_set_filter(png, PNG_FILTER_TYPE_BASE,
                 settings.adaptive_filters ? PNG_ALL_FILTERS : PNG_FILTER_NONE);
  // Which build drew it (a figure's own record; the date is in the report beside it, so that
  // the same figure drawn twice is the same file).
  const std::string software = util::build_stamp().text();
  png_text text{};
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = const_cast<char*>("Software");
  text.text = const_cast<char*>(software.c_str());
  png_set_text(png, info, &text, 1);
  png_write_info(png, info);
  png_set_filler(png, 0, PNG_FILLER_AFTER);  // rows are given as RGBA; the filler byte is dropped
  for (int row = 0; row < image.height; ++row)
    png_write_row(png, image.rgba.data() + static_cast<std::size_t>(row) * image.width * 4);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

void write_png(const Image& image, const std::string& path, const PngSettings& settings) {
  util::write_file_atomically(path, encode_png(image, settings));
}

Image read_png(const std::string& path) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str()))
    throw std::runtime_error(path + ": not a readable PNG (" + img.message + ")");
  img.format = PNG_FORMAT_RGBA;
  Image out;
  out.width = static_cast<int>(img.width);
  out.height = static_cast<int>(img.height);
  out.rgba.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.rgba.data(), 0, nullptr)) {
    png_image_free(&img);
    throw std::runtime_error(path + ": PNG decoding failed (" + img.message + ")");
  }
  return out;
}

}  // namespace plantsim::render
