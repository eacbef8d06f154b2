// Temporary-file-then-rename writes, with every system call checked.
#include "util/atomic_file.h"

#include <fcntl.h>
#include <fnmatch.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace plantsim::util {
namespace {

namespace fs = std::filesystem;

std::string parent_or_dot(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

/// `path` with `suffix` appended to its last name, that name cut first (never inside a UTF-8
/// character) so the whole stays within the system's 255-byte limit on one name: a legal
/// 250-byte `--out` name was refused because its "<name>.partial-<pid>" was not.
std::string sibling_name(const std::string& path, const std::string& suffix) {
  constexpr std::size_t kNameMax = 255;
  const fs::path p(path);
  std::string base = p.filename().string();
  const std::size_t room = kNameMax > suffix.size() ? kNameMax - suffix.size() : 0;
  if (base.size() > room) {
    base.resize(room);
    while (!base.empty() && (static_cast<unsigned char>(base.back()) & 0xC0) == 0x80)
      base.pop_back();  // a continuation byte: drop the partial character with its lead byte
    if (!base.empty() && (static_cast<unsigned char>(base.back()) & 0x80) != 0) base.pop_back();
  }
  return (p.parent_path() / (base + suffix)).string();
}

}  // namespace

std::string system_error_text(const std::string& what) {
  return what + ": " + std::strerror(errno);
}

void sync_path(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(system_error_text("cannot open " + path + " to sync it"));
  // Some file systems do not sync folders (EINVAL): the rename is then as durable as they allow.
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL || errno == EROFS;
  const int saved = errno;
  ::close(fd);
  errno = saved;
  if (!ok) throw std::runtime_error(system_error_text("cannot sync " + path));
}

namespace {

/// What stands at `path` when it is not a regular file (empty when missing or regular).
std::string not_a_regular_file(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return "";
  if (S_ISREG(st.st_mode)) return "";
  if (S_ISLNK(st.st_mode)) return "a symbolic link";
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  return "not a regular file";
}

/// A new temporary file beside `path`, created exclusively (never an existing file or link).
std::pair<int, std::string> exclusive_temporary(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  // A file name near the system's 255-byte limit leaves no room for the suffix (a 254-byte
  // --junit name failed after the whole batch): sibling_name cuts the name to fit.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string tmp =
        sibling_name(path, ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0) return {fd, tmp};
    if (errno != EEXIST)
      throw std::runtime_error(
          system_error_text("cannot write " + path + " (creating " + tmp + ")"));
  }
  throw std::runtime_error("cannot write " + path + ": 100 temporary names beside it are taken");
}

}  // namespace

std::string file_head(const std::string& path, std::size_t bytes) {
  if (!not_a_regular_file(path).empty()) return "";
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return head;
}

void check_output_file(const std::string& path, const std::string& option, const OutputKind& kind) {
  const std::string what = not_a_regular_file(path);
  if (!what.empty())
    throw std::invalid_argument(option + " " + path + " is " + what +
                                "; plantsim writes only new or regular files");
  std::error_code exists_ec;
  if (fs::exists(fs::symlink_status(path, exists_ec)) && !kind.is_own(path))
    throw std::invalid_argument(option + " " + path + " exists and is not " + kind.what +
                                " plantsim wrote; it would be replaced: name a new file (or "
                                "remove this one yourself)");
  const std::string folder = parent_or_dot(path);
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw std::invalid_argument(option + " " + path + ": the folder " + folder + " does not exist");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw std::invalid_argument(
        system_error_text(option + " " + path + ": cannot write into " + folder));
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  if (const std::string what = not_a_regular_file(path); !what.empty())
    throw std::invalid_argument("will not replace " + path + ": it is " + what +
                                " (plantsim writes only new or regular files)");
  // Plain names, not a structured binding: clang 14 cannot capture one in the lambda below.
  const std::pair<int, std::string> temporary = exclusive_temporary(path);
  const int fd = temporary.first;
  const std::string& tmp = temporary.second;
  auto fail = [&](const std::string& step) {
    const std::string text = system_error_text("cannot write " + path + " (" + step + ")");
    ::close(fd);
    ::unlink(tmp.c_str());
    throw std::runtime_error(text);
  };
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write");
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("fsync");
  if (::close(fd) != 0) {
    const std::string text = system_error_text("cannot write " + path + " (close)");
    ::unlink(tmp.c_str());
    throw std::runtime_error(text);
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string text = system_error_text("cannot write " + path + " (rename)");
    ::unlink(tmp.c_str());
    throw std::runtime_error(text);
  }
  sync_path(parent_or_dot(path));
}

