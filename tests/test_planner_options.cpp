// Family options by name: each family takes its own, the registry refuses the others before
// building, and a value changes the plan as the family says.
#include <gtest/gtest.h>

#include <string>

#include "planner/planner.h"
#include "planner/registry.h"

namespace plantsim::planner {
namespace {

PlannerInput open_floor() {
  PlannerInput in;
  in.floor = {0, 0, 10, 6};
  in.obstacles = {{4, 2, 6, 4}};
  in.inflation_m = 0.3;
  return in;
}

std::string refusal(std::string_view name, const PlannerInput& in) {
  try {
    make_planner(name, in);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(PlannerOptions, EachFamilyDeclaresItsOwnAndNoOther) {
  EXPECT_EQ(planner_option_specs("interval").at(0).name, "landmarks");
  EXPECT_EQ(planner_option_specs("polyanya").at(0).name, "landmarks");
  EXPECT_EQ(planner_option_specs("grid").at(0).name, "resolution_m");
  EXPECT_EQ(planner_option_specs("gcr-shortcut").at(0).name, "step_m");
  EXPECT_TRUE(planner_option_specs("vg").empty());
  EXPECT_THROW(planner_option_specs("dijkstra"), std::invalid_argument);
}

TEST(PlannerOptions, AnOptionTheFamilyDoesNotTakeIsRefusedNamingBoth) {
  PlannerInput in = open_floor();
  in.options.set("landmarks", 4);
  const std::string vg = refusal("vg", in);
  EXPECT_NE(vg.find("planner vg"), std::string::npos) << vg;
  EXPECT_NE(vg.find("'landmarks'"), std::string::npos) << vg;
  EXPECT_NE(vg.find("takes none"), std::string::npos) << vg;
  const std::string grid = refusal("grid", in);
  EXPECT_NE(grid.find("it takes: resolution_m"), std::string::npos) << grid;
  EXPECT_EQ(refusal("interval", in), "");
}

TEST(PlannerOptions, AValueOutOfBoundsOrNotWholeIsRefused) {
  for (double bad : {-1.0, 65.0, 2.5}) {
    PlannerInput in = open_floor();
    in.options.set("landmarks", bad);
    const std::string why = refusal("polyanya", in);
    EXPECT_NE(why.find("must be a whole number from 0 to 64"), std::string::npos) << bad << why;
  }
  PlannerInput in = open_floor();
  in.options.set("resolution_m", 0.0);
  EXPECT_NE(refusal("grid", in).find("'resolution_m'"), std::string::npos);
}

// A coarser grid blocks more cells around the box, so its path is no shorter; the default
// (0.1 m) is what an empty options set gives.
TEST(PlannerOptions, TheGridsResolutionReachesTheGrid) {
  PlannerInput fine = open_floor(), coarse = open_floor(), stated = open_floor();
  coarse.options.set("resolution_m", 0.5);
  stated.options.set("resolution_m", 0.1);
  const Vec2 a{1, 3}, b{9, 3};
  const PlanResult f = make_planner("grid", fine)->plan(a, b);
  const PlanResult c = make_planner("grid", coarse)->plan(a, b);
  const PlanResult s = make_planner("grid", stated)->plan(a, b);
  ASSERT_EQ(f.status, PlanStatus::kOk);
  ASSERT_EQ(c.status, PlanStatus::kOk);
  EXPECT_EQ(f.path.size(), s.path.size());
  EXPECT_DOUBLE_EQ(f.length, s.length);
  EXPECT_NE(f.stats.vertices, c.stats.vertices);
  EXPECT_GT(f.stats.vertices, 20 * c.stats.vertices);  // 25 times the cells, fewer blocked
}

}  // namespace
}  // namespace plantsim::planner
