// Hostile inputs, second round (issue 36), each as a user would meet it through the command
// line: limits that bound the work (obstacles from any map, an episode's and a batch's steps,
// file sizes), merges that refuse conflicts and foreign or missing episodes, names that cannot
// make ids collide, gates over nothing, outputs checked before the work and never written
// through links or over devices, FIFOs or a user's own files.
#include <chrono>

#include "cli_fixture.h"

namespace plantsim {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const std::string kCorridor = test::source_file("data/worlds/examples/corridor_crossing.json");

TEST_F(Cli, ACheckerboardMapIsRefusedAtTheObstacleLimitWhileItIsRead) {
  // 2000 x 2000 pixels at 1 m, alternating: two million one-pixel obstacles if nobody counts.
  std::string pgm = "P5\n2000 2000\n255\n";
  pgm.reserve(pgm.size() + 4000000);
  for (int y = 0; y < 2000; ++y)
    for (int x = 0; x < 2000; ++x) pgm.push_back((x + y) % 2 ? '\xfe' : '\0');
  write("board.pgm", pgm);
  write("board.yaml",
        "image: board.pgm\nresolution: 1.0\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: "
        "0.65\nfree_thresh: 0.196\n");
  const auto t0 = Clock::now();
  const Outcome o = run("plan board.yaml");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("more than 200000 rectangles"), std::string::npos) << o.err;
  EXPECT_LT(seconds_since(t0), 15.0);
}

TEST_F(Cli, AConfigAskingForTooManyStepsIsRefusedBeforeRunning) {
  write(
      "c.json",
      R"({"step": {"dt_s": 0.0001}, "timeout_s": 86400, "tracking": {"max_linear_speed_mps": 0.05}})");
  const auto t0 = Clock::now();
  const Outcome o = run("run " + kCorridor + " --config c.json --out out");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("timeout_s"), std::string::npos);
  EXPECT_NE(o.err.find("physics steps"), std::string::npos);
  EXPECT_LT(seconds_since(t0), 5.0);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  write("p.json", R"({"step": {"control_period_steps": 0}})");
  EXPECT_EQ(run("run " + kCorridor + " --config p.json --out out").exit_code, 2);
}

TEST_F(Cli, AHugeWorldFileIsRefusedBeforeItIsParsed) {
  std::string big = "{\"obstacles\": [";
  while (big.size() < (33u << 20)) big += "[1.0, 1.0, 2.0, 2.0],";
  big += "[1, 1, 2, 2]]}";
  write("big.json", big);
  const auto t0 = Clock::now();
  const Outcome o = run("plan big.json");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.err.find("more than the"), std::string::npos) << o.err;
  EXPECT_LT(seconds_since(t0), 3.0);
}

