// posix_spawnp with file actions for the working folder and redirections, then waitpid.
#include "util/process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

extern char** environ;

namespace plantsim::util {

namespace {

class FileActions {
 public:
  FileActions() { ::posix_spawn_file_actions_init(&actions_); }
  ~FileActions() { ::posix_spawn_file_actions_destroy(&actions_); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
  posix_spawn_file_actions_t* get() { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

}  // namespace

ProgramEnd run_program_measured(const std::vector<std::string>& argv, const SpawnOptions& o) {
  if (argv.empty()) throw std::invalid_argument("run_program: no program named");
  for (const std::string& e : o.environment_additions)
    if (e.find('=') == std::string::npos || e.front() == '=')
      throw std::invalid_argument("run_program: an environment addition is not NAME=value");
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  FileActions actions;
  if (!o.working_dir.empty())
    ::posix_spawn_file_actions_addchdir_np(actions.get(), o.working_dir.c_str());
  if (o.stdin_null) ::posix_spawn_file_actions_addopen(actions.get(), 0, "/dev/null", O_RDONLY, 0);
  if (!o.stdout_path.empty())
    ::posix_spawn_file_actions_addopen(actions.get(), 1, o.stdout_path.c_str(),
                                       O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!o.stderr_path.empty())
    ::posix_spawn_file_actions_addopen(actions.get(), 2, o.stderr_path.c_str(),
                                       O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // The additions, then the caller's variables they do not name (the dynamic loader reads the
  // last of two equal names, getenv the first: one of each leaves no doubt).
  std::vector<char*> environment;
  auto named = [](std::string_view entry, std::string_view addition) {
    const std::size_t name_end = addition.find('=') + 1;  // the name and its '='
    return entry.substr(0, name_end) == addition.substr(0, name_end);
  };
  for (const std::string& e : o.environment_additions)
    environment.push_back(const_cast<char*>(e.c_str()));
  for (char** e = environ; *e; ++e)
    if (std::none_of(o.environment_additions.begin(), o.environment_additions.end(),
                     [&](const std::string& a) { return named(*e, a); }))
      environment.push_back(*e);
  environment.push_back(nullptr);
  ProgramEnd end;
  pid_t pid = 0;
  if (::posix_spawnp(&pid, args[0], actions.get(), nullptr, args.data(), environment.data()) != 0)
    return end;
  int status = 0;
  struct rusage usage {};
  while (::wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR) return end;
  end.peak_resident_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  if (WIFEXITED(status)) end.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) end.exit_code = 128 + WTERMSIG(status);
  return end;
}

int run_program(const std::vector<std::string>& argv, const SpawnOptions& o) {
  return run_program_measured(argv, o).exit_code;
}

std::string find_on_path(const std::string& program) {
  if (program.empty()) return "";
  if (program.find('/') != std::string::npos)
    return ::access(program.c_str(), X_OK) == 0 ? program : "";
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    std::size_t end = dirs.find(':', begin);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end == begin ? "." : dirs.substr(begin, end - begin);
    const std::string candidate = dir + "/" + program;
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    begin = end + 1;
  }
  return "";
}

}  // namespace plantsim::util
