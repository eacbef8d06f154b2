// Regular-file checks on the opened descriptor (not the path, which could change in between).
#include "util/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace plantsim::util {
namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_input_file(const std::string& path, std::uint64_t max_bytes) {
  // O_NONBLOCK: opening a FIFO with no writer must not wait for one.
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0)
    throw InputFileError("cannot be opened (" + std::string(std::strerror(errno)) + ")");
  struct stat info {};
  if (::fstat(file.fd, &info) != 0)
    throw InputFileError("cannot be read (" + std::string(std::strerror(errno)) + ")");
  if (!S_ISREG(info.st_mode))
    throw InputFileError(std::string("is ") + kind_of(info.st_mode) + ", expected a regular file");
  const auto size = static_cast<std::uint64_t>(info.st_size);
  if (size > max_bytes)
    throw InputFileError("is " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(max_bytes) + " allowed");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(file.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputFileError("cannot be read (" + std::string(std::strerror(errno)) + ")");
    if (n == 0) break;  // shrank while read: what is there
    got += static_cast<std::size_t>(n);
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace plantsim::util
