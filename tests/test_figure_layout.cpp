// Every figure type against its own data: the legend lists exactly what is drawn (each entry's
// colour in the picture, each layer the run has in the legend, nothing it lacks), titles say what
// summary.json says, and no text overlaps another or leaves the canvas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "episode/episode_config.h"
#include "episode/episode_json.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "figure_checks.h"
#include "planner/coverage/coverage_planner.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "render/batch_charts.h"
#include "render/colour_vision.h"
#include "render/comparison_figure.h"
#include "render/coverage_figure.h"
#include "render/navigation_chart.h"
#include "render/palette.h"
#include "render/png_io.h"
#include "render/run_figure.h"
#include "render/scaling_chart.h"
#include "test_paths.h"
#include "util/fixed_text.h"
#include "worlds/world_loader.h"

namespace plantsim::render {
namespace {

struct Case {
  worlds::World world;
  episode::EpisodeResult run;
};

Case simulate(const std::string& file, const std::string& travel = "path") {
  Case c{worlds::load_world(file), {}};
  auto p = planner::make_planner("vg", planner::planner_input(c.world, true));
  episode::EpisodeConfig config;
  config.travel = travel;
  c.run = episode::run_episode(c.world, *p, config);
  return c;
}

void keep(const Image& img, const std::string& name) {
  if (std::getenv("PLANTSIM_KEEP")) write_png(img, "/tmp/" + name + ".png");
}

std::string format(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The subtitle carries summary.json's numbers, as summary.json has them.
void expect_title_matches_summary(const FigureLayout& layout, const episode::EpisodeResult& run) {
  nlohmann::ordered_json j;
  episode::add_episode_metrics(j, run);
  std::string sub;
  for (const std::string& s : layout.texts)
    if (s.find("  |  planned ") != std::string::npos) sub = s;
  ASSERT_FALSE(sub.empty());
  EXPECT_EQ(sub.rfind(j["status"].get<std::string>() + ",", 0), 0u) << sub;
  if (run.error_measured) {
    EXPECT_NE(sub.find(format("error %.1f mm", 1000 * j["position_error_m"].get<double>())),
              std::string::npos)
        << sub;
  } else {
    EXPECT_NE(sub.find("error n/a"), std::string::npos) << sub;
  }
  EXPECT_NE(sub.find(std::to_string(j["collisions"].get<int>()) + " collisions"), std::string::npos)
      << sub;
  EXPECT_NE(sub.find(format("planned %.2f m", j["path_length_m"].get<double>())), std::string::npos)
      << sub;
  EXPECT_NE(sub.find(format("driven %.2f m", j["driven_length_m"].get<double>())),
            std::string::npos)
      << sub;
}

TEST(FigureLayout, RunWithAReplanShowsBothPlansEventsSweptTracksAndTheDockingCloseUp) {
  const Case c = simulate(test::source_file("data/worlds/examples/parked_cart.json"));
  ASSERT_TRUE(c.run.docked);
  ASSERT_GT(c.run.replans, 0);
  FigureLayout layout;
  PixelTransform t;
  const Image img = draw_run_figure(c.world, c.run, {}, &t, &layout);
  keep(img, "layout_parked_cart");
  test::expect_sound_layout(img, layout, "parked_cart run figure");
  expect_title_matches_summary(layout, c.run);
  // The cart stands where it was put (one waypoint): "parked", not "moving (swept)".
  for (const char* label :
       {"first plan", "final plan", "replan", "parked", "driven (speed)", "start", "charger"})
    EXPECT_TRUE(test::has_legend(layout, label)) << label;
  // Absent things are not listed.
  for (const char* label : {"wall following", "target", "collision", "not on map", "plan",
                            "explored", "graph", "moving (swept)"})
    EXPECT_FALSE(test::has_legend(layout, label)) << label;
  // No two entries look alike: the same colour is drawn as a different swatch (a stop's black
  // ring, the first plan's black dashes, a tracked box's black outline).
  for (std::size_t i = 0; i < layout.legend.size(); ++i)
    for (std::size_t j = i + 1; j < layout.legend.size(); ++j) {
      const LegendEntry &a = layout.legend[i], &b = layout.legend[j];
      EXPECT_FALSE(a.colour.r == b.colour.r && a.colour.g == b.colour.g &&
                   a.colour.b == b.colour.b && a.swatch == b.swatch)
          << "'" << a.label << "' and '" << b.label << "' share one swatch";
    }
  // The footprint's entry fits its legend column (it was cut to "robot, every 1...").
  EXPECT_TRUE(test::has_legend(layout, "robot / 10 s") || test::has_legend(layout, "robot / 5 s"))
      << "footprint entry";
  // The final plan shows over the driven path along its length (it is drawn on top).
  int seen = 0, checked = 0;
  for (std::size_t i = 0; i + 1 < c.run.plan.size(); ++i)
    for (double f : {0.3, 0.5, 0.7}) {
      const Vec2 p = t.to_pixel(c.run.plan[i] + f * (c.run.plan[i + 1] - c.run.plan[i]));
      ++checked;
      bool near = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Rgb px = img.at(static_cast<int>(p.x) + dx, static_cast<int>(p.y) + dy);
          near = near ||
                 (std::abs(px.r - palette::kPlan.r) < 30 &&
                  std::abs(px.g - palette::kPlan.g) < 30 && std::abs(px.b - palette::kPlan.b) < 30);
        }
      seen += near;
    }
  EXPECT_GE(seen, checked * 9 / 10);
  // The close-up is there, inside the canvas, with the pose at contact.
  ASSERT_EQ(layout.insets.size(), 1u);
  EXPECT_LE(layout.insets[0].bottom, img.height);
  bool contact_line = false;
  for (const std::string& s : layout.texts)
    contact_line = contact_line || (s.rfind("at contact: ", 0) == 0 && s.find(" mm, ") != s.npos);
  EXPECT_TRUE(contact_line);
}

// Issue 89: in run and failure figures the failure diamond, the replan rings and the sensed
// layer were one blue under deuteranopia. Every two legend entries of a figure with all of its
// marks that differ in colour (the same colour is told by its swatch: the test above) stay
// apart for readers with deuteranopia, protanopia and tritanopia. 15 Delta E: Okabe and Ito's
// own pairs in these figures come to 16.5 (the charger's green and the replan blue under
// tritanopia); the old palette's failure / layer was 10.5, replan / layer 9.4.
TEST(FigureLayout, EveryLegendColourStaysApartUnderTheThreeCommonColourVisionDeficiencies) {
  Case c = simulate(test::source_file("data/worlds/examples/parked_cart.json"));
  ASSERT_FALSE(c.run.trajectory.empty());
  using Kind = episode::EpisodeResult::Event::Kind;
  const Vec2 at = c.run.trajectory[c.run.trajectory.size() / 2].truth.position();
  for (Kind k : {Kind::kStop, Kind::kReplan, Kind::kRecovery, Kind::kCollision, Kind::kRetry,
                 Kind::kFailure})
    c.run.events.push_back({k, 10.0, at});
  c.run.layer_final.push_back(geom::Rect{at.x + 1.0, at.y, at.x + 1.2, at.y + 0.2});
  c.run.last_scan.explained = {at + Vec2{0.5, 0.5}};
  c.run.last_scan.unexplained = {at + Vec2{0.7, 0.5}};
  c.run.failure = robot::Failure{robot::FailureReason::kCollision, 10.0, {at.x, at.y, 0}, "x"};
  FigureLayout layout;
  const Image img = draw_run_figure(c.world, c.run, {}, nullptr, &layout);
  keep(img, "layout_colour_vision");
  for (const char* label : {"failure", "replan", "sensed layer", "collision", "retry", "recovery",
                            "stop", "last scan", "scan off map"})
    ASSERT_TRUE(test::has_legend(layout, label)) << label;
  int pairs = 0;
  for (std::size_t i = 0; i < layout.legend.size(); ++i)
    for (std::size_t j = i + 1; j < layout.legend.size(); ++j) {
      const LegendEntry &a = layout.legend[i], &b = layout.legend[j];
      if (colour_difference(a.colour, b.colour) < 20) continue;  // one colour, told by swatch
      // The driven path's swatch is one sample of the cividis speed scale (its colour bar reads
      // it); cividis is itself made for colour-deficient readers.
      if (a.label == "driven (speed)" || b.label == "driven (speed)") continue;
      ++pairs;
      for (ColourVision v :
           {ColourVision::kDeuteranopia, ColourVision::kProtanopia, ColourVision::kTritanopia})
        EXPECT_GE(colour_difference(simulate(a.colour, v), simulate(b.colour, v)), 15.0)
            << "'" << a.label << "' and '" << b.label << "' under vision " << static_cast<int>(v);
    }
  EXPECT_GT(pairs, 100);
}

// Issue 89: a kidnap's carry was drawn as a solid driven segment with no marker, legend entry or
// time. Now it is dashed in its own colour from a ring where the robot was lifted to a square
// where it was set down, and the legend gives its time.
TEST(FigureLayout, AKidnapsCarryIsDashedMarkedAndTimedInTheLegend) {
  Case c = simulate(test::source_file("data/worlds/examples/parked_cart.json"));
  ASSERT_GT(c.run.trajectory.size(), 10u);
  const episode::TrajectorySample& lifted = c.run.trajectory[c.run.trajectory.size() / 3];
  const geom::Pose2 from = lifted.truth;
  const geom::Pose2 to{from.x + 3.0, from.y + 1.5, from.yaw};
  c.run.carries.push_back({lifted.t_s, from, to});
  FigureLayout layout;
  PixelTransform t;
  const Image img = draw_run_figure(c.world, c.run, {}, &t, &layout);
  keep(img, "layout_kidnap");
  test::expect_sound_layout(img, layout, "kidnap run figure");
  const std::string label = "kidnap " + util::fixed(lifted.t_s, 1) + " s";
  EXPECT_NE(std::find(layout.texts.begin(), layout.texts.end(), label), layout.texts.end())
      << "the legend's text, time and all, drawn uncut";
  const auto entry = std::find_if(layout.legend.begin(), layout.legend.end(),
                                  [&](const LegendEntry& e) { return e.label == label; });
  ASSERT_NE(entry, layout.legend.end()) << label;
  EXPECT_EQ(entry->swatch, Swatch::kDashed);
  EXPECT_EQ(entry->colour, palette::kCarry);
  const Vec2 down = t.to_pixel(to.position());
  EXPECT_EQ(img.at(static_cast<int>(down.x), static_cast<int>(down.y)), palette::kCarry);
  int dashed = 0;  // the carry's line: about half of it in dashes
  for (int k = 1; k < 20; ++k) {
    const Vec2 p = t.to_pixel(from.position() + (k / 20.0) * (to.position() - from.position()));
    dashed += img.at(static_cast<int>(p.x), static_cast<int>(p.y)) == palette::kCarry;
  }
  EXPECT_GE(dashed, 5);
  EXPECT_LE(dashed, 15);
  // The time plots mark it (and a failure) as a line across every plot, named in the legend.
  c.run.failure = robot::Failure{robot::FailureReason::kLocalizationLost, lifted.t_s + 20.0,
                                 c.run.trajectory.back().truth, "x"};
  FigureLayout plots;
  const Image timeplots = draw_time_plots(c.world, c.run, 1000, 900, &plots);
  keep(timeplots, "layout_kidnap_timeplots");
  test::expect_sound_layout(timeplots, plots, "kidnap time plots");
  for (const char* name : {"kidnap", "failure"}) EXPECT_TRUE(test::has_legend(plots, name)) << name;
  auto count = [&](Rgb colour) {
    int n = 0;
    for (int y = 0; y < timeplots.height; ++y)
      for (int x = 0; x < timeplots.width; ++x) n += timeplots.at(x, y) == colour;
    return n;
  };
  EXPECT_GT(count(palette::kCarry), 4 * 100);  // four plots, each well over 100 px high
  EXPECT_GT(count(palette::kFailureMark), 4 * 100);
}

// A run that failed far from the charger gets a close-up of where it failed (6 m around the
// failure's pose, its reason, time and detail), not the docking close-up of a charger it never
// reached. The run is cut at a pose halfway along and given a failure there.
TEST(FigureLayout, AFailureAwayFromTheDockIsShownCloseUp) {
  Case c = simulate(test::source_file("data/worlds/examples/small_plant.json"));
  ASSERT_GT(c.run.trajectory.size(), 100u);
  std::size_t mid = c.run.trajectory.size() / 2;
  while (mid > 0 &&
         geom::distance(c.run.trajectory[mid].truth.position(), c.world.charger.position()) < 4.0)
    --mid;
  c.run.trajectory.resize(mid + 1);
  for (auto& s : c.run.trajectory) s.phase = controller::DockPhase::kTravel;
  c.run.docked = c.run.charging = c.run.error_measured = false;
  c.run.status = episode::EpisodeStatus::kFailed;
  const geom::Pose2 at = c.run.trajectory.back().truth;
  c.run.failure = robot::Failure{robot::FailureReason::kLocalizationLost, 12.25, at,
                                 "the estimate was 0.40 m off"};
  FigureLayout layout;
  PixelTransform map;
  const Image img = draw_run_figure(c.world, c.run, {}, &map, &layout);
  keep(img, "layout_failure_close_up");
  test::expect_sound_layout(img, layout, "failed run figure");
  ASSERT_EQ(layout.insets.size(), 1u);
  auto has = [&](const std::string& line) {
    return std::find(layout.texts.begin(), layout.texts.end(), line) != layout.texts.end();
  };
  EXPECT_TRUE(has("localization_lost at 12.2 s") || has("localization_lost at 12.3 s"));
  EXPECT_TRUE(has("6 m around where it failed:"));
  EXPECT_TRUE(has("the estimate was 0.40 m off"));
  // The robot's outline at the failure, drawn at the close-up's scale (a ring of kRobot pixels
  // around the inset's centre, 0.2 m of 6 m: about 8 of its 270 pixels).
  const PixelBox& inset = layout.insets[0];
  const double cx = 0.5 * (inset.left + inset.right);
  int robot_pixels = 0;
  for (int y = static_cast<int>(inset.top); y < static_cast<int>(inset.bottom); ++y)
    for (int x = static_cast<int>(inset.left); x < static_cast<int>(inset.right); ++x)
      if (std::abs(x - cx) < 20 && img.at(x, y) == palette::kRobot) ++robot_pixels;
  EXPECT_GT(robot_pixels, 20);
}

TEST(FigureLayout, PursuitSaysNoErrorWasMeasuredAndDrawsTargetAndWallFollowing) {
  const Case c =
      simulate(test::source_file("data/worlds/plants/seed001_slow_target.json"), "potential-field");
  ASSERT_TRUE(c.run.caught);
  FigureLayout layout;
  const Image img = draw_run_figure(c.world, c.run, {}, nullptr, &layout);
  keep(img, "layout_pursuit");
  test::expect_sound_layout(img, layout, "pursuit run figure");
  expect_title_matches_summary(layout, c.run);
  EXPECT_TRUE(test::has_legend(layout, "target"));
  EXPECT_EQ(test::has_legend(layout, "wall following"), c.run.wall_follows > 0);
  EXPECT_TRUE(layout.insets.empty()) << "no docking close-up for a pursuit";

  FigureLayout plots;
  const Image tp = draw_time_plots(c.world, c.run, 1280, 1000, &plots);
  keep(tp, "layout_pursuit_time");
  test::expect_sound_layout(tp, plots, "pursuit time plots");
}

TEST(FigureLayout, TimePlotsShadePhasesAndKeepLabelsOnTheCanvas) {
  const Case c = simulate(test::shared_data("worlds/world_N10.json"));
  ASSERT_TRUE(c.run.docked);
  FigureLayout layout;
  const Image img = draw_time_plots(c.world, c.run, 1280, 1000, &layout);
  keep(img, "layout_time");
  test::expect_sound_layout(img, layout, "time plots");
  EXPECT_TRUE(test::has_legend(layout, "travel"));
  EXPECT_TRUE(test::has_legend(layout, "docking"));
  bool time_label = false;
  for (const std::string& s : layout.texts) time_label = time_label || s == "time (s)";
  EXPECT_TRUE(time_label);
}

TEST(FigureLayout, CoveragePanelsListTheirCellTintsAndSayHowEachOrderWasFound) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/plants/depot_pit_coverage.json"));
  std::vector<std::unique_ptr<planner::CoveragePlanner>> planners;
  std::vector<CoveragePanel> panels;
  // The sanitizer tree cuts the exact search short (the Release tree proves the pit's order):
  // the panel then says "NOT proven optimal" and draws the best order found.
  planner::CoverageParams params;
  if (!test::full_size()) params.exact.max_prefixes = 2000;
  for (const char* name :
       {"coverage-chnn", "coverage-exact", "coverage-greedy", "coverage-cells"}) {
    planners.push_back(
        std::make_unique<planner::CoveragePlanner>(planner::planner_input(w, true), name, params));
    ASSERT_EQ(planners.back()->plan(w.start.position(), worlds::staging_pose(w).position()).status,
              planner::PlanStatus::kOk);
    panels.push_back({name, &planners.back()->grid(), planners.back()->last_plan(), {}, ""});
  }
  // A network that settled on no order: its panel says so instead of drawing a path.
  planner::CoveragePlan failed;
  failed.ok = false;
  failed.failure = "the Hopfield network settled on a valid order in 0 of 50 restarts";
  panels.push_back({"coverage-chnn (no order)", &planners.front()->grid(), failed, {}, ""});
  FigureLayout layout;
  const Image img = draw_coverage(w, panels, "coverage", "document vs here", 1600, 560, &layout);
  keep(img, "layout_coverage");
  test::expect_sound_layout(img, layout, "coverage");
  for (const char* label :
       {"covered once", "coverage path", "sub-region, order", "sweep start", "start", "charger"})
    EXPECT_TRUE(test::has_legend(layout, label)) << label;
  EXPECT_FALSE(test::has_legend(layout, "driven"));
  auto said = [&](const std::string& part) {
    return std::any_of(layout.texts.begin(), layout.texts.end(),
                       [&](const std::string& t) { return t.find(part) != std::string::npos; });
  };
  EXPECT_TRUE(said(test::full_size() ? "proven optimal in" : "NOT proven optimal"));
  EXPECT_TRUE(said("valid order in"));
  EXPECT_TRUE(said("NO PLAN"));
  EXPECT_TRUE(said("settled on a valid order in 0 of 50 restarts"));
}

TEST(FigureLayout, LongNamesAreShortenedInsideTheCanvas) {
  Case c = simulate(test::shared_data("worlds/world_N10.json"));
  c.world.name = std::string(120, 'w');
  c.world.name +=
      "_\u4e2d\u6587";  // appended in place: GCC 12 misreads the move of a `+` temporary
  RunFigureOptions o;
  o.setting = "episode " + std::string(200, 's');
  FigureLayout layout;
  const Image img = draw_run_figure(c.world, c.run, o, nullptr, &layout);
  test::expect_sound_layout(img, layout, "long names");
}

TEST(FigureLayout, FourComparisonPanelsAreTwoByTwoWithALegend) {
  const Case c = simulate(test::shared_data("worlds/world_N10.json"));
  std::vector<ComparisonPanel> panels;
  for (const char* name : {"vg", "vg-traditional", "grid", "gcr"}) {
    auto p = planner::make_planner(name, planner::planner_input(c.world, true));
    episode::EpisodeResult r;
    const planner::PlanResult plan =
        p->plan(c.world.start.position(), worlds::staging_pose(c.world).position());
    r.planner = name;
    r.plan = plan.path;
    r.path_length_m = plan.length;
    r.plan_stats = plan.stats;
    r.status = episode::EpisodeStatus::kPlannerAnswer;
    r.plan_status = plan.status;
    panels.push_back({name, r, {}, false});
  }
  panels[0] = {"vg", c.run, {}, true};
  FigureLayout layout;
  const Image img = draw_comparison(c.world, panels, "four planners", 1800, 640, &layout);
  keep(img, "layout_comparison");
  test::expect_sound_layout(img, layout, "comparison");
  EXPECT_EQ(img.height, 110 + 2 * 640) << "two rows of two";
  for (const char* label : {"plan", "driven (speed)", "start", "charger", "obstacle"})
    EXPECT_TRUE(test::has_legend(layout, label)) << label;
  // No panel line boasts a meaningless graph size.
  for (const std::string& s : layout.texts)
    EXPECT_EQ(s.find(" 0 vertices"), std::string::npos) << s;
}

// Each planner's plan from the start to the charger, as a comparison panel with its graph
// (plans only, nothing driven); a planner that finds no path is left out.
std::vector<ComparisonPanel> plan_only_panels(const worlds::World& w,
                                              const std::vector<std::string>& names) {
  std::vector<ComparisonPanel> panels;
  for (const std::string& name : names) {
    auto p = planner::make_planner(name, planner::planner_input(w, false));
    const planner::PlanResult plan = p->plan(w.start.position(), w.charger.position());
    if (plan.status != planner::PlanStatus::kOk) continue;
    episode::EpisodeResult r;
    r.planner = name;
    r.plan = plan.path;
    r.path_length_m = plan.length;
    r.plan_stats = plan.stats;
    r.status = episode::EpisodeStatus::kPlannerAnswer;
    r.plan_status = plan.status;
    panels.push_back({name, r, p->graph_edges(), false});
  }
  return panels;
}

// Seed 000's Fig. 5 vs Fig. 6 on its own plant: both graphs exact, so the line under the title
// says the lengths agree and gives the work each did, as the panels' statistics have it.
TEST(FigureLayout, TwoGraphPlannersSayWhatDiffersAndWhatDoesNot) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/plants/desulfurization_plant.json"));
  const std::vector<ComparisonPanel> panels = plan_only_panels(w, {"vg", "vg-traditional"});
  ASSERT_EQ(panels.size(), 2u);
  FigureLayout layout;
  const Image img = draw_comparison(w, panels, "Fig. 5 vs Fig. 6", 1800, 640, &layout);
  keep(img, "layout_fig5_fig6");
  test::expect_sound_layout(img, layout, "fig5 vs fig6");
  const std::string line = what_differs(panels[0], panels[1]);
  EXPECT_TRUE(std::find(layout.texts.begin(), layout.texts.end(), line) != layout.texts.end())
      << line;
  EXPECT_NE(line.find("(the same length)"), std::string::npos) << line;
  const auto& a = panels[0].run.plan_stats;
  const auto& b = panels[1].run.plan_stats;
  EXPECT_NE(line.find("segment tests " + std::to_string(a.segment_tests) + " vs " +
                      std::to_string(b.segment_tests)),
            std::string::npos)
      << line;
  EXPECT_LT(a.segment_tests, b.segment_tests);  // the document's claim: less work for the same path
  EXPECT_LT(a.edges, b.edges);
}

