// The tuning's steps in order; every input checked before the first episode.
#include "tune/run_tune.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>

#include "episode/robot_limits.h"
#include "tune/held_out.h"
#include "tune/part_runner.h"
#include "tune/search.h"
#include "tune/tune_report.h"
#include "util/fingerprint.h"
#include "util/fixed_text.h"
#include "util/folder_lock.h"
#include "util/made_by.h"

namespace plantsim::tune {

namespace {

namespace fs = std::filesystem;

bool tune_output(const std::string& name) {
  for (const std::string& n : tune_output_names())
    if (name == n || (name.rfind(n + ".tmp.", 0) == 0)) return true;
  return name == ".plantsim.lock";
}

/// The folder holds nothing but a tuning's outputs (never a link): a tuning resumes its own folder
/// and never replaces anyone's files.
void prepare_folder(const TuneOptions& o) {
  std::error_code ec;
  const fs::file_status top = fs::symlink_status(o.out_dir, ec);
  if (fs::is_symlink(top))
    throw std::invalid_argument("output folder '" + o.out_dir +
                                "' is a symbolic link; name the folder itself");
  if (fs::exists(top)) {
    if (!fs::is_directory(top))
      throw std::invalid_argument("output folder '" + o.out_dir + "' is not a folder");
    bool records = false, others = false;
    for (const fs::directory_entry& e : fs::directory_iterator(o.out_dir, ec)) {
      const std::string name = e.path().filename().string();
      if (e.is_symlink(ec) || !e.is_regular_file(ec) || !tune_output(name))
        throw std::invalid_argument("output folder '" + o.out_dir + "' holds '" + name +
                                    "', not a tuning's output; choose a new or empty folder");
      (name == "evaluations.jsonl" ? records : others) |= name != ".plantsim.lock";
    }
    if (others && !records)
      throw std::invalid_argument("output folder '" + o.out_dir +
                                  "' holds report files but no evaluations.jsonl: choose a new or "
                                  "empty folder");
  }
  fs::create_directories(o.out_dir, ec);
  if (ec || !fs::is_directory(o.out_dir))
    throw std::invalid_argument("output folder '" + o.out_dir + "' cannot be created");
}

void remove_outputs(const std::string& dir, bool keep_records) {
  std::error_code ec;
  std::vector<fs::path> old;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name != ".plantsim.lock" && !(keep_records && name == "evaluations.jsonl") &&
        tune_output(name))
      old.push_back(e.path());
  }
  for (const fs::path& p : old) fs::remove(p, ec);
}

std::string tune_fingerprint(const TuneSpec& spec, const PartRunner& tuning,
                             const PartRunner& validation) {
  util::Fingerprint f;
  f.add(tuning.fingerprint()).add(validation.fingerprint());
  for (const TunedParameter& p : spec.parameters) f.add(p.info.path).add(p.lo).add(p.hi);
  f.add(objective_name(spec.objective)).add(spec.min_wilson.value_or(-1.0));
  f.add(static_cast<std::uint64_t>(spec.budget)).add(method_name(spec.method)).add(spec.seed);
  return f.hex();
}

/// Settings equal to a billionth: the optimiser's start, scaled into the unit cube and back, is the
/// default it came from, though not to the last bit.
std::vector<double> memo_key(const std::vector<double>& values) {
  std::vector<double> key;
  for (double v : values) key.push_back(std::round(v * 1e9));
  return key;
}

/// Evaluations run once: recorded ones are read back, new ones appended as they finish.
class Evaluations {
 public:
  Evaluations(const TuneSpec& spec, EvaluationLog& log, const TuneOptions& options)
      : spec_(spec), log_(log), progress_(options.progress), interrupted_(options.interrupted) {}

