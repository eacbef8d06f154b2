// ROS map_server maps: thresholds and modes, merging into rectangles, automatic charger and
// start placement, bad files, and docking on both shared maps.
#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <fstream>

#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "scratch_folder.h"
#include "test_paths.h"
#include "worlds/ros_map.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim::worlds {
namespace {

using TinyMaps = test::ScratchFolder;

TEST_F(TinyMaps, TrinaryNegateAndRawModes) {
  // One row: black (occupied), white (free), mid grey (unknown), near-white (free at 0.196).
  write("row.pgm", "P2\n# a comment\n4 1\n255\n0 255 128 210\n");
  const std::string yaml =
      "image: row.pgm\nresolution: 0.5\norigin: [1.0, 2.0, 0.0]\noccupied_thresh: "
      "0.65\nfree_thresh: 0.196\n";
  const RosMap m = load_ros_map(write("row.yaml", yaml + "negate: 0\n"));
  EXPECT_EQ(std::string(m.grid.cells.begin(), m.grid.cells.end()), "@.@.");
  EXPECT_EQ(m.occupied, 1u);
  EXPECT_EQ(m.unknown, 1u);
  EXPECT_EQ(m.free, 2u);
  const RosMap n = load_ros_map(write("neg.yaml", yaml + "negate: 1\n"));
  EXPECT_EQ(std::string(n.grid.cells.begin(), n.grid.cells.end()),
            ".@@@");  // white is occupied when negated
  write("raw.pgm", "P2\n4 1\n255\n0 100 50 10\n");
  const RosMap r = load_ros_map(
      write("raw.yaml",
            "image: raw.pgm\nresolution: 0.5\norigin: [0, 0, 0]\noccupied_thresh: 0.65\n"
            "free_thresh: 0.196\nmode: raw\n"));
  EXPECT_EQ(std::string(r.grid.cells.begin(), r.grid.cells.end()), ".@@.");
}

// map_server reads PNG images too: the same pixels as PNG give the same map as PGM.
TEST_F(TinyMaps, PngImagesReadLikePgm) {
  // One row of 4 pixels, written with libpng's simplified API.
  auto write_row_png = [&](const char* name, png_uint_32 format, const unsigned char* pixels) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = 4;
    image.height = 1;
    image.format = format;
    return png_image_write_to_file(&image, (dir_ / name).c_str(), 0, pixels, 0, nullptr) != 0;
  };
  const unsigned char gray[4] = {0, 255, 128, 210};
  ASSERT_TRUE(write_row_png("row.png", PNG_FORMAT_GRAY, gray));
  // And as colour, where map_server averages the channels.
  const unsigned char rgb[12] = {0, 0, 0, 255, 255, 255, 128, 128, 128, 200, 220, 210};
  ASSERT_TRUE(write_row_png("rgb.png", PNG_FORMAT_RGB, rgb));
  const std::string yaml =
      "resolution: 0.5\norigin: [1.0, 2.0, 0.0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  const RosMap m = load_ros_map(write("png.yaml", "image: row.png\n" + yaml));
  EXPECT_EQ(std::string(m.grid.cells.begin(), m.grid.cells.end()), "@.@.");
  EXPECT_EQ(m.free, 2u);
  const RosMap c = load_ros_map(write("rgb.yaml", "image: rgb.png\n" + yaml));
  EXPECT_EQ(std::string(c.grid.cells.begin(), c.grid.cells.end()), "@.@.");
}

TEST_F(TinyMaps, BadFilesNameFileAndField) {
  auto expect = [](const std::string& path, const std::string& needle) {
    try {
      load_ros_map(path);
      ADD_FAILURE() << path;
    } catch (const WorldError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect(write("a.yaml",
               "image: none.pgm\nresolution: 0.05\norigin: [0,0,0]\noccupied_thresh: "
               "0.65\nfree_thresh: 0.2\n"),
         "none.pgm: cannot be opened");
  expect(
      write("b.yaml", "image: x.pgm\norigin: [0,0,0]\noccupied_thresh: 0.65\nfree_thresh: 0.2\n"),
      "field 'resolution': missing");
  expect(write("c.yaml",
               "image: x.pgm\nresolution: -1\norigin: [0,0,0]\noccupied_thresh: 0.65\nfree_thresh: "
               "0.2\n"),
         "field 'resolution': must be from 0.001 to 10 m per pixel");
  expect(write("d.yaml",
               "image: x.pgm\nresolution: 1\norigin: [0,0,0.5]\noccupied_thresh: "
               "0.65\nfree_thresh: 0.2\n"),
         "rotated map");
  write("short.pgm", "P5\n10 10\n255\nabc");
  expect(write("e.yaml",
               "image: short.pgm\nresolution: 1\norigin: [0,0,0]\noccupied_thresh: "
               "0.65\nfree_thresh: 0.2\n"),
         "file ends before the last pixel");
  expect(write("f.yaml", "[1, 2"), "malformed YAML");
  // yaml-cpp keeps the first of two copies of a key silently: which resolution was meant?
  expect(write("twice.yaml",
               "image: x.pgm\nresolution: 0.05\nresolution: 0.5\norigin: [0,0,0]\n"
               "occupied_thresh: 0.65\nfree_thresh: 0.2\n"),
         "field 'resolution': given twice in one mapping");
  write("text.pgm",
        "P2\n1000000 1000000\n255\n0 0 0\n");  // a header promising more than the file holds
  expect(write("g.yaml",
               "image: text.pgm\nresolution: 0.05\norigin: [0,0,0]\noccupied_thresh: "
               "0.65\nfree_thresh: 0.2\n"),
         "image too large");
  write("png.pgm", "GIF89a");
  expect(write("h.yaml",
               "image: png.pgm\nresolution: 0.05\norigin: [0,0,0]\noccupied_thresh: "
               "0.65\nfree_thresh: 0.2\n"),
         "not a PGM (P5, P2) or PNG image");
}

TEST(SharedRosMaps, MergedIntoFewRectanglesCoveringTheBlockedArea) {
  for (const char* name : {"depot", "tb3_sandbox"}) {
    const RosMap m = load_ros_map(test::shared_data(std::string("ros_maps/") + name + ".yaml"));
    const World w = load_world(test::shared_data(std::string("ros_maps/") + name + ".yaml"));
    const std::size_t blocked = m.occupied + m.unknown;
    double area = 0;
    for (const auto& r : w.obstacles) area += r.width() * r.height();
    EXPECT_NEAR(area, blocked * m.resolution_m * m.resolution_m, 1e-6 * blocked) << name;
    EXPECT_LT(w.obstacles.size() * 4, blocked)
        << name << ": merging must reduce the count well below the pixels";
    std::printf("%s: %zu occupied + %zu unknown pixels merged into %zu rectangles\n", name,
                m.occupied, m.unknown, w.obstacles.size());
  }
}

TEST(SharedRosMaps, AutomaticPlacementDocksOnBothMaps) {
  for (const char* name : {"depot", "tb3_sandbox"}) {
    const World w = load_world(test::shared_data(std::string("ros_maps/") + name + ".yaml"));
    auto p = planner::make_planner("vg", planner::planner_input(w, true));
    const episode::EpisodeResult r = episode::run_episode(w, *p, {});
    EXPECT_TRUE(r.docked) << name << ": " << episode::status_name(r);
    EXPECT_EQ(r.collisions, 0) << name;
  }
}

}  // namespace
}  // namespace plantsim::worlds
