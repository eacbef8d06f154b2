// Pixels of a rendered run: the PNG decodes at the requested size, obstacle colour at the
// rectangle centres, trajectory colour along the driven path, charger colour at the charger.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "figure_checks.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "render/colormap.h"
#include "render/comparison_figure.h"
#include "render/figure.h"
#include "render/layers.h"
#include "render/palette.h"
#include "render/png_io.h"
#include "render/replay_html.h"
#include "render/report.h"
#include "render/run_figure.h"
#include "render/text.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::render {
namespace {

class RenderedRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    world_ = new worlds::World(worlds::load_world(test::shared_data("worlds/world_N10.json")));
    auto p = planner::make_planner("vg", planner::planner_input(*world_, true));
    run_ = new episode::EpisodeResult(episode::run_episode(*world_, *p, {}));
    path_ = (std::filesystem::temp_directory_path() /
             ("plantsim_run_" + std::to_string(::getpid()) + ".png"))
                .string();
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
  static episode::EpisodeResult* run_;
  static std::string path_;
  static PixelTransform transform_;
};

worlds::World* RenderedRun::world_ = nullptr;
episode::EpisodeResult* RenderedRun::run_ = nullptr;
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
  for (const auto& r : world_->obstacles)
    EXPECT_EQ(pixel_at(img, transform_, r.center()), palette::kObstacle);
}

// The driven path is coloured by speed: its pixels lie on the cividis colour map.
bool on_cividis(Rgb c) {
  for (int k = 0; k <= 1000; ++k) {
    const Rgb v = cividis(k / 1000.0);
    if (std::abs(v.r - c.r) <= 3 && std::abs(v.g - c.g) <= 3 && std::abs(v.b - c.b) <= 3)
      return true;
  }
  return false;
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
    // The plan is drawn thin over the path: the path shows on either side of it.
    const geom::Vec2 px = transform_.to_pixel(p);
    bool seen = false;
    for (int dy = -2; dy <= 2 && !seen; ++dy)
      for (int dx = -2; dx <= 2 && !seen; ++dx)
        seen = on_cividis(img.at(static_cast<int>(px.x) + dx, static_cast<int>(px.y) + dy));
    hits += seen;
  }
  EXPECT_GT(checked, 50);
  EXPECT_EQ(hits, checked);
}

TEST_F(RenderedRun, ChargerWhereItBelongs) {
  const Image img = read_png(path_);
  EXPECT_EQ(pixel_at(img, transform_, worlds::charger_body(*world_).center), palette::kCharger);
}

TEST(Text, ProducesInkInsideItsBoxAndNoneOutside) {
  Image img;
  img.width = 300;
  img.height = 80;
  img.rgba.assign(300 * 80 * 4, 255);
  TextRenderer& tr = shared_text_renderer();
  const TextBox box = tr.draw(img, "Docked 0.4 cm", 20, 50, 24, {0, 0, 0});
  EXPECT_EQ(box.x0, tr.measure("Docked 0.4 cm", 20, 50, 24).x0);
  int inside = 0, outside = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const bool ink = img.at(x, y).r < 128;
      const bool in_box = x >= box.x0 && x < box.x1 && y >= box.y0 && y < box.y1;
      (in_box ? inside : outside) += ink;
    }
  EXPECT_GT(inside, 200);
  EXPECT_EQ(outside, 0);
  EXPECT_LT(box.y1, 50 + 8);   // descenders only just below the baseline
  EXPECT_GT(box.y0, 50 - 24);  // no taller than the size
  const TextBox centred = tr.measure("abc", 150, 50, 24, Anchor::kCenter);
  EXPECT_NEAR(0.5 * (centred.x0 + centred.x1), 150, 3);
}