namespace {

/// "" when the entry is one an earlier run wrote: a file named in `replaceable`, or a folder
/// named by a "folder/pattern" entry holding only files that match the pattern (fnmatch). Else
/// the entry in the way, as the message names it: a user's frames/ folder is never deleted.
std::string not_replaceable(const fs::directory_entry& entry,
                            const std::vector<std::string>& replaceable) {
  std::error_code ec;
  const std::string name = entry.path().filename().string();
  if (entry.is_symlink(ec)) return name;
  for (const std::string& r : replaceable) {
    const std::size_t slash = r.find('/');
    if (slash == std::string::npos) {
      if (r == name && entry.is_regular_file(ec)) return "";
      continue;
    }
    if (r.compare(0, slash, name) != 0 || slash != name.size() || !entry.is_directory(ec)) continue;
    const std::string pattern = r.substr(slash + 1);
    for (const auto& inner : fs::directory_iterator(entry.path(), ec)) {
      const std::string inner_name = inner.path().filename().string();
      if (inner.is_symlink(ec) || !inner.is_regular_file(ec) ||
          ::fnmatch(pattern.c_str(), inner_name.c_str(), FNM_PATHNAME | FNM_PERIOD) != 0)
        return name + "/" + inner_name;
    }
    return "";
  }
  return name;
}

}  // namespace

StagedFolder::StagedFolder(std::string destination, const std::vector<std::string>& replaceable)
    : destination_(std::move(destination)) {
  std::error_code ec;
  // "out/", "out/." and "./out" name the same folder; "." or ".." would replace the current one.
  destination_ = fs::path(destination_).lexically_normal().string();
  while (destination_.size() > 1 && destination_.back() == '/') destination_.pop_back();
  if (destination_ == "." || destination_ == ".." || destination_.empty() ||
      fs::path(destination_).filename() == "..")
    throw std::invalid_argument("output folder '" + destination_ +
                                "': name a folder of its own (it is replaced as a whole)");
  // A link is never followed or replaced: a dangling one ran the whole episode, then failed to
  // move the folder over it (exit 1); one to a folder would write into the user's elsewhere.
  if (fs::is_symlink(fs::symlink_status(destination_, ec)))
    throw std::invalid_argument("output folder '" + destination_ +
                                "' is a symbolic link; name a folder, not a link");
  if (fs::exists(destination_, ec)) {
    if (!fs::is_directory(destination_, ec))
      throw std::invalid_argument("output folder '" + destination_ + "' is a file");
    for (const auto& entry : fs::directory_iterator(destination_, ec)) {
      const std::string name = entry.path().filename().string();
      const std::string problem = not_replaceable(entry, replaceable);
      if (!problem.empty())
        throw std::invalid_argument("output folder '" + destination_ + "' holds '" + problem +
                                    "', not a plantsim output; it is replaced as a whole, so "
                                    "choose a new or empty folder");
    }
  }
  staging_ = sibling_name(destination_, ".partial-" + std::to_string(::getpid()));
  fs::remove_all(staging_, ec);
  fs::create_directories(staging_, ec);
  if (ec || !fs::is_directory(staging_))
    throw std::invalid_argument("cannot create output folder '" + staging_ + "'" +
                                (ec ? ": " + ec.message() : ""));
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void StagedFolder::commit() {
  for (const auto& entry : fs::recursive_directory_iterator(staging_))
    if (entry.is_regular_file()) sync_path(entry.path().string());
  sync_path(staging_);
  std::error_code ec;
  // A folder cannot be renamed over a non-empty one: the old one steps aside first, and is
  // removed only once the new one is in place.
  std::string aside;
  if (fs::exists(destination_, ec)) {
    aside = sibling_name(destination_, ".old-" + std::to_string(::getpid()));
    fs::remove_all(aside, ec);
    if (::rename(destination_.c_str(), aside.c_str()) != 0)
      throw std::runtime_error(system_error_text("cannot replace " + destination_));
  }
  if (::rename(staging_.c_str(), destination_.c_str()) != 0) {
    const std::string text = system_error_text("cannot move " + staging_ + " to " + destination_);
    if (!aside.empty()) ::rename(aside.c_str(), destination_.c_str());
    throw std::runtime_error(text);
  }
  committed_ = true;
  if (!aside.empty()) fs::remove_all(aside, ec);
  sync_path(parent_or_dot(destination_));
}

}  // namespace plantsim::util