// The mesh planners search a mesh, not a graph: each panel names cells (rectangles, or convex
// polygons for polyanya), portals and the intervals expanded, the portals are listed as such,
// and no vertex/edge comparison with vg is printed (cells are not vertices).
TEST(FigureLayout, AMeshPlannerIsDescribedAsAMesh) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/plants/desulfurization_plant.json"));
  for (const std::string mesh_planner : {"interval", "polyanya"}) {
    const std::vector<ComparisonPanel> panels = plan_only_panels(w, {"vg", mesh_planner});
    ASSERT_EQ(panels.size(), 2u);
    FigureLayout layout;
    const Image img = draw_comparison(w, panels, "vg vs " + mesh_planner, 1800, 640, &layout);
    keep(img, "layout_vg_" + mesh_planner);
    test::expect_sound_layout(img, layout, "vg vs " + mesh_planner);
    EXPECT_TRUE(test::has_legend(layout, "mesh portals")) << mesh_planner;
    EXPECT_TRUE(test::has_legend(layout, "graph")) << mesh_planner;
    EXPECT_EQ(what_differs(panels[0], panels[1]), "") << mesh_planner;
    const auto& st = panels[1].run.plan_stats;
    const std::string mesh =
        "mesh " + std::to_string(st.vertices) + " cells, " + std::to_string(st.edges) + " portals";
    EXPECT_TRUE(std::any_of(layout.texts.begin(), layout.texts.end(), [&](const std::string& t) {
      return t.find(mesh) != std::string::npos;
    })) << mesh;
  }
}

