// Hostile inputs, third round (issue 51), as a user meets them through the command line: no
// character of a world's name or a folder reaches a shell (--animate runs ffmpeg with an
// argument vector), every command line printed for pasting reads back as the words it names,
// a batch re-runs in its own folder however it was left (figures, a kill mid-write, --fresh),
// a run never deletes a user's files; one rule for names, degenerate worlds refused at load,
// links never followed, the episode limit per shard, Markdown and links as text.
#include <chrono>
#include <cstdlib>
#include <functional>

#include "cli_fixture.h"
#include "util/shell_word.h"

namespace plantsim {
namespace {

const std::string kCorridor = test::source_file("data/worlds/examples/corridor_crossing.json");
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A stand-in ffmpeg first on the PATH: it records its arguments, one a line, and writes the
// file it is asked for (its last argument), as the real one would.
class FakeFfmpeg : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    const fs::path bin = root_ / "bin";
    fs::create_directories(bin);
    args_ = root_ / "ffmpeg_args.txt";
    std::ofstream(bin / "ffmpeg") << "#!/bin/sh\nprintf '%s\\n' \"$@\" > '" << args_.string()
                                  << "'\nfor last; do :; done\n: > \"$last\"\n";
    fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
    const char* path = std::getenv("PATH");
    old_path_ = path ? path : "";
    ::setenv("PATH", (bin.string() + ":" + old_path_).c_str(), 1);
  }
  void TearDown() override {
    ::setenv("PATH", old_path_.c_str(), 1);
    Cli::TearDown();
  }
  std::vector<std::string> ffmpeg_args() const {
    std::ifstream in(args_);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  }
  fs::path args_;
  std::string old_path_;
};

TEST_F(FakeFfmpeg, AWorldsNameOrAnOutputFolderNeverReachesAShell) {
  write("w.json", world_json([](nlohmann::json& j) { j["name"] = "plant';touch${IFS}X;'"; }));
  Outcome o = run("run w.json --animate", 180);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "X"));
  const fs::path folder = dir_ / "results" / "plant';touch${IFS}X;'";
  EXPECT_TRUE(fs::exists(folder / "animation.mp4")) << o.out;
  EXPECT_FALSE(fs::exists(folder / "animation.mp4.tmp.mp4"));
  // The folder (its staging copy, moved into place after) reached ffmpeg inside one argument.
  const std::vector<std::string> args = ffmpeg_args();
  ASSERT_FALSE(args.empty());
  const std::string staging =
      fs::canonical(dir_ / "results").string() + "/plant';touch${IFS}X;'.partial-";
  EXPECT_EQ(args.back().rfind(staging, 0), 0u) << args.back();
  EXPECT_NE(args.back().find("/animation.mp4.tmp.mp4"), std::string::npos) << args.back();

  o = run("run w.json --animate --out \"o'; touch Y; '\"", 180);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "Y"));
  EXPECT_TRUE(fs::exists(dir_ / "o'; touch Y; '" / "animation.mp4"));
  // A '%' in the folder is not read as ffmpeg's frame pattern, a leading '-' not as an option.
  o = run("run w.json --animate --out -100%d", 180);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const std::vector<std::string> pct = ffmpeg_args();
  ASSERT_GE(pct.size(), 2u);
  const std::string pattern = pct[std::find(pct.begin(), pct.end(), "-i") - pct.begin() + 1];
  EXPECT_EQ(pattern.rfind(dir_.string() + "/-100%%d.partial-", 0), 0u) << pattern;
  EXPECT_EQ(pattern.substr(pattern.size() - 22), "/frames/frame_%04d.png") << pattern;
  EXPECT_TRUE(fs::exists(dir_ / "-100%d" / "animation.mp4"));
}

TEST(ShellWord, EveryPrintedWordReadsBackAsItself) {
  for (const std::string& w :
       {std::string("plain"), std::string("x'; touch F; echo '"), std::string("a b"),
        std::string("$HOME"), std::string("`id`"), std::string("\"q\""), std::string("back\\slash"),
        std::string("world_N10|vg|default|wet|3"), std::string("'"), std::string("''"),
        std::string("new\nline"), std::string("*"), std::string("~user"), std::string("!x")}) {
    const std::vector<std::string> back = Cli::words("plantsim " + util::shell_word(w) + " x");
    ASSERT_EQ(back.size(), 3u) << w;
    EXPECT_EQ(back[1], w);
  }
  EXPECT_EQ(util::shell_word("world_N10.json"), "world_N10.json");  // no quotes where none needed
}