  Evaluation evaluate(const PartRunner& part, const std::string& search, int index,
                      const std::vector<double>& values, std::optional<double> floor) {
    // The first evaluation (the default settings) sets the floor from its own success.
    auto floor_for = [&](const Statistics& s) {
      return floor ? *floor : spec_.min_wilson.value_or(s.wilson_low);
    };
    if (const Evaluation* known = log_.find(search, index, values)) {
      Evaluation e = *known;
      if (e.problem.empty())
        e.score = score(spec_.objective, e.stats, floor_for(e.stats), part.timeout_s());
      same_values_.try_emplace({&part, memo_key(values)}, e);
      return e;
    }
    Evaluation e;
    const auto seen = same_values_.find({&part, memo_key(values)});
    if (seen != same_values_.end()) {  // a search asked again for settings already judged
      e = seen->second;
      e.search = search, e.index = index, e.values = values, e.wall_s = 0;
      if (e.problem.empty())
        e.score = score(spec_.objective, e.stats, floor_for(e.stats), part.timeout_s());
      log_.append(e);
      return e;
    }
    e.search = search, e.index = index, e.values = values;
    const auto began = std::chrono::steady_clock::now();
    try {
      e.outcomes = part.run(overrides_json(spec_.parameters, values), interrupted_);
      e.stats = statistics(e.outcomes);
      e.score = score(spec_.objective, e.stats, floor_for(e.stats), part.timeout_s());
    } catch (const std::invalid_argument& refused) {
      e.problem = refused.what();  // settings that contradict each other: ranked last
      e.score = {-1e9, false};
    }
    e.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    log_.append(e);
    same_values_[{&part, memo_key(values)}] = e;
    ++ran_;
    if (progress_)
      std::fprintf(
          stderr, "tune: %s %d: score %.5f, %lld/%lld succeeded, mean time %s s%s (%.1f s)\n",
          search.c_str(), index + 1, e.score.value, static_cast<long long>(e.stats.succeeded),
          static_cast<long long>(e.stats.episodes),
          e.stats.mean_time_s ? util::fixed(*e.stats.mean_time_s, 1).c_str() : "-",
          e.problem.empty() ? "" : (" refused: " + e.problem).c_str(), e.wall_s);
    return e;
  }
  int ran() const { return ran_; }

 private:
  const TuneSpec& spec_;
  EvaluationLog& log_;
  bool progress_;
  std::function<bool()> interrupted_;
  int ran_ = 0;
  std::map<std::pair<const PartRunner*, std::vector<double>>, Evaluation> same_values_;
};

/// The best of one search's evaluations: the highest score, the first on a tie.
const Evaluation& best_of(const std::vector<Evaluation>& history, const std::string& search) {
  const Evaluation* best = nullptr;
  for (const Evaluation& e : history)
    if (e.search == search && (!best || e.score.value > best->score.value)) best = &e;
  if (!best) throw std::logic_error("a search without evaluations");
  return *best;
}

/// The shards' evaluations, every folder checked before the output folder is touched: a shard
/// folder must hold an evaluations.jsonl of this very tuning.
std::vector<Evaluation> read_shards(const TuneSpec& spec, const TuneOptions& o,
                                    const std::string& fingerprint) {
  std::vector<Evaluation> all;
  std::error_code ec;
  for (const std::string& dir : o.merge_dirs) {
    const fs::path file = fs::path(dir) / "evaluations.jsonl";
    if (!fs::is_directory(dir, ec))
      throw std::invalid_argument("--merge: '" + dir + "' is not a folder");
    if (fs::exists(o.out_dir, ec) && fs::equivalent(dir, o.out_dir, ec))
      throw std::invalid_argument("--merge: '" + dir + "' is the output folder itself");
    if (!fs::is_regular_file(fs::symlink_status(file, ec)))
      throw std::invalid_argument("--merge: '" + dir +
                                  "' holds no evaluations.jsonl (not a tuning shard's folder)");
    std::int64_t cut = 0;
    std::vector<Evaluation> some;
    try {
      some = read_evaluations(file.string(), fingerprint, spec.parameters, cut);
    } catch (const std::invalid_argument& other) {
      throw std::invalid_argument(std::string("--merge: ") + other.what());
    }
    if (cut > 0)
      std::fprintf(stderr, "tune: warning: left out %lld unfinished line(s) of %s\n",
                   static_cast<long long>(cut), file.c_str());
    for (Evaluation& e : some) all.push_back(std::move(e));
  }
  return all;
}

/// Random search's points a shard of n evaluates: every (n-1)th, shard 0 being NLopt's.
Evaluator share_of_random(const TuneOptions& o, const Evaluator& evaluate) {
  return [&o, evaluate](const char* search, int index, const std::vector<double>& values) {
    return index % (o.shard_count - 1) == o.shard_index - 1 ? evaluate(search, index, values) : 0.0;
  };
}

std::vector<double> default_values(const TuneSpec& spec) {
  std::vector<double> v;
  for (const TunedParameter& p : spec.parameters) v.push_back(p.info.default_value);
  return v;
}

}  // namespace

