// An episode driven a control period at a time (see the header).
#include "episode/stepped_episode.h"

#include <stdexcept>

#include "planner/registry.h"
#include "robot/travel_steered.h"

namespace plantsim::episode {

SteppedEpisode::SteppedEpisode(std::shared_ptr<const worlds::World> plant,
                               const std::string& planner, episode::EpisodeConfig config,
                               DockingSteps docking)
    : plant_(std::move(plant)),
      config_(std::move(config)),
      docking_(docking),
      planner_(planner::make_planner(planner, planner::planner_input(*plant_, true))) {
  // The outside's steering only notes what it is shown and asks the loop to pause: the command
  // comes with the next step.
  const robot::Steering note =
      [this](const robot::SteeringInput& in) -> std::optional<controller::Twist> {
    view_ = {&in.perception, in.plan, in.phase, in.builtin.twist, in.staging};
    wanted_ = true;
    return std::nullopt;
  };
  EpisodeSteering steering;
  steering.name = "step-wise";
  // Docking a period a step, plantsim's own: the loop pauses there too, and step() hands back
  // the manoeuvre's command (the same episode, bit for bit, as docking within one step).
  const bool pause_docking = docking != DockingSteps::kBuiltinToTheEnd;
  steering.wrap = [note, pause_docking](std::unique_ptr<robot::Travel> builtin,
                                        const worlds::World& map,
                                        const std::vector<geom::Vec2>& first_plan) {
    return robot::steered_by(std::move(builtin), map, first_plan, note,
                             pause_docking ? note : robot::Steering{});
  };
  run_ = std::make_unique<EpisodeRun>(*plant_, *planner_, config_, steering);
}

SteppedEpisode::~SteppedEpisode() = default;

bool SteppedEpisode::run_on() {
  const EpisodeRun::Stop stop = run_->advance({}, [this] {
    const bool wanted = wanted_;
    wanted_ = false;
    return wanted;
  });
  ended_ = stop != EpisodeRun::Stop::kAwaitingCommand;
  if (ended_) {  // what the robot perceived at the end, not at the last period it was steered
    if (const robot::Perception* last = run_->last_perception()) view_.perception = last;
    if (!run_->result().trajectory.empty()) view_.phase = run_->result().trajectory.back().phase;
  }
  return !ended_;
}

bool SteppedEpisode::start() {
  if (started_) throw std::logic_error("the episode has started");
  started_ = true;
  return run_on();
}

bool SteppedEpisode::step(controller::Twist command) {
  if (!started_ || ended_) throw std::logic_error("no period awaits a command");
  run_->command(outside_steers() ? command : view_.builtin);
  ++steps_;
  return run_on();
}

}  // namespace plantsim::episode
