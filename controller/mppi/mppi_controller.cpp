// MPPI behind the local controller interface, and its configuration rows.
#include "controller/mppi/mppi_controller.h"

#include <algorithm>
#include <cmath>

#include "controller/mppi/mppi_optimizer.h"
#include "controller/sampling_follow.h"

namespace plantsim::controller::mppi {

using util::kMaxParameter;

const util::ParamRows<MppiControllerParams>& mppi_param_rows() {
  static const util::ParamRows<MppiControllerParams> rows = {
      PLANTSIM_PARAM("mppi", optimizer.batch_size, "batch_size", 1, 100000),
      PLANTSIM_PARAM("mppi", optimizer.time_steps, "time_steps", 2, 1000),
      PLANTSIM_PARAM_ABOVE("mppi", optimizer.model_dt, "model_dt", 0.0, 10.0),
      PLANTSIM_PARAM("mppi", optimizer.iteration_count, "iteration_count", 1, 100),
      PLANTSIM_PARAM_ABOVE("mppi", optimizer.temperature, "temperature", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.gamma, "gamma", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.vx_std, "vx_std", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.wz_std, "wz_std", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.vx_max, "vx_max", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.vx_min, "vx_min", -kMaxParameter, 0.0),
      PLANTSIM_PARAM("mppi", optimizer.wz_max, "wz_max", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.ax_max, "ax_max", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.ax_min, "ax_min", -kMaxParameter, 0.0),
      PLANTSIM_PARAM("mppi", optimizer.az_max, "az_max", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", optimizer.prune_distance, "prune_distance", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.constraint_weight, "constraint_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.critical_weight, "critical_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.repulsion_weight, "repulsion_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.collision_cost, "collision_cost", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.collision_margin_distance, "collision_margin_distance", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.inflation_radius, "inflation_radius", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.obstacles_near_goal_distance, "obstacles_near_goal_distance",
                     0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.goal_weight, "goal_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.goal_threshold_to_consider, "goal_threshold_to_consider", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.goal_angle_weight, "goal_angle_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.goal_angle_threshold_to_consider,
                     "goal_angle_threshold_to_consider", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.path_align_weight, "path_align_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.path_align_trajectory_point_step,
                     "path_align_trajectory_point_step", 1, 1000),
      PLANTSIM_PARAM("mppi", critics.path_align_threshold_to_consider,
                     "path_align_threshold_to_consider", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.max_path_occupancy_ratio, "max_path_occupancy_ratio", 0.0,
                     1.0),
      PLANTSIM_PARAM("mppi", critics.path_follow_weight, "path_follow_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.path_follow_offset_from_furthest,
                     "path_follow_offset_from_furthest", 0, 1000),
      PLANTSIM_PARAM("mppi", critics.path_follow_threshold_to_consider,
                     "path_follow_threshold_to_consider", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.path_angle_weight, "path_angle_weight", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.path_angle_offset_from_furthest,
                     "path_angle_offset_from_furthest", 0, 1000),
      PLANTSIM_PARAM("mppi", critics.path_angle_threshold_to_consider,
                     "path_angle_threshold_to_consider", 0.0, kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.max_angle_to_furthest, "max_angle_to_furthest", 0.0, M_PI),
      PLANTSIM_PARAM("mppi", critics.prefer_forward_weight, "prefer_forward_weight", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("mppi", critics.prefer_forward_threshold_to_consider,
                     "prefer_forward_threshold_to_consider", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("mppi", goal_tolerance_m, "goal_tolerance_m", 0.0, kMaxParameter),
  };
  return rows;
}

namespace {

class MppiController : public SamplingController, public SketchesTrajectories {
 public:
  MppiController(const LocalControllerContext& ctx, MppiControllerParams p)
      : SamplingController(
            ctx, p.goal_tolerance_m,
            field_reach(ctx.footprint_radius_m,
                        std::max(p.critics.inflation_radius, p.critics.collision_margin_distance))),
        p_(bounded_by_motors(p, ctx)),
        optimizer_(p_.optimizer, p_.critics, ctx.seed) {}

 private:
  void set_method_path(const std::vector<geom::Vec2>& path) override { optimizer_.set_path(path); }

  Twist sample(const LocalQuery& q, const ClearanceGrid& field, const Pose2& goal) override {
    MppiQuery query;
    query.state = {static_cast<float>(q.pose.x), static_cast<float>(q.pose.y),
                   static_cast<float>(q.pose.yaw), static_cast<float>(q.speed_mps),
                   static_cast<float>(q.yaw_rate_radps)};
    query.goal = goal;
    query.clearance = &field;
    query.robot_radius_m = static_cast<float>(context().footprint_radius_m);
    return optimizer_.step(query);
  }

  TrajectorySketch last_trajectories(int max_sampled, int max_points) const override {
    TrajectorySketch sketch;
    for (const std::vector<geom::Pose2>& rollout : optimizer_.sampled_trajectories(max_sampled))
      sketch.sampled.push_back(sketch_points(rollout, max_points));
    sketch.chosen = sketch_points(optimizer_.optimal_trajectory(), max_points);
    return sketch;
  }

  /// No faster than the wheels turn: a forward speed the motors cannot reach would be sampled
  /// and scored as if it could.
  static MppiControllerParams bounded_by_motors(MppiControllerParams p,
                                                const LocalControllerContext& ctx) {
    p.optimizer.vx_max = std::min(p.optimizer.vx_max, ctx.max_wheel_speed_mps);
    p.optimizer.vx_min = std::max(p.optimizer.vx_min, -ctx.max_wheel_speed_mps);
    return p;
  }

  MppiControllerParams p_;
  MppiOptimizer optimizer_;
};

}  // namespace

LocalControllerEntry mppi_entry() {
  LocalControllerEntry e;
  e.name = "mppi";
  e.summary = "model predictive path integral control, Nav2's default controller and critics";
  e.params = util::specs_of(mppi_param_rows());
  e.capabilities = {"samples-trajectories", "reverses"};
  e.make = [](const LocalControllerContext& ctx, const util::ParamValues& v) {
    return std::make_unique<MppiController>(ctx, util::struct_of(mppi_param_rows(), v));
  };
  return e;
}

}  // namespace plantsim::controller::mppi
