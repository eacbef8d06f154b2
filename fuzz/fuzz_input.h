// Shared by the libFuzzer harnesses: inputs written to files (the loaders read paths), and
// the rule that a loader may refuse input only with the project's bad-input errors.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "worlds/world_error.h"

namespace plantsim::fuzz {

/// A per-process scratch folder in memory when /dev/shm exists.
inline const std::string& scratch() {
  static const std::string dir = [] {
    const std::string base = std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp";
    const std::string d = base + "/plantsim_fuzz_" + std::to_string(::getpid());
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

inline std::string write_scratch(const std::string& name, const std::string& bytes) {
  const std::string path = scratch() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

/// A tiny world file, w.json, in the scratch folder, written once per process: the world a fuzzed
/// scenario names.
inline void ensure_scratch_world() {
  static const bool written = [] {
    write_scratch(
        "w.json",
        R"({"W": 10, "H": 10, "rects": [[4, 4, 5, 5]], "start": [1, 1], "goal": [8, 8]})");
    return true;
  }();
  (void)written;
}

/// The input split at the first "\n--8<--\n" into two files' contents (the second may be empty).
inline std::pair<std::string, std::string> two_parts(const std::uint8_t* data, std::size_t size) {
  const std::string all(reinterpret_cast<const char*>(data), size);
  const std::string cut = "\n--8<--\n";
  const auto at = all.find(cut);
  if (at == std::string::npos) return {all, ""};
  return {all.substr(0, at), all.substr(at + cut.size())};
}

/// Runs a load; bad input must come back as WorldError or std::invalid_argument (exit 2 in the
/// app). Anything else escaping is a finding: abort so libFuzzer records the input.
template <typename Load>
void expect_clean_refusal(Load&& load) {
  try {
    load();
  } catch (const worlds::WorldError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception type: %s\n", e.what());
    std::abort();
  }
}

}  // namespace plantsim::fuzz