const std::vector<std::string>& tune_output_names() {
  static const std::vector<std::string> names = {
      "evaluations.jsonl", "best.json",       "summary.json",  "validation.csv",
      "report.html",       "convergence.png", "parameters.png"};
  return names;
}

/// No parameter tuned past what the robot's motors drive, on any world of the part.
void check_tuning_bounds(const TuneSpec& spec, const PartRunner& part) {
  for (const episode::EpisodeConfig& c : batch::episode_configs(part.spec()))
    for (const worlds::World& w : part.worlds().worlds)
      for (const TunedParameter& p : spec.parameters)
        episode::check_tuning_bound(w, c, p.info.path, p.hi);
}

TuneOutcome run_tune(const TuneSpec& spec, const TuneOptions& o) {
  const auto began = std::chrono::steady_clock::now();
  const PartRunner tuning(spec.tuning, spec.threads), validation(spec.validation, spec.threads);
  check_held_out(tuning.spec(), tuning.worlds(), validation.spec(), validation.worlds());
  check_tuning_bounds(spec, tuning);
  check_tuning_bounds(spec, validation);
  TuneOutcome out;
  out.tuning_episodes = static_cast<std::int64_t>(tuning.ids().size());
  out.validation_episodes = static_cast<std::int64_t>(validation.ids().size());
  out.fingerprint = tune_fingerprint(spec, tuning, validation);
  // The defaults must be a valid setting: its values are the search's start.
  const std::vector<double> defaults = default_values(spec);
  for (std::size_t i = 0; i < defaults.size(); ++i)
    if (defaults[i] < spec.parameters[i].lo || defaults[i] > spec.parameters[i].hi)
      std::fprintf(stderr,
                   "tune: note: %s's default %g lies outside its bounds; the search starts at the "
                   "nearer bound\n",
                   spec.parameters[i].info.path.c_str(), defaults[i]);
  const std::vector<Evaluation> merged = read_shards(spec, o, out.fingerprint);
  if (o.check_only) return out;

  prepare_folder(o);
  const util::FolderLock lock(o.out_dir);
  prepare_folder(o);  // again, now that no other plantsim writes there
  remove_outputs(o.out_dir, !o.fresh);
  EvaluationLog log(o.out_dir + "/evaluations.jsonl", out.fingerprint, spec.parameters);
  for (const Evaluation& e : merged) out.evaluations_merged += log.adopt(e) ? 1 : 0;
  Evaluations evaluations(spec, log, o);

  out.history.push_back(evaluations.evaluate(tuning, "default", 0, defaults, std::nullopt));
  out.floor = spec.min_wilson.value_or(out.history.back().stats.wilson_low);
  const Evaluator evaluate = [&](const char* search, int index, const std::vector<double>& values) {
    out.history.push_back(evaluations.evaluate(tuning, search, index, values, out.floor));
    return out.history.back().score.value;
  };
  if (o.shard_count > 1) {  // a shard: its part of the searches, the rest is the merge's
    if (o.shard_index == 0)
      nlopt_search(spec, defaults, evaluate);
    else
      random_search(spec, share_of_random(o, evaluate));
    out.evaluations_run = evaluations.ran();
    out.evaluations_reused = static_cast<int>(log.reused());
    return out;
  }
  nlopt_search(spec, defaults, evaluate);
  random_search(spec, evaluate);

  // Proven on the held-out episodes: the default, and each search's best.
  for (const char* name : {"default", "nlopt", "random"}) {
    Proven p;
    p.name = name;
    p.tuning = best_of(out.history, name);
    p.validation = evaluations.evaluate(validation, std::string("validation:") + name, 0,
                                        p.tuning.values, out.floor);
    out.proven.push_back(std::move(p));
  }
  // best.json: the best tuning score of either search (the optimiser's on a tie).
  out.best =
      out.proven[2].tuning.score.value > out.proven[1].tuning.score.value ? "random" : "nlopt";
  const Proven& best = out.proven[out.best == "nlopt" ? 1 : 2];
  out.best_against_default =
      compare_paired(out.proven[0].validation.outcomes, best.validation.outcomes);
  out.evaluations_run = evaluations.ran();
  out.evaluations_reused = static_cast<int>(log.reused());

  util::MadeBy made_by;
  made_by.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  made_by.input = "tuning";
  made_by.input_hash = out.fingerprint;
  write_tune_outputs(spec, out, o, made_by);
  return out;
}

}  // namespace plantsim::tune
