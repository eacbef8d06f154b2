// plantsim tune (issue 55): the parameters named as docs/config.md names them and bounded by its
// ranges; NLopt and random search spending exactly their budget, deterministically; the paired
// statistics on known answers; and the command end to end on small plants: outputs that `run`
// takes, held-out validation, a resume that reruns nothing, and bad input refused with exit 2
// before any episode, nothing of the user's touched.
#include <cmath>
#include <map>

#include "cli_fixture.h"
#include "episode/robot_limits.h"
#include "test_paths.h"
#include "tune/objective.h"
#include "tune/paired_test.h"
#include "tune/search.h"
#include "tune/tune_spec.h"
#include "worlds/world_loader.h"

namespace plantsim {
namespace {

using tune::EpisodeOutcome;

TEST(TuneParameters, NamedAsTheConfigNamesThemWithTheirRanges) {
  const auto p = episode::number_parameter("tracking.max_linear_speed_mps");
  EXPECT_DOUBLE_EQ(p.default_value, 0.6);
  EXPECT_FALSE(p.whole);
  EXPECT_TRUE(episode::number_parameter("docking.max_retries").whole);
  try {
    episode::number_parameter("tracking.max_linear_sped_mps");
    FAIL() << "an unknown key was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'tracking.max_linear_speed_mps'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(episode::number_parameter("detection.enabled"), std::invalid_argument);  // a flag
}

tune::TuneSpec analytic_spec(tune::Method method, int budget) {
  tune::TuneSpec spec;
  spec.budget = budget;
  spec.method = method;
  for (const char* key : {"tracking.max_linear_speed_mps", "tracking.lookahead_time_s"}) {
    tune::TunedParameter p;
    p.info = episode::number_parameter(key);
    p.lo = 0, p.hi = 2;
    spec.parameters.push_back(p);
  }
  return spec;
}

// A smooth bowl with its top at (1.4, 0.5): what any of the optimisers must find.
double bowl(const std::vector<double>& v) {
  return -std::pow(v[0] - 1.4, 2) - std::pow(v[1] - 0.5, 2);
}

TEST(TuneSearch, EachSearchSpendsExactlyItsBudgetAndNloptFindsTheTop) {
  for (tune::Method m : {tune::Method::kSbplx, tune::Method::kSbplxStarts, tune::Method::kBobyqa,
                         tune::Method::kNelderMead, tune::Method::kCrs2, tune::Method::kIsres}) {
    const tune::TuneSpec spec = analytic_spec(m, 80);
    int calls = 0;
    double best = -HUGE_VAL;
    tune::nlopt_search(spec, {0.6, 1.2},
                       [&](const char* search, int index, const std::vector<double>& v) {
                         EXPECT_STREQ(search, "nlopt");
                         EXPECT_EQ(index, calls++);
                         for (double x : v) EXPECT_TRUE(x >= 0 && x <= 2) << x;
                         best = std::max(best, bowl(v));
                         return bowl(v);
                       });
    EXPECT_EQ(calls, 80) << tune::method_name(m);
    EXPECT_GT(best, -0.01) << tune::method_name(m);
  }
}

// Two bowls: a narrow one about the defaults (0.6, 1.2), topping at -0.6, and a broad deeper one
// at (1.8, 0.2). sbplx-starts evaluates its design first (the defaults, then 2n uniform points),
// then Subplex sets off from the design's best and climbs to the deeper top.
double two_bowls(const std::vector<double>& v) {
  const double near = -0.6 - 20 * (std::pow(v[0] - 0.6, 2) + std::pow(v[1] - 1.2, 2));
  const double far = -0.5 * (std::pow(v[0] - 1.8, 2) + std::pow(v[1] - 0.2, 2));
  return std::max(near, far);
}

TEST(TuneSearch, StartsFromTheBestOfADesignBeyondTheDefaultsBasin) {
  const tune::TuneSpec spec = analytic_spec(tune::Method::kSbplxStarts, 30);
  std::vector<std::vector<double>> asked;
  std::vector<double> values;
  tune::nlopt_search(spec, {0.6, 1.2}, [&](const char*, int, const std::vector<double>& v) {
    asked.push_back(v);
    values.push_back(two_bowls(v));
    return two_bowls(v);
  });
  ASSERT_EQ(asked.size(), 30u);
  EXPECT_EQ(asked[0], (std::vector<double>{0.6, 1.2}));  // the defaults first
  const std::size_t design = 5;                          // 2 n + 1 points
  const std::size_t best_of_design =
      std::max_element(values.begin(), values.begin() + design) - values.begin();
  EXPECT_NE(best_of_design, 0u);       // a design point beat the defaults ...
  for (std::size_t k = 0; k < 2; ++k)  // ... and Subplex set off from it
    EXPECT_NEAR(asked[design][k], asked[best_of_design][k], 1e-9);
  EXPECT_GT(*std::max_element(values.begin(), values.end()), -0.01);  // the deeper bowl's top
}

TEST(TuneSearch, RandomSearchIsUniformAndRepeatsForItsSeed) {
  tune::TuneSpec spec = analytic_spec(tune::Method::kSbplx, 400);
  std::vector<std::vector<double>> first, second;
  tune::random_search(spec, [&](const char*, int, const std::vector<double>& v) {
    first.push_back(v);
    return 0.0;
  });
  tune::random_search(spec, [&](const char*, int, const std::vector<double>& v) {
    second.push_back(v);
    return 0.0;
  });
  EXPECT_EQ(first, second);
  double mean = 0;
  for (const auto& v : first) mean += v[0] / first.size();
  EXPECT_NEAR(mean, 1.0, 0.1);  // uniform on [0, 2]
  spec.seed = 2;
  second.clear();
  tune::random_search(spec, [&](const char*, int, const std::vector<double>& v) {
    second.push_back(v);
    return 0.0;
  });
  EXPECT_NE(first, second);
}

TEST(TuneSearch, WholeNumbersAreSearchedAsWholeNumbers) {
  tune::TuneSpec spec;
  spec.budget = 30;
  tune::TunedParameter p;
  p.info = episode::number_parameter("docking.max_retries");
  p.lo = 1, p.hi = 6;
  spec.parameters = {p};
  tune::random_search(spec, [&](const char*, int, const std::vector<double>& v) {
    EXPECT_EQ(v[0], std::round(v[0]));
    return 0.0;
  });
}

TEST(TunePaired, McNemarAndTheSignTestOnKnownAnswers) {
  EXPECT_NEAR(tune::two_sided_binomial_p(0, 5), 2.0 / 32, 1e-12);
  EXPECT_NEAR(tune::two_sided_binomial_p(2, 4), 1.0, 1e-12);
  EXPECT_NEAR(tune::two_sided_binomial_p(1, 10), 2.0 * 11 / 1024, 1e-12);
  std::vector<EpisodeOutcome> a, b;
  for (int i = 0; i < 12; ++i) {
    const std::string id = "e" + std::to_string(i);
    a.push_back({id, i >= 8, 100.0, 0.0, 0});               // the default docked 4
    b.push_back({id, true, i >= 8 ? 80.0 : 90.0, 0.0, 0});  // the tuned one all 12, faster
  }
  const tune::PairedComparison c = tune::compare_paired(a, b);
  EXPECT_EQ(c.only_b, 8);
  EXPECT_EQ(c.only_a, 0);
  EXPECT_NEAR(c.success_p, 2.0 / 256, 1e-12);
  EXPECT_EQ(c.both_docked, 4);
  EXPECT_DOUBLE_EQ(c.time_difference_s, -20.0);
  EXPECT_DOUBLE_EQ(c.time_change, -0.2);
  EXPECT_NEAR(c.time_p, 2.0 / 16, 1e-12);
  b.pop_back();
  EXPECT_THROW(tune::compare_paired(a, b), std::invalid_argument);
}

TEST(TuneObjective, BelowTheFloorRanksUnderEveryCandidateThatKeepsIt) {
  std::vector<EpisodeOutcome> slow_sure, fast_unsure;
  for (int i = 0; i < 40; ++i) {
    slow_sure.push_back({"e", true, 590.0, 0.01, 0});
    fast_unsure.push_back({"e", i % 10 != 0, 20.0, 0.01, 0});
  }
  const tune::Statistics sure = tune::statistics(slow_sure), unsure = tune::statistics(fast_unsure);
  const double floor = sure.wilson_low;
  for (tune::Objective o :
       {tune::Objective::kTime, tune::Objective::kDockingError, tune::Objective::kContacts}) {
    const tune::Score s = tune::score(o, sure, floor, 600), u = tune::score(o, unsure, floor, 600);
    EXPECT_TRUE(s.feasible);
    EXPECT_FALSE(u.feasible);
    EXPECT_GT(s.value, u.value) << tune::objective_name(o);
  }
  // The default objective weighs 10 s as 0.001 of the Wilson bound.
  EXPECT_NEAR(tune::score(tune::Objective::kSuccessThenTime, sure, 0, 600).value,
              sure.wilson_low - 0.059, 1e-12);
  EXPECT_THROW(tune::parse_objective("fastest", "--objective"), std::invalid_argument);
}

// --- The command ---

const std::string kSmall = test::source_file("data/worlds/examples/small_plant.json");
const std::string kCorridor = test::source_file("data/worlds/examples/corridor_crossing.json");

std::string tiny_scenario(const std::string& tune_section) {
  return "name: tiny\nworlds: [" + kSmall + ", " + kCorridor + "]\nseeds: 2\ntune:\n" +
         tune_section;
}

// A folder's evaluations without their wall-clock times (the one thing a rerun changes).
std::vector<nlohmann::json> evaluations(const fs::path& jsonl) {
  std::vector<nlohmann::json> out;
  std::ifstream in(jsonl);
  for (std::string line; std::getline(in, line);) {
    out.push_back(nlohmann::json::parse(line));
    out.back().erase("wall_s");
  }
  return out;
}

const char* kHeldOutSeeds =
    "  validation_seeds: [11, 12]\n"
    "  parameters: {tracking.max_linear_speed_mps: [0.3, 0.8], docking.approach_speed_mps: [0.04, "
    "0.16]}\n";

TEST_F(Cli, TuneEndToEndHeldOutResumableAndItsBestRuns) {
  write("t.yaml", tiny_scenario(kHeldOutSeeds));
  const Outcome first = run("tune t.yaml --budget 3 --out a", 600);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  for (const char* f : {"best.json", "summary.json", "validation.csv", "report.html",
                        "convergence.png", "parameters.png", "evaluations.jsonl"})
    EXPECT_TRUE(fs::exists(dir_ / "a" / f)) << f;
  const auto summary = nlohmann::json::parse(read(dir_ / "a/summary.json"));
  EXPECT_EQ(summary["kind"], "tune");
  EXPECT_EQ(summary["tuning_episodes"], 4);
  EXPECT_EQ(summary["validation_episodes"], 4);
  // Every evaluation: 1 default + 3 NLopt + 3 random on the tuning episodes, 3 validations.
  const std::vector<nlohmann::json> lines = evaluations(dir_ / "a/evaluations.jsonl");
  ASSERT_EQ(lines.size(), 10u);
  std::set<std::string> tuning_ids, validation_ids;
  for (const auto& l : lines)
    for (const auto& e : l["episode_outcomes"])
      (l["search"].get<std::string>().rfind("validation:", 0) == 0 ? validation_ids : tuning_ids)
          .insert(e[0].get<std::string>());
  EXPECT_EQ(tuning_ids.size(), 4u);
  EXPECT_EQ(validation_ids.size(), 4u);
  for (const std::string& id : validation_ids)
    EXPECT_EQ(tuning_ids.count(id), 0u) << id << " was tuned on";
  // The table's success counts are the validation episodes' own.
  for (const auto& s : summary["settings"]) EXPECT_EQ(s["validation"]["episodes"], 4);

  // The dashboard lists it under its own heading, with its verdict and chart.
  ASSERT_EQ(run("run " + kSmall + " --out plain", 120).exit_code, 0);
  const Outcome d = run("summarize plain --html index.html --link a/report.html", 60);
  EXPECT_EQ(d.exit_code, 0) << d.err;
  const std::string index = read(dir_ / "index.html");
  EXPECT_NE(index.find("<h2>Tunings</h2>"), std::string::npos);
  EXPECT_NE(index.find("a/convergence.png"), std::string::npos);
  EXPECT_NE(index.find("held-out validation episodes"), std::string::npos);

  // best.json is a configuration `run` takes as it is.
  const Outcome r = run("run " + kSmall + " --config a/best.json --out r", 120);
  EXPECT_NE(r.exit_code, 2) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "r/summary.json"));
  // ... and a batch scenario names it as a controller.
  write("b.yaml",
        "worlds: [" + kSmall + "]\nseeds: 1\ncontrollers: {default: {}, tuned: a/best.json}\n");
  const Outcome b = run("batch b.yaml --out batch --quiet --no-figures", 300);
  EXPECT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(read(dir_ / "batch/episodes.jsonl").find("\"controller\":\"tuned\""),
            std::string::npos);
  write("bad.yaml", "worlds: [" + kSmall + "]\nseeds: 1\ncontrollers: {tuned: a/summary.json}\n");
  const Outcome bad = run("batch bad.yaml --out batch2 --quiet", 60);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("unknown parameter"), std::string::npos) << bad.err;

