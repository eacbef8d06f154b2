// The charts of a batch report: success rate with its Wilson 95 % interval per configuration,
// strip plots of the docking errors with their gates, the ECDF of driven length over the shortest
// possible and the time to dock per method, and success against a swept fault parameter with its
// band. They take plain outcomes, not the batch's record format: batch/ turns records into these.
#pragma once

#include <string>
#include <vector>

#include "render/figure.h"
#include "worlds/world.h"

namespace plantsim::render {

/// One configuration's count of successes.
struct RateRow {
  std::string label;
  long long successes = 0, episodes = 0;
  double low = 0, high = 1;  ///< Wilson 95 % interval of the success rate
  double gate = -1;          ///< the threshold it is judged against, if any
};

/// One episode, as the charts need it.
struct EpisodeOutcome {
  std::string method;  ///< planner / controller: the strip, ECDF line and time row it joins
  std::string world;   ///< the world it ran on (time to dock is compared within a world)
  bool docked = false;
  double position_error_m = 0;
  double heading_error_deg = 0;
  double driven_over_shortest = -1;  ///< driven length over the shortest possible (< 0: unknown)
  double time_s = 0;
  double localization_error_max_m = -1;  ///< worst true-vs-estimated position error (< 0: unknown)
  bool localization_ok = true;           ///< the estimator never reported worse than `ok`
  // Navigation metrics (docs/batch.md); < 0: not measured.
  double min_clearance_m = -1;       ///< the true footprint's smallest clearance on the travel
  double rms_jerk_mps3 = -1;         ///< RMS jerk of the true motion
  double controller_ms_median = -1;  ///< the local controller's median wall time per cycle
};

/// One episode's driven path (thinned) and whether it succeeded.
struct EpisodePath {
  std::vector<Vec2> points;
  bool succeeded = false;  ///< docked, or caught in a pursuit
};

struct DockingGates {
  double position_m = 0.02;
  double heading_deg = 2.0;
};

/// Horizontal bars of the success rate, whiskers for the interval, a tick at the gate.
Image draw_success_chart(const std::vector<RateRow>& rows, const std::string& title,
                         int width_px = 1400, FigureLayout* layout = nullptr);
/// Position and heading errors of docked episodes, one strip per method, gates as lines.
Image draw_error_strips(const std::vector<EpisodeOutcome>& episodes, const DockingGates& gates,
                        int width_px = 1400, FigureLayout* layout = nullptr);
/// Localisation per method: each episode's worst position error (docked or not) against the 10 cm
/// line `ok` must never stand beside, and how many episodes' estimator reported worse than `ok`.
Image draw_localization_chart(const std::vector<EpisodeOutcome>& episodes, int width_px = 1400,
                              FigureLayout* layout = nullptr);
/// ECDF of driven length over the shortest possible (docked episodes) and time to dock, per method.
Image draw_efficiency_chart(const std::vector<EpisodeOutcome>& episodes, int width_px = 1400,
                            FigureLayout* layout = nullptr);
/// Time to dock of docked episodes per world (worlds differ in size: each its own scale), one
/// strip per method within each world's panel, methods coloured as in the other charts.
Image draw_time_by_world(const std::vector<EpisodeOutcome>& episodes, int width_px = 1400,
                         FigureLayout* layout = nullptr);
/// Every episode's driven path over the world, those that succeeded thin in blue (named
/// `success_word`: "docked", or "caught" in a pursuit), failed ones on top in vermillion, with
/// their starts and the charger.
Image draw_episode_paths(const worlds::World& world, const std::vector<EpisodePath>& paths,
                         const std::string& title, const std::string& success_word = "docked",
                         int width_px = 1400, int height_px = 900, FigureLayout* layout = nullptr);
/// Success rate against the swept parameter's values (rows in increasing order), with the band.
Image draw_sweep_chart(const std::string& parameter, const std::vector<double>& values,
                       const std::vector<RateRow>& rows, int width_px = 1000,
                       FigureLayout* layout = nullptr);

}  // namespace plantsim::render
