// The drawable layers of a world figure, each a free function on a canvas whose transform is
// already set for the panel. Order of calls is the stacking order.
#pragma once

#include <utility>
#include <vector>

#include "render/gl_canvas.h"
#include "sim/episode.h"

namespace plantsim::render {

void draw_floor(GlCanvas& c, const worlds::World& w);                  ///< floor and metre grid
void draw_obstacles(GlCanvas& c, const worlds::World& w);              ///< margins, then obstacles
/// Obstacles the plant has and the map lacks: outlined and hatched, never filled like the map's.
void draw_unmapped(GlCanvas& c, const worlds::World& w);
/// Where the map puts the charger, as an outline, when that is not where it stands.
void draw_mapped_charger(GlCanvas& c, const worlds::World& w);
/// The local obstacle layer's occupied cells (merged), as perception remembered them.
void draw_layer(GlCanvas& c, const std::vector<geom::Rect>& cells);
void draw_graph(GlCanvas& c, const std::vector<std::pair<Vec2, Vec2>>& edges);
void draw_charger(GlCanvas& c, const worlds::World& w);                ///< block and approach axis
void draw_start(GlCanvas& c, const worlds::World& w);
/// Routes, and the boxes where given (else where their scripts put them at t).
void draw_moving(GlCanvas& c, const worlds::World& w, double t_s, const std::vector<geom::Rect>& boxes = {});
void draw_plan(GlCanvas& c, const std::vector<Vec2>& plan);
/// The last lidar scan as perception placed it: returns the map explains and those it does not.
void draw_scan(GlCanvas& c, const sim::ScanView& scan);
/// Outlines of the obstacles perception tracked, and their velocity (1 s ahead).
void draw_tracked(GlCanvas& c, const std::vector<controller::MovingBox>& boxes);
/// The estimated path as a band wider than the true path, drawn under it.
void draw_estimate(GlCanvas& c, const std::vector<sim::TrajectorySample>& t);
/// The moving target's scripted track and where it was at the last sample.
void draw_target(GlCanvas& c, const worlds::World& w, const std::vector<sim::TrajectorySample>& t);
/// A wide band under the stretches driven in the wall-following state.
void draw_wall_following(GlCanvas& c, const std::vector<sim::TrajectorySample>& t);
/// The driven path, each segment coloured by speed on viridis from 0 to `max_speed_mps`.
void draw_trajectory_by_speed(GlCanvas& c, const std::vector<sim::TrajectorySample>& t, double max_speed_mps,
                              std::size_t upto = static_cast<std::size_t>(-1));
/// Rings where the robot stopped, replanned and recovered, a few pixels across at any scale.
void draw_events(GlCanvas& c, const std::vector<sim::EpisodeResult::Event>& events);
/// Footprint outlines every `every_s` seconds of the trajectory.
void draw_footprints(GlCanvas& c, const worlds::RobotSpec& robot, const std::vector<sim::TrajectorySample>& t,
                     double every_s);
void draw_footprint(GlCanvas& c, const worlds::RobotSpec& robot, const geom::Pose2& pose, Rgb colour);

}  // namespace plantsim::render
