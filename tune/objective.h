// What a tuning maximises, from one candidate's episodes (docs/tune.md#objectives): by default the
// Wilson 95 % lower bound of the success rate first and the mean time to dock second; or the time,
// the docking error or the contacts alone while the success stays at a floor.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace plantsim::tune {

enum class Objective { kSuccessThenTime, kTime, kDockingError, kContacts, kSuccess };

/// "success_then_time", "time", "docking_error", "contacts", "success"; parse throws
/// std::invalid_argument naming `where` and the choices.
std::string objective_name(Objective o);
Objective parse_objective(const std::string& text, const std::string& where);
/// One sentence a report prints: what is maximised.
std::string objective_description(Objective o);

/// The default objective's weight of time against success: a second of mean time to dock is
/// worth this much Wilson lower bound (10 s faster weighs as 0.001 more of the bound).
inline constexpr double kSecondsWeight = 1e-4;

/// What one candidate's episodes did.
struct EpisodeOutcome {
  std::string id;
  bool succeeded = false;
  double time_s = 0;
  double position_error_m = 0;  ///< of a docked episode
  int contacts = 0;
};

struct Statistics {
  std::int64_t episodes = 0, succeeded = 0, contacts = 0;
  double success_rate = 0, wilson_low = 0, wilson_high = 0;
  std::optional<double> mean_time_s;            ///< over the docked episodes; unset: none docked
  std::optional<double> mean_position_error_m;  ///< the same
};
Statistics statistics(const std::vector<EpisodeOutcome>& episodes);

/// The score to maximise. The constrained objectives (time, docking error, contacts) rank every
/// candidate whose Wilson low is below `floor` under every one that keeps it, the further below
/// the worse. `timeout_s` bounds the time of a candidate none of whose episodes docked.
struct Score {
  double value = 0;
  bool feasible = true;
};
Score score(Objective o, const Statistics& s, double floor, double timeout_s);

}  // namespace plantsim::tune