TEST_F(Cli, ARunNeverDeletesAUsersFolderNamedLikeItsOwn) {
  write("out/frames/mine.txt", "my notes");
  write("out/frames/frame_0000.png", "my picture");
  const Outcome o = run("run " + kCorridor + " --out out", 120);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("frames/mine.txt"), std::string::npos) << o.err;
  EXPECT_EQ(read(dir_ / "out/frames/mine.txt"), "my notes");
  EXPECT_EQ(read(dir_ / "out/frames/frame_0000.png"), "my picture");
  // A folder where a file belongs is the user's too.
  fs::remove_all(dir_ / "out");
  fs::create_directories(dir_ / "out/run.png");
  EXPECT_EQ(run("run " + kCorridor + " --out out", 120).exit_code, 2);
  EXPECT_TRUE(fs::is_directory(dir_ / "out/run.png"));
}

TEST_F(Cli, ABatchWithFiguresRerunsInItsOwnFolderHoweverItWasLeft) {
  write("s.yaml", "name: again\nworlds: [" + kCorridor + "]\nseeds: 2\n");
  Outcome o = run("batch s.yaml --out b --quiet", 300);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  ASSERT_TRUE(fs::exists(dir_ / "b/plans_corridor_crossing.png"));
  o = run("batch s.yaml --out b --quiet", 300);  // the same command again: a resume
  EXPECT_EQ(o.exit_code, 0) << o.err;
  // What a kill leaves mid-write, and a figure no run of this batch draws any more.
  write("b/summary.csv.tmp.4242.0", "half");
  write("b/failures/x.png.tmp.4242.1", "half");
  write("b/chart_gone.png", "old");
  o = run("batch s.yaml --out b --quiet", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_FALSE(fs::exists(dir_ / "b/summary.csv.tmp.4242.0"));
  EXPECT_FALSE(fs::exists(dir_ / "b/failures/x.png.tmp.4242.1"));
  EXPECT_FALSE(fs::exists(dir_ / "b/chart_gone.png"));
  EXPECT_TRUE(fs::exists(dir_ / "b/summary.csv"));
  o = run("batch s.yaml --out b --quiet --fresh", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("2 run now"), std::string::npos) << o.out;
  // A temporary of something a batch never writes is still a user's file.
  write("b/notes.txt.tmp.1.2", "mine");
  o = run("batch s.yaml --out b --quiet", 300);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(read(dir_ / "b/notes.txt.tmp.1.2"), "mine");
}

TEST_F(Cli, NotANumberIsRefusedByEveryNumberOptionBeforeAnyWork) {
  write("s.yaml", "name: nan\nworlds: [" + kCorridor + "]\nseeds: 2\n");
  for (const std::string& args :
       {std::string("batch s.yaml --out b --min-success nan"),
        "plan " + kCorridor + " --inflate nan", "plan " + kCorridor + " --inflate inf",
        "coverage " + kCorridor + " --cell NaN", std::string("generate --width -inf")}) {
    const Outcome o = run(args, 60);
    EXPECT_EQ(o.exit_code, 2) << args << ": " << o.err;
    if (args.find("inf") == std::string::npos) {  // an infinity already fails the range
      EXPECT_NE(o.err.find("finite number"), std::string::npos) << args << ": " << o.err;
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "b"));
}

TEST_F(Cli, AnOutputInAFolderThatDoesNotExistIsBadInputBeforeAnyWork) {
  const std::string nav2 = test::source_file("tests/fixtures/nav2/rpp_readme.yaml");
  ASSERT_EQ(run("run " + kCorridor + " --out r", 120).exit_code, 0);
  for (const std::string& args : {std::string("generate --out missing/x.json"),
                                  "vary " + kCorridor + " --unmapped 1 --out missing/v.json",
                                  "nav2-import " + nav2 + " --out missing/c.json",
                                  std::string("summarize r --out missing/s.md"),
                                  std::string("summarize r --html missing/index.html")}) {
    const Outcome o = run(args, 60);
    EXPECT_EQ(o.exit_code, 2) << args << ": " << o.err;  // was 1, after the work
    EXPECT_NE(o.err.find("does not exist"), std::string::npos) << args << ": " << o.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

// One rule for every name, wherever it comes from (worlds/names.h): a world's "name", its file's
// name when it has none, a moving obstacle's, a scenario's faults; and messages that quote a name
// show its escapes, never act on them (the terminal would).
TEST_F(Cli, OneNamingRuleForEveryNameWhereverItComesFrom) {
  for (const std::string& name :
       {std::string("\x1b[2Jwiped"),
        std::string("a\xc2\x85"
                    "b"),
        std::string("a\u202e"
                    "gnp.exe"),
        std::string("\ufeffplant"), std::string(" plant"), std::string(".."), std::string("a|b"),
        std::string(101, 'x'), std::string("\u200b")}) {
    write("w.json", world_json([&](nlohmann::json& j) { j["name"] = name; }));
    const Outcome o = run("run w.json --out r", 60);
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find("field 'name'"), std::string::npos) << o.err;
    EXPECT_EQ(o.err.find('\x1b'), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "r"));
  }
  // Named by its file: the same rule, the file named in the message with its escapes shown.
  write("w\x1b[31m.json", world_json([](nlohmann::json& j) { j.erase("name"); }));
  Outcome o = run("run 'w\x1b[31m.json' --out r", 60);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("w\\x1b[31m.json"), std::string::npos) << o.err;
  EXPECT_EQ(o.err.find('\x1b'), std::string::npos);
  write("mover.json", world_json([](nlohmann::json& j) {
          j["moving_obstacles"] = {
              {{"name", "cart\x07"}, {"size_m", {1, 1}}, {"waypoints", {{5, 5}}}}};
        }));
  o = run("run mover.json --out r", 60);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("moving_obstacles[0].name"), std::string::npos) << o.err;
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 1\nfaults: {\"\u202ewet\": {}}\n");
  o = run("batch s.yaml --check", 60);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("direction-changing"), std::string::npos) << o.err;
  // Two worlds whose figures would share a file ("plant a" and "plant_a", or by case).
  write("a.json", world_json([](nlohmann::json& j) { j["name"] = "plant a"; }));
  write("b.json", world_json([](nlohmann::json& j) { j["name"] = "Plant_a"; }));
  write("two.yaml", "worlds: [a.json, b.json]\nseeds: 1\n");
  o = run("batch two.yaml --check", 60);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("would share figure files"), std::string::npos) << o.err;
  // Names people use pass: letters of any script, inner spaces.
  write("ok.json", world_json([](nlohmann::json& j) { j["name"] = "脱硫 plant #2 (100%)"; }));
  write("ok.yaml",
        "worlds: [ok.json]\nseeds: 1\nfaults: {湿地面: {drive: {tyre_friction: 0.3}}}\n");
  o = run("batch ok.yaml --check", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
}

