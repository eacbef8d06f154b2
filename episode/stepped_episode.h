// One episode an outside controller drives a control period at a time (the Python module's
// step-wise environment): each step hands it what the robot perceives and takes back the command
// for that period. plantsim's own travel runs beside it as the referee, as for a steered run
// (robot/travel_steered.h): it keeps the plan, hands over to docking at the staging pose, and
// judges docked or failed. Periods the outside does not steer (the gyro's calibration at rest
// first, and docking as `DockingSteps` says) run on by themselves between steps.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "controller/diff_drive.h"
#include "controller/docking.h"
#include "episode/episode_config.h"
#include "episode/episode_loop.h"
#include "episode/episode_result.h"
#include "planner/planner.h"
#include "robot/perception.h"
#include "worlds/world.h"

namespace plantsim::episode {

/// What the outside sees at one step: the robot's perception (never the truth) with plantsim's
/// plan, phase and own command, as a steered run's controller does. The perception is the
/// perceiver's own, unchanged until the next step (not copied: 8 environments a step).
struct OutsideView {
  const robot::Perception* perception = nullptr;
  std::vector<geom::Vec2> plan;
  controller::DockPhase phase = controller::DockPhase::kTravel;
  controller::Twist builtin;
  geom::Pose2 staging;
};

/// Who drives the docking manoeuvre, and how a step meets it.
enum class DockingSteps {
  kOutside,            ///< the outside steers it, a period a step
  kBuiltinEachPeriod,  ///< plantsim's manoeuvre drives, a period a step (the command ignored)
  kBuiltinToTheEnd,    ///< plantsim's manoeuvre drives to the end within the step that begins it
};

class SteppedEpisode {
 public:
  /// The episode of `plant` (its start included) with `config` (its seed included); plans with
  /// a fresh planner named `planner`.
  SteppedEpisode(std::shared_ptr<const worlds::World> plant, const std::string& planner,
                 episode::EpisodeConfig config, DockingSteps docking);
  ~SteppedEpisode();
  SteppedEpisode(const SteppedEpisode&) = delete;
  SteppedEpisode& operator=(const SteppedEpisode&) = delete;

  /// Runs to the first period the outside steers; false when the episode ended before it.
  bool start();
  /// The command for the period at hand (plantsim's own instead while its docking drives, see
  /// outside_steers()); runs to the next period the outside is asked for. False when the
  /// episode ended (view() then holds the perception and phase at the end).
  bool step(controller::Twist command);
  /// Whether the period at hand takes the outside's command (not while plantsim docks).
  bool outside_steers() const {
    return docking_ == DockingSteps::kOutside || view_.phase == controller::DockPhase::kTravel;
  }
  bool ended() const { return ended_; }
  /// Periods the outside has steered so far.
  std::int64_t steps() const { return steps_; }
  const OutsideView& view() const { return view_; }
  const episode::EpisodeResult& result() const { return run_->result(); }
  const worlds::World& plant() const { return *plant_; }
  const episode::EpisodeConfig& config() const { return config_; }
  double time_s() const { return run_->time_s(); }

 private:
  bool run_on();
  std::shared_ptr<const worlds::World> plant_;
  episode::EpisodeConfig config_;
  DockingSteps docking_;
  std::unique_ptr<planner::Planner> planner_;
  OutsideView view_;
  bool wanted_ = false, started_ = false, ended_ = false;
  std::int64_t steps_ = 0;
  std::unique_ptr<EpisodeRun> run_;
};

}  // namespace plantsim::episode
