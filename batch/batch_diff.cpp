// plantsim diff's comparison (see the header): each folder's records read and checked, paired
// by id, and judged configuration by configuration.
#include "batch/batch_diff.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "batch/batch_gate.h"
#include "batch/episode_record.h"
#include "batch/episode_records.h"
#include "batch/record_paths.h"
#include "util/fingerprint.h"
#include "util/fixed_text.h"
#include "util/input_file.h"
#include "worlds/json_input.h"

namespace plantsim::batch {
namespace {

using nlohmann::json;
using util::fixed;
using Configuration = std::tuple<std::string, std::string, std::string, std::string>;

constexpr std::size_t kIdsListed = 20;  ///< episodes of one side only, named in the outputs

struct SideRecord {
  Configuration configuration;
  std::uint64_t seed = 0;
  DiffSide side;
  std::uint64_t result_hash = 0;
};

struct FolderRecords {
  DiffFolder info;
  std::map<std::string, SideRecord> by_id;
};

/// The same episode written twice differs in its index, scenario file and build at most (a
/// merge's rule, batch_merge.cpp); anything else is a different result.
std::uint64_t result_hash(json record) {
  record.erase("index"), record.erase("scenario_file"), record.erase("build");
  return util::Fingerprint().add(record.dump()).value();
}

DiffSide side_of(const json& j) {
  DiffSide s;
  s.succeeded = record_succeeded(j);
  s.status = j.value("status", std::string());
  if (!s.succeeded) {
    const auto failure = j.find("failure");
    s.reason = failure != j.end() && failure->is_string() ? failure->get<std::string>() : s.status;
    s.detail = j.value("failure_detail", std::string());
  }
  s.time_s = j["time_s"].get<double>();
  s.position_error_m = j["position_error_m"].get<double>();
  s.error_measured = j.value("error_measured", true);
  s.scenario_file = j.value("scenario_file", std::string());
  return s;
}

void add_record(FolderRecords& f, std::set<std::string>& scenarios, const std::string& path,
                std::string&& line) {
  const json j = json::parse(line);
  const std::string id = j["id"].get<std::string>();
  const std::string scenario = j["scenario"].get<std::string>();
  if (j.contains("key") && j["key"].get<std::string>() != episode_key(scenario, id))
    throw std::invalid_argument(path + ": episode '" + id +
                                "' has a key that does not match its scenario and id: a record "
                                "edited, or of another run; diff only what batches wrote");
  scenarios.insert(scenario);
  SideRecord r;
  r.configuration = {j["world"].get<std::string>(), j["planner"].get<std::string>(),
                     j["controller"].get<std::string>(), j["fault"].get<std::string>()};
  r.seed = j["seed"].get<std::uint64_t>();
  r.side = side_of(j);
  r.side.scenario_file = scenario_path_from_record(r.side.scenario_file, f.info.folder);
  r.result_hash = result_hash(j);
  const auto [at, fresh] = f.by_id.try_emplace(id, std::move(r));
  if (!fresh && at->second.result_hash != result_hash(j))
    throw std::invalid_argument(path + ": episode '" + id +
                                "' appears twice with different results; a batch keeps each "
                                "episode once (a folder of two runs' records?)");
  f.info.records += fresh;
}

nlohmann::ordered_json made_by_of(const std::string& dir) {
  const std::string path = dir + "/summary.json";
  try {
    const json j = worlds::parse_json_input(util::read_input_file(path, 64u << 20), path);
    if (j.contains("made_by") && j["made_by"].is_object())
      return nlohmann::ordered_json::parse(j["made_by"].dump());
  } catch (const std::exception&) {  // no summary (a batch still running): said as unknown
  }
  return nullptr;
}

FolderRecords read_folder(const std::string& dir, const std::string& role) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir, ec)))
    throw std::invalid_argument(role + " folder '" + dir + "' does not exist");
  if (!fs::is_directory(dir, ec))
    throw std::invalid_argument(role + " '" + dir +
                                "' is not a folder: name a batch's output folder");
  const std::string path = (fs::path(dir) / "episodes.jsonl").string();
  if (!fs::exists(fs::symlink_status(path, ec)))
    throw std::invalid_argument(path + ": missing; " + role + " '" + dir +
                                "' is not a batch folder (plantsim batch SCENARIO --out DIR "
                                "writes its episodes.jsonl)");
  FolderRecords f;
  f.info.folder = dir;
  std::set<std::string> scenarios;
  const JsonlScan scan = scan_jsonl(
      path, [&](std::string&& line) { add_record(f, scenarios, path, std::move(line)); });
  if (scan.bad_lines > 0)
    throw std::invalid_argument(path + ": " + std::to_string(scan.bad_lines) +
                                " line(s) are not records a batch writes (" + scan.first_problem +
                                "); a diff judges whole records only");
  if (scan.torn_tail)
    throw std::invalid_argument(path +
                                ": its last line is cut short (a batch killed while "
                                "writing): run the batch again to finish it first");
  if (f.by_id.empty()) throw std::invalid_argument(path + ": holds no records");
  f.info.scenarios.assign(scenarios.begin(), scenarios.end());
  f.info.made_by = made_by_of(dir);
  return f;
}

