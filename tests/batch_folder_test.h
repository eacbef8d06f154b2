// A test fixture owning a fresh temporary folder per test, for batch runs: files written into
// it and RunOptions pointing into it (quiet, no figures).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "batch/batch_runner.h"

namespace plantsim::test {

class BatchFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("plantsim_batch_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    if (!std::getenv("PLANTSIM_KEEP")) std::filesystem::remove_all(dir_);
  }
  std::string write(const std::string& name, const std::string& text) {
    const auto p = (dir_ / name).string();
    std::filesystem::create_directories(std::filesystem::path(p).parent_path());
    std::ofstream(p) << text;
    return p;
  }
  batch::RunOptions options(const std::string& out, int i = 0, int n = 1) {
    batch::RunOptions o;
    o.out_dir = (dir_ / out).string();
    o.shard_index = i;
    o.shard_count = n;
    o.progress = false;
    o.figures = false;
    return o;
  }
  std::filesystem::path dir_;
};

}  // namespace plantsim::test