// Seed 003 shows its working: the ring search's walks with where each ended, and the letters
// recorded at the junctions, all listed and none on top of another text.
TEST(FigureLayout, MazeRunDrawsTheSearchWalksAndTheJunctionLetters) {
  Case c{worlds::load_world(test::source_file("data/worlds/plants/cable_tunnel_ring.json")), {}};
  auto p = planner::make_planner("maze-left", planner::planner_input(c.world, true));
  c.run = episode::run_episode(c.world, *p, {});
  FigureLayout layout;
  const Image img = draw_run_figure(c.world, c.run, {}, nullptr, &layout);
  keep(img, "layout_maze");
  test::expect_sound_layout(img, layout, "maze run");
  expect_title_matches_summary(layout, c.run);
  for (const char* label : {"explored", "ring search walks", "letters explored", "letters driven"})
    EXPECT_TRUE(test::has_legend(layout, label)) << label;
  const auto count = [&](const std::string& prefix) {
    return std::count_if(layout.texts.begin(), layout.texts.end(),
                         [&](const std::string& t) { return t.rfind(prefix, 0) == 0; });
  };
  EXPECT_GE(count("tr"), 2);  // "tries 1, 2: closed" and "try 3: exit"
  EXPECT_GE(count("U"), 3);   // dead ends of the exploration
}

