// Hostile inputs, fourth round (issue 85), as a user meets them through the command line: poses
// Box2D cannot take, outputs named over inputs, a held-out part that is a tuning world under
// another path, a merge standing in a foreign record for a missing one, names near the file
// system's limit, a staging pose inside the charger's margin, an episode asking for an hour.
#include <sys/resource.h>

#include "cli_fixture.h"

namespace plantsim {
namespace {

const std::string kSmallPlant = test::source_file("data/worlds/examples/small_plant.json");

std::string small_batch(const std::string& world, int seeds) {
  return "name: s\nworlds: [" + world +
         "]\nplanners: [vg]\ncontrollers:\n  default: {}\nfaults:\n  none: {}\nseeds: " +
         std::to_string(seeds) + "\nstarts: random\n";
}

// A yaw Box2D cannot normalise aborted the process (b2IsValid) from --start and --charger.
TEST_F(Cli, APoseOptionBeyondTheYawLimitIsRefusedNotAnAbort) {
  for (const std::string option :
       {"--start 1.2,7,1e39", "--charger 23.5,12,-1e39", "--start 1.2,7,100.5"}) {
    const Outcome o = run("run " + kSmallPlant + " " + option + " --out r", 60);
    EXPECT_EQ(o.exit_code, 2) << option << ": " << o.err;
    EXPECT_NE(o.err.find(".yaw': must lie within +-100 rad"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "r"));
  }
  EXPECT_EQ(run("run " + kSmallPlant + " --start 1.2,7,99.9 --out r", 120).exit_code, 0);
}

// A staging pose within the planning margin of the charger lies inside its inflated body: it
// loaded, then every episode ended "goal blocked" (exit 1).
TEST_F(Cli, AStagingDistanceInsideTheChargersMarginIsRefusedAtLoad) {
  for (const double d : {5e-324, 0.05, 0.1}) {
    write("w.json", world_json([d](nlohmann::json& j) { j["charger"]["staging_distance_m"] = d; }));
    const Outcome o = run("run w.json --out r", 60);
    EXPECT_EQ(o.exit_code, 2) << d << ": " << o.err;
    EXPECT_NE(o.err.find("charger.staging_distance_m': must exceed the planning margin"),
              std::string::npos)
        << o.err;
  }
  write("w.json", world_json([](nlohmann::json& j) { j["charger"]["staging_distance_m"] = 0.15; }));
  const Outcome o = run("run w.json --out r", 120);
  EXPECT_EQ(o.exit_code, 0) << o.err << o.out;  // just past the margin it docks
}

// "<name>.partial-<pid>" of a legal 250-byte name is longer than a name may be.
TEST_F(Cli, ARunIntoALegalNameNearTheLimitIsWritten) {
  const std::string ascii(250, 'r');
  std::string accented;
  for (int i = 0; i < 127; ++i) accented += "\xC3\xA9";  // 254 bytes of two-byte characters
  for (const std::string& name : {ascii, accented}) {
    const Outcome o = run("run " + kSmallPlant + " --out " + name, 120);
    EXPECT_EQ(o.exit_code, 0) << o.err;
    EXPECT_TRUE(fs::is_regular_file(dir_ / name / "summary.json"));
  }
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
}

// An output named over an input (or over any file that is not that output's own kind) is
// refused before any work, and the file is kept as it was.
TEST_F(Cli, AnOutputNeverReplacesAnInputOrAUsersFile) {
  write("w.json", read(kSmallPlant));
  write("s.yaml", small_batch("w.json", 1));
  write("n.yaml",
        "controller_server:\n  ros__parameters:\n    FollowPath:\n      plugin: "
        "\"nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController\"\n      "
        "desired_linear_vel: 0.5\n");
  ASSERT_EQ(run("run w.json --out r", 120).exit_code, 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"batch s.yaml --out b --quiet --no-figures --junit s.yaml", "s.yaml"},
      {"batch s.yaml --out b --quiet --no-figures --junit w.json", "w.json"},
      {"summarize r --out r/summary.json", "r/summary.json"},
      {"summarize r --html r/report.html", "r/report.html"},
      {"summarize r --out s.yaml", "s.yaml"},
      {"nav2-import n.yaml --out w.json", "w.json"},
      {"generate --count 3 --out s.yaml", "s.yaml"},
      {"vary w.json --unmapped 1 --out s.yaml", "s.yaml"}};
  for (const auto& [args, victim] : cases) {
    const std::string before = read(dir_ / victim);
    const Outcome o = run(args, 120);
    EXPECT_EQ(o.exit_code, 2) << args << ": " << o.err;
    EXPECT_NE(o.err.find("exists and is not"), std::string::npos) << args << ": " << o.err;
    EXPECT_EQ(read(dir_ / victim), before) << args;
  }
  EXPECT_FALSE(fs::exists(dir_ / "b"));
  // Each kind still replaces its own earlier output.
  for (const std::string args :
       {"batch s.yaml --out b --quiet --no-figures --junit j.xml",
        "summarize r --out t.md --html index.html", "nav2-import n.yaml --out c.json"}) {
    EXPECT_EQ(run(args, 300).exit_code, 0) << args;
    const Outcome again = run(args, 300);
    EXPECT_EQ(again.exit_code, 0) << args << ": " << again.err;
  }
}

// A plan option given twice planned with one of them, unsaid.
TEST_F(Cli, APlanOptionGivenTwiceIsRefused) {
  const Outcome o = run("plan " + kSmallPlant +
                        " --planner grid --option resolution_m=0.1 --option resolution_m=0.2");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("--option resolution_m is given twice"), std::string::npos) << o.err;
}

