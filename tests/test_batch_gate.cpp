// The batch as a gate users can trust: configurations judged against thresholds (and the JUnit
// report), episodes the same whatever a world's place in the list, merges that refuse mixed
// scenarios and missing shards, one writer per folder, resume past malformed lines, and
// scenario paths relative to the scenario file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "batch/batch_gate.h"
#include "batch/batch_merge.h"
#include "batch/batch_runner.h"
#include "batch/episode_runner.h"
#include "batch/episode_space.h"
#include "batch/report_verdicts.h"
#include "batch/summary_tables.h"
#include "batch_folder_test.h"
#include "render/report.h"
#include "test_paths.h"
#include "util/csv.h"
#include "util/folder_lock.h"
#include "worlds/known_keys.h"
#include "worlds/world_error.h"

namespace plantsim::batch {
namespace {

namespace fs = std::filesystem;

std::string record(const std::string& world, const std::string& planner, const std::string& fault,
                   bool docked) {
  return nlohmann::json{{"world", world},
                        {"planner", planner},
                        {"controller", "default"},
                        {"fault", fault},
                        {"docked", docked}}
      .dump();
}

std::vector<std::string> records(const std::string& world, const std::string& planner,
                                 const std::string& fault, int docked, int failed) {
  std::vector<std::string> out;
  for (int i = 0; i < docked; ++i) out.push_back(record(world, planner, fault, true));
  for (int i = 0; i < failed; ++i) out.push_back(record(world, planner, fault, false));
  return out;
}

TEST(Gate, JudgesEachConfigurationAgainstItsThreshold) {
  std::vector<std::string> lines = records("w", "vg", "none", 19, 1);  // 0.95
  const auto gcr = records("w", "gcr", "none", 6, 4);                  // 0.60
  lines.insert(lines.end(), gcr.begin(), gcr.end());
  Gate gate;
  EXPECT_TRUE(judge_configurations(lines, gate)[0].passed);  // no threshold: nothing gated
  EXPECT_FALSE(judge_configurations(lines, gate)[0].threshold.has_value());
  gate.min_success = 0.9;
  auto v = judge_configurations(lines, gate);
  ASSERT_EQ(v.size(), 2u);
  const auto& by_gcr = v[0].planner == "gcr" ? v[0] : v[1];
  const auto& by_vg = v[0].planner == "vg" ? v[0] : v[1];
  EXPECT_FALSE(by_gcr.passed);
  EXPECT_TRUE(by_vg.passed);
  EXPECT_NE(gate_failures_text(v, gate.statistic)
                .find("w / gcr / default / none: 6/10 docked, success_rate 0.600 < 0.900"),
            std::string::npos)
      << gate_failures_text(v, gate.statistic);
  // A rule for the baseline planner: the last matching rule wins over the default.
  gate.rules.push_back({"", "gcr", "", "", 0.5});
  v = judge_configurations(lines, gate);
  EXPECT_TRUE(v[0].passed && v[1].passed);
  // The Wilson lower bound is stricter: 19 of 20 has a lower bound of 0.764.
  gate.statistic = GateStatistic::kWilsonLow;
  v = judge_configurations(lines, gate);
  const auto& vg_wilson = v[0].planner == "vg" ? v[0] : v[1];
  EXPECT_NEAR(vg_wilson.wilson_low, 0.7639, 1e-3);
  EXPECT_FALSE(vg_wilson.passed);
}

// A pursuit world's episodes never dock: their success is the catch, and the verdict says so.
TEST(Gate, APursuitSucceedsByCatchingNotDocking) {
  std::vector<std::string> lines;
  for (int i = 0; i < 4; ++i)
    lines.push_back(nlohmann::json{
        {"world", "chase"},
        {"planner", "vg"},
        {"controller", "path"},
        {"fault", "none"},
        {"docked", false},
        {"caught", i < 3},
        {"succeeded", i < 3},
        {"goal",
         "catch"}}.dump());
  Gate gate;
  gate.min_success = 0.9;
  const auto v = judge_configurations(lines, gate);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].succeeded, 3);
  EXPECT_NEAR(v[0].success_rate, 0.75, 1e-12);
  EXPECT_NE(gate_failures_text(v, gate.statistic).find("chase / vg / path / none: 3/4 caught"),
            std::string::npos)
      << gate_failures_text(v, gate.statistic);
  // Records from before the "succeeded" field still count by "docked".
  EXPECT_TRUE(record_succeeded(nlohmann::json{{"docked", true}}));
  EXPECT_FALSE(record_succeeded(nlohmann::json{{"docked", false}}));
}

