// The objectives' scores and the statistics they are computed from.
#include "tune/objective.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "batch/wilson_interval.h"

namespace plantsim::tune {

namespace {

struct Named {
  Objective objective;
  const char* name;
  const char* description;
};

constexpr Named kObjectives[] = {
    {Objective::kSuccessThenTime, "success_then_time",
     "the Wilson 95 % lower bound of the success rate, minus 0.0001 per second of mean time to "
     "dock (10 s faster weighs as much as 0.001 more of the bound)"},
    {Objective::kTime, "time",
     "the mean time to dock, shortest first, among settings whose success keeps the floor"},
    {Objective::kDockingError, "docking_error",
     "the mean docking position error, smallest first, among settings whose success keeps the "
     "floor"},
    {Objective::kContacts, "contacts",
     "the contacts per episode, fewest first, among settings whose success keeps the floor"},
    {Objective::kSuccess, "success", "the Wilson 95 % lower bound of the success rate"},
};

const Named& named(Objective o) {
  for (const Named& n : kObjectives)
    if (n.objective == o) return n;
  throw std::logic_error("objective without a name");
}

}  // namespace

std::string objective_name(Objective o) { return named(o).name; }
std::string objective_description(Objective o) { return named(o).description; }

Objective parse_objective(const std::string& text, const std::string& where) {
  std::string choices;
  for (const Named& n : kObjectives) {
    if (text == n.name) return n.objective;
    choices += std::string(choices.empty() ? "" : ", ") + n.name;
  }
  throw std::invalid_argument(where + ": unknown objective '" + text + "' (expected one of " +
                              choices + ")");
}

Statistics statistics(const std::vector<EpisodeOutcome>& episodes) {
  Statistics s;
  double time = 0, error = 0;
  for (const EpisodeOutcome& e : episodes) {
    ++s.episodes;
    s.contacts += e.contacts;
    if (!e.succeeded) continue;
    ++s.succeeded;
    time += e.time_s;
    error += e.position_error_m;
  }
  if (s.episodes > 0) s.success_rate = static_cast<double>(s.succeeded) / s.episodes;
  std::tie(s.wilson_low, s.wilson_high) = batch::wilson_interval(s.succeeded, s.episodes);
  if (s.succeeded > 0) {
    s.mean_time_s = time / s.succeeded;
    s.mean_position_error_m = error / s.succeeded;
  }
  return s;
}

Score score(Objective o, const Statistics& s, double floor, double timeout_s) {
  const double time = s.mean_time_s.value_or(timeout_s);
  if (o == Objective::kSuccessThenTime) return {s.wilson_low - kSecondsWeight * time, true};
  if (o == Objective::kSuccess) return {s.wilson_low, true};
  // The constrained objectives: what is minimised, and a bound above every value it can take, so
  // that a candidate below the floor ranks under every one that keeps it.
  double cost = 0, bound = 0;
  if (o == Objective::kTime) {
    cost = time, bound = timeout_s;
  } else if (o == Objective::kDockingError) {
    cost = s.mean_position_error_m.value_or(1.0), bound = 1.0;
  } else {
    cost = s.episodes ? static_cast<double>(s.contacts) / s.episodes : 0.0;
    bound = std::max(cost, 1000.0);
  }
  const double shortfall = floor - s.wilson_low;
  if (shortfall > 1e-12) return {-bound - 1.0 - 100.0 * shortfall, false};
  return {-cost, true};
}

}  // namespace plantsim::tune