// tune's held-out check compared paths as written: the tuning world under another name passed,
// and the report called the tuning episodes held out.
TEST_F(Cli, AValidationWorldIsJudgedByItsContentNotItsPath) {
  write("w.json", read(kSmallPlant));
  write("sub/copy.json", read(kSmallPlant));
  fs::create_symlink(dir_ / "w.json", dir_ / "link.json");
  for (const std::string& v : std::vector<std::string>{
           "./w.json", "sub/../w.json", "link.json", "sub/copy.json", (dir_ / "w.json").string()}) {
    write("t.yaml",
          small_batch("w.json", 2) + "tune:\n  validation_worlds: [" + v + "]\n  budget: 2\n");
    const Outcome o = run("tune t.yaml --check --out tt", 60);
    EXPECT_EQ(o.exit_code, 2) << v << ": " << o.err;
    EXPECT_NE(o.err.find("validation episodes must be held out"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("content fingerprint"), std::string::npos) << o.err;
  }
  // The same world on other seeds is held out by its seeds.
  write("t.yaml", small_batch("w.json", 2) +
                      "tune:\n  validation_worlds: [sub/copy.json]\n  validation_seeds: [7, 8]\n"
                      "  budget: 2\n");
  const Outcome o = run("tune t.yaml --check --out tt", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
}

// Without its scenario file a merge counted a foreign record in place of a missing one
// ("4 of 4", exit 0); with the file given again by --scenario it is judged by its content.
TEST_F(Cli, AMergeWithoutItsScenarioRefusesAForeignRecord) {
  write("w.json", read(kSmallPlant));
  write("s.yaml", small_batch("w.json", 4));
  ASSERT_EQ(run("batch s.yaml --out a --shard 0/2 --quiet --no-figures", 600).exit_code, 0);
  ASSERT_EQ(run("batch s.yaml --out b --shard 1/2 --quiet --no-figures", 600).exit_code, 0);
  fs::rename(dir_ / "s.yaml", dir_ / "moved.yaml");
  // Shard b loses its last episode and takes in an edited one: another seed, the same index.
  std::vector<std::string> lines;
  {
    std::ifstream in(dir_ / "b/episodes.jsonl");
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  ASSERT_EQ(lines.size(), 2u);
  const std::string original = lines.back();
  nlohmann::json forged = nlohmann::json::parse(original);
  std::string id = forged["id"];
  id.replace(id.rfind('|') + 1, std::string::npos, "99");
  forged["id"] = id, forged["seed"] = 99;
  lines.back() = forged.dump();
  {
    std::ofstream out(dir_ / "b/episodes.jsonl");
    for (const std::string& l : lines) out << l << "\n";
  }
  Outcome o = run("merge a b --out m", 120);
  EXPECT_EQ(o.exit_code, 2) << o.out << o.err;
  EXPECT_NE(o.err.find("key does not match"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "m"));
  // The moved scenario, named again, checks the ids themselves.
  o = run("merge a b --out m --scenario moved.yaml", 120);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  // Another scenario named by --scenario is refused by its content.
  write("other.yaml", small_batch("w.json", 3));
  o = run("merge a --out m --scenario other.yaml", 120);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("the records are of scenario"), std::string::npos) << o.err;
  // Unforged, the moved scenario named again merges whole.
  {
    std::ofstream out(dir_ / "b/episodes.jsonl");
    out << lines.front() << "\n" << original << "\n";
  }
  o = run("merge a b --out m --scenario moved.yaml", 120);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("4 of 4"), std::string::npos) << o.out;
}

// A resume that cannot read its records (here: records of another scenario) failed after it had
// removed the earlier report; the report stays until the records are read.
TEST_F(Cli, AResumeThatCannotReadItsRecordsKeepsTheEarlierReport) {
  write("w.json", read(kSmallPlant));
  write("s.yaml", small_batch("w.json", 1));
  ASSERT_EQ(run("batch s.yaml --out b --quiet", 600).exit_code, 0);
  ASSERT_TRUE(fs::exists(dir_ / "b/report.html"));
  write("s.yaml", small_batch("w.json", 2));  // another scenario now
  const Outcome o = run("batch s.yaml --out b --quiet", 600);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("holds episodes of another scenario"), std::string::npos) << o.err;
  EXPECT_TRUE(fs::exists(dir_ / "b/report.html"));
  EXPECT_TRUE(fs::exists(dir_ / "b/summary.json"));
}