TEST_F(Cli, WholeNumbersAreReadAsDecimalsThatFitOrRefused) {
  // CLI11 alone read all three as 2^64 - 1: three seeds asked for, one world written three times.
  for (const std::string seed :
       {"-1", "99999999999999999999999", "18446744073709551616", "1.5", "", "7x"}) {
    const Outcome o = run("generate --seed '" + seed + "'");
    EXPECT_EQ(o.exit_code, 2) << seed << ": " << o.err;
    EXPECT_NE(o.err.find("expects a whole number from 0 to 18446744073709551615"),
              std::string::npos)
        << o.err;
    EXPECT_TRUE(o.out.empty()) << seed;
  }
  const Outcome largest = run("generate --seed 18446744073709551615");
  const Outcome padded = run("generate --seed 018446744073709551615");
  const Outcome next = run("generate --seed 18446744073709551614");
  ASSERT_EQ(largest.exit_code, 0) << largest.err;
  EXPECT_EQ(padded.out, largest.out);
  EXPECT_NE(next.out, largest.out);
  EXPECT_EQ(run("generate --seed 010").out, run("generate --seed 10").out);  // not octal 8
  EXPECT_NE(run("generate --seed 010").out, run("generate --seed 8").out);
  // Every whole-number option reads decimal digits: ten rectangles, not eight or sixteen.
  for (const std::string count : {"010", "10"}) {
    const Outcome o = run("generate --count " + count + " --seed 3");
    ASSERT_EQ(o.exit_code, 0) << o.err;
    EXPECT_EQ(nlohmann::json::parse(o.out)["obstacles"].size(), 10u) << count;
  }
  EXPECT_EQ(run("generate --count 0x10").exit_code, 2);
  EXPECT_EQ(run("batch " + kCorridor + " --threads -1 --check").exit_code, 2);
  EXPECT_EQ(run("run " + kCorridor + " --seed -1 --out out").exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(Cli, AnOutputIsNeverTheInputItIsMadeFrom) {
  write("w.json", read(kCorridor));
  const Outcome o = run("vary w.json --unmapped 1 --out ./w.json");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("is the input"), std::string::npos) << o.err;
  EXPECT_EQ(read(dir_ / "w.json"), read(kCorridor));
  write("nav2.yaml",
        "controller_server:\n  ros__parameters:\n    FollowPath:\n      plugin: "
        "nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController\n");
  EXPECT_EQ(run("nav2-import nav2.yaml --out nav2.yaml").exit_code, 2);
  EXPECT_NE(read(dir_ / "nav2.yaml").find("FollowPath"), std::string::npos);
  EXPECT_EQ(run("vary w.json --unmapped 1 --out v.json").exit_code, 0);
}

TEST_F(Cli, APlannerComparedWithItselfIsRefused) {
  const Outcome twice = run("compare " + kCorridor + " --planners vg,grid,vg --out c");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("'vg' is listed twice"), std::string::npos) << twice.err;
  EXPECT_FALSE(fs::exists(dir_ / "c"));
  // Local controllers compared follow one planner's plan, and are driven.
  for (const auto& [args, needle] : std::vector<std::pair<std::string, std::string>>{
           {"--controllers dwb,pure-pursuit,dwb", "'dwb' is listed twice"},
           {"--controllers dwb --plan-only", "drives nothing"},
           {"--controllers dwb --planners vg,grid", "name one planner"},
           {"--controllers teleport", "teleport"}}) {
    const Outcome o = run("compare " + kCorridor + " " + args + " --out c");
    EXPECT_EQ(o.exit_code, 2) << args;
    EXPECT_NE(o.err.find(needle), std::string::npos) << args << ": " << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "c"));
  }
  const Outcome one = run("compare " + kCorridor + " --controllers pure-pursuit --out c");
  EXPECT_EQ(one.exit_code, 0) << one.err;
  const std::string report = read(dir_ / "c/report.html");
  EXPECT_NE(report.find("local controllers compared (vg)"), std::string::npos);
  EXPECT_NE(report.find("<td>pure-pursuit</td>"), std::string::npos);  // its navigation row
}

TEST_F(Cli, ScenariosThatRunNothingOrTooMuchOrCollideIdsAreRefused) {
  const std::string head = "worlds: [" + kCorridor + "]\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "controllers: {}\nseeds: 1\ngate: {min_success: 1.0}\n", "controllers"},
      {head + "planners: []\nseeds: 1\ngate: {min_success: 1.0}\n", "planners"},
      {head + "faults: {}\nseeds: 1\n", "faults"},
      {head + "controllers: {'a|b': {}}\nseeds: 1\n", "'|'"},
      {head + "faults: {'x|1': {}}\nseeds: 1\n", "'|'"},
      {head + "seeds: 1\ngate: {configurations: [{fault: wet, min_success: 0.9}]}\n",
       "judge nothing"},
      {head + "seeds: 1\ngate: {configurations: [{world: nowhere, min_success: 0.9}]}\n",
       "judge nothing"},
      {head + "planners: [vg, grid]\nseeds: 600000\n", "one run makes at most 1000000 episodes"},
      {head + "controllers: {slow: {timeout_s: 86400, step: {dt_s: 0.001}}}\nseeds: 200\n",
       "physics steps"},
  };
  for (const auto& [text, message] : cases) {
    write("s.yaml", text);
    const auto t0 = Clock::now();
    const Outcome o = run("batch s.yaml --check --quiet");
    EXPECT_EQ(o.exit_code, 2) << text << o.err;
    EXPECT_NE(o.err.find(message), std::string::npos) << text << "\n" << o.err;
    EXPECT_LT(seconds_since(t0), 10.0) << text;
  }
}

TEST_F(Cli, AMapsQueriesMustBeForThatMap) {
  write("one.map", "type octile\nheight 1\nwidth 1\nmap\n.\n");
  const Outcome o = run("plan --map one.map --scen " + test::shared_data("anyangle/arena.scen"));
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.err.find("49 x 49"), std::string::npos) << o.err;
  EXPECT_TRUE(o.out.empty());
}