// Worlds that load but cannot be run are refused at load (exit 2), not failed at run time.
TEST_F(Cli, DegenerateChargersAndMoversOnTheStartAreRefusedAtLoad) {
  const std::vector<std::pair<std::function<void(nlohmann::json&)>, std::string>> cases = {
      {[](nlohmann::json& j) { j["charger"]["width_m"] = 5e-324; }, "charger.width_m"},
      {[](nlohmann::json& j) { j["charger"]["depth_m"] = 1e-9; }, "charger.depth_m"},
      {[](nlohmann::json& j) {
         j["moving_obstacles"] = {
             {{"size_m", {1, 1}}, {"waypoints", {{j["start"]["x"], j["start"]["y"]}}}}};
       },
       "covers the robot at the start"},
      {[](nlohmann::json& j) {
         j["moving_obstacles"] = {{{"size_m", {1e-300, 1}}, {"waypoints", {{5, 5}}}}};
       },
       "at least 0.01 m"}};
  for (const auto& [edit, message] : cases) {
    write("w.json", world_json(edit));
    const Outcome o = run("run w.json --out r", 60);
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find(message), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "r"));
  }
}

// An output that is a link is never followed or replaced, dangling or not, before any work.
TEST_F(Cli, ARunIntoALinkIsRefusedBeforeAnyWork) {
  fs::create_symlink(dir_ / "nowhere" / "target", dir_ / "dangling");
  fs::create_directories(dir_ / "mine");
  write("mine/keep.txt", "mine");
  fs::create_directory_symlink(dir_ / "mine", dir_ / "link");
  for (const std::string out : {"dangling", "link"}) {
    const Outcome o = run("run " + kCorridor + " --out " + out, 60);
    EXPECT_EQ(o.exit_code, 2) << o.err;  // was 1, after the episode
    EXPECT_NE(o.err.find("symbolic link"), std::string::npos) << o.err;
    EXPECT_TRUE(fs::is_symlink(dir_ / out));
  }
  EXPECT_EQ(read(dir_ / "mine/keep.txt"), "mine");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "mine"), fs::directory_iterator()), 1);
}