TEST_F(RenderedRun, ReportReferencesOnlyFilesThatExist) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("plantsim_report_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_png(draw_run_figure(*world_, *run_), (dir / "run.png").string());
  write_png(draw_time_plots(*world_, *run_), (dir / "timeplots.png").string());
  { std::ofstream((dir / "summary.json").string()) << "{}"; }
  Report r;  // by member: a field added to Report must not break this
  r.title = "test <report>";
  r.command = "plantsim run x";
  r.headers = {"a"};
  r.rows = {{"1"}};
  r.figures = {{"run.png", "run"}, {"timeplots.png", "plots"}};
  r.files = {"summary.json"};
  r.notes = "notes & more";
  r.made_by = "Made by <a build>";
  write_report(r, (dir / "report.html").string());
  std::ifstream f((dir / "report.html").string());
  const std::string html((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("test &lt;report&gt;"), std::string::npos);  // escaped
  const auto refs = referenced_files(html);
  EXPECT_EQ(refs.size(), 3u);
  for (const auto& ref : refs) {
    EXPECT_TRUE(std::filesystem::exists(dir / ref)) << ref;
    EXPECT_EQ(ref.find("://"), std::string::npos) << "offline: no remote links";
  }
  const Image plots = read_png((dir / "timeplots.png").string());
  EXPECT_EQ(plots.width, 1280);
  std::filesystem::remove_all(dir);
}

// A name that HTML would read as markup inside the player's data block: "</script>" ending it, or
// "<!--<script>" opening the parser's escaped states (which hid the player). The block holds
// no "<" at all and reads back to the name.
TEST_F(RenderedRun, AHostileWorldNameStaysInsideTheReplaysData) {
  worlds::World w = *world_;
  w.name = "<!--<script>x</script><!-- & -->";
  const std::string html = replay_html(w, *run_);
  const std::string open = "<script type=\"application/json\" id=\"replay-data\">";
  const std::size_t begin = html.find(open) + open.size();
  const std::size_t end = html.find("</script>", begin);
  ASSERT_NE(end, std::string::npos);
  const std::string data = html.substr(begin, end - begin);
  EXPECT_EQ(data.find_first_of("<>&"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(data)["world"], w.name);
  EXPECT_EQ(html.find("<!--"), std::string::npos);
}

TEST_F(RenderedRun, ComparisonPanelsShareTheScale) {
  ComparisonPanel a{"vg", *run_, {}, true}, b{"vg-traditional", *run_, {}, true};
  const Image img = draw_comparison(*world_, {a, b}, "test", 1600, 500);
  EXPECT_EQ(img.width, 1600);
  // Title and legend: 110 px (both panels show one planner's run, so no line of differences).
  const int top = 110;
  EXPECT_EQ(img.height, top + 500);
  // Panel 0's box as draw_comparison lays it out (margins 60/80/20/45); panel 1 is the same box
  // 800 pixels to the right, so every obstacle centre repeats there.
  const int h = img.height;
  const PixelTransform t =
      PixelTransform::fit(world_->floor, 60, h - (top + 500 - 45), 800 - 20, h - (top + 80), h);
  for (const auto& r : world_->obstacles) {
    const geom::Vec2 p = t.to_pixel(r.center());
    EXPECT_EQ(img.at(static_cast<int>(p.x), static_cast<int>(p.y)), palette::kObstacle);
    EXPECT_EQ(img.at(static_cast<int>(p.x) + 800, static_cast<int>(p.y)), palette::kObstacle);
  }
}

TEST(Png, ReadingGarbageThrows) {
  const auto p = (std::filesystem::temp_directory_path() / "plantsim_garbage.png").string();
  { std::ofstream(p) << "not a png"; }
  EXPECT_THROW(read_png(p), std::runtime_error);
  std::filesystem::remove(p);
}

}  // namespace
}  // namespace plantsim::render

