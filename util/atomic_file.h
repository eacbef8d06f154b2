// Writing output so that a reader never sees half of it: the bytes go to a temporary file
// beside the target, flushed to the disk (fsync), then renamed over it; a folder of outputs
// is written as a whole the same way (util::StagedFolder).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace plantsim::util {

/// Writes through a temporary file made in the target's folder with O_EXCL | O_NOFOLLOW (a
/// planted file or link of that name is never opened) and renamed over the target. The target
/// must be missing or a regular file: a link, a device, a FIFO or a folder is refused with
/// std::invalid_argument, never replaced or followed. Throws std::runtime_error naming the path
/// and the system's reason ("No space left on device").
void write_file_atomically(const std::string& path, std::string_view bytes);

/// What an output file may replace: an earlier output of its own kind, told by its content
/// (`is_own` reads the existing file; it must not throw). Anything else at the path (the
/// scenario, a world, a run's summary.json given by mistake) is the user's and is kept.
struct OutputKind {
  std::string what;  ///< "a JUnit report", for the message
  std::function<bool(const std::string& existing_path)> is_own;
};

/// Checks, before any work, that write_file_atomically(path, ...) can succeed as far as can be
/// known: the folder exists and is writable, the target is missing or a regular file that
/// `kind` recognises as an earlier output of its own. Throws std::invalid_argument naming
/// `option` (e.g. "--junit") and the problem.
void check_output_file(const std::string& path, const std::string& option, const OutputKind& kind);

/// The first `bytes` of a regular file (empty when it cannot be read), for OutputKind tests.
std::string file_head(const std::string& path, std::size_t bytes = 4096);

/// Flushes a file or folder to the disk; throws std::runtime_error naming it and the reason.
void sync_path(const std::string& path);

/// "<what>: <strerror(errno)>", for messages about failed system calls.
std::string system_error_text(const std::string& what);

/// A folder of outputs built beside its destination and moved into place as a whole: a rerun
/// never leaves old and new files mixed, and a failed run leaves the old folder untouched.
class StagedFolder {
 public:
  /// Creates "<destination>.partial-<pid>" next to the destination (parents created). An
  /// existing destination is replaced on commit only if it is empty or holds nothing but
  /// entries named in `replaceable` (an earlier run's outputs: regular files by name, and a
  /// sub-folder as "folder/pattern", accepted only when every file in it matches the pattern
  /// and is a regular file); a folder holding anything else
  /// (a user's own files, `--out .`) is refused here, before any work, with
  /// std::invalid_argument naming what is in the way.
  StagedFolder(std::string destination, const std::vector<std::string>& replaceable);
  ~StagedFolder();  ///< removes the staging folder unless committed
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::string& path() const { return staging_; }  ///< write here
  const std::string& destination() const { return destination_; }
  /// Syncs and moves the staging folder to the destination (replacing an older one).
  void commit();

 private:
  std::string destination_, staging_;
  bool committed_ = false;
};

}  // namespace plantsim::util