  // Killed mid-line: the torn line is cut, everything else is read back, the result the same.
  const std::string jsonl = read(dir_ / "a/evaluations.jsonl");
  const std::size_t last = jsonl.rfind('\n', jsonl.size() - 2);
  std::ofstream(dir_ / "a/evaluations.jsonl", std::ios::trunc) << jsonl.substr(0, last + 40);
  const Outcome again = run("tune t.yaml --budget 3 --out a", 600);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("1 evaluations run"), std::string::npos) << again.out;
  EXPECT_TRUE(evaluations(dir_ / "a/evaluations.jsonl") == lines);
  // The same seed in another folder: the same evaluations, line for line.
  ASSERT_EQ(run("tune t.yaml --budget 3 --out b --quiet --no-figures", 600).exit_code, 0);
  EXPECT_TRUE(evaluations(dir_ / "b/evaluations.jsonl") == lines);
  EXPECT_EQ(read(dir_ / "b/best.json"), read(dir_ / "a/best.json"));
}

// Evaluations keyed by search and index, wall-clock times left out: a merge's file holds them in
// the shards' order, one run's in the searches' order.
std::map<std::string, nlohmann::json> by_search(const fs::path& jsonl) {
  std::map<std::string, nlohmann::json> out;
  for (const nlohmann::json& e : evaluations(jsonl))
    out[e["search"].get<std::string>() + " " + std::to_string(e["index"].get<int>())] = e;
  return out;
}

