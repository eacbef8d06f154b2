// DWB behind the local controller interface, and its configuration rows.
#include "controller/dwb/dwb_controller.h"

#include <algorithm>

#include "controller/dwb/dwb_planner.h"
#include "controller/sampling_follow.h"

namespace plantsim::controller::dwb {

using util::kMaxParameter;

const util::ParamRows<DwbControllerParams>& dwb_param_rows() {
  static const util::ParamRows<DwbControllerParams> rows = {
      PLANTSIM_PARAM("dwb", planner.min_vel_x, "min_vel_x", -kMaxParameter, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.max_vel_x, "max_vel_x", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.max_vel_theta, "max_vel_theta", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.min_speed_theta, "min_speed_theta", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.acc_lim_x, "acc_lim_x", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.decel_lim_x, "decel_lim_x", -kMaxParameter, 0.0),
      PLANTSIM_PARAM("dwb", planner.acc_lim_theta, "acc_lim_theta", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.decel_lim_theta, "decel_lim_theta", -kMaxParameter, 0.0),
      PLANTSIM_PARAM("dwb", planner.vx_samples, "vx_samples", 1, 1000),
      PLANTSIM_PARAM("dwb", planner.vtheta_samples, "vtheta_samples", 1, 1000),
      PLANTSIM_PARAM_ABOVE("dwb", planner.sim_time, "sim_time", 0.0, 60.0),
      PLANTSIM_PARAM_ABOVE("dwb", planner.time_granularity, "time_granularity", 0.0, 10.0),
      PLANTSIM_PARAM("dwb", planner.xy_goal_tolerance, "xy_goal_tolerance", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.base_obstacle_scale, "base_obstacle_scale", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.path_align_scale, "path_align_scale", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.goal_align_scale, "goal_align_scale", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.path_dist_scale, "path_dist_scale", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.goal_dist_scale, "goal_dist_scale", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.rotate_to_goal_scale, "rotate_to_goal_scale", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.forward_point_distance, "forward_point_distance", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.slowing_factor, "slowing_factor", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.oscillation_reset_dist, "oscillation_reset_dist", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.oscillation_reset_angle, "oscillation_reset_angle", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.x_only_threshold, "x_only_threshold", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.inflation_radius_m, "inflation_radius_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.forward_prune_distance, "forward_prune_distance", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("dwb", planner.local_goal_margin_m, "local_goal_margin_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("dwb", goal_tolerance_m, "goal_tolerance_m", 0.0, kMaxParameter),
  };
  return rows;
}

namespace {

class DwbController : public SamplingController, public SketchesTrajectories {
 public:
  DwbController(const LocalControllerContext& ctx, DwbControllerParams p)
      : SamplingController(
            ctx, p.goal_tolerance_m,
            field_reach(ctx.footprint_radius_m,
                        std::max(p.planner.inflation_radius_m, p.planner.local_goal_margin_m))),
        p_(fitted(p, ctx)),
        planner_(p_.planner) {}

 private:
  void set_method_path(const std::vector<geom::Vec2>& path) override { planner_.set_path(path); }

  Twist sample(const LocalQuery& q, const ClearanceGrid& field, const Pose2& goal) override {
    DwbQuery query;
    query.pose = q.pose;
    query.velocity = {q.speed_mps, q.yaw_rate_radps};
    query.goal = goal;
    query.clearance = &field;
    query.robot_radius_m = context().footprint_radius_m;
    return planner_.step(query);
  }

  TrajectorySketch last_trajectories(int max_sampled, int max_points) const override {
    TrajectorySketch sketch;
    const std::vector<ScoredTrajectory>& all = planner_.trajectories();
    const std::size_t count =
        std::min(all.size(), static_cast<std::size_t>(std::max(0, max_sampled)));
    for (std::size_t k = 0; k < count; ++k)  // spread over the window's samples
      sketch.sampled.push_back(sketch_points(all[k * all.size() / count].poses, max_points));
    if (const ScoredTrajectory* best = planner_.chosen())
      sketch.chosen = sketch_points(best->poses, max_points);
    return sketch;
  }

  /// No faster, and no quicker to speed up or brake, than the wheels: a trajectory the drive
  /// cannot follow would be scored as if it could, and the robot would leave it towards what
  /// it passes.
  static DwbControllerParams fitted(DwbControllerParams p, const LocalControllerContext& ctx) {
    p.planner.max_vel_x = std::min(p.planner.max_vel_x, ctx.max_wheel_speed_mps);
    p.planner.acc_lim_x = std::min(p.planner.acc_lim_x, ctx.max_accel_mps2);
    p.planner.decel_lim_x = std::max(p.planner.decel_lim_x, -ctx.max_accel_mps2);
    return p;
  }

  DwbControllerParams p_;
  DwbPlanner planner_;
};

}  // namespace

LocalControllerEntry dwb_entry() {
  LocalControllerEntry e;
  e.name = "dwb";
  e.summary = "the dynamic window approach with Nav2 DWB's critics";
  e.params = util::specs_of(dwb_param_rows());
  e.capabilities = {"samples-trajectories"};
  e.make = [](const LocalControllerContext& ctx, const util::ParamValues& v) {
    return std::make_unique<DwbController>(ctx, util::struct_of(dwb_param_rows(), v));
  };
  return e;
}

}  // namespace plantsim::controller::dwb
