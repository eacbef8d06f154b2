// evaluations.jsonl, a tuning's memory: one line per evaluation (its search, index, values,
// statistics, score and every episode's id and outcome), appended and flushed as it finishes.
// A killed tuning run again reads it back: the searches are deterministic, so they ask for the
// same candidates again and get the recorded answers without running an episode.
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tune/objective.h"
#include "tune/tune_spec.h"

namespace plantsim::tune {

struct Evaluation {
  std::string search;  ///< "default", "nlopt", "random", or "validation:<setting>"
  int index = 0;
  std::vector<double> values;  ///< in the parameters' order and units
  std::string problem;         ///< non-empty: the settings were refused (no episode ran)
  Statistics stats;
  Score score;
  double wall_s = 0;
  std::vector<EpisodeOutcome> outcomes;
};

/// The evaluations of tuning `fingerprint` an evaluations file holds, in its order. A line of
/// another tuning is refused (std::invalid_argument naming the file and both fingerprints); a
/// torn or malformed line is left out and counted in `cut`. A missing file holds none.
std::vector<Evaluation> read_evaluations(const std::string& path, const std::string& fingerprint,
                                         const std::vector<TunedParameter>& parameters,
                                         std::int64_t& cut, std::string* kept_text = nullptr);

/// The folder's evaluations file, locked by the caller.
class EvaluationLog {
 public:
  /// Reads the file's evaluations of this tuning (`fingerprint`); a line of another tuning is
  /// refused (std::invalid_argument: "--fresh to discard them"); a torn or malformed line is cut.
  EvaluationLog(const std::string& path, const std::string& fingerprint,
                const std::vector<TunedParameter>& parameters);
  ~EvaluationLog();
  EvaluationLog(const EvaluationLog&) = delete;
  EvaluationLog& operator=(const EvaluationLog&) = delete;

  /// The recorded evaluation `index` of `search` when it had these values.
  const Evaluation* find(const std::string& search, int index,
                         const std::vector<double>& values) const;
  /// Appends and flushes (throws std::runtime_error naming the file on a full disk).
  void append(const Evaluation& e);
  /// Appends another folder's evaluation of this tuning (a shard's) unless one with its search
  /// and index is recorded; returns whether it was added.
  bool adopt(const Evaluation& e);
  std::size_t recorded() const { return recorded_.size(); }
  std::size_t reused() const { return reused_; }

 private:
  std::string path_, fingerprint_;
  const std::vector<TunedParameter>& parameters_;
  std::map<std::pair<std::string, int>, Evaluation> recorded_;
  mutable std::size_t reused_ = 0;
  std::FILE* out_ = nullptr;
};

}  // namespace plantsim::tune
