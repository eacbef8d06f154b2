// The command-line test fixture: each test in a fresh folder, plantsim run there under
// `timeout` (a hang fails the case), its exit code and output captured, and what it left
// outside that folder listed. Shared by test_cli.cpp and test_cli_hardening.cpp.
#pragma once

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_paths.h"
#include "util/process.h"

namespace plantsim {

namespace fs = std::filesystem;

struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

class Cli : public ::testing::Test {
 public:  // the hostile-input table's lambdas prepare files through these
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("plantsim_cli_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    dir_ = root_ / "work";
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  static std::string read(const fs::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // The words of `args` as a POSIX shell splits them ('...', "..." and \ quote; nothing is
  // expanded): the tests write command lines as a person would type them, and run them with an
  // argument vector, no shell.
  static std::vector<std::string> words(const std::string& args) {
    std::vector<std::string> out;
    std::string word;
    bool in_word = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
      const char c = args[i];
      if (c == '\'') {
        const std::size_t end = args.find('\'', i + 1);
        if (end == std::string::npos) throw std::invalid_argument("unclosed ' in " + args);
        word += args.substr(i + 1, end - i - 1);
        i = end;
        in_word = true;
      } else if (c == '"') {
        for (++i; i < args.size() && args[i] != '"'; ++i) {
          if (args[i] == '\\' && i + 1 < args.size() &&
              std::string("\"\\$`").find(args[i + 1]) != std::string::npos)
            ++i;
          word += args[i];
        }
        if (i >= args.size()) throw std::invalid_argument("unclosed \" in " + args);
        in_word = true;
      } else if (c == '\\' && i + 1 < args.size()) {
        word += args[++i];
        in_word = true;
      } else if (c == ' ' || c == '\t' || c == '\n') {
        if (in_word) out.push_back(word);
        word.clear();
        in_word = false;
      } else {
        word += c;
        in_word = true;
      }
    }
    if (in_word) out.push_back(word);
    return out;
  }
  // Runs plantsim in dir_ with a time limit; 124 is timeout's code for a hang.
  Outcome run(const std::string& args, int seconds = 30) {
    std::vector<std::string> argv = {"timeout", std::to_string(seconds), PLANTSIM_BINARY};
    for (std::string& w : words(args)) argv.push_back(std::move(w));
    util::SpawnOptions spawn;
    spawn.working_dir = dir_.string();
    spawn.stdout_path = (root_ / "out.txt").string();
    spawn.stderr_path = (root_ / "err.txt").string();
    Outcome o;
    o.exit_code = util::run_program(argv, spawn);
    o.out = read(root_ / "out.txt");
    o.err = read(root_ / "err.txt");
    return o;
  }
  // Everything under root_ other than the work folder and the captured output.
  std::set<std::string> outside() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(root_))
      if (e.path().filename() != "work" && e.path().filename() != "out.txt" &&
          e.path().filename() != "err.txt")
        names.insert(e.path().filename().string());
    return names;
  }
  std::string world_json(const std::function<void(nlohmann::json&)>& edit) {
    std::ifstream in(test::source_file("data/worlds/examples/small_plant.json"));
    nlohmann::json j = nlohmann::json::parse(in);
    edit(j);
    return j.dump();
  }
  std::string ros_map(const std::string& field, const std::string& value) {
    std::string yaml = read(test::shared_data("ros_maps/depot.yaml"));
    const auto at = yaml.find(field + ":");
    yaml.replace(at, yaml.find('\n', at) - at, field + ": " + value);
    const auto image = yaml.find("image:");
    yaml.replace(image, yaml.find('\n', image) - image,
                 "image: " + test::shared_data("ros_maps/depot.pgm"));
    return yaml;
  }
  fs::path root_, dir_;
};

}  // namespace plantsim