TEST(FigureLayout, BatchChartsDrawGatesIntervalsAndEveryMethod) {
  // Three configurations: one meeting its gate with its lower bound too, one meeting it by the
  // point estimate only, one below it; two methods with docked and failed episodes.
  const std::vector<RateRow> rates = {{"w / vg / pp / dry", 200, 200, 0.981, 1.0, 0.9},
                                      {"w / vg / pp / damp", 19, 20, 0.76, 0.99, 0.9},
                                      {"w / vg / pp / wet", 12, 20, 0.39, 0.78, 0.9}};
  FigureLayout layout;
  Image img = draw_success_chart(rates, "test batch", 1400, &layout);
  keep(img, "layout_success");
  test::expect_sound_layout(img, layout, "success chart");
  EXPECT_TRUE(test::has_legend(layout, "success rate (below gate)"));
  EXPECT_TRUE(test::has_legend(layout, "success rate (meets gate)"));
  EXPECT_TRUE(test::has_legend(layout, "meets gate, 95 % low below it"));
  EXPECT_TRUE(test::has_legend(layout, "gate"));
  EXPECT_TRUE(test::has_legend(layout, "Wilson 95 %"));

  std::vector<EpisodeOutcome> episodes;
  for (int i = 0; i < 40; ++i) {
    EpisodeOutcome e;
    e.method = i % 2 ? "vg / pure-pursuit / dry" : "gcr / pure-pursuit / dry";
    e.docked = i % 7 != 0;
    e.position_error_m = 0.001 * (i % 15);
    e.heading_error_deg = 0.1 * (i % 12);
    e.driven_over_shortest = 1.0 + 0.01 * i;
    e.time_s = 60 + i;
    episodes.push_back(e);
  }
  img = draw_error_strips(episodes, {}, 1400, &layout);
  keep(img, "layout_errors");
  test::expect_sound_layout(img, layout, "error strips");
  // Each strip is named, in its dots' colour, with its count of docked episodes.
  auto has_text = [&](const std::string& t) {
    return std::find(layout.texts.begin(), layout.texts.end(), t) != layout.texts.end();
  };
  EXPECT_TRUE(has_text("vg / pure-pursuit / dry (17)"));
  EXPECT_TRUE(has_text("gcr / pure-pursuit / dry (17)"));
  EXPECT_TRUE(test::has_legend(layout, "gate"));
  // Localisation: every episode's worst error, docked or not; the ones past 1 m are counted.
  for (std::size_t i = 0; i < episodes.size(); ++i) {
    episodes[i].localization_error_max_m = i == 3 ? 12.0 : 0.002 * static_cast<double>(i % 9);
    episodes[i].localization_ok = i % 10 != 0;
  }
  img = draw_localization_chart(episodes, 1400, &layout);
  keep(img, "layout_localization");
  test::expect_sound_layout(img, layout, "localisation chart");
  EXPECT_TRUE(test::has_legend(layout, "100 mm"));  // the axis's unit, not "10 cm" on an mm axis
  // Docked and failed episodes drawn apart, each kind listed.
  EXPECT_TRUE(test::has_legend(layout, "docked (dot, its method's colour)"));
  EXPECT_TRUE(test::has_legend(layout, "failed (black cross)"));
  EXPECT_TRUE(has_text("gcr / pure-pursuit / dry (20)"));  // every episode, not only the docked
  EXPECT_TRUE(has_text("4 of 20 not ok"));                 // gcr: episodes 0, 10, 20, 30
  EXPECT_TRUE(has_text("0 of 20 not ok, 1 past 1 m"));     // vg: episode 3, 12 m off
  // Time to dock world by world: a panel per world on its own scale, its strips counting only
  // that world's docked episodes.
  for (std::size_t i = 0; i < episodes.size(); ++i) {
    episodes[i].world = i < 30 ? "large_plant" : "small_room";
    if (i >= 30) episodes[i].time_s = 10 + static_cast<double>(i - 30);
  }
  img = draw_time_by_world(episodes, 1400, &layout);
  keep(img, "layout_time_by_world");
  test::expect_sound_layout(img, layout, "time by world");
  EXPECT_TRUE(has_text("large_plant"));
  EXPECT_TRUE(has_text("small_room"));
  EXPECT_TRUE(has_text("vg / pure-pursuit / dry (13)"));  // odd i < 30, not 7 or 21
  EXPECT_TRUE(has_text("gcr / pure-pursuit / dry (5)"));  // even i in 30..38, not 35
  EXPECT_EQ(layout.legend.size(), 2u);
  img = draw_efficiency_chart(episodes, 1400, &layout);
  keep(img, "layout_efficiency");
  test::expect_sound_layout(img, layout, "efficiency chart");
  EXPECT_EQ(layout.legend.size(), 2u);
  // Many methods with long names still fit: legends wrap and labels are shortened.
  std::vector<EpisodeOutcome> many;
  for (int i = 0; i < 96; ++i) {
    EpisodeOutcome e = episodes[i % episodes.size()];
    e.method = "planner-" + std::to_string(i % 12) + " / a-controller-with-a-long-name / fault-" +
               std::string(30, 'f');
    e.docked = true;
    many.push_back(e);
  }
  img = draw_efficiency_chart(many, 1400, &layout);
  test::expect_sound_layout(img, layout, "efficiency chart, 12 methods");
  EXPECT_EQ(layout.legend.size(), 12u);
  img = draw_error_strips(many, {}, 1400, &layout);
  test::expect_sound_layout(img, layout, "error strips, 12 methods");
  img = draw_sweep_chart("friction", {0.05, 0.1, 0.3},
                         {{"0.05", 7, 10, 0.4, 0.9, 0.9},
                          {"0.1", 9, 10, 0.6, 0.98, 0.9},
                          {"0.3", 10, 10, 0.72, 1.0, 0.9}},
                         1000, &layout);
  keep(img, "layout_sweep");
  test::expect_sound_layout(img, layout, "sweep chart");
  EXPECT_TRUE(test::has_legend(layout, "Wilson 95 % band"));

  // Every episode's path: failures listed only when there are some, and drawn on top.
  const worlds::World w = worlds::load_world(test::shared_data("worlds/world_N10.json"));
  const Vec2 a = w.start.position(), b = w.charger.position();
  std::vector<EpisodePath> paths = {{{a, 0.5 * (a + b), b}, true}};
  img = draw_episode_paths(w, paths, "paths", "docked", 1400, 900, &layout);
  test::expect_sound_layout(img, layout, "episode paths");
  EXPECT_TRUE(test::has_legend(layout, "docked"));
  EXPECT_FALSE(test::has_legend(layout, "failed"));
  paths.push_back({{a, a + Vec2{5, 5}}, false});
  img = draw_episode_paths(w, paths, "paths", "caught", 1400, 900, &layout);
  keep(img, "layout_paths");
  test::expect_sound_layout(img, layout, "episode paths with a failure");
  EXPECT_TRUE(test::has_legend(layout, "failed"));
  EXPECT_TRUE(test::has_legend(layout, "caught"));  // a pursuit's successes are catches

  // Two families of maps: a method keeps its colour, the second family dashed; the legend wraps.
  img = draw_scaling_chart(
      {{"vg", {10, 100, 1000}, {0.03, 2, 16}, false, "vg"},
       {"grid", {10, 100, 1000}, {19, 13, 15}, false, "grid"},
       {"vg, plants", {1000, 5000, 20000}, {20, 90, 900}, true, "vg"},
       {"polyanya, plants", {1000, 5000, 20000}, {30, 200, 1000}, true, "polyanya"},
       {"nothing measured", {}, {}, true, "none"}},
      "time", "subtitle", "obstacles", "time (ms)", 1300, 760, &layout);
  keep(img, "layout_scaling");
  test::expect_sound_layout(img, layout, "scaling chart");
  ASSERT_EQ(layout.legend.size(), 4u);                          // what has no points is not listed
  EXPECT_EQ(layout.legend[0].colour, layout.legend[2].colour);  // vg, both families
  EXPECT_NE(layout.legend[0].colour, layout.legend[3].colour);
  EXPECT_EQ(layout.legend[2].swatch, Swatch::kDashed);
  EXPECT_EQ(layout.legend[0].swatch, Swatch::kBar);
}

