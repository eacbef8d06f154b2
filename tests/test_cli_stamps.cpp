// Outputs that say which build made them (issue 52): a run's and a batch's summary.json and
// report.html, junit.xml and every PNG carry plantsim's version and commit (and the date, the
// duration and the hash of the config or scenario where the file has room); the dashboard flags
// an output another build made, or one made before stamps; an episode re-run alone into its
// batch's folder goes beside the records, and the batch re-runs around it. And the verdict first:
// a banner on the batch report and the dashboard, failing rows first with the gate early.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli_fixture.h"

namespace plantsim {
namespace {

const std::string kCorridor = test::source_file("data/worlds/examples/corridor_crossing.json");

// "plantsim 0.15.0 (commit 1234567890ab...)": the commit this binary was built from.
std::string commit_of(const std::string& version_line) {
  const std::size_t at = version_line.find("(commit ") + 8;
  return version_line.substr(at, 12);
}

TEST_F(Cli, EveryOutputNamesTheBuildThatMadeIt) {
  const std::string commit = commit_of(run("--version").out);
  ASSERT_EQ(commit.find_first_not_of("0123456789abcdefunknow"), std::string::npos) << commit;
  ASSERT_EQ(run("run " + kCorridor + " --out r", 120).exit_code, 0);
  const auto summary = nlohmann::json::parse(read(dir_ / "r/summary.json"));
  EXPECT_EQ(summary["made_by"]["commit"], commit);
  EXPECT_EQ(summary["made_by"]["config"].get<std::string>().size(), 16u);
  EXPECT_GT(summary["made_by"]["duration_s"].get<double>(), 0.0);
  EXPECT_EQ(summary["made_by"]["date"].get<std::string>().size(), 20u);  // 2026-12-03T15:02:11Z
  EXPECT_NE(read(dir_ / "r/report.html").find("Made by plantsim"), std::string::npos);
  // A figure's own record: the PNG's Software text.
  const std::string png = read(dir_ / "r/run.png");
  EXPECT_NE(png.find("tEXtSoftware"), std::string::npos);
  EXPECT_NE(png.find("(commit " + commit), std::string::npos);

  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 1\n");
  const Outcome b = run("batch s.yaml --out b --quiet --no-figures --junit j.xml", 300);
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto batch = nlohmann::json::parse(read(dir_ / "b/summary.json"));
  EXPECT_EQ(batch["made_by"]["commit"], commit);
  EXPECT_EQ(batch["made_by"]["scenario"],
            nlohmann::json::parse(read(dir_ / "b/episodes.jsonl"))["scenario"]);
  EXPECT_NE(read(dir_ / "b/report.html").find("Made by plantsim"), std::string::npos);
  const std::string junit = read(dir_ / "j.xml");
  EXPECT_NE(junit.find("<property name=\"plantsim_commit\" value=\"" + commit + "\"/>"),
            std::string::npos)
      << junit;
}

TEST_F(Cli, TheDashboardFlagsWhatAnotherBuildMade) {
  for (const std::string out : {"mine", "other", "old"})
    ASSERT_EQ(run("run " + kCorridor + " --out " + out, 120).exit_code, 0);
  auto edit = [&](const std::string& folder, const std::function<void(nlohmann::json&)>& f) {
    nlohmann::json j = nlohmann::json::parse(read(dir_ / folder / "summary.json"));
    f(j);
    std::ofstream(dir_ / folder / "summary.json") << j.dump();
  };
  edit("other", [](nlohmann::json& j) { j["made_by"]["commit"] = "000000000000"; });
  edit("old", [](nlohmann::json& j) { j.erase("made_by"); });
  const Outcome o = run("summarize mine other old --out s.md --html index.html", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  const std::string html = read(dir_ / "index.html");
  EXPECT_NE(html.find("made by another build (commit 000000000000"), std::string::npos);
  EXPECT_NE(html.find("no build stamp"), std::string::npos);
  EXPECT_NE(html.find("of the outputs below were not made by this build"), std::string::npos);
  EXPECT_NE(read(dir_ / "s.md").find("Made by plantsim"), std::string::npos);
}

TEST_F(Cli, AnEpisodeReRunAloneGoesBesideItsBatchsRecords) {
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 2\n");
  ASSERT_EQ(run("batch s.yaml --out b --quiet --no-figures", 300).exit_code, 0);
  const std::string id = "corridor_crossing|vg|default|none|2";
  Outcome o = run("batch s.yaml --episode '" + id + "' --out b", 120);
  EXPECT_EQ(o.exit_code, 0) << o.err;  // was exit 2: "holds episodes.jsonl"
  const fs::path alone = dir_ / "b/episodes" / "corridor_crossing_vg_default_none_2";
  EXPECT_TRUE(fs::exists(alone / "summary.json")) << o.out;
  EXPECT_TRUE(fs::exists(alone / "report.html"));
  o = run("batch s.yaml --out b --quiet --no-figures", 300);  // a resume keeps it
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(fs::exists(alone / "summary.json"));
  o = run("batch s.yaml --out b --quiet --no-figures --fresh", 300);  // records gone: so is it
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "b/episodes"));
}

TEST_F(Cli, TheVerdictComesFirstFailingRowsFirstWithTheirGate) {
  write("s.yaml", "worlds: [" + kCorridor +
                      "]\nseeds: 1\nfaults: {ok: {}, short: {timeout_s: 2}}\n"
                      "gate: {min_success: 1.0}\n");
  Outcome o = run("batch s.yaml --out b --quiet --no-figures", 300);
  EXPECT_EQ(o.exit_code, 1) << o.err;
  const std::string html = read(dir_ / "b/report.html");
  const std::size_t banner = html.find("<div class=\"banner fail\"><b>FAIL</b>: 1 of 2 gated");
  ASSERT_NE(banner, std::string::npos) << html.substr(0, 2000);
  EXPECT_LT(banner, html.find("<table>"));  // before any table
  EXPECT_NE(html.find("corridor_crossing / vg / default / short: 0/1 docked", banner),
            std::string::npos);
  EXPECT_NE(html.find("short by 1.000", banner), std::string::npos);
  // The gate is the fifth column, and the failing row comes first, in red.
  const std::size_t header = html.find(
      "<tr><th>world</th><th>planner</th><th>controller</th>"
      "<th>fault</th><th>gate</th>");
  ASSERT_NE(header, std::string::npos);
  const std::size_t first_row = html.find("<tr", header + 5);
  EXPECT_EQ(html.substr(first_row, 17), "<tr class=\"fail\">");
  EXPECT_NE(html.find("<td>short</td><td>FAIL success_rate 0.000 &lt; 1.000", first_row),
            std::string::npos);
  // None docked: its mean docking error is no value, not a perfect 0.000.
  EXPECT_NE(html.find("<td>1</td><td>0</td><td>-</td>", first_row), std::string::npos);
  EXPECT_NE(html.find("Details per configuration"), std::string::npos);
  // The dashboard says it first too.
  ASSERT_EQ(run("run " + kCorridor + " --out r", 120).exit_code, 0);
  o = run("summarize r --html index.html --link b/report.html", 60);
  EXPECT_NE(read(dir_ / "index.html").find("<b>FAIL</b>: 1 of 1 batches below their gates: b"),
            std::string::npos);
  EXPECT_EQ(o.exit_code, 1);  // a linked batch below its gate fails the overview too
  // summary.md mirrors it: the batch, its verdict and its failures by reason; a batch folder given
  // as a run is listed as its report, not read as a run.
  o = run("summarize r b --out s.md", 60);
  EXPECT_EQ(o.exit_code, 1) << o.err;
  const std::string md = read(dir_ / "s.md");
  EXPECT_NE(md.find("## Batches"), std::string::npos) << md;
  EXPECT_NE(
      md.find("- **FAIL** [b](b/report.html): 1 of 2 episodes succeeded; failures\\: timeout 1"),
      std::string::npos)
      << md;
  EXPECT_EQ(md.find("| ? |"), std::string::npos) << md;
  // The dashboard keeps each batch's runs (history.jsonl beside it) and draws the last ones.
  ::sleep(1);  // a run is known by its date, to the second
  ASSERT_EQ(run("batch s.yaml --out b --quiet --no-figures --fresh --min-success 0", 300).exit_code,
            0);
  o = run("summarize r --html index.html --link b/report.html", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  o = run("summarize r --html index.html --link b/report.html", 60);  // the same run: not twice
  const std::string history = read(dir_ / "history.jsonl");
  EXPECT_EQ(std::count(history.begin(), history.end(), '\n'), 2) << history;
  EXPECT_NE(history.find("\"verdict\":\"failed\""), std::string::npos);
  EXPECT_NE(history.find("\"verdict\":\"passed\""), std::string::npos);
  const std::string dashboard = read(dir_ / "index.html");
  EXPECT_NE(dashboard.find("last 2 runs: FAIL PASS"), std::string::npos);
  EXPECT_NE(dashboard.find("<circle"), std::string::npos);
  // A batch that meets its gate: PASS, and the sample's doubt said.
  write("p.yaml", "worlds: [" + kCorridor + "]\nseeds: 1\ngate: {min_success: 0.5}\n");
  ASSERT_EQ(run("batch p.yaml --out p --quiet --no-figures", 300).exit_code, 0);
  const std::string pass = read(dir_ / "p/report.html");
  EXPECT_NE(pass.find("<b>PASS</b>: all 1 gated configurations meet the gate: success_rate at or "
                      "above 0.500"),
            std::string::npos);
  EXPECT_NE(pass.find("more episodes would tell"), std::string::npos);  // 1/1: low 0.21 < 0.5
}

/// The replay's data as a report embeds it (null when the report has no replay).
nlohmann::json replay_of(const std::string& html) {
  const std::string marker = "id=\"replay-data\">";
  const std::size_t data = html.find(marker);
  if (data == std::string::npos) return nullptr;
  const std::size_t begin = data + marker.size();
  return nlohmann::json::parse(html.substr(begin, html.find("</script>", begin) - begin));
}

// A failed run says why first, and its replay carries what it needs to end on the failure: the
// reason, time, place and detail, the estimate beside the truth and the events.
TEST_F(Cli, AFailedRunsReportAndReplayEndOnTheFailure) {
  write("short.json", "{\"timeout_s\": 25}");
  const Outcome o = run("run " + test::source_file("data/worlds/examples/small_plant.json") +
                            " --config short.json --out f",
                        120);
  ASSERT_EQ(o.exit_code, 1) << o.err;
  EXPECT_NE(o.out.find("timeout, position error -, heading error -"), std::string::npos) << o.out;
  const std::string html = read(dir_ / "f/report.html");
  const std::size_t banner =
      html.find("<div class=\"banner fail\"><b>FAILED</b>: timeout at t = 25.0 s, at (");
  ASSERT_NE(banner, std::string::npos);
  EXPECT_LT(banner, html.find("<table"));  // before the table
  EXPECT_NE(html.find("still moving on when the time ran out", banner), std::string::npos);
  // No docking error where it never docked (it was the distance to the charger).
  EXPECT_NE(html.find("<td>timeout</td><td>-</td><td>-</td>"), std::string::npos);
  const nlohmann::json replay = replay_of(html);
  ASSERT_FALSE(replay.is_null());
  EXPECT_EQ(replay["failure"]["reason"], "timeout");
  EXPECT_NEAR(replay["failure"]["t"].get<double>(), 25.0, 0.1);
  EXPECT_EQ(replay["ex"].size(), replay["x"].size());
  EXPECT_EQ(replay["sigma"].size(), replay["x"].size());
  EXPECT_TRUE(replay["events"].is_array());
}

// A kidnapped run: its replay carries the estimator's verdict frame by frame (ok before the carry,
// lost after it) and the carry itself; trajectory.csv says the same; the carry is not driven.
TEST_F(Cli, AKidnappedRunsReplayShowsTheCarryAndTheEstimatorsVerdictPerFrame) {
  write("kidnap.json",
        "{\"kidnap\": {\"at_s\": 15, \"dx_m\": 3, \"dy_m\": 1, \"dyaw_rad\": 1.0}, "
        "\"timeout_s\": 40}");
  const Outcome o = run("run " + test::source_file("data/worlds/examples/small_plant.json") +
                            " --config kidnap.json --out k",
                        120);
  ASSERT_EQ(o.exit_code, 1) << o.err;  // the EKF does not find itself again here
  const std::string html = read(dir_ / "k/report.html");
  const nlohmann::json replay = replay_of(html);
  ASSERT_FALSE(replay.is_null());
  ASSERT_EQ(replay["health"].size(), replay["t"].size());
  int ok_before = 0, lost_after = 0, frames_after = 0;
  for (std::size_t i = 0; i < replay["t"].size(); ++i) {
    const double t = replay["t"][i].get<double>();
    const int h = replay["health"][i].get<int>();
    if (t < 14.9) ok_before += h == 0;
    if (t > 16) ++frames_after, lost_after += h == 2;
  }
  EXPECT_GT(ok_before, 0);
  EXPECT_GT(frames_after, 0);
  EXPECT_EQ(lost_after, frames_after);
  ASSERT_EQ(replay["carries"].size(), 1u);
  EXPECT_NEAR(replay["carries"][0]["t"].get<double>(), 15.0, 0.1);
  const auto& from = replay["carries"][0]["from"];
  const auto& to = replay["carries"][0]["to"];
  EXPECT_NEAR(to[0].get<double>() - from[0].get<double>(), 3.0, 1e-3);
  EXPECT_NEAR(to[1].get<double>() - from[1].get<double>(), 1.0, 1e-3);
  const std::string csv = read(dir_ / "k/trajectory.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')).substr(csv.find('\n') - 11), ",est_status");
  EXPECT_NE(csv.find(",ok\n"), std::string::npos);
  EXPECT_NE(csv.find(",lost\n"), std::string::npos);
  // Driven length: the trajectory's polyline (every control period) less the 3.16 m carry.
  std::istringstream rows(csv.substr(csv.find('\n') + 1));
  std::string row;
  double polyline = 0, last_x = NAN, last_y = NAN;
  while (std::getline(rows, row)) {
    double t = 0, x = 0, y = 0;
    ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf", &t, &x, &y), 3) << row;
    if (!std::isnan(last_x)) polyline += std::hypot(x - last_x, y - last_y);
    last_x = x, last_y = y;
  }
  const auto summary = nlohmann::json::parse(read(dir_ / "k/summary.json"));
  EXPECT_LT(summary["driven_length_m"].get<double>(), polyline - 3.0);
}

}  // namespace
}  // namespace plantsim

namespace plantsim {
namespace {

// A command that draws nothing starts without OSMesa (and the LLVM it brings): the render library
// opens it when the first canvas is made (render/osmesa_library.h). The dynamic loader's own log
// (glibc's LD_DEBUG=files) says which libraries a process mapped.
TEST_F(Cli, OnlyACommandThatDrawsOpensOsMesa) {
  auto loaded = [&](const std::vector<std::string>& args) {
    util::SpawnOptions o;
    o.working_dir = dir_.string();
    o.stdout_path = (dir_ / "out.txt").string();
    o.stderr_path = (dir_ / "loader.txt").string();
    o.environment_additions = {"LD_DEBUG=files"};
    std::vector<std::string> argv{PLANTSIM_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    EXPECT_EQ(util::run_program_measured(argv, o).exit_code, 0) << read(dir_ / "loader.txt");
    return read(dir_ / "loader.txt");
  };
  const std::string version = loaded({"--version"});
  EXPECT_NE(version.find("file=libstdc++"), std::string::npos) << "no loader log: " << version;
  EXPECT_EQ(version.find("libOSMesa"), std::string::npos);
  EXPECT_EQ(loaded({"plan", kCorridor}).find("libOSMesa"), std::string::npos);
  EXPECT_NE(loaded({"run", kCorridor, "--out", "r"}).find("file=libOSMesa"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "r/run.png"));
}

// The dashboard said PASS ("0 failed") over a single run that failed, and summary.md had no
// headline: one verdict over runs and linked reports heads both, and the exit code agrees.
TEST_F(Cli, OneVerdictOverRunsAndBatchesHeadsTheDashboardAndTheTable) {
  write("short.json", R"({"timeout_s": 5})");
  ASSERT_EQ(run("run " + kCorridor + " --out good", 120).exit_code, 0);
  ASSERT_EQ(run("run " + kCorridor + " --config short.json --out bad", 120).exit_code, 1);
  Outcome o = run("summarize good bad --html index.html --out s.md", 60);
  EXPECT_EQ(o.exit_code, 1) << o.err;
  const std::string html = read(dir_ / "index.html");
  const std::size_t banner = html.find(
      "<div class=\"banner fail\"><b>FAIL</b>: 1 of 2 single runs did not succeed: "
      "corridor_crossing (timeout)");
  ASSERT_NE(banner, std::string::npos) << html.substr(0, 3000);
  EXPECT_LT(banner, html.find("<table"));
  const std::string md = read(dir_ / "s.md");
  EXPECT_EQ(md.rfind("# plantsim results: FAIL\n\n**FAIL**: 1 of 2 single runs", 0), 0u) << md;
  // Without the failed run: PASS, exit 0, on both.
  o = run("summarize good --html index.html --out s.md", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(read(dir_ / "index.html").find("<div class=\"banner pass\"><b>PASS</b>: every single"),
            std::string::npos);
  EXPECT_EQ(read(dir_ / "s.md").rfind("# plantsim results: PASS\n", 0), 0u);
}

}  // namespace
}  // namespace plantsim