TEST_F(Cli, TuneShardsJoinedByAMergeEqualOneRun) {
  write("t.yaml", tiny_scenario(kHeldOutSeeds));
  ASSERT_EQ(run("tune t.yaml --budget 3 --out whole --quiet --no-figures", 600).exit_code, 0);
  // Shard 0 searches with NLopt, shards 1 and 2 share random search's points; none validates.
  std::size_t shard_lines = 0;
  for (int i = 0; i < 3; ++i) {
    const std::string dir = "s" + std::to_string(i);
    const Outcome s =
        run("tune t.yaml --budget 3 --quiet --shard " + std::to_string(i) + "/3 --out " + dir, 600);
    ASSERT_EQ(s.exit_code, 0) << s.err;
    EXPECT_FALSE(fs::exists(dir_ / dir / "best.json")) << dir;
    for (const auto& [key, e] : by_search(dir_ / dir / "evaluations.jsonl")) {
      EXPECT_EQ(key.rfind("validation:", 0), std::string::npos) << dir << " validated";
      if (key != "default 0") ++shard_lines;
      const std::string search = i == 0 ? "nlopt " : "random ";
      EXPECT_TRUE(key == "default 0" || key.rfind(search, 0) == 0) << dir << ": " << key;
    }
  }
  EXPECT_EQ(shard_lines, 6u);  // three NLopt and three random points, each in one shard
  const Outcome m =
      run("tune t.yaml --budget 3 --merge s0 s1 s2 --out m --quiet --no-figures", 600);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_NE(m.out.find("3 evaluations run"), std::string::npos) << m.out;  // the validations
  EXPECT_TRUE(by_search(dir_ / "m/evaluations.jsonl") ==
              by_search(dir_ / "whole/evaluations.jsonl"));
  EXPECT_EQ(read(dir_ / "m/best.json"), read(dir_ / "whole/best.json"));
  // A missing shard is run by the merge itself; a shard of another tuning is refused.
  const Outcome partial =
      run("tune t.yaml --budget 3 --merge s0 --out p --quiet --no-figures", 600);
  ASSERT_EQ(partial.exit_code, 0) << partial.err;
  EXPECT_NE(partial.out.find("6 evaluations run"), std::string::npos) << partial.out;
  EXPECT_EQ(read(dir_ / "p/best.json"), read(dir_ / "whole/best.json"));
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"--budget 4 --merge s0", "another tuning"},
           {"--budget 3 --merge s0 nowhere", "'nowhere' is not a folder"},
           {"--budget 3 --merge t.yaml", "not a folder"},
           {"--budget 3 --shard 3/3", "--shard expects i/n"},
           {"--budget 3 --shard 1/3 --merge s0", "excludes"}}) {
    const Outcome bad = run("tune t.yaml " + args + " --out out", 60);
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_NE(bad.err.find(expected), std::string::npos) << args << "\n" << bad.err;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << args << " wrote its folder";
  }
}