// The navigation chart: a strip per method in each of its three panels, episodes that never
// travelled left out, failures as crosses beside the 0.3 m line.
TEST(FigureLayout, NavigationChartDrawsEveryMethodsClearanceJerkAndComputeTime) {
  std::vector<EpisodeOutcome> episodes;
  const char* methods[] = {"vg / pure-pursuit / none", "vg / dwb / none", "vg / mppi / none"};
  for (int i = 0; i < 30; ++i) {
    EpisodeOutcome e;
    e.method = methods[i % 3];
    e.docked = i % 7 != 0;
    e.min_clearance_m = i == 4 ? -1.0 : 0.05 * (i % 11);  // one never travelled
    e.rms_jerk_mps3 = 0.5 + 0.1 * (i % 5);
    e.controller_ms_median = i % 3 == 2 ? 4.0 + 0.1 * i : 0.01 * i;
    episodes.push_back(e);
  }
  FigureLayout layout;
  const Image img = draw_navigation_chart(episodes, 1400, &layout);
  keep(img, "layout_navigation");
  test::expect_sound_layout(img, layout, "navigation chart");
  auto has_text = [&](const std::string& t) {
    return std::find(layout.texts.begin(), layout.texts.end(), t) != layout.texts.end();
  };
  EXPECT_TRUE(has_text("vg / pure-pursuit / none (10)"));
  EXPECT_TRUE(has_text("vg / dwb / none (9)"));  // episode 4 never travelled
  EXPECT_TRUE(has_text("vg / mppi / none (10)"));
  EXPECT_TRUE(test::has_legend(layout, "0.3 m"));
  EXPECT_TRUE(test::has_legend(layout, "succeeded (dot, its method's colour)"));
  EXPECT_TRUE(test::has_legend(layout, "failed (black cross)"));
}

}  // namespace
}  // namespace plantsim::render