// The longest episode a config accepted (83,000 s with 1,000 movers) ran for an hour or more.
TEST_F(Cli, AnEpisodeAskingForAnHourIsRefusedSayingHowLong) {
  write("w.json", world_json([](nlohmann::json& j) {
          nlohmann::json movers = nlohmann::json::array();
          for (int i = 0; i < 1000; ++i) {
            const double x = 2 + (i % 40) * 0.5, y = 0.3 + (i / 40) * 0.02;
            movers.push_back({{"size_m", {0.1, 0.1}},
                              {"waypoints", {{x, y}, {x, y + 0.01}}},
                              {"speed_mps", 0.01},
                              {"start_time_s", 1000}});
          }
          j["moving_obstacles"] = movers;
        }));
  write("long.json", R"({"timeout_s": 83000})");
  Outcome o = run("run w.json --config long.json --out r", 30);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("minutes of computing"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "r"));
  write("s.yaml", "worlds: [w.json]\ncontrollers:\n  long: long.json\nseeds: 1\n");
  o = run("batch s.yaml --out b --quiet --no-figures", 30);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("minutes of computing"), std::string::npos) << o.err;
}

// Under a memory limit, --threads 256 aborted the process when a thread could not start (its
// stack and malloc arena did not fit); the threads that started do the work. (ASan reserves
// terabytes of address space: the limit is not for the sanitizer build.)
TEST_F(Cli, ABatchWhoseThreadsCannotAllStartStillRuns) {
#if defined(__SANITIZE_ADDRESS__) || defined(__has_feature)
#if defined(__SANITIZE_ADDRESS__) || __has_feature(address_sanitizer)
  GTEST_SKIP() << "an address-space limit cannot hold an ASan process";
#endif
#endif
  write("s.yaml", small_batch(kSmallPlant, 2));
  // prlimit is util-linux's, on every Debian: 1 GB of address space holds the batch, not the
  // 256 threads' 8 MiB stacks and 64 MiB arenas.
  std::vector<std::string> argv = {
      "prlimit", "--as=1000000000", "--", "timeout", "600",          PLANTSIM_BINARY, "batch",
      "s.yaml",  "--out",           "b",  "--quiet", "--no-figures", "--threads",     "256"};
  util::SpawnOptions spawn;
  spawn.working_dir = dir_.string();
  spawn.stderr_path = (root_ / "err.txt").string();
  spawn.stdout_path = (root_ / "out.txt").string();
  EXPECT_EQ(util::run_program(argv, spawn), 0) << read(root_ / "err.txt");
  EXPECT_NE(read(root_ / "out.txt").find("2 of those run now succeeded"), std::string::npos)
      << read(root_ / "out.txt");
}

}  // namespace
}  // namespace plantsim
