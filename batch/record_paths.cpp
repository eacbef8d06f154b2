// Record paths relative to the records' folder (see the header).
#include "batch/record_paths.h"

#include <filesystem>
#include <nlohmann/json.hpp>

namespace plantsim::batch {

namespace fs = std::filesystem;

namespace {

fs::path absolute_of(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::absolute(path, ec);
  return (ec ? fs::path(path) : p).lexically_normal();
}

}  // namespace

std::string scenario_path_for_records(const std::string& scenario, const std::string& records_dir) {
  if (scenario.empty()) return scenario;
  const fs::path relative = absolute_of(scenario).lexically_relative(absolute_of(records_dir));
  return relative.empty() ? absolute_of(scenario).string() : relative.string();
}

std::string scenario_path_from_record(const std::string& value, const std::string& records_dir) {
  if (value.empty() || fs::path(value).is_absolute()) return value;
  return (absolute_of(records_dir) / value).lexically_normal().string();
}

std::string rebased_record(const std::string& line, const std::string& from_dir,
                           const std::string& to_dir) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(line);
  const auto it = j.find("scenario_file");
  if (it == j.end() || !it->is_string() || it->get<std::string>().empty()) return line;
  const std::string absolute = scenario_path_from_record(it->get<std::string>(), from_dir);
  *it = to_dir.empty() ? absolute : scenario_path_for_records(absolute, to_dir);
  return j.dump();
}

}  // namespace plantsim::batch