TEST_F(Cli, TuneRefusesBadInputBeforeAnyEpisode) {
  write("t.yaml", tiny_scenario(kHeldOutSeeds));
  write("no_tune.yaml", "worlds: [" + kSmall + "]\nseeds: 1\n");
  write("no_validation.yaml", tiny_scenario("  budget: 4\n"));
  write("overlap.yaml", tiny_scenario("  validation_seeds: [2, 3]\n"));
  write("typo.yaml", tiny_scenario("  validation_seeds: 3\n  budjet: 4\n"));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"tune t.yaml --param tracking.max_linear_sped_mps=0.3:1",
       "did you mean 'tracking.max_linear_speed_mps'"},
      {"tune t.yaml --param docking.max_retries=1.5:4", "whole bounds"},
      {"tune t.yaml --param lidar.dropout_probability=0:1.5", "documented range [0, 1]"},
      {"tune t.yaml --param tracking.max_linear_speed_mps=1:0.5", "LOW < HIGH"},
      {"tune t.yaml --param tracking.max_linear_speed_mps", "KEY=LOW:HIGH"},
      {"tune t.yaml --param tracking.max_linear_speed_mps=a:1", "'a' is not a number"},
      // Issue 88: a bound above the motors' rim speed (0.8 m/s on these worlds) is refused.
      {"tune t.yaml --param tracking.max_linear_speed_mps=0.3:1.2",
       "tracking.max_linear_speed_mps tuned up to 1.2 m/s is above the robot's motor limit of 0.8"},
      {"tune t.yaml --budget 0", "--budget"},
      {"tune t.yaml --objective fastest", "unknown objective 'fastest'"},
      {"tune t.yaml --method lbfgs", "unknown method 'lbfgs'"},
      {"tune t.yaml --min-wilson 1.5", "--min-wilson"},
      {"tune no_tune.yaml", "field 'tune'"},
      {"tune no_validation.yaml", "tune.validation_worlds"},
      {"tune overlap.yaml", "must be held out"},
      {"tune typo.yaml", "did you mean 'budget'"},
  };
  for (const auto& [args, expected] : cases) {
    const Outcome o = run(args + " --out out", 60);
    EXPECT_EQ(o.exit_code, 2) << args << "\n" << o.err;
    EXPECT_NE(o.err.find(expected), std::string::npos) << args << "\n" << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << args << " wrote its folder";
  }
  // A folder of the user's own is refused and left as it was.
  write("mine/notes.txt", "keep");
  const Outcome o = run("tune t.yaml --budget 1 --out mine", 60);
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.err.find("not a tuning's output"), std::string::npos) << o.err;
  EXPECT_EQ(read(dir_ / "mine/notes.txt"), "keep");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "mine"), fs::directory_iterator()), 1);
}

