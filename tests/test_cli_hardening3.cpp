// Hostile inputs, third round (issue 51), as a user meets them through the command line: no
// character of a world's name or a folder reaches a shell (--animate runs ffmpeg with an
// argument vector), every command line printed for pasting reads back as the words it names,
// a batch re-runs in its own folder however it was left (figures, a kill mid-write, --fresh),
// and a run never deletes a user's files.
#include <cstdlib>

#include "cli_fixture.h"
#include "util/shell_word.h"

namespace plantsim {
namespace {

const std::string kCorridor = test::source_file("worlds/examples/corridor_crossing.json");

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

}  // namespace
}  // namespace plantsim
