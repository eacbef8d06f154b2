// One writer per output folder: an exclusive advisory lock (flock) on a lock file inside it,
// held for the lock's lifetime and released by the kernel if the process dies.
#pragma once

#include <string>

namespace plantsim::util {

class FolderLock {
 public:
  /// Throws std::invalid_argument when another process holds the folder ("another plantsim
  /// batch is writing to DIR").
  explicit FolderLock(const std::string& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace plantsim::util
