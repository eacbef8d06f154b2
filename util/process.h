// Running another program without a shell: the program and its arguments as a vector, found on
// the PATH by its name (posix_spawnp), so no character of a world's name, a folder or an option
// is ever read by /bin/sh. The one place plantsim starts processes (ffmpeg for --animate, the
// test fixture for the command line); std::system and popen are not used anywhere.
#pragma once

#include <string>
#include <vector>

namespace plantsim::util {

struct SpawnOptions {
  std::string working_dir;  ///< "" keeps the caller's
  std::string stdout_path;  ///< "" inherits; else the file is created or truncated
  std::string stderr_path;  ///< "" inherits
  bool stdin_null = true;   ///< reads /dev/null, never the terminal
  std::vector<std::string> environment_additions;  ///< "NAME=value", before the caller's own
};

/// How a program ended and the most memory it held.
struct ProgramEnd {
  int exit_code = -1;            ///< as run_program returns it
  double peak_resident_mib = 0;  ///< the child's maximum resident set (wait4's ru_maxrss)
};

/// Runs argv[0] (searched on the PATH unless it holds a '/') with argv and waits for it.
/// Returns its exit code, 128 + the signal's number if a signal ended it, or -1 if it could
/// not be started (not found, not executable). argv must not be empty.
int run_program(const std::vector<std::string>& argv, const SpawnOptions& options = {});
/// run_program, also reporting the child's peak memory.
ProgramEnd run_program_measured(const std::vector<std::string>& argv,
                                const SpawnOptions& options = {});

/// The program's full path found on the PATH as posix_spawnp would, or "" when it is absent.
std::string find_on_path(const std::string& program);

}  // namespace plantsim::util