TEST_F(Cli, AMappedChargerFarFromTheRealOneIsAnotherCharger) {
  write("w.json", world_json([](nlohmann::json& j) {
          j["charger_map_offset"] = {0.0, 0.0, 1000.0};
        }));
  const Outcome o = run("run w.json --out out");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.err.find("charger_map_offset"), std::string::npos) << o.err;
}

TEST_F(Cli, AMapWithoutBorderWallsGetsAStartInsideIt) {
  // 40 x 30 free pixels with one block: nothing walls the edges.
  std::string pgm = "P2\n40 30\n255\n";
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) pgm += (x >= 18 && x < 22 && y >= 10 && y < 20) ? "0 " : "254 ";
    pgm += "\n";
  }
  write("open.pgm", pgm);
  write("open.yaml",
        "image: open.pgm\nresolution: 0.25\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: "
        "0.65\nfree_thresh: 0.196\n");
  const Outcome o = run("plan open.yaml");
  EXPECT_EQ(o.err.find("crosses the floor boundary"), std::string::npos) << o.err;
  EXPECT_EQ(o.exit_code, 0) << o.err;
}

// summarize reads summary.json files a user may have edited or another tool written: a field of
// another type once ended it with nlohmann's "type must be number" (exit 1).
TEST_F(Cli, ASummaryOfAnotherShapeIsRefusedNamingItsField) {
  ASSERT_EQ(run("run " + kCorridor + " --out r", 120).exit_code, 0);
  const std::string text = read(dir_ / "r/summary.json");
  nlohmann::json j = nlohmann::json::parse(text);
  const std::vector<std::pair<nlohmann::json, std::string>> cases = {
      {"far", "field 'position_error_m': expected a number"},
      {nullptr, "field 'position_error_m': expected a number"},
  };
  fs::create_directories(dir_ / "r2");
  for (const auto& [value, problem] : cases) {
    j["position_error_m"] = value;
    write("r2/summary.json", j.dump());
    const Outcome o = run("summarize r r2 --out table.md");
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find("r2/summary.json: " + problem), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "table.md"));
  }
  j = nlohmann::json::parse(text);
  j["retries"] = -3;
  write("r2/summary.json", j.dump());
  EXPECT_NE(run("summarize r r2").err.find("field 'retries': expected a whole number from 0"),
            std::string::npos);
  write("r2/summary.json", text.substr(0, text.rfind('}')) + R"(, "docked": false})");
  EXPECT_NE(run("summarize r r2").err.find("field 'docked': given twice"), std::string::npos);
  write("r2/summary.json", text);
  EXPECT_EQ(run("summarize r r2").exit_code, 0);
}

class ShardFolders : public Cli {
 protected:
  // A small finished batch in two shards, and its scenario.
  void SetUp() override {
    Cli::SetUp();
    scenario_ = write("s.yaml", "name: two\nworlds: [" + kCorridor + "]\nseeds: 4\n");
    ASSERT_EQ(run("batch s.yaml --shard 0/2 --out a --quiet --no-figures", 300).exit_code, 0);
    ASSERT_EQ(run("batch s.yaml --shard 1/2 --out b --quiet --no-figures", 300).exit_code, 0);
  }
  std::vector<std::string> lines(const std::string& folder) {
    std::ifstream in(dir_ / folder / "episodes.jsonl");
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  }
  void put(const std::string& folder, const std::vector<std::string>& ls) {
    std::ofstream out(dir_ / folder / "episodes.jsonl");
    for (const auto& l : ls) out << l << "\n";
  }
  std::string scenario_;
};