TEST(Gate, JUnitReportHasOneCasePerConfigurationAndTheFailures) {
  std::vector<std::string> lines = records("plant<1>", "vg", "wet", 3, 1);
  const auto ok = records("plant<1>", "vg", "dry", 4, 0);
  lines.insert(lines.end(), ok.begin(), ok.end());
  Gate gate;
  gate.min_success = 0.9;
  const std::string xml = junit_xml("suite", judge_configurations(lines, gate), gate.statistic);
  EXPECT_NE(xml.find("tests=\"2\" failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("classname=\"suite.plant&lt;1&gt;\""), std::string::npos) << xml;  // escaped
  EXPECT_NE(xml.find("<failure message=\"plant&lt;1&gt; / vg / default / wet: 3/4 docked"),
            std::string::npos)
      << xml;
  EXPECT_GT(xml.find("<failure"), xml.find("/ wet\""))
      << xml;  // the failure is the wet case's, not the dry one's
  EXPECT_EQ(xml.find("<failure", xml.find("<failure") + 1), std::string::npos) << xml;
}

// JUnit's <failure> had one line: a CI page showed "3/4 docked" and nothing to act on. It lists
// each failed episode with its reason and the command that replays it alone.
TEST(Gate, JUnitFailuresListTheFailedEpisodesWithReasonsAndReplays) {
  std::vector<std::string> lines = records("plant", "vg", "wet", 3, 0);
  lines.push_back(nlohmann::json{{"world", "plant"},
                                 {"planner", "vg"},
                                 {"controller", "default"},
                                 {"fault", "wet"},
                                 {"id", "plant|vg|default|wet|4"},
                                 {"succeeded", false},
                                 {"status", "failed"},
                                 {"failure", "localization_lost"}}
                      .dump());
  Gate gate;
  gate.min_success = 0.9;
  const std::string xml = junit_xml("suite", judge_configurations(lines, gate), gate.statistic, {},
                                    {"my scenario.yaml", "out"});
  EXPECT_NE(xml.find("1 failed episode(s):\n  plant|vg|default|wet|4: localization_lost\n"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("replay: plantsim batch &apos;my scenario.yaml&apos; --episode "
                     "&apos;plant|vg|default|wet|4&apos; --out out  (then "
                     "out/episodes/plant_vg_default_wet_4/report.html)"),
            std::string::npos)
      << xml;
}

// XML 1.0 has no U+FFFE or U+FFFF: a fault so named made junit.xml that no reader parses.
TEST(Gate, JUnitReportHoldsNoCharacterXmlRefuses) {
  const std::string name =
      "wet\xEF\xBF\xBE\xEF\xBF\xBF"
      "end\x01\xEF\xBF\xBD";
  const std::vector<std::string> lines = records("plant", "vg", name, 3, 1);
  Gate gate;
  gate.min_success = 0.9;
  const std::string xml = junit_xml("suite", judge_configurations(lines, gate), gate.statistic);
  EXPECT_EQ(xml.find("\xEF\xBF\xBE"), std::string::npos);
  EXPECT_EQ(xml.find("\xEF\xBF\xBF"), std::string::npos);
  EXPECT_EQ(xml.find('\x01'), std::string::npos);
  EXPECT_NE(xml.find("wet??end?\xEF\xBF\xBD"), std::string::npos) << xml;  // U+FFFD is allowed
}

class BatchFolders : public test::BatchFolderTest {
 protected:
  std::string two_worlds(const std::string& name, bool reversed, int seeds = 2) {
    std::string a = test::shared_data("worlds/world_N10.json"),
                b = test::source_file("data/worlds/examples/small_plant.json");
    if (reversed) std::swap(a, b);
    return write(name, "worlds: [" + a + ", " + b +
                           "]\nplanners: [vg]\nseeds: " + std::to_string(seeds) + "\n");
  }
  static std::map<std::string, std::string> starts_by_id(const std::string& dir) {
    std::map<std::string, std::string> out;
    for (const std::string& line : read_episode_records(dir)) {
      const auto j = nlohmann::json::parse(line);
      out[j["id"]] = j["start"].dump();
    }
    return out;
  }
};

TEST_F(BatchFolders, AnEpisodeIsTheSameWhateverTheWorldsOrder) {
  run_batch(two_worlds("ab.yaml", false), options("ab"));
  run_batch(two_worlds("ba.yaml", true), options("ba"));
  const auto ab = starts_by_id((dir_ / "ab").string()), ba = starts_by_id((dir_ / "ba").string());
  ASSERT_EQ(ab.size(), 4u);
  EXPECT_EQ(ab, ba);
  // Same episodes, so the same scenario: their shards merge.
  EXPECT_EQ(merge_batches({(dir_ / "ab").string(), (dir_ / "ba").string()}, (dir_ / "m").string())
                .episodes,
            4);
}

TEST_F(BatchFolders, MergeRefusesMixedScenariosAndMissingShards) {
  run_batch(two_worlds("two.yaml", false, 2), options("two"));
  run_batch(two_worlds("three.yaml", false, 3), options("three"));
  try {
    merge_batches({(dir_ / "two").string(), (dir_ / "three").string()}, (dir_ / "mixed").string());
    ADD_FAILURE() << "merged two scenarios";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("different scenarios"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "mixed" / "episodes.jsonl"));
  // Three of four shards of the 6-episode scenario.
  const std::string scenario = (dir_ / "three.yaml").string();
  std::vector<std::string> shards;
  std::int64_t in_three = 0;
  for (int i = 0; i < 3; ++i) {
    const std::string name =
        std::string("s") + static_cast<char>('0' + i);  // (GCC 12 warns falsely on "s" + to_string)
    in_three += run_batch(scenario, options(name, i, 4)).episodes;
    shards.push_back((dir_ / name).string());
  }
  try {
    merge_batches(shards, (dir_ / "partial").string());
    ADD_FAILURE() << "merged 3 of 4 shards silently";
  } catch (const IncompleteBatch& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(6 - in_three) +
                                         " of the scenario's 6 episodes are missing"),
              std::string::npos)
        << e.what();
  }
  MergeOptions partial;
  partial.allow_partial = true;
  EXPECT_EQ(merge_batches(shards, (dir_ / "partial").string(), partial).episodes, in_three);
}