// A legal file name near the system's 255-byte limit is written (its temporary's name is cut).
TEST_F(Cli, AJunitNameNearTheFileSystemsLimitIsWritten) {
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 1\n");
  const std::string junit = std::string(250, 'j') + ".xml";  // 254 bytes
  const Outcome o = run("batch s.yaml --out b --quiet --no-figures --junit " + junit, 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / junit));
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

// A sweep value the parameter cannot take is named as a value, not the parameter as unknown.
TEST_F(Cli, SweepValuesThatAreNotNumbersAreNamedAsValues) {
  for (const std::string value : {".nan", "0x10", "ten"}) {
    write("s.yaml", "worlds: [" + kCorridor +
                        "]\nseeds: 1\nsweep: {parameter: drive.tyre_friction, values: [0.5, " +
                        value + "]}\n");
    const Outcome o = run("batch s.yaml --check", 60);
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find("field 'sweep.values[1]'"), std::string::npos) << value << ": " << o.err;
  }
  write("s.yaml", "worlds: [" + kCorridor +
                      "]\nseeds: 1\nsweep: {parameter: drive.tyre_frction, values: [0.5]}\n");
  const Outcome o = run("batch s.yaml --check", 60);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("is not a fault parameter"), std::string::npos) << o.err;
}

// The episode limit holds per run, not per scenario: a shard of a 100-million-episode scenario
// is checked in seconds, holding its own episodes only; the whole is refused in one run.
TEST_F(Cli, AHundredMillionEpisodeScenarioRunsShardByShard) {
  std::string faults = "faults: {";
  for (int i = 0; i < 100; ++i) faults += (i ? ", f" : "f") + std::to_string(i) + ": {}";
  write("s.yaml", "worlds: [" + kCorridor + "]\nseeds: 1000000\n" + faults + "}\n");
  const auto t0 = Clock::now();
  Outcome o = run("batch s.yaml --check --shard 7/2000", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_LT(seconds_since(t0), 20.0);
  o = run("batch s.yaml --check --shard 7/50", 60);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("with n >= 100"), std::string::npos) << o.err;
  // 2e12 episodes: a sweep of 100 values over the 100 faults, 100 controllers, 2 planners.
  std::string values = "[";
  for (int i = 0; i < 100; ++i) values += (i ? ", 0." : "0.") + std::to_string(100 + i);
  write("huge.yaml", "worlds: [" + kCorridor + "]\nseeds: 1000000\nplanners: [vg, grid]\n" +
                         faults + "}\ncontrollers: {" + faults.substr(9) +
                         "}\nsweep: {parameter: drive.tyre_friction, values: " + values + "]}\n");
  o = run("batch huge.yaml --check --shard 0/100000", 60);
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("more than the limit of 1e12"), std::string::npos) << o.err;
}

// summarize's Markdown shows names as text: '|' does not split a column, a name in [..](..) is
// no link, and a folder named like a URL scheme is linked as a path.
TEST_F(Cli, SummarizeWritesNamesAsTextAndLinksAsPaths) {
  ASSERT_EQ(run("run " + kCorridor + " --out 'javascript:alert(1)#%'", 120).exit_code, 0);
  const fs::path summary = dir_ / "javascript:alert(1)#%" / "summary.json";
  nlohmann::json j = nlohmann::json::parse(read(summary));
  j["world"] = "x | [y](javascript:alert(2)) <b>";
  std::ofstream(summary) << j.dump();
  const Outcome o = run("summarize 'javascript:alert(1)#%' --out s.md", 60);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  const std::string md = read(dir_ / "s.md");
  const std::string row = md.substr(md.rfind("\n|", md.size() - 2) + 1);
  int columns = 0;
  for (std::size_t i = 0; i < row.size(); ++i)
    columns += row[i] == '|' && (i == 0 || row[i - 1] != '\\');
  EXPECT_EQ(columns, 15) << row;
  EXPECT_EQ(row.find("](javascript:"), std::string::npos) << row;
  EXPECT_EQ(row.find("<b>"), std::string::npos) << row;
  EXPECT_NE(row.find("(javascript%3Aalert%281%29%23%25/run.png)"), std::string::npos) << row;
}

}  // namespace
}  // namespace plantsim