TEST_F(ShardFolders, AMergeRefusesConflictingCopiesAndForeignOrMissingEpisodes) {
  ASSERT_EQ(run("merge a b --out m").exit_code, 0);
  // The same id in both shards with a different result.
  auto a = lines("a"), b = lines("b");
  ASSERT_EQ(a.size() + b.size(), 4u);
  nlohmann::json changed = nlohmann::json::parse(a[0]);
  changed["time_s"] = changed["time_s"].get<double>() + 1;
  put("b", {b[0], b[1], changed.dump()});
  Outcome o = run("merge a b --out m2");
  EXPECT_EQ(o.exit_code, 2) << o.out << o.err;
  EXPECT_NE(o.err.find("twice with different results"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find(changed["id"].get<std::string>()), std::string::npos);
  // An exact copy is the same episode: merged once.
  put("b", {b[0], b[1], a[0]});
  EXPECT_EQ(run("merge a b --out m3").exit_code, 0);
  // One missing and a foreign id in its place (same fingerprint, index in range).
  nlohmann::json foreign = nlohmann::json::parse(b[1]);
  foreign["id"] =
      foreign["id"].get<std::string>().substr(0, foreign["id"].get<std::string>().rfind('|')) +
      "|999";
  put("b", {b[0], foreign.dump()});
  o = run("merge a b --out m4");
  EXPECT_EQ(o.exit_code, 2) << o.out << o.err;
  EXPECT_NE(o.err.find("|999"), std::string::npos) << o.err;
  EXPECT_EQ(o.out.find("4 of 4"), std::string::npos);
  // Only missing: refused, exit 2, naming the missing episode.
  put("b", {b[0]});
  o = run("merge a b --out m5");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("are missing ("), std::string::npos) << o.err;
}

// Issue 51: with the scenario file gone (moved, changed, or a Python dict's temporary), the
// records' own ids still tell a foreign one among them: a seed the scenario never had beside its
// own episodes (merged before as "5 of 4").
TEST_F(ShardFolders, AMergeWithoutItsScenarioFileStillRefusesAForeignEpisode) {
  auto b = lines("b");
  nlohmann::json foreign = nlohmann::json::parse(b[1]);
  const std::string id = foreign["id"].get<std::string>();
  foreign["id"] = id.substr(0, id.rfind('|')) + "|999";
  foreign["seed"] = 999;
  put("b", {b[0], b[1], foreign.dump()});
  fs::remove(scenario_);
  const Outcome o = run("merge a b --out m");
  EXPECT_EQ(o.exit_code, 2) << o.out << o.err;
  EXPECT_NE(o.err.find("a record of another run"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "m" / "episodes.jsonl"));
  // The shards as they were merge without it.
  put("b", b);
  EXPECT_EQ(run("merge a b --out m2").exit_code, 0);
}

TEST_F(ShardFolders, OutputFoldersAreNeverAUsersNorReachedThroughLinks) {
  // A folder holding a user's own report.html and notes: refused, both untouched.
  fs::create_directories(dir_ / "mine");
  write("mine/report.html", "my report");
  write("mine/notes.txt", "my notes");
  Outcome o = run("batch s.yaml --out mine --quiet --no-figures");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("notes.txt"), std::string::npos) << o.err;
  o = run("merge a b --out mine");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(read(dir_ / "mine/report.html"), "my report");
  fs::remove(dir_ / "mine/notes.txt");
  EXPECT_EQ(run("batch s.yaml --out mine --quiet --no-figures").exit_code,
            2);  // report.html but no episodes
  EXPECT_EQ(read(dir_ / "mine/report.html"), "my report");
  // A symlinked episodes.jsonl: refused, its target untouched.
  write("elsewhere.jsonl", "");
  fs::create_directories(dir_ / "linked");
  fs::create_symlink(dir_ / "elsewhere.jsonl", dir_ / "linked/episodes.jsonl");
  o = run("batch s.yaml --out linked --quiet --no-figures");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("symbolic link"), std::string::npos) << o.err;
  EXPECT_EQ(read(dir_ / "elsewhere.jsonl"), "");
  // Resuming its own folder still works.
  EXPECT_EQ(run("batch s.yaml --shard 0/2 --out a --quiet --no-figures").exit_code, 0);
}

TEST_F(ShardFolders, ReportsThatCannotBeWrittenAreRefusedBeforeTheEpisodes) {
  Outcome o = run("batch s.yaml --out c --junit missing/j.xml --quiet");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("--junit"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "c/episodes.jsonl"));
  ::mkfifo((dir_ / "fifo").c_str(), 0644);
  o = run("batch s.yaml --out c --junit fifo --quiet");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("a FIFO"), std::string::npos) << o.err;
  o = run("generate --style sparse --out fifo");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  struct stat st {};
  ASSERT_EQ(::lstat((dir_ / "fifo").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));  // never replaced by a regular file
  write("target.json", "mine");
  fs::create_symlink(dir_ / "target.json", dir_ / "link.json");
  EXPECT_EQ(run("generate --style sparse --out link.json").exit_code, 2);
  EXPECT_EQ(read(dir_ / "target.json"), "mine");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
}