namespace plantsim::render {
namespace {

// A batch of 30 worlds and 14 configurations (7 controllers x 2 faults) needed a world-by-world
// chart 16,500 pixels tall: the figure refused it and the batch's report stopped after its
// episodes. It now draws the worlds that fit and says how many of how many.
TEST(FigureLayout, TimeByWorldOfManyWorldsAndConfigurationsFitsAFigureAndSaysSo) {
  std::vector<EpisodeOutcome> episodes;
  for (int w = 0; w < 30; ++w)
    for (int m = 0; m < 14; ++m) {
      EpisodeOutcome e;
      e.world = "world_" + std::to_string(w);
      e.method = "vg / controller-" + std::to_string(m % 7) + " / fault-" + std::to_string(m / 7);
      e.docked = true;
      e.time_s = 50 + w + m;
      episodes.push_back(e);
    }
  FigureLayout layout;
  const Image img = draw_time_by_world(episodes, 1400, &layout);
  EXPECT_LE(img.height, 16384);
  test::expect_sound_layout(img, layout, "time by world, 30 worlds");
  const auto said =
      std::find_if(layout.texts.begin(), layout.texts.end(), [](const std::string& t) {
        return t.find("of 30 worlds (the tables list every one)") != std::string::npos;
      });
  EXPECT_NE(said, layout.texts.end());
  EXPECT_NE(std::find(layout.texts.begin(), layout.texts.end(), "world_0"), layout.texts.end());
}

}  // namespace
}  // namespace plantsim::render
