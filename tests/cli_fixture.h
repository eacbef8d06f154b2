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
#include <string>

#include "test_paths.h"

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
  // Runs plantsim in dir_ with a time limit; 124 is timeout's code for a hang.
  Outcome run(const std::string& args, int seconds = 30) {
    const std::string cmd = "cd '" + dir_.string() + "' && timeout " + std::to_string(seconds) +
                            " " PLANTSIM_BINARY " " + args + " > '" + (root_ / "out.txt").string() +
                            "' 2> '" + (root_ / "err.txt").string() + "'";
    const int status = std::system(cmd.c_str());
    Outcome o;
    o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
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
    std::ifstream in(test::source_file("worlds/examples/small_plant.json"));
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