namespace plantsim::render {
namespace {

// A plant that differs from its map: unmapped boxes outlined and hatched in their own colour
// (never filled like the map's), the mapped charger outlined where the map has it, the sensed
// layer drawn, and each of these in the legend.
TEST(RenderedMismatch, UnmappedHatchedMappedChargerOutlinedLayerDrawnAndInTheLegend) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/examples/small_plant_mismatch.json"));
  auto p = planner::make_planner("vg", planner::planner_input(w, true));
  const episode::EpisodeResult run = episode::run_episode(w, *p, {});
  ASSERT_FALSE(run.layer_final.empty());
  RunFigureOptions o;
  o.width_px = 1600;
  o.height_px = 1000;
  PixelTransform t;
  FigureLayout layout;
  const Image img = draw_run_figure(w, run, o, &t, &layout);
  test::expect_sound_layout(img, layout, "mismatch run figure");
  if (std::getenv("PLANTSIM_KEEP")) write_png(img, "/tmp/mismatch_render.png");
  // Pixels of the colour or of its blend with the floor, at least a quarter strong (thin
  // anti-aliased lines are mostly blend).
  auto near = [](Rgb px, Rgb c) {
    const Rgb f = palette::kFloor;
    const double a = (static_cast<double>(f.g) - px.g) / (static_cast<double>(f.g) - c.g);
    if (a < 0.25 || a > 1.05) return false;
    auto off = [&](double fc, double cc, double pc) { return std::fabs(fc + a * (cc - fc) - pc); };
    return off(f.r, c.r, px.r) < 20 && off(f.b, c.b, px.b) < 20;
  };
  auto count = [&](const geom::Rect& r, Rgb c) {
    const geom::Vec2 a = t.to_pixel({r.xmin, r.ymax}), b = t.to_pixel({r.xmax, r.ymin});
    int n = 0;
    for (int y = static_cast<int>(a.y); y <= static_cast<int>(b.y); ++y)
      for (int x = static_cast<int>(a.x); x <= static_cast<int>(b.x); ++x)
        n += near(img.at(x, y), c);
    return n;
  };
  for (const geom::Rect& u : w.unmapped) {
    const int inside = count(u, palette::kUnmapped),
              area = static_cast<int>(u.width() * u.height() * t.scale * t.scale);
    EXPECT_GT(inside, area / 20) << "hatch and outline drawn";
    EXPECT_LT(count(u, palette::kObstacle), area / 20) << "not filled like a mapped obstacle";
  }
  // The mapped charger's outline: its colour around where the map has it, 5 cm off the real one.
  worlds::World on_map = worlds::robot_map(w);
  const geom::Rect mapped = worlds::charger_body(on_map).bounding_box().inflated(0.03);
  EXPECT_GT(count(mapped, palette::kCharger), 0);
  // Each new layer in the legend.
  EXPECT_TRUE(test::has_legend(layout, "not on map"));
  EXPECT_TRUE(test::has_legend(layout, "sensed layer"));
  EXPECT_TRUE(test::has_legend(layout, "mapped charger"));
  // Stops and replans marked where they happened, and in the legend.
  ASSERT_GT(run.replans, 0);
  ASSERT_GT(run.stops, 0);
  EXPECT_TRUE(test::has_legend(layout, "replan"));
  EXPECT_TRUE(test::has_legend(layout, "stop"));
  int replans = 0;
  for (const auto& e : run.events) {
    if (e.kind != episode::EpisodeResult::Event::Kind::kReplan) continue;
    ++replans;
    const double r = 9.0 / t.scale;
    EXPECT_GT(count({e.at.x - r - 0.05, e.at.y - r - 0.05, e.at.x + r + 0.05, e.at.y + r + 0.05},
                    palette::kReplanMark),
              0);
  }
  EXPECT_EQ(replans, run.replans);
  // The replay shows the plan in force: the first until the last replan, the final one after.
  const std::string html = replay_html(w, run);
  const std::size_t data_at = html.find("<script type=\"application/json\" id=\"replay-data\">");
  ASSERT_NE(data_at, std::string::npos);
  const std::size_t begin = html.find('>', data_at) + 1;
  const auto data =
      nlohmann::json::parse(html.substr(begin, html.find("</script>", begin) - begin));
  double last_replan_s = 0;
  for (const auto& e : run.events)
    if (e.kind == episode::EpisodeResult::Event::Kind::kReplan) last_replan_s = e.t_s;
  if (!data["first_plan"].empty())
    EXPECT_NEAR(data["plan_from_t"].get<double>(), last_replan_s, 1e-3);
  else
    EXPECT_EQ(data["plan_from_t"].get<double>(), 0.0);
  EXPECT_GT(data["plan_from_t"].get<double>() + data["first_plan"].empty(), 0.0);
  EXPECT_EQ(data["moving_label"], moving_tracks_label(run.moving_tracks));
  // Pure pursuit samples no trajectories: none in the replay (and none in its legend).
  EXPECT_TRUE(data["sketches"].empty());
}

// A sampling controller's sketches reach the replay at their times, to the centimetre, thinned
// to 400 at most however long the episode.
TEST(Replay, CarriesTheControllersSampledAndChosenTrajectories) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/examples/small_plant.json"));
  episode::EpisodeResult run;
  for (int k = 0; k < 1000; ++k)
    run.controller_sketches.push_back(
        {1.0 * k,
         {{{{0.0, 0.0}, {1.004, 2.0}}, {{0.0, 0.0}, {1.0, -2.0}}}, {{0.0, 0.0}, {0.5, 0.123}}}});
  const std::string html = replay_html(w, run);
  const std::size_t begin = html.find('>', html.find("id=\"replay-data\"")) + 1;
  const auto data =
      nlohmann::json::parse(html.substr(begin, html.find("</script>", begin) - begin));
  const auto& sketches = data["sketches"];
  ASSERT_EQ(sketches.size(), 334u);  // every third of 1,000
  EXPECT_EQ(sketches[1]["t"].get<double>(), 3.0);
  ASSERT_EQ(sketches[1]["s"].size(), 2u);
  EXPECT_NEAR(sketches[1]["s"][0][1][0].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(sketches[1]["c"][1][1].get<double>(), 0.12, 1e-9);
}

}  // namespace
}  // namespace plantsim::render
