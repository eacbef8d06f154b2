// The shared data folder and paths written in files.
#include "util/data_dir.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace plantsim::util {
namespace {

namespace fs = std::filesystem;

std::string& chosen() {
  static std::string dir;
  return dir;
}

constexpr const char* kDataPrefix = "$data/";

}  // namespace

void set_data_dir(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::invalid_argument("--data: '" + dir + "' is not a folder");
  chosen() = dir;
}

const std::string& chosen_data_dir() { return chosen(); }

std::string data_dir() {
  if (!chosen().empty()) return chosen();
  if (const char* env = std::getenv("PLANTSIM_DATA"); env && *env) return env;
  std::error_code ec;
  // <checkout>/build/plantsim (or build/tests/...) -> the nearest ancestor's shared/data, that
  // is <checkout>/../shared/data.
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (fs::path up = exe.parent_path(); !up.empty() && up != up.root_path();
         up = up.parent_path()) {
      const fs::path beside = up / "shared" / "data";
      if (fs::is_directory(beside, ec)) return beside.string();
    }
  }
  return "../shared/data";
}

std::string checkout_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  for (fs::path up = exe.parent_path(); !up.empty() && up != up.root_path(); up = up.parent_path())
    if (fs::is_directory(up / "data" / "worlds" / "plants", ec)) return up.string();
  return "";
}

std::string resolve_input_path(const std::string& written, const std::string& base) {
  if (written.rfind(kDataPrefix, 0) == 0)
    return (fs::path(data_dir()) / written.substr(6)).string();
  const fs::path p(written);
  if (p.is_absolute() || base.empty()) return written;
  return (fs::path(base) / p).lexically_normal().string();
}

}  // namespace plantsim::util