double mean_of(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return v.empty() ? 0 : sum / static_cast<double>(v.size());
}

/// The rule for time and error: worse when the whole interval lies above zero and the mean
/// change exceeds the margin; better, the mirror image.
MetricDiff judge_metric(const std::vector<double>& differences,
                        const std::vector<double>& baseline_values, double margin, double level) {
  MetricDiff m;
  m.difference = paired_difference(differences, level);
  m.baseline_mean = mean_of(baseline_values);
  m.margin = margin;
  if (const auto& ci = m.difference.interval) {
    if (ci->first > 0 && m.difference.mean > margin) m.verdict = DiffVerdict::kWorse;
    if (ci->second < 0 && m.difference.mean < -margin) m.verdict = DiffVerdict::kBetter;
  }
  return m;
}

std::string metric_finding(const MetricDiff& m, const std::string& what, double scale,
                           const std::string& unit, double level) {
  const auto& ci = *m.difference.interval;
  const bool rose = m.verdict == DiffVerdict::kWorse;
  return what + (rose ? " rose" : " fell") + " by " +
         fixed(std::abs(m.difference.mean) * scale, 1) + " " + unit + " on average (" +
         fixed(100 * (1 - level), 0) + " % interval " + fixed(ci.first * scale, 1) + " to " +
         fixed(ci.second * scale, 1) + " " + unit + ", " + std::to_string(m.difference.pairs) +
         " episodes both succeeded in), beyond the margin of " + fixed(m.margin * scale, 1) + " " +
         unit;
}

void judge(ConfigurationDiff& c, const std::vector<double>& time_d,
           const std::vector<double>& time_base, const std::vector<double>& error_d,
           const std::vector<double>& error_base, double level) {
  c.mcnemar_p = mcnemar_exact_p(c.lost, c.gained);
  if (c.mcnemar_p < level)
    c.success = c.lost > c.gained ? DiffVerdict::kWorse : DiffVerdict::kBetter;
  if (c.success != DiffVerdict::kNoChange)
    c.why.push_back(std::string("success ") + (c.success == DiffVerdict::kWorse ? "fell" : "rose") +
                    ": " + std::to_string(c.lost) + " lost, " + std::to_string(c.gained) +
                    " gained of " + std::to_string(c.pairs) + " episodes, McNemar exact p = " +
                    fixed(c.mcnemar_p, 4) + " < " + fixed(level, 3));
  c.time = judge_metric(time_d, time_base, kDiffTimeMargin * mean_of(time_base), level);
  if (c.time.verdict != DiffVerdict::kNoChange)
    c.why.push_back(metric_finding(c.time, "time", 1, "s", level));
  c.error = judge_metric(error_d, error_base, kDiffErrorMarginM, level);
  if (c.error.verdict != DiffVerdict::kNoChange)
    c.why.push_back(metric_finding(c.error, "position error", 1000, "mm", level));
  for (DiffVerdict v : {c.success, c.time.verdict, c.error.verdict})
    if (v == DiffVerdict::kWorse ||
        (v == DiffVerdict::kBetter && c.verdict == DiffVerdict::kNoChange))
      c.verdict = v;
}

}  // namespace

