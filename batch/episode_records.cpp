// Streaming reads of episodes.jsonl and the checks on a batch's output folder.
#include "batch/episode_records.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "batch/batch_gate.h"
#include "batch/record_schema.h"
#include "util/atomic_file.h"

namespace plantsim::batch {
namespace {

using nlohmann::json;

/// Closes the descriptor on every way out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

/// A JUnit report an earlier run wrote into its folder with --junit (batch_gate.h).
bool junit_report(const std::filesystem::directory_entry& e) {
  std::error_code ec;
  if (e.path().extension() != ".xml" || !e.is_regular_file(ec) || e.is_symlink(ec)) return false;
  return looks_like_junit_report(util::file_head(e.path().string(), 512));
}

}  // namespace

JsonlScan scan_jsonl(const std::string& path, const std::function<void(std::string&& line)>& each) {
  JsonlScan scan;
  const Fd f{::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC)};
  if (f.fd < 0) {
    if (errno == ENOENT) return scan;
    if (errno == ELOOP)
      throw std::invalid_argument(
          path + " is a symbolic link; plantsim neither follows nor replaces links");
    throw std::invalid_argument(util::system_error_text("cannot read " + path));
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode))
    throw std::invalid_argument(path + " is not a regular file");
  std::string line, chunk(1 << 16, '\0');
  bool too_long = false;
  std::int64_t line_number = 0;
  auto bad = [&](const std::string& problem) {
    if (scan.bad_lines++ == 0)
      scan.first_problem = "line " + std::to_string(line_number) + ": " + problem;
  };
  auto finish_line = [&]() {
    ++line_number;
    if (too_long) {
      bad("longer than any record");
    } else if (line.find_first_not_of(" \t\r") != std::string::npos) {
      const std::string problem = record_problem(line);
      if (problem.empty())
        each(std::move(line));
      else
        bad(problem);
    }
    line.clear();
    too_long = false;
  };
  for (;;) {
    const ssize_t n = ::read(f.fd, chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::invalid_argument(util::system_error_text("cannot read " + path));
    if (n == 0) break;
    for (std::size_t at = 0; at < static_cast<std::size_t>(n);) {
      const char* begin = chunk.data() + at;
      const void* newline = std::memchr(begin, '\n', static_cast<std::size_t>(n) - at);
      const std::size_t len =
          newline ? static_cast<const char*>(newline) - begin : static_cast<std::size_t>(n) - at;
      if (!too_long) {
        if (line.size() + len > kMaxRecordBytes)
          too_long = true, line.clear(), line.shrink_to_fit();
        else
          line.append(begin, len);
      }
      at += len;
      if (newline) {
        finish_line();
        ++at;
      }
    }
  }
  scan.torn_tail = too_long || !line.empty();
  return scan;
}

std::vector<std::string> read_records(const std::string& path) {
  std::vector<std::string> records;
  scan_jsonl(path, [&](std::string&& line) { records.push_back(std::move(line)); });
  return records;
}

namespace {

/// "X.tmp.PID.N": what util::write_file_atomically leaves of X when killed mid-write.
std::string temporary_target(const std::string& name) {
  const std::size_t at = name.rfind(".tmp.");
  if (at == std::string::npos || at == 0) return "";
  const std::string tail = name.substr(at + 5);
  const std::size_t dot = tail.find('.');
  const auto digits = [](const std::string& t) {
    return !t.empty() && t.size() <= 20 && t.find_first_not_of("0123456789") == std::string::npos;
  };
  if (dot == std::string::npos || !digits(tail.substr(0, dot)) || !digits(tail.substr(dot + 1)))
    return "";
  return name.substr(0, at);
}

bool is_written_output_name(const std::string& name) {
  static const char* const exact[] = {"episodes.jsonl", "summary.csv", "summary.json",
                                      "sweep.csv",      "report.html", ".plantsim.lock",
                                      "failures",       "episodes"};
  for (const char* e : exact)
    if (name == e) return true;
  auto png_with_prefix = [&](const std::string& prefix) {
    return name.rfind(prefix, 0) == 0 && name.size() > prefix.size() + 4 &&
           name.compare(name.size() - 4, 4, ".png") == 0;
  };
  return png_with_prefix("chart_") || png_with_prefix("paths_") || png_with_prefix("plans_");
}

}  // namespace

bool is_batch_output_name(const std::string& name) {
  if (is_written_output_name(name)) return true;
  const std::string target = temporary_target(name);
  return !target.empty() && target != "failures" && target != "episodes" &&
         target != ".plantsim.lock" && is_written_output_name(target);
}

void remove_batch_temporaries(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const fs::path& folder : {fs::path(dir), fs::path(dir) / "failures"}) {
    if (!fs::is_directory(fs::symlink_status(folder, ec))) continue;
    std::vector<fs::path> stale;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
      if (!temporary_target(e.path().filename().string()).empty() && e.is_regular_file(ec) &&
          !e.is_symlink(ec))
        stale.push_back(e.path());
    for (const fs::path& p : stale) fs::remove(p, ec);
  }
}

void remove_batch_outputs(const std::string& dir, bool keep_records) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> old;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    // The records, and the episodes re-run alone from them (episodes/, `batch --episode`), stay
    // unless the records go too.
    if (name != ".plantsim.lock" &&
        !(keep_records && (name == "episodes.jsonl" || name == "episodes")) &&
        is_batch_output_name(name) && !e.is_symlink(ec))
      old.push_back(e.path());
  }
  for (const fs::path& p : old) fs::remove_all(p, ec);
}

void check_batch_output_folder(const std::string& dir, const std::vector<std::string>& own) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status top = fs::symlink_status(dir, ec);
  if (fs::is_symlink(top))
    throw std::invalid_argument("output folder '" + dir +
                                "' is a symbolic link; name the folder itself");
  if (!fs::exists(top)) return;
  if (!fs::is_directory(top))
    throw std::invalid_argument("output folder '" + dir + "' is not a folder");
  bool has_records = false, has_other_outputs = false;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_symlink(ec))
      throw std::invalid_argument(
          "output folder '" + dir + "' holds the symbolic link '" + name +
          "'; plantsim neither follows nor replaces links in its output folders");
    if (!is_batch_output_name(name) && std::find(own.begin(), own.end(), name) == own.end() &&
        !junit_report(e))
      throw std::invalid_argument("output folder '" + dir + "' holds '" + name +
                                  "', not a batch output; choose a new or empty folder (a batch "
                                  "resumes only its own folder)");
    if (name == "episodes" && !e.is_directory(ec))
      throw std::invalid_argument("output folder '" + dir +
                                  "' holds 'episodes', not the folder of episodes re-run alone");
    (name == "episodes.jsonl" ? has_records : has_other_outputs) |= name != ".plantsim.lock";
  }
  if (has_other_outputs && !has_records)
    throw std::invalid_argument(
        "output folder '" + dir +
        "' holds report files but no episodes.jsonl: not a batch's folder "
        "(or one whose records were removed); choose a new or empty folder");
  if (const fs::path failures = fs::path(dir) / "failures";
      fs::exists(fs::symlink_status(failures, ec)))
    for (const fs::directory_entry& e : fs::directory_iterator(failures, ec))
      if (e.is_symlink(ec) || !e.is_regular_file(ec))
        throw std::invalid_argument("output folder '" + dir + "' holds " + e.path().string() +
                                    ", not a figure a batch wrote");
}

}  // namespace plantsim::batch
