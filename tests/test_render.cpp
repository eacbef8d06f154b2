// Pixels of a rendered run: the PNG decodes at the requested size, obstacle colour at the
// rectangle centres, trajectory colour along the driven path, charger colour at the charger.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "planner/planner.h"
#include "render/palette.h"
#include "render/png_io.h"
#include "render/run_figure.h"
#include "sim/episode.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::render {
namespace {

class RenderedRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    world_ = new worlds::World(worlds::load_world(test::shared_data("worlds/world_N10.json")));
    auto p = planner::make_planner("vg", planner::planner_input(*world_, true));
    run_ = new sim::EpisodeResult(sim::run_episode(*world_, *p, {}));
    path_ = (std::filesystem::temp_directory_path() / ("plantsim_run_" + std::to_string(::getpid()) + ".png")).string();
    RunFigureOptions o;
    o.width_px = 1000;
    o.height_px = 640;
    const Image drawn = draw_run_figure(*world_, *run_, o, &transform_);
    write_png(drawn, path_);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove(path_);
    delete world_;
    delete run_;
  }
  static worlds::World* world_;
  static sim::EpisodeResult* run_;
  static std::string path_;
  static PixelTransform transform_;
};

worlds::World* RenderedRun::world_ = nullptr;
sim::EpisodeResult* RenderedRun::run_ = nullptr;
std::string RenderedRun::path_;
PixelTransform RenderedRun::transform_;

Rgb pixel_at(const Image& img, const PixelTransform& t, geom::Vec2 world) {
  const geom::Vec2 px = t.to_pixel(world);
  return img.at(static_cast<int>(px.x), static_cast<int>(px.y));
}

TEST_F(RenderedRun, DecodesAtRequestedSize) {
  const Image img = read_png(path_);
  EXPECT_EQ(img.width, 1000);
  EXPECT_EQ(img.height, 640);
}

TEST_F(RenderedRun, ObstacleColourAtRectangleCentres) {
  const Image img = read_png(path_);
  for (const auto& r : world_->obstacles) EXPECT_EQ(pixel_at(img, transform_, r.center()), palette::kObstacle);
}

TEST_F(RenderedRun, TrajectoryColourAlongTheDrivenPath) {
  ASSERT_TRUE(run_->docked);
  const Image img = read_png(path_);
  int checked = 0, hits = 0;
  // Every metre of the drive, away from the start marker and the robot drawn at the end.
  double since = 0;
  for (std::size_t i = 1; i < run_->trajectory.size(); ++i) {
    const geom::Vec2 p = run_->trajectory[i].truth.position();
    since += geom::distance(run_->trajectory[i - 1].truth.position(), p);
    if (since < 1.0) continue;
    since = 0;
    if (geom::distance(p, world_->start.position()) < 1.0 ||
        geom::distance(p, world_->charger.position()) < 1.5)
      continue;
    ++checked;
    hits += pixel_at(img, transform_, p) == palette::kTrajectory;
  }
  EXPECT_GT(checked, 50);
  EXPECT_EQ(hits, checked);
}

TEST_F(RenderedRun, ChargerWhereItBelongs) {
  const Image img = read_png(path_);
  EXPECT_EQ(pixel_at(img, transform_, worlds::charger_body(*world_).center), palette::kCharger);
}

TEST(Png, ReadingGarbageThrows) {
  const auto p = (std::filesystem::temp_directory_path() / "plantsim_garbage.png").string();
  { std::ofstream(p) << "not a png"; }
  EXPECT_THROW(read_png(p), std::runtime_error);
  std::filesystem::remove(p);
}

}  // namespace
}  // namespace plantsim::render