TEST_F(ShardFolders, AJUnitReportNeverTakesTheNameOfABatchFile) {
  const std::string records = read(dir_ / "a/episodes.jsonl");
  const std::string summary = read(dir_ / "a/summary.json");
  for (const std::string& args :
       {std::string(
            "batch s.yaml --shard 0/2 --out a --quiet --no-figures --junit a/episodes.jsonl"),
        std::string("batch s.yaml --shard 0/2 --out a --quiet --junit ./a/../a/summary.json"),
        std::string("merge a b --out m --junit a/episodes.jsonl"),
        std::string("merge a b --out m --junit m/report.html")}) {
    const Outcome o = run(args);
    EXPECT_EQ(o.exit_code, 2) << args << ": " << o.err;
    EXPECT_NE(o.err.find("name the report otherwise"), std::string::npos) << o.err;
  }
  EXPECT_EQ(read(dir_ / "a/episodes.jsonl"), records);
  EXPECT_EQ(read(dir_ / "a/summary.json"), summary);
  EXPECT_FALSE(fs::exists(dir_ / "m"));
  // Any other name in the folder is the report's own.
  EXPECT_EQ(run("merge a b --out m --junit m/junit.xml").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "m/junit.xml"));
}

TEST_F(ShardFolders, AResumeReadsRecordsAsAStreamAndCutsLinesNoRecordIsAsLongAs) {
  auto a = lines("a");
  std::ofstream(dir_ / "a/episodes.jsonl", std::ios::app) << std::string(3u << 20, 'x') << "\n";
  const Outcome o = run("batch s.yaml --shard 0/2 --out a --quiet --no-figures");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("cut 1"), std::string::npos) << o.err;
  EXPECT_EQ(lines("a"), a);
}

// A record is read whole or not at all: a field of the wrong type once stopped a merge with
// nlohmann's own "type must be number" (exit 1) or, for a flag written as text, was counted.
TEST_F(ShardFolders, ARecordThatIsNotWhatTheBatchWritesIsMalformedNeverHalfRead) {
  const auto a = lines("a");
  const nlohmann::json good = nlohmann::json::parse(a[0]);
  auto with = [&](const std::string& key, const nlohmann::json& value) {
    nlohmann::json j = good;
    j[key] = value;
    return j.dump();
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {with("position_error_m", "far"), "field 'position_error_m': expected a number"},
      {with("succeeded", "yes"), "field 'succeeded': expected true or false"},
      {with("collisions", -1), "field 'collisions': expected a whole number from 0"},
      {with("seed", 99), "is not the record's own episode"},
      {good.dump().substr(0, good.dump().size() - 1) + R"(,"succeeded":false})",
       "field 'succeeded': given twice"},
  };
  for (const auto& [record, problem] : cases) {
    put("a", {record, a[1]});
    const Outcome o = run("merge a b --out m");
    EXPECT_EQ(o.exit_code, 2) << o.out << o.err;
    EXPECT_NE(o.err.find("a/episodes.jsonl has 1 malformed line(s), left out (line 1: "),
              std::string::npos)
        << o.err;
    EXPECT_NE(o.err.find(problem), std::string::npos) << o.err;
    EXPECT_NE(
        o.err.find("1 of the scenario's 4 episodes are missing (" + good["id"].get<std::string>()),
        std::string::npos)
        << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "m"));
  }
  // A resume reruns the episode the malformed line claimed, and the merge is whole again.
  const Outcome o = run("batch s.yaml --shard 0/2 --out a --quiet --no-figures");
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("(line 1: field 'succeeded': given twice"), std::string::npos) << o.err;
  ASSERT_EQ(lines("a").size(), 2u);
  // Rerun: the same episode exactly, but for the controller's wall times (the machine's, not its).
  auto without_clock = [](nlohmann::json j) {
    j.erase("controller_ms_median");
    j.erase("controller_ms_p99");
    return j;
  };
  EXPECT_EQ(without_clock(nlohmann::json::parse(lines("a")[1])), without_clock(good));
  const Outcome merged = run("merge a b --out m");
  EXPECT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_NE(merged.out.find("4 of 4 episodes"), std::string::npos) << merged.out;
}

}  // namespace
}  // namespace plantsim
