// plantsim diff (batch/batch_diff.h, app/cmd_diff.cpp): McNemar's exact p-value and the paired
// interval against hand-computed values; two batch folders whose records are written by the
// batch's own record writer (batch::record_line), compared in process and through the command
// line: a candidate that loses episodes is worse (exit 1, the lost and gained ids and reasons
// right), identical folders show no detectable change (exit 0), bad input exits 2 and writes
// nothing; and two real batches of a small scenario (seconds), the candidate's timeout shorter.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "batch/batch_diff.h"
#include "batch/episode_record.h"
#include "batch/paired_tests.h"
#include "cli_fixture.h"

namespace plantsim {
namespace {

// ---- the statistics, by hand --------------------------------------------------------------

TEST(PairedTests, McNemarExactMatchesTheBinomialByHand) {
  // 8 lost, 1 gained: 2 P(X <= 1), X ~ Bin(9, 1/2) = 2 (1 + 9) / 512.
  EXPECT_NEAR(batch::mcnemar_exact_p(8, 1), 20.0 / 512.0, 1e-12);
  EXPECT_NEAR(batch::mcnemar_exact_p(1, 8), 20.0 / 512.0, 1e-12);  // two-sided
  // 7 lost, 1 gained: 2 (1 + 8) / 256 = 0.0703: not below 0.05.
  EXPECT_NEAR(batch::mcnemar_exact_p(7, 1), 18.0 / 256.0, 1e-12);
  EXPECT_NEAR(batch::mcnemar_exact_p(6, 0), 2.0 / 64.0, 1e-12);
  EXPECT_DOUBLE_EQ(batch::mcnemar_exact_p(3, 3), 1.0);  // 2 * 42/64 capped at 1
  EXPECT_DOUBLE_EQ(batch::mcnemar_exact_p(0, 0), 1.0);
  EXPECT_EQ(batch::mcnemar_smallest_detectable(0.05), 6);  // 2/32 = 0.0625, 2/64 = 0.031
  EXPECT_EQ(batch::mcnemar_smallest_detectable(0.01), 8);  // 2/128 = 0.0156, 2/256 = 0.0078
}

TEST(PairedTests, PairedIntervalIsStudentT) {
  // {1, 2, 3}: mean 2, sd 1, t(0.975, 2) = 4.302652729911275, half 4.3027 / sqrt(3).
  const batch::PairedDifference d = batch::paired_difference({1, 2, 3}, 0.05);
  EXPECT_EQ(d.pairs, 3);
  EXPECT_DOUBLE_EQ(d.mean, 2.0);
  EXPECT_NEAR(d.sd, 1.0, 1e-12);
  ASSERT_TRUE(d.interval);
  const double half = 4.302652729911275 / std::sqrt(3.0);
  EXPECT_NEAR(d.interval->first, 2 - half, 1e-9);
  EXPECT_NEAR(d.interval->second, 2 + half, 1e-9);
  EXPECT_FALSE(batch::paired_difference({1.5}, 0.05).interval);  // one pair: no interval
}

// ---- record folders written by the batch's own writer -------------------------------------

struct Ran {
  std::string world, controller;
  std::uint64_t seed;
  bool docked;
  double time_s, error_m;
  robot::FailureReason reason = robot::FailureReason::kTimeout;
};

std::string record_of(const Ran& o, std::int64_t index, const std::string& fingerprint) {
  batch::BatchSpec spec;
  spec.planners = {"vg"};
  spec.controllers = {{o.controller, "{}"}};
  batch::FaultSetting none;
  none.name = "none";
  spec.faults = {none};
  batch::Episode e;
  e.index = index;
  e.id = o.world + "|vg|" + o.controller + "|none|" + std::to_string(o.seed);
  e.seed = o.seed;
  batch::ScenarioIdentity scenario{fingerprint, 1000, "/nowhere/diff_scenario.yaml"};
  worlds::World plant;
  plant.name = o.world;
  episode::EpisodeResult r;
  r.time_s = o.time_s;
  r.position_error_m = o.error_m;
  r.error_measured = true;
  if (o.docked) {
    r.status = episode::EpisodeStatus::kDocked;
    r.docked = r.charging = true;
  } else {
    r.status = episode::EpisodeStatus::kTimeout;
    r.failure = robot::Failure{o.reason, o.time_s, {}, "made by the test"};
  }
  return batch::record_line(e, spec, scenario, plant, r, 10.0, std::nullopt);
}

void write_folder(const std::filesystem::path& dir, const std::vector<Ran>& outcomes,
                  const std::string& fingerprint = "00000000000000aa") {
  std::filesystem::create_directories(dir);
  std::ofstream out(dir / "episodes.jsonl");
  for (std::size_t i = 0; i < outcomes.size(); ++i)
    out << record_of(outcomes[i], static_cast<std::int64_t>(i), fingerprint) << "\n";
}

/// Two configurations of ten seeds: w1/default (docked but seed 9) and w1/cautious (all docked).
std::vector<Ran> baseline_outcomes() {
  std::vector<Ran> v;
  for (std::uint64_t s = 0; s < 10; ++s) {
    v.push_back({"w1", "default", s, s != 9, 30.0 + s, 0.005, robot::FailureReason::kCollision});
    v.push_back({"w1", "cautious", s, true, 40.0 + s, 0.004});
  }
  return v;
}

/// The candidate loses w1/default's seeds 0-7 (timeouts) and gains its seed 9: 8 lost, 1
/// gained, McNemar p = 20/512 = 0.039 < 0.05; w1/cautious unchanged.
std::vector<Ran> losing_outcomes() {
  std::vector<Ran> v = baseline_outcomes();
  for (Ran& o : v)
    if (o.controller == "default" && o.seed < 8)
      o.docked = false, o.time_s = 120, o.reason = robot::FailureReason::kTimeout;
    else if (o.controller == "default")
      o.docked = true;
  return v;
}

class Diff : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("plantsim_diff_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string at(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(Diff, LostEpisodesMakeTheCandidateWorse) {
  write_folder(dir_ / "base", baseline_outcomes());
  write_folder(dir_ / "cand", losing_outcomes());
  const batch::BatchDiff d = batch::diff_batches(at("base"), at("cand"), 0.05);
  EXPECT_EQ(d.verdict, batch::DiffVerdict::kWorse);
  EXPECT_EQ(d.paired, 20);
  EXPECT_EQ(d.lost, 8);
  EXPECT_EQ(d.gained, 1);
  ASSERT_EQ(d.configurations.size(), 2u);
  const batch::ConfigurationDiff& cautious = d.configurations[0];  // sorted by name
  const batch::ConfigurationDiff& plain = d.configurations[1];
  EXPECT_EQ(cautious.controller, "cautious");
  EXPECT_EQ(cautious.verdict, batch::DiffVerdict::kNoChange);
  EXPECT_DOUBLE_EQ(cautious.mcnemar_p, 1.0);
  EXPECT_EQ(plain.verdict, batch::DiffVerdict::kWorse);
  EXPECT_NEAR(plain.mcnemar_p, 20.0 / 512.0, 1e-12);
  ASSERT_EQ(d.changed.size(), 9u);
  for (std::uint64_t s = 0; s < 8; ++s) {  // by seed as a number
    EXPECT_EQ(d.changed[s].id, "w1|vg|default|none|" + std::to_string(s));
    EXPECT_FALSE(d.changed[s].gained);
    EXPECT_EQ(d.changed[s].candidate.reason, "timeout");
  }
  EXPECT_EQ(d.changed[8].id, "w1|vg|default|none|9");
  EXPECT_TRUE(d.changed[8].gained);
  EXPECT_EQ(d.changed[8].baseline.reason, "collision");
}

TEST_F(Diff, SevenLostOneGainedIsNotDetectable) {
  std::vector<Ran> cand = losing_outcomes();
  cand[0].docked = true;  // w1/default seed 0 kept: 7 lost, 1 gained, p = 0.070
  write_folder(dir_ / "base", baseline_outcomes());
  write_folder(dir_ / "cand", cand);
  const batch::BatchDiff d = batch::diff_batches(at("base"), at("cand"), 0.05);
  EXPECT_EQ(d.verdict, batch::DiffVerdict::kNoChange);
  EXPECT_NEAR(d.configurations[1].mcnemar_p, 18.0 / 256.0, 1e-12);
  // At level 0.1 it is.
  EXPECT_EQ(batch::diff_batches(at("base"), at("cand"), 0.1).verdict, batch::DiffVerdict::kWorse);
}

TEST_F(Diff, SlowerEverywhereIsWorseFasterBetterWithinTheMarginNoChange) {
  std::vector<Ran> slower = baseline_outcomes(), faster = slower, nudged = slower;
  for (std::size_t i = 0; i < slower.size(); ++i) {
    slower[i].time_s += 10 + 0.1 * static_cast<double>(i % 3);
    faster[i].time_s -= 10 + 0.1 * static_cast<double>(i % 3);
    nudged[i].time_s += 0.5 + 0.1 * static_cast<double>(i % 3);  // sure, but under 5 %
  }
  write_folder(dir_ / "base", baseline_outcomes());
  write_folder(dir_ / "slower", slower);
  write_folder(dir_ / "faster", faster);
  write_folder(dir_ / "nudged", nudged);
  const batch::BatchDiff s = batch::diff_batches(at("base"), at("slower"), 0.05);
  EXPECT_EQ(s.verdict, batch::DiffVerdict::kWorse);
  EXPECT_EQ(s.configurations[0].time.verdict, batch::DiffVerdict::kWorse);
  EXPECT_EQ(s.configurations[0].success, batch::DiffVerdict::kNoChange);
  EXPECT_EQ(batch::diff_batches(at("base"), at("faster"), 0.05).verdict,
            batch::DiffVerdict::kBetter);
  EXPECT_EQ(batch::diff_batches(at("base"), at("nudged"), 0.05).verdict,
            batch::DiffVerdict::kNoChange);
}

TEST_F(Diff, OnlyOverlappingEpisodesArePaired) {
  std::vector<Ran> cand = baseline_outcomes();
  cand.push_back({"w1", "default", 10, true, 30, 0.005});  // the candidate ran one more seed
  std::vector<Ran> base = baseline_outcomes();
  base.erase(base.begin());  // and the baseline lacks seed 0 of w1/default
  write_folder(dir_ / "base", base);
  write_folder(dir_ / "cand", cand, "00000000000000bb");  // another scenario, same ids
  const batch::BatchDiff d = batch::diff_batches(at("base"), at("cand"), 0.05);
  EXPECT_EQ(d.paired, 19);
  EXPECT_EQ(d.only_baseline, 0);
  EXPECT_EQ(d.only_candidate, 2);
  EXPECT_EQ(d.verdict, batch::DiffVerdict::kNoChange);
}

TEST_F(Diff, BadInputIsRefusedNamingTheFile) {
  write_folder(dir_ / "base", baseline_outcomes());
  auto refused = [&](const std::string& cand, const std::string& named) {
    try {
      batch::diff_batches(at("base"), cand, 0.05);
      ADD_FAILURE() << cand << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
    }
  };
  refused(at("missing"), "missing' does not exist");
  std::filesystem::create_directories(dir_ / "no_records");
  refused(at("no_records"), "no_records/episodes.jsonl: missing");
  std::filesystem::create_directories(dir_ / "empty");
  std::ofstream(dir_ / "empty" / "episodes.jsonl").flush();
  refused(at("empty"), "empty/episodes.jsonl: holds no records");
  write_folder(dir_ / "bad", baseline_outcomes());
  std::ofstream(dir_ / "bad" / "episodes.jsonl", std::ios::app) << "{\"id\": 3}\n";
  refused(at("bad"), "bad/episodes.jsonl: 1 line(s) are not records");
  write_folder(dir_ / "torn", baseline_outcomes());
  std::ofstream(dir_ / "torn" / "episodes.jsonl", std::ios::app) << "{\"index\": 0, \"id";
  refused(at("torn"), "torn/episodes.jsonl: its last line is cut short");
  std::vector<Ran> other = baseline_outcomes();
  for (Ran& o : other) o.world = "w2";
  write_folder(dir_ / "other", other);
  refused(at("other"), "share no episode id");
  // A record whose key is not its own (edited to stand for another scenario's episode).
  write_folder(dir_ / "edited", baseline_outcomes());
  {
    std::string text = Cli::read(dir_ / "edited" / "episodes.jsonl");
    const std::size_t key = text.find("\"key\":\"");
    text[key + 7] = text[key + 7] == '0' ? '1' : '0';
    std::ofstream(dir_ / "edited" / "episodes.jsonl") << text;
  }
  refused(at("edited"), "edited/episodes.jsonl: episode 'w1|vg|default|none|0' has a key");
}

// ---- through the command line -------------------------------------------------------------

class DiffCli : public Cli {};

TEST_F(DiffCli, WorseExitsOneWithEveryOutputStamped) {
  write_folder(dir_ / "base", baseline_outcomes());
  write_folder(dir_ / "cand", losing_outcomes());
  const Outcome o = run("diff base cand --out d --junit junit.xml");
  ASSERT_EQ(o.exit_code, 1) << o.out << o.err;
  EXPECT_NE(o.err.find("WORSE w1 / vg / default / none: success fell: 8 lost, 1 gained"),
            std::string::npos)
      << o.err;
  const std::string md = read(dir_ / "d" / "diff.md");
  EXPECT_EQ(md.substr(0, md.find('\n')), "# plantsim diff: WORSE");
  EXPECT_NE(md.find("Made by plantsim"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(read(dir_ / "d" / "diff.json"));
  EXPECT_EQ(j["verdict"], "worse");
  EXPECT_EQ(j["lost"], 8);
  EXPECT_EQ(j["gained"], 1);
  EXPECT_TRUE(j["made_by"].contains("commit"));
  EXPECT_EQ(j["made_by"]["records"].get<std::string>().size(), 16u);
  EXPECT_EQ(j["changed"][0]["id"], "w1|vg|default|none|0");
  EXPECT_EQ(j["changed"][0]["change"], "lost");
  EXPECT_EQ(j["changed"][0]["candidate"]["reason"], "timeout");
  EXPECT_EQ(j["changed"][0]["baseline"]["rerun"],
            "plantsim batch /nowhere/diff_scenario.yaml --episode 'w1|vg|default|none|0' --out "
            "base");
  const std::string html = read(dir_ / "d" / "diff.html");
  EXPECT_NE(html.find("<b>WORSE</b>"), std::string::npos);
  EXPECT_NE(html.find("Made by plantsim"), std::string::npos);
  EXPECT_NE(html.find("--out cand"), std::string::npos);
  const std::string junit = read(dir_ / "junit.xml");
  EXPECT_NE(junit.find("tests=\"2\" failures=\"1\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("plantsim_commit"), std::string::npos);
  EXPECT_NE(junit.find("lost w1|vg|default|none|3: timeout"), std::string::npos);
}

TEST_F(DiffCli, IdenticalFoldersShowNoDetectableChange) {
  write_folder(dir_ / "base", baseline_outcomes());
  write_folder(dir_ / "again", baseline_outcomes());
  const Outcome o = run("diff base again --junit junit.xml");
  ASSERT_EQ(o.exit_code, 0) << o.out << o.err;
  const fs::path out = dir_ / "results" / "diff_base_vs_again";  // the default folder
  const std::string md = read(out / "diff.md");
  EXPECT_EQ(md.substr(0, md.find('\n')), "# plantsim diff: NO DETECTABLE CHANGE");
  EXPECT_NE(read(dir_ / "junit.xml").find("failures=\"0\""), std::string::npos);
  // A second diff into the same folder replaces its own outputs, a JUnit report it holds too.
  EXPECT_EQ(run("diff base again --junit results/diff_base_vs_again/j.xml").exit_code, 0);
  EXPECT_TRUE(fs::exists(out / "j.xml"));
  EXPECT_EQ(run("diff base again").exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "j.xml"));
}

TEST_F(DiffCli, ReplaysInTheFoldersAreLinkedSideBySide) {
  write_folder(dir_ / "base", baseline_outcomes());
  write_folder(dir_ / "cand", losing_outcomes());
  write("cand/failures/3_w1_vg_default_none_2.html", "<html></html>");
  write("base/episodes/w1_vg_default_none_2/report.html", "<html></html>");
  ASSERT_EQ(run("diff base cand --out d").exit_code, 1);
  const std::string html = read(dir_ / "d" / "diff.html");
  EXPECT_NE(html.find("href=\"../cand/failures/3_w1_vg_default_none_2.html\""), std::string::npos)
      << html;
  EXPECT_NE(html.find("src=\"../base/episodes/w1_vg_default_none_2/report.html\""),
            std::string::npos);
}

TEST_F(DiffCli, BadInputExitsTwoAndWritesNothing) {
  write_folder(dir_ / "base", baseline_outcomes());
  std::filesystem::create_directories(dir_ / "not_a_batch");
  for (const char* args :
       {"diff base missing --out d --junit j.xml", "diff base not_a_batch --out d --junit j.xml",
        "diff missing base --out d --junit j.xml"}) {
    const Outcome o = run(args);
    EXPECT_EQ(o.exit_code, 2) << args << o.out << o.err;
    EXPECT_NE(o.err.find("plantsim: "), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "d")) << args;
    EXPECT_FALSE(fs::exists(dir_ / "j.xml")) << args;
    EXPECT_FALSE(fs::exists(dir_ / "results")) << args;
  }
  EXPECT_NE(run("diff base not_a_batch").err.find("not_a_batch/episodes.jsonl: missing"),
            std::string::npos);
  // A user's file is never replaced: a folder holding notes, a --junit that is not a report.
  write_folder(dir_ / "cand", losing_outcomes());
  write("mine/notes.txt", "mine");
  EXPECT_EQ(run("diff base cand --out mine").exit_code, 2);
  EXPECT_EQ(read(dir_ / "mine" / "notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir_ / "mine" / "diff.md"));
  write("scenario.yaml", "name: x\n");
  EXPECT_EQ(run("diff base cand --out d2 --junit scenario.yaml").exit_code, 2);
  EXPECT_EQ(read(dir_ / "scenario.yaml"), "name: x\n");
  EXPECT_FALSE(fs::exists(dir_ / "d2"));
  EXPECT_EQ(run("diff base cand --out base").exit_code, 2);       // the batch folder itself
  EXPECT_EQ(run("diff base cand --out cand/diff").exit_code, 2);  // or a folder in it
  EXPECT_FALSE(fs::exists(dir_ / "cand" / "diff"));
  EXPECT_EQ(run("diff base cand --level 0").exit_code, 2);
}

// Two real batches of one scenario's episodes, the candidate's controller given a timeout of 45 s
// under the same name: six of its eight episodes (those the baseline docked after 45 s) time out.
TEST_F(DiffCli, TwoRealBatchesOfAShorterTimeoutAreWorse) {
  const std::string world = test::source_file("data/worlds/examples/small_plant.json");
  write("base.yaml", "name: d\nworlds: [" + world + "]\ncontrollers: {default: {}}\nseeds: 8\n");
  write("cand.yaml",
        "name: d\nworlds: [" + world + "]\ncontrollers: {default: {timeout_s: 45}}\nseeds: 8\n");
  ASSERT_EQ(run("batch base.yaml --out base --quiet --no-figures", 120).exit_code, 0);
  ASSERT_EQ(run("batch cand.yaml --out cand --quiet --no-figures", 120).exit_code, 0);
  const Outcome o = run("diff base cand --out d");
  ASSERT_EQ(o.exit_code, 1) << o.out << o.err;
  const nlohmann::json j = nlohmann::json::parse(read(dir_ / "d" / "diff.json"));
  std::vector<nlohmann::json> base;
  std::ifstream records(dir_ / "base" / "episodes.jsonl");
  for (std::string line; std::getline(records, line);) base.push_back(nlohmann::json::parse(line));
  std::set<std::string> slow, lost;
  for (const nlohmann::json& r : base)
    if (r["time_s"].get<double>() > 45) slow.insert(r["id"].get<std::string>());
  for (const nlohmann::json& e : j["changed"]) {
    EXPECT_EQ(e["change"], "lost");
    EXPECT_EQ(e["candidate"]["reason"], "timeout");
    lost.insert(e["id"].get<std::string>());
  }
  EXPECT_EQ(lost, slow);
  EXPECT_GE(lost.size(), 6u);  // enough for McNemar at 0.05
  EXPECT_EQ(j["configurations"][0]["verdict"], "worse");
}

}  // namespace
}  // namespace plantsim
