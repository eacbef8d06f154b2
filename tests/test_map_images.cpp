// Map images read as map_server reads them (issue 85): 16-bit samples scaled exactly (no gamma
// curve), alpha kept (a transparent cell is not free), interlaced PNG like progressive, sizes
// refused from the header. The PNGs are written here with libpng's low-level writer, which
// stores the samples as given.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "scratch_folder.h"
#include "worlds/ros_map.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {
namespace {

class MapImages : public test::ScratchFolder {
 protected:
  // A PNG of `width` x (samples / channels / width) pixels, samples row by row.
  void write_png(const std::string& name, int width, int depth, int colour_type,
                 const std::vector<std::uint16_t>& samples, bool interlaced = false) {
    const int channels = colour_type == PNG_COLOR_TYPE_GRAY         ? 1
                         : colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                         : colour_type == PNG_COLOR_TYPE_RGB        ? 3
                                                                    : 4;
    const int height = static_cast<int>(samples.size()) / channels / width;
    const int bytes = depth / 8;
    std::vector<std::vector<png_byte>> rows(height);
    for (int y = 0; y < height; ++y)
      for (int k = 0; k < width * channels; ++k) {
        const std::uint16_t v = samples[static_cast<std::size_t>(y) * width * channels + k];
        if (bytes == 2) rows[y].push_back(static_cast<png_byte>(v >> 8));
        rows[y].push_back(static_cast<png_byte>(v & 0xff));
      }
    std::vector<png_bytep> pointers;
    for (auto& r : rows) pointers.push_back(r.data());
    FILE* f = std::fopen((dir_ / name).c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, width, height, depth, colour_type,
                 interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
  }

  RosMap load(const std::string& image, const std::string& mode = "trinary") {
    return load_ros_map(write("map.yaml", "image: " + image +
                                              "\nresolution: 0.5\norigin: [0, 0, 0]\n"
                                              "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: " +
                                              mode + "\n"));
  }
  static std::string cells(const RosMap& m) { return {m.grid.cells.begin(), m.grid.cells.end()}; }
};

// 0.75 of white is unknown at these thresholds (occupancy 0.25): the simplified API's
// linear-to-sRGB curve made it 0.88, free, and the planner crossed it.
TEST_F(MapImages, SixteenBitGreyIsScaledExactlyWithoutAGammaCurve) {
  write_png("grey16.png", 4, 16, PNG_COLOR_TYPE_GRAY, {0x0000, 0xFFFF, 0xC000, 0x3333});
  const RosMap m = load("grey16.png");
  EXPECT_EQ(cells(m), "@.@@");
  EXPECT_EQ(m.occupied, 2u);  // black, and 0.2 of white (occupancy 0.8)
  EXPECT_EQ(m.unknown, 1u);
  EXPECT_EQ(m.free, 1u);
  // The same shades in 8 bits read the same.
  write_png("grey8.png", 4, 8, PNG_COLOR_TYPE_GRAY, {0x00, 0xFF, 0xC0, 0x33});
  EXPECT_EQ(cells(load("grey8.png")), "@.@@");
}

// map_server (Nav2's map_io) averages alpha in as a fourth channel in trinary mode and makes a
// pixel not fully opaque unknown in scale mode; alpha was dropped, so transparent white was free.
TEST_F(MapImages, SixteenBitGreyWithAlphaMakesTransparentCellsUnknown) {
  // White opaque, white transparent, white barely transparent, black opaque.
  write_png("ga16.png", 4, 16, PNG_COLOR_TYPE_GRAY_ALPHA,
            {0xFFFF, 0xFFFF, 0xFFFF, 0x0000, 0xFFFF, 0xFFFE, 0x0000, 0xFFFF});
  const RosMap trinary = load("ga16.png");
  EXPECT_EQ(cells(trinary), ".@.@");  // (3 + 0) / 4 = 0.75 of white: unknown
  EXPECT_EQ(trinary.unknown, 1u);
  const RosMap scale = load("ga16.png", "scale");
  EXPECT_EQ(cells(scale), ".@@@");
  EXPECT_EQ(scale.unknown, 2u);
  EXPECT_EQ(scale.occupied, 1u);
}

TEST_F(MapImages, EightBitRgbaTransparentCellsAreUnknownInEveryMode) {
  // Opaque white, transparent white, transparent black, opaque mid grey; then a row of raw
  // values: opaque 0 (free), transparent 0.
  write_png("rgba.png", 4, 8, PNG_COLOR_TYPE_RGB_ALPHA,
            {255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0, 0,   128, 128, 128, 255,
             0,   0,   0,   255, 0,   0,   0,   0, 0, 0, 0, 255, 0,   0,   0,   0});
  const RosMap trinary = load("rgba.png");
  EXPECT_EQ(cells(trinary),
            ".@@@"
            "@@@@");
  EXPECT_EQ(trinary.free, 1u);
  const RosMap raw = load("rgba.png", "raw");
  EXPECT_EQ(cells(raw),
            "@@@@"
            ".@.@");           // raw 0 is free, transparent is unknown
  EXPECT_EQ(raw.unknown, 6u);  // 255 and 128 are no percentage; 4 transparent
}

TEST_F(MapImages, AnInterlacedPngReadsAsTheSamePixels) {
  std::vector<std::uint16_t> samples;
  for (int i = 0; i < 11 * 9; ++i) samples.push_back((i * 37) % 7 < 3 ? 0 : 0xFFFF);
  write_png("flat.png", 11, 16, PNG_COLOR_TYPE_GRAY, samples);
  write_png("adam7.png", 11, 16, PNG_COLOR_TYPE_GRAY, samples, true);
  const std::string flat = cells(load("flat.png"));
  EXPECT_EQ(cells(load("adam7.png")), flat);
  EXPECT_NE(flat.find('.'), std::string::npos);
  EXPECT_NE(flat.find('@'), std::string::npos);
}

// The sizes come from the header, before any pixel buffer: a header claiming 10^10 pixels in a
// few bytes is refused at once; a PGM sample above its header's maximum has no shade.
TEST_F(MapImages, SizesAreCheckedFromTheHeaderAndPgmSamplesWithinTheirMaximum) {
  write_png("small.png", 1, 8, PNG_COLOR_TYPE_GRAY, {0});
  std::ifstream in(dir_ / "small.png", std::ios::binary);
  std::string png((std::istreambuf_iterator<char>(in)), {});
  // IHDR's width and height (bytes 16..23) raised to 100000 x 100000, its CRC (over the
  // chunk's type and data, bytes 12..28) made to match; the pixel data stays one pixel's.
  const unsigned char huge[8] = {0, 1, 0x86, 0xA0, 0, 1, 0x86, 0xA0};
  png.replace(16, 8, reinterpret_cast<const char*>(huge), 8);
  const auto crc =
      static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(png.data() + 12), 17));
  for (int k = 0; k < 4; ++k) png[29 + k] = static_cast<char>(crc >> (24 - 8 * k));
  write("huge.png", png);
  try {
    load("huge.png");
    ADD_FAILURE() << "a 10^10-pixel header was accepted";
  } catch (const WorldError& e) {
    EXPECT_NE(std::string(e.what()).find("image too large (over 64 Mpixel)"), std::string::npos)
        << e.what();
  }
  write("huge.pgm", "P5\n100000 100000\n255\n");
  try {
    load("huge.pgm");
    ADD_FAILURE() << "a 10^10-pixel PGM header was accepted";
  } catch (const WorldError& e) {
    EXPECT_NE(std::string(e.what()).find("image too large"), std::string::npos) << e.what();
  }
  write("over.pgm", std::string("P5\n2 1\n100\n") + char(0) + char(200));
  try {
    load("over.pgm");
    ADD_FAILURE() << "a sample of 200 under a maximum of 100 was read";
  } catch (const WorldError& e) {
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plantsim::worlds
