// Counting the builds of a batch's records (see the header).
#include "batch/record_builds.h"

#include <algorithm>
#include <map>

#include "util/build_stamp.h"

namespace plantsim::batch {

std::string this_build() {
  const util::BuildStamp& b = util::build_stamp();
  return b.version + " " + b.commit + (b.dirty ? "+dirty" : "");
}

std::string build_of(const nlohmann::json& record) {
  const auto it = record.find("build");
  return it != record.end() && it->is_string() ? it->get<std::string>() : "unrecorded";
}

std::vector<BuildCount> record_builds(const std::vector<std::string>& jsonl_lines) {
  std::map<std::string, std::int64_t> count;
  for (const std::string& line : jsonl_lines) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_object()) ++count[build_of(j)];
  }
  std::vector<BuildCount> out;
  for (const auto& [build, n] : count) out.push_back({build, n});
  std::stable_sort(out.begin(), out.end(), [](const BuildCount& a, const BuildCount& b) {
    return a.episodes > b.episodes;
  });
  return out;
}

std::string builds_text(const std::vector<BuildCount>& builds) {
  std::string s = "records of " + std::to_string(builds.size()) +
                  (builds.size() == 1 ? " build: " : " builds: ");
  for (std::size_t i = 0; i < builds.size(); ++i)
    s += (i ? ", " : "") + builds[i].build + " (" + std::to_string(builds[i].episodes) +
         (builds[i].episodes == 1 ? " episode)" : " episodes)");
  return s;
}

nlohmann::json builds_json(const std::vector<BuildCount>& builds) {
  nlohmann::json a = nlohmann::json::array();
  for (const BuildCount& b : builds) a.push_back({{"build", b.build}, {"episodes", b.episodes}});
  return a;
}

}  // namespace plantsim::batch