TEST_F(BatchFolders, BatchRefusesAFolderOfAnotherScenarioUnlessFresh) {
  run_batch(two_worlds("two.yaml", false, 2), options("out"));
  try {
    run_batch(two_worlds("three.yaml", false, 3), options("out"));
    ADD_FAILURE() << "appended another scenario's episodes";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("holds episodes of another scenario"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(read_episode_records((dir_ / "out").string()).size(), 4u);
  RunOptions fresh = options("out");
  fresh.fresh = true;
  EXPECT_EQ(run_batch((dir_ / "three.yaml").string(), fresh).ran, 6);
  EXPECT_EQ(read_episode_records((dir_ / "out").string()).size(), 6u);
}

TEST_F(BatchFolders, OneBatchPerOutputFolder) {
  const std::string scenario = two_worlds("s.yaml", false);
  fs::create_directories(dir_ / "busy");
  const util::FolderLock held((dir_ / "busy").string());  // as another process would hold it
  try {
    run_batch(scenario, options("busy"));
    ADD_FAILURE() << "two writers on one folder";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("another plantsim process is writing"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "busy" / "episodes.jsonl"));
}

TEST_F(BatchFolders, ResumeCutsMalformedLinesAndRerunsTheirEpisodes) {
  const std::string scenario = two_worlds("s.yaml", false);
  run_batch(scenario, options("whole"));
  const auto whole = starts_by_id((dir_ / "whole").string());
  // Keep two good records, add lines resume cannot use: no id, not an object, not JSON, torn.
  const auto good = read_episode_records((dir_ / "whole").string());
  fs::create_directories(dir_ / "damaged");
  std::string damaged = good[0];
  for (const char* bad : {"\n{}\n[1,2]\nnot json\n"}) damaged.append(bad);
  damaged.append(good[1]).append("\n{\"id\": 5}\n").append(good[2], 0, 20);
  write("damaged/episodes.jsonl", damaged);
  const BatchOutcome r = run_batch(scenario, options("damaged"));
  EXPECT_EQ(r.malformed_lines_cut, 5);
  EXPECT_EQ(r.skipped, 2);
  EXPECT_EQ(r.ran, 2);
  EXPECT_EQ(starts_by_id((dir_ / "damaged").string()), whole);
}

// The failure gallery replays each failed episode for its figure, outside the batch's workers:
// the replay must run the same episode (a failure drawn from a dangling controller crashed it).
TEST_F(BatchFolders, TheFailureGalleryReplaysTheFailedEpisodes) {
  const std::string scenario =
      write("fail.yaml", "worlds: [" + test::source_file("data/worlds/examples/small_plant.json") +
                             "]\nplanners: [vg]\nfaults: {short: {timeout_s: 2}}\nseeds: 1\n");
  RunOptions o = options("fail");
  o.figures = true;
  const BatchOutcome r = run_batch(scenario, o);
  ASSERT_EQ(r.ran, 1);
  EXPECT_EQ(r.succeeded, 0);
  const std::string id =
      nlohmann::json::parse(read_episode_records((dir_ / "fail").string()).at(0))["id"];
  EXPECT_TRUE(
      fs::exists(dir_ / "fail" / "failures" / ("1_" + worlds::file_name_component(id) + ".png")))
      << id;
  // Its panel links to its replay, a page of its own that says why first and links back.
  const std::string page_name = "failures/1_" + worlds::file_name_component(id) + ".html";
  std::ifstream page_in(dir_ / "fail" / page_name), report_in(dir_ / "fail" / "report.html");
  const std::string page((std::istreambuf_iterator<char>(page_in)),
                         std::istreambuf_iterator<char>());
  const std::string report((std::istreambuf_iterator<char>(report_in)),
                           std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("<b>FAILED</b>: timeout at 2.0 s"), std::string::npos);
  EXPECT_NE(page.find("id=\"replay-data\""), std::string::npos);
  EXPECT_NE(page.find("href=\"../report.html\""), std::string::npos);
  EXPECT_NE(report.find("<a href=\"" + render::url_attribute(page_name) + "\">Replay it</a>"),
            std::string::npos);
}

TEST_F(BatchFolders, ScenarioPathsAreRelativeToTheScenarioFile) {
  fs::create_directories(dir_ / "sc" / "w");
  fs::copy_file(test::source_file("data/worlds/examples/small_plant.json"),
                dir_ / "sc" / "w" / "plant.json");
  const std::string scenario =
      write("sc/rel.yaml", "worlds: [w/plant.json, $data/worlds/world_N10.json]\nseeds: 1\n");
  // Whatever the current folder, the scenario finds its worlds.
  const fs::path before = fs::current_path();
  fs::current_path(fs::temp_directory_path());
  RunOptions check = options("rel");
  check.check_only = true;
  EXPECT_EQ(run_batch(scenario, check).episodes, 2);
  fs::current_path(before);
  try {
    run_batch(write("sc/missing.yaml", "worlds: [nowhere.json]\nseeds: 1\n"), check);
    ADD_FAILURE();
  } catch (const worlds::WorldError& e) {
    EXPECT_NE(std::string(e.what()).find("'nowhere.json' not found (looked for " +
                                         (dir_ / "sc" / "nowhere.json").string()),
              std::string::npos)
        << e.what();
  }
}

// The scenario's episodes computed from their index and found from their id, never listed whole:
// every index reads back from its id, the shards cover each index once, and ids the scenario
// does not make (a seed it lacks, a name off its lists, a sixth part) are not found.
TEST(EpisodeSpace, EveryIdReadsBackToItsIndexAndTheShardsCoverEachOnce) {
  BatchSpec spec;
  spec.planners = {"vg", "grid"};
  spec.controllers = {{"default", "{}"}, {"slow", "{}"}, {"fast", "{}"}};
  spec.faults = {{}, {}};
  spec.faults[0].name = "none";
  spec.faults[1].name = "wet";
  spec.seeds = {3, 1, 40};
  const EpisodeSpace space(spec, {"a", "b"});
  ASSERT_EQ(space.size(), 2 * 2 * 3 * 2 * 3);
  EXPECT_EQ(space.at(0).id, "a|vg|default|none|3");
  EXPECT_EQ(space.at(1).id, "a|vg|default|none|1");  // seeds vary fastest, in the list's order
  EXPECT_EQ(space.at(space.size() - 1).id, "b|grid|fast|wet|40");
  for (std::int64_t i = 0; i < space.size(); ++i) EXPECT_EQ(space.find(space.at(i).id), i);
  std::vector<int> seen(static_cast<std::size_t>(space.size()), 0);
  for (int i = 0; i < 5; ++i) {
    const std::vector<Episode> mine = space.shard(i, 5);
    EXPECT_EQ(static_cast<std::int64_t>(mine.size()), space.shard_size(i, 5));
    for (const Episode& e : mine) ++seen[static_cast<std::size_t>(e.index)];
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), space.size());
  for (const std::string id :
       {"a|vg|default|none|2", "c|vg|default|none|1", "a|vg|default|none", "a|vg|default|none|1|x",
        "a|vg|default|none|01", "a|vg|default|none|+1", "a|vg|default|none|"})
    EXPECT_FALSE(space.find(id)) << id;
}

// summary.csv's columns by name for the row of `fault`.
std::map<std::string, std::string> summary_row(const std::string& csv, const std::string& fault) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = util::csv_split(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = util::csv_split(line);
    if (cells.size() != header.size())
      ADD_FAILURE() << "a row of " << cells.size() << " cells under " << header.size();
    if (cells.size() < 4 || cells[3] != fault) continue;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    return row;
  }
  return {};
}

