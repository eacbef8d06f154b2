// Which build ran what (issue 89): every record names its build; a report over the records of
// more than one build says so, per build, and its banner is not green unless the mix is
// accepted (--accept-mixed-builds on batch, merge and summarize); a resume that runs nothing
// leaves the outputs of the run that made the records as they were (no new date, commit or
// "in 0.0 s", no second point on the dashboard's trend); records name their scenario relative to
// their folder; comparisons and bench lines are stamped; and a real episode's run report under
// the integrity rule's 1 m side.
#include <fstream>
#include <sstream>

#include "cli_fixture.h"

namespace plantsim {
namespace {

const std::string kCorridor = test::source_file("data/worlds/examples/corridor_crossing.json");

std::vector<nlohmann::json> records(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(nlohmann::json::parse(line));
  return out;
}

TEST_F(Cli, EveryRecordNamesItsBuildAndAResumeThatRanNothingRewritesNothing) {
  const std::string version = run("--version").out;  // "plantsim 0.15.0 (commit 1234...)"
  const std::string commit = version.substr(version.find("(commit ") + 8, 12);
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 2\ngate: {min_success: 0.5}\n");
  ASSERT_EQ(run("batch s.yaml --out b --quiet --no-figures --junit j.xml", 300).exit_code, 0);
  for (const nlohmann::json& r : records(read(dir_ / "b/episodes.jsonl")))
    EXPECT_NE(r["build"].get<std::string>().find(commit), std::string::npos) << r["build"];
  const std::string summary = read(dir_ / "b/summary.json");
  const std::string report = read(dir_ / "b/report.html");
  const std::string junit = read(dir_ / "j.xml");
  const auto stamp = fs::last_write_time(dir_ / "b/summary.json");
  ::sleep(1);  // a rewrite would carry another date to the second
  const Outcome o = run("batch s.yaml --out b --quiet --no-figures --junit j.xml", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("nothing to run"), std::string::npos) << o.out;
  EXPECT_EQ(read(dir_ / "b/summary.json"), summary);
  EXPECT_EQ(read(dir_ / "b/report.html"), report);
  EXPECT_EQ(read(dir_ / "j.xml"), junit);
  EXPECT_EQ(fs::last_write_time(dir_ / "b/summary.json"), stamp);
  // The dashboard's trend: one run, however often it is summarized after a no-op resume.
  ASSERT_EQ(run("summarize b --out s.md --html index.html", 60).exit_code, 0);
  ASSERT_EQ(run("batch s.yaml --out b --quiet --no-figures", 300).exit_code, 0);
  ASSERT_EQ(run("summarize b --out s.md --html index.html", 60).exit_code, 0);
  EXPECT_EQ(records(read(dir_ / "history.jsonl")).size(), 1u) << read(dir_ / "history.jsonl");
  // A resume asked for another gate judges anew: the outputs are written again.
  ASSERT_EQ(run("batch s.yaml --out b --quiet --no-figures --min-success 0.4", 300).exit_code, 0);
  EXPECT_NE(read(dir_ / "b/summary.json"), summary);
}

TEST_F(Cli, RecordsOfTwoBuildsAreCountedPerBuildAndTheirPassIsNotGreenUnlessAccepted) {
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 2\ngate: {min_success: 0.5}\n");
  ASSERT_EQ(run("batch s.yaml --out b --quiet --no-figures", 300).exit_code, 0);
  // An older build ran the first episode; the second is left to this one (a resume).
  std::vector<nlohmann::json> r = records(read(dir_ / "b/episodes.jsonl"));
  ASSERT_EQ(r.size(), 2u);
  r[0]["build"] = "0.14.0 000000000000";
  std::ofstream(dir_ / "b/episodes.jsonl") << r[0].dump() << "\n";
  Outcome o = run("batch s.yaml --out b --quiet --no-figures", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;  // the gate passed; the banner says what it is worth
  nlohmann::json summary = nlohmann::json::parse(read(dir_ / "b/summary.json"));
  ASSERT_EQ(summary["builds"].size(), 2u) << summary["builds"];
  EXPECT_EQ(summary["builds"][0]["episodes"], 1);
  EXPECT_EQ(summary["mixed_builds"]["builds"], 2);
  EXPECT_EQ(summary["mixed_builds"]["accepted"], false);
  std::string html = read(dir_ / "b/report.html");
  EXPECT_NE(html.find("<b>MIXED BUILDS</b>: records of 2 builds: "), std::string::npos);
  EXPECT_NE(html.find("0.14.0 000000000000 (1 episode)"), std::string::npos);
  EXPECT_EQ(html.find("banner pass"), std::string::npos);  // not green
  EXPECT_NE(html.find("<div class=\"banner mixed\"><b>PASS</b> (mixed builds)"), std::string::npos);
  // The dashboard: no PASS over it, unless summarize accepts the mix.
  o = run("summarize b --out s.md --html index.html", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_EQ(read(dir_ / "s.md").rfind("# plantsim results: MIXED BUILDS", 0), 0u)
      << read(dir_ / "s.md").substr(0, 300);
  EXPECT_EQ(read(dir_ / "index.html").find("banner pass"), std::string::npos);
  o = run("summarize b --out s.md --accept-mixed-builds", 60);
  EXPECT_EQ(read(dir_ / "s.md").rfind("# plantsim results: PASS", 0), 0u);
  // The batch accepts it: green again, and said so.
  o = run("batch s.yaml --out b --quiet --no-figures --accept-mixed-builds", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  summary = nlohmann::json::parse(read(dir_ / "b/summary.json"));
  EXPECT_EQ(summary["mixed_builds"]["accepted"], true);
  html = read(dir_ / "b/report.html");
  EXPECT_NE(html.find("<div class=\"banner pass\"><b>PASS</b>"), std::string::npos);
  EXPECT_NE(html.find("accepted with --accept-mixed-builds"), std::string::npos);
}

TEST_F(Cli, AMergeOfShardsRunByTwoBuildsSaysSo) {
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 2\ngate: {min_success: 0.5}\n");
  ASSERT_EQ(run("batch s.yaml --out a --shard 0/2 --quiet --no-figures", 300).exit_code, 0);
  ASSERT_EQ(run("batch s.yaml --out c --shard 1/2 --quiet --no-figures", 300).exit_code, 0);
  std::vector<nlohmann::json> r = records(read(dir_ / "c/episodes.jsonl"));
  ASSERT_EQ(r.size(), 1u);
  r[0]["build"] = "0.14.0 000000000000";
  std::ofstream(dir_ / "c/episodes.jsonl") << r[0].dump() << "\n";
  Outcome o = run("merge a c --out m", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_EQ(read(dir_ / "m/report.html").find("banner pass"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(read(dir_ / "m/summary.json"))["mixed_builds"]["builds"], 2);
  o = run("merge a c --out m2 --accept-mixed-builds", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(read(dir_ / "m2/report.html").find("banner pass"), std::string::npos);
}

// Records name their scenario relative to their folder: no machine's directory layout in them,
// and a results tree moved with its scenario still finds it (a merge draws its plan figures).
TEST_F(Cli, RecordsNameTheScenarioRelativeToTheirFolder) {
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 2\n");
  ASSERT_EQ(run("batch s.yaml --out out/a --shard 0/2 --quiet --no-figures", 300).exit_code, 0);
  ASSERT_EQ(run("batch s.yaml --out out/c --shard 1/2 --quiet --no-figures", 300).exit_code, 0);
  const std::string text = read(dir_ / "out/a/episodes.jsonl");
  EXPECT_EQ(text.find(dir_.string()), std::string::npos) << text.substr(0, 300);
  for (const nlohmann::json& r : records(text)) EXPECT_EQ(r["scenario_file"], "../../s.yaml");
  // The tree moved elsewhere: the merge finds the scenario from the records' folders.
  const fs::path moved = root_ / "moved";
  fs::rename(dir_, moved);
  fs::create_directories(dir_);
  write("s.yaml", "worlds: []\n");  // the old place holds something else now
  const Outcome o = run(
      "merge " + (moved / "out/a").string() + " " + (moved / "out/c").string() + " --out m", 300);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(fs::exists(dir_ / "m/plans_corridor_crossing.png")) << o.err;
  for (const nlohmann::json& r : records(read(dir_ / "m/episodes.jsonl")))
    EXPECT_EQ(fs::path(r["scenario_file"].get<std::string>()),
              fs::path("../../moved/s.yaml"));  // from m: root/work/m -> root/moved/s.yaml
}

// Issue 89, item 2, on a real episode: a tuning yard, very wet, every noise doubled, the robot
// untold (test_localization.cpp's AnAmbiguousMatchRepeatedDoesNotBecomeCertainty): it said
// `lost`, drove on 88 m, and charged. Its run report carries the failure banner naming the rule.
TEST_F(Cli, ARunReportOfAnEpisodeThatDroveOnALostEstimateCarriesTheFailureBanner) {
  write("s.yaml", "name: yard_alike\nworlds: [" +
                      test::source_file("data/worlds/generated/styles/yard_s3.json") +
                      "]\nplanners: [vg]\ncontrollers:\n  shortest: {coastal: {enabled: false}}\n"
                      "faults:\n  very_wet_noise2x_untold:\n    drive: {tyre_friction: 0.05}\n"
                      "    odometry: {wheel_speed_noise: 0.04, left_scale_error: 0.006, "
                      "right_scale_error: -0.006}\n"
                      "    lidar: {range_noise_m: 0.06, dropout_probability: 0.1}\n"
                      "    imu: {yaw_rate_noise_radps: 0.012, bias_radps: 0.012}\n"
                      "    detection: {position_noise_m: 0.01, yaw_noise_rad: 0.01, "
                      "false_negative_probability: 0.6, outlier_probability: 0.06, "
                      "latency_s: 0.4}\nseeds: [1]\n");
  const Outcome o =
      run("batch s.yaml --episode 'yard_s3|vg|shortest|very_wet_noise2x_untold|1' --out r", 300);
  EXPECT_EQ(o.exit_code, 1) << o.err;  // not a success
  EXPECT_NE(o.out.find("docked_off_estimate"), std::string::npos) << o.out;
  const std::string html = read(dir_ / "r/report.html");
  const std::size_t banner =
      html.find("<div class=\"banner fail\"><b>FAILED</b>: localization_lost");
  ASSERT_NE(banner, std::string::npos) << html.substr(0, 1500);
  EXPECT_NE(html.find("in all on an estimate more than 0.25 m off", banner), std::string::npos);
  EXPECT_NE(html.find("whatever its estimator reported", banner), std::string::npos);
  const nlohmann::json summary = nlohmann::json::parse(read(dir_ / "r/summary.json"));
  EXPECT_EQ(summary["status"], "docked_off_estimate");
  EXPECT_GT(summary["driven_off_estimate_m"].get<double>(), 1.0);
}

// fig5_vs_fig6 and every `plantsim compare`: comparison.json and its page name the build and date.
TEST_F(Cli, AComparisonIsStampedWithItsBuildAndDate) {
  const std::string version = run("--version").out;
  const std::string commit = version.substr(version.find("(commit ") + 8, 12);
  const Outcome o =
      run("compare " + kCorridor + " --planners vg,vg-traditional --plan-only --out c", 120);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const nlohmann::json j = nlohmann::json::parse(read(dir_ / "c/comparison.json"));
  EXPECT_EQ(j["made_by"]["commit"], commit);
  EXPECT_EQ(j["made_by"]["date"].get<std::string>().size(), 20u);  // 2026-12-08T03:02:11Z
  EXPECT_NE(read(dir_ / "c/report.html").find("Made by plantsim"), std::string::npos);
}

// Bench output: every JSON line names the build that measured it and when.
TEST_F(Cli, EveryBenchLineNamesItsBuildAndDate) {
  const std::string version = run("--version").out;
  const std::string commit = version.substr(version.find("(commit ") + 8, 12);
  const Outcome o = run("bench startup --quick", 120);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const std::vector<nlohmann::json> lines = records(o.out);
  ASSERT_FALSE(lines.empty());
  for (const nlohmann::json& j : lines) {
    EXPECT_NE(j["build"].get<std::string>().find("(commit " + commit), std::string::npos) << j;
    EXPECT_EQ(j["date"].get<std::string>().size(), 20u) << j;
  }
}

}  // namespace
}  // namespace plantsim