// Issue 88: a travel speed the robot's motors cannot drive (its world's robot.max_speed_mps, 0.8
// m/s here) is refused with exit 2 before any episode, in a run's configuration, a batch's
// controllers and a sweep's values alike; the motor limit itself is accepted.
// A default is nobody's setting: a robot slower than the default cruise (0.6 m/s) runs with it,
// the drive capping the speed as before; what a user sets above the limit is refused.
TEST(RobotLimits, ASlowRobotRunsWithTheDefaultsAndRefusesASetSpeedAboveItsMotors) {
  worlds::World slow =
      worlds::load_world(test::source_file("data/worlds/examples/small_plant.json"));
  slow.robot.max_speed_mps = 0.5;
  episode::EpisodeConfig c;
  ASSERT_GT(c.tracking.max_linear_speed_mps, slow.robot.max_speed_mps);
  EXPECT_NO_THROW(episode::check_robot_limits(slow, c));
  c.tracking.max_linear_speed_mps = 0.55;
  EXPECT_THROW(episode::check_robot_limits(slow, c), std::invalid_argument);
  c.tracking.max_linear_speed_mps = 0.5;
  EXPECT_NO_THROW(episode::check_robot_limits(slow, c));
}

TEST_F(Cli, SpeedsAboveTheMotorLimitAreRefusedEverywhere) {
  write("fast.json", R"({"tracking": {"max_linear_speed_mps": 1.2}})");
  write("field.json",
        R"({"travel": "potential-field", "potential_field": {"max_speed_mps": 0.9}})");
  const std::string world = "worlds: [" + kSmall + "]\nseeds: 1\n";
  write("controllers.yaml",
        world + "controllers:\n  fast: {tracking: {max_linear_speed_mps: 1.5}}\n");
  const std::string sweep = "sweep:\n  parameter: tracking.max_linear_speed_mps\n";
  write("sweep.yaml", world + sweep + "  values: [0.6, 1.0]\n");
  write("ok.yaml", world + sweep + "  values: [0.6, 0.8]\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"run " + kSmall + " --config fast.json",
       "tracking.max_linear_speed_mps = 1.2 m/s is above the robot's motor limit of 0.8 m/s"},
      {"run " + kSmall + " --config field.json", "potential_field.max_speed_mps = 0.9 m/s"},
      {"batch controllers.yaml --check", "tracking.max_linear_speed_mps = 1.5 m/s"},
      {"batch sweep.yaml --check", "tracking.max_linear_speed_mps = 1 m/s"},
  };
  for (const auto& [args, expected] : cases) {
    const Outcome o = run(args + " --out out", 60);
    EXPECT_EQ(o.exit_code, 2) << args << "\n" << o.err;
    EXPECT_NE(o.err.find(expected), std::string::npos) << args << "\n" << o.err;
    EXPECT_NE(o.err.find("robot.max_speed_mps"), std::string::npos) << args << "\n" << o.err;
  }
  const Outcome ok = run("batch ok.yaml --check --out ok", 60);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

}  // namespace
}  // namespace plantsim