const char* diff_verdict_name(DiffVerdict v) {
  switch (v) {
    case DiffVerdict::kWorse:
      return "worse";
    case DiffVerdict::kBetter:
      return "better";
    case DiffVerdict::kNoChange:
      break;
  }
  return "no detectable change";
}

BatchDiff diff_batches(const std::string& baseline_dir, const std::string& candidate_dir,
                       double level) {
  if (!(level > 0 && level < 1))
    throw std::invalid_argument("--level must lie between 0 and 1, got " + fixed(level, 4));
  FolderRecords base = read_folder(baseline_dir, "baseline");
  FolderRecords cand = read_folder(candidate_dir, "candidate");
  BatchDiff d;
  d.level = level;
  struct Samples {
    ConfigurationDiff c;
    std::vector<double> time_d, time_base, error_d, error_base;
  };
  std::map<Configuration, Samples> by_configuration;
  util::Fingerprint inputs;
  for (const auto& [id, b] : base.by_id) {
    const auto it = cand.by_id.find(id);
    if (it == cand.by_id.end()) {
      if (d.only_baseline++ < static_cast<std::int64_t>(kIdsListed))
        d.only_baseline_ids.push_back(id);
      continue;
    }
    const SideRecord& c = it->second;
    inputs.add(id).add(b.result_hash).add(c.result_hash);
    Samples& s = by_configuration[b.configuration];
    std::tie(s.c.world, s.c.planner, s.c.controller, s.c.fault) = b.configuration;
    ++d.paired, ++s.c.pairs;
    s.c.baseline_succeeded += b.side.succeeded;
    s.c.candidate_succeeded += c.side.succeeded;
    if (b.side.succeeded != c.side.succeeded) {
      ++(c.side.succeeded ? s.c.gained : s.c.lost);
      ++(c.side.succeeded ? d.gained : d.lost);
      d.changed.push_back({id, s.c.name(), b.seed, c.side.succeeded, b.side, c.side});
    } else if (b.side.succeeded) {
      s.time_d.push_back(c.side.time_s - b.side.time_s);
      s.time_base.push_back(b.side.time_s);
      if (b.side.error_measured && c.side.error_measured) {
        s.error_d.push_back(c.side.position_error_m - b.side.position_error_m);
        s.error_base.push_back(b.side.position_error_m);
      }
    }
  }
  for (const auto& [id, c] : cand.by_id)
    if (!base.by_id.count(id) && d.only_candidate++ < static_cast<std::int64_t>(kIdsListed))
      d.only_candidate_ids.push_back(id);
  if (d.paired == 0)
    throw std::invalid_argument(
        "no episode is in both folders: " + baseline_dir + " and " + candidate_dir +
        " share no episode id (a diff compares the same episodes: one scenario run twice, or "
        "scenarios with the same worlds, planners, controllers, faults and seeds)");
  for (auto& [key, s] : by_configuration) {
    judge(s.c, s.time_d, s.time_base, s.error_d, s.error_base, level);
    if (s.c.verdict == DiffVerdict::kWorse ||
        (s.c.verdict == DiffVerdict::kBetter && d.verdict == DiffVerdict::kNoChange))
      d.verdict = s.c.verdict;
    d.configurations.push_back(std::move(s.c));
  }
  // By configuration (the map's order), then by seed as a number.
  std::map<std::string, std::size_t> place;
  for (std::size_t i = 0; i < d.configurations.size(); ++i) place[d.configurations[i].name()] = i;
  std::sort(d.changed.begin(), d.changed.end(),
            [&](const ChangedEpisode& a, const ChangedEpisode& b) {
              return std::make_pair(place.at(a.configuration), a.seed) <
                     std::make_pair(place.at(b.configuration), b.seed);
            });
  d.pooled_mcnemar_p = mcnemar_exact_p(d.lost, d.gained);
  d.baseline = std::move(base.info);
  d.candidate = std::move(cand.info);
  d.input_hash = inputs.hex();
  return d;
}

}  // namespace plantsim::batch