std::string full_record(const std::string& fault, bool docked, const std::string& health,
                        double worst_error_m, double not_ok_s) {
  return nlohmann::json{{"world", "w"},
                        {"planner", "vg"},
                        {"controller", "default"},
                        {"fault", fault},
                        {"docked", docked},
                        {"succeeded", docked},
                        {"status", docked ? "docked" : "failed"},
                        {"collisions", 0},
                        {"retries", 0},
                        {"time_s", 100.0},
                        {"optimal_length_m", 10.0},
                        {"path_length_m", 10.5},
                        {"driven_length_m", 11.0},
                        {"position_error_m", 0.004},
                        {"heading_error_deg", 0.5},
                        {"localization_status", health},
                        {"localization_error_max_m", worst_error_m},
                        {"localization_not_ok_s", not_ok_s}}
      .dump();
}

// Issue 89: below 20 episodes the nearest-rank 95th percentile is the worst itself, so the
// report's detail table does not show it as a second number: gone when every configuration is
// that small; a small configuration beside large ones says "= worst".
TEST(SummaryTable, TheNinetyFifthPercentileIsNoColumnOfItsOwnBelowTwentyEpisodes) {
  auto details = [](const std::vector<std::string>& lines) {
    render::Report report;
    const std::string csv = summary_csv(lines);
    const std::string html = fill_verdict_table(report, csv, judge_configurations(lines, {}),
                                                GateStatistic::kSuccessRate);
    return html.substr(0, html.find("<h2>Navigation"));
  };
  std::vector<std::string> small;
  for (int i = 0; i < 19; ++i) small.push_back(full_record("small", true, "ok", 0.01 * (i + 1), 0));
  std::string html = details(small);
  EXPECT_EQ(html.find("95th pct"), std::string::npos) << html;
  EXPECT_NE(html.find("worst localisation error (mm)"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>190.00</td>"), std::string::npos) << html;  // the worst, once
  std::vector<std::string> mixed = small;
  for (int i = 0; i < 20; ++i) mixed.push_back(full_record("large", true, "ok", 0.01 * (i + 1), 0));
  html = details(mixed);
  EXPECT_NE(html.find("95th pct localisation error (mm)"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>= worst (under 20 episodes)</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>200.00</td><td>190.00</td>"), std::string::npos) << html;  // 19th of 20
}

TEST(SummaryTable, IntegrityPerConfigurationNoValueIsEmptyAndTheGateIsItsColumns) {
  std::vector<std::string> lines;
  // 20 docked, 2 of them lost and 1 degraded at the end; errors 0.01 .. 0.20 m.
  for (int i = 0; i < 20; ++i)
    lines.push_back(full_record("noisy", true,
                                i < 2    ? "lost"
                                : i == 2 ? "degraded"
                                         : "ok",
                                0.01 * (i + 1), i < 3 ? 50.0 : 0.0));
  for (int i = 0; i < 4; ++i)
    lines.push_back(full_record("stuck", false, "ok", 0.02, 0.0));  // none docked
  Gate gate;
  gate.min_success = 0.9;
  const std::string csv = summary_csv(lines, &gate);
  auto noisy = summary_row(csv, "noisy");
  EXPECT_EQ(noisy["docked_lost"], "2");
  EXPECT_EQ(noisy["docked_not_ok"], "3");
  EXPECT_EQ(noisy["p95_localization_error_mm"], "190.00");  // the 19th of 20 by rank
  EXPECT_EQ(noisy["max_localization_error_mm"], "200.00");
  EXPECT_EQ(noisy["localization_not_ok_share"], "0.0750");  // 150 s of 2000
  EXPECT_EQ(noisy["gate_statistic"], "success_rate");
  EXPECT_EQ(noisy["gate_threshold"], "0.9000");
  EXPECT_EQ(noisy["gate_verdict"], "pass");
  auto stuck = summary_row(csv, "stuck");
  EXPECT_EQ(stuck["succeeded"], "0");
  EXPECT_EQ(stuck["mean_position_error_mm"], "");  // no docked episode: no error, not a perfect 0
  EXPECT_EQ(stuck["mean_heading_error_deg"], "");
  EXPECT_EQ(stuck["driven_over_shortest"], "");
  EXPECT_EQ(stuck["gate_verdict"], "fail");
  // Pooled over worlds, and without a gate.
  gate.pool_worlds = true;
  EXPECT_EQ(summary_row(summary_csv(lines, &gate), "noisy")["gate_verdict"],
            "pass (all worlds pooled)");
  EXPECT_EQ(summary_row(summary_csv(lines), "noisy").count("gate_verdict"), 0u);
}

}  // namespace
}  // namespace plantsim::batch

namespace plantsim::util {
namespace {

// summary.csv is RFC 4180: a name with a comma or a quote survives a round trip, and the report
// reads the columns where they are.
TEST(Csv, QuotedFieldsRoundTrip) {
  const std::vector<std::string> fields = {"plain", "a,b", "say \"hi\"", "", "end"};
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csv_field(fields[i]);
  }
  EXPECT_EQ(line, "plain,\"a,b\",\"say \"\"hi\"\"\",,end");
  EXPECT_EQ(csv_split(line), fields);
}

// A name a spreadsheet would run as a formula is written to be shown as text (issue 51); numbers,
// negative ones too, stay numbers.
TEST(Csv, FormulasAreNeutralisedNumbersAreNot) {
  EXPECT_EQ(csv_field("=HYPERLINK(\"http://x\",\"y\")"),
            "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
  EXPECT_EQ(csv_field("+1+2"), "'+1+2");
  EXPECT_EQ(csv_field("@SUM(1)"), "'@SUM(1)");
  EXPECT_EQ(csv_field("-cmd"), "'-cmd");
  EXPECT_EQ(csv_field("\tx"), "'\tx");
  EXPECT_EQ(csv_field("-0.5"), "-0.5");
  EXPECT_EQ(csv_field("+3"), "+3");
  EXPECT_EQ(csv_field("1e-3"), "1e-3");
  EXPECT_EQ(csv_field("plant=2"), "plant=2");
}

}  // namespace
}  // namespace plantsim::util
