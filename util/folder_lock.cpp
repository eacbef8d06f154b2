// flock-based folder lock.
#include "util/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

#include "util/atomic_file.h"

namespace plantsim::util {

FolderLock::FolderLock(const std::string& folder) {
  const std::string path = folder + "/.plantsim.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::invalid_argument(
        system_error_text("output folder '" + folder + "' is not writable"));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = errno == EWOULDBLOCK;
    const std::string text = busy ? "another plantsim process is writing to '" + folder +
                                        "' (it holds " + path +
                                        "); wait for it or choose another --out"
                                  : system_error_text("cannot lock " + path);
    ::close(fd_);
    throw std::invalid_argument(text);
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace plantsim::util
