// The drawable layers of a world figure, each a free function on a canvas whose transform is
// already set for the panel. Order of calls is the stacking order. Layers that may have nothing
// to draw return whether they drew, so that a legend lists exactly what is in the picture.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "episode/episode_result.h"
#include "render/gl_canvas.h"

namespace plantsim::render {

void draw_floor(GlCanvas& c, const worlds::World& w);  ///< floor and metre grid
/// How a planner grows obstacles by the planning margin: to rectangles, or by a disk (rounded
/// corners: planner vg-round). Figures draw the margin the plan was made around.
enum class MarginShape { kSquare, kRound };
MarginShape margin_shape(const std::string& planner_name);
/// Margins, then obstacles; false when the world has none.
bool draw_obstacles(GlCanvas& c, const worlds::World& w, MarginShape shape = MarginShape::kSquare);
/// Obstacles the plant has and the map lacks: outlined and hatched, never filled like the map's.
bool draw_unmapped(GlCanvas& c, const worlds::World& w);
/// Where the map puts the charger, as an outline, when that is not where it stands.
bool draw_mapped_charger(GlCanvas& c, const worlds::World& w);
/// The local obstacle layer's occupied cells (merged), as perception remembered them.
bool draw_layer(GlCanvas& c, const std::vector<geom::Rect>& cells);
bool draw_graph(GlCanvas& c, const std::vector<std::pair<Vec2, Vec2>>& edges);
/// True for a planner whose "graph" is a mesh of the free floor (planner interval): its
/// vertices are cells and its edges the portals between them, named so in figures.
bool searches_a_mesh(const std::string& planner_name);
void draw_charger(GlCanvas& c, const worlds::World& w);  ///< block and approach axis
void draw_start(GlCanvas& c, const worlds::World& w);
/// Routes, and the boxes where given (else where their scripts put them at t).
bool draw_moving(GlCanvas& c, const worlds::World& w, double t_s,
                 const std::vector<geom::Rect>& boxes = {});
/// The legend's words for the tracks drawn: "moving (swept)", "parked" when none moved (a cart
/// standing where it was put), or both when some did.
std::string moving_tracks_label(const std::vector<episode::EpisodeResult::MovingTrack>& tracks);
/// Where the moving obstacles went: the area each swept (faint), its centre track, and its box
/// where it ended. Drawn at one instant alone they would make a passing look like a collision.
bool draw_moving_tracks(GlCanvas& c,
                        const std::vector<episode::EpisodeResult::MovingTrack>& tracks);
/// The plan, thin, to be drawn over the driven path so that it stays visible.
bool draw_plan(GlCanvas& c, const std::vector<Vec2>& plan, Rgb colour, double width_px = 1.3);
/// A polyline in dashes of `dash_px` pixels (a plan that was replaced).
bool draw_dashed(GlCanvas& c, const std::vector<Vec2>& pts, double width_px, double dash_px,
                 Rgb colour);
/// The last lidar scan as perception placed it: returns the map explains and those it does not.
/// Returns {explained drawn, unexplained drawn}.
std::pair<bool, bool> draw_scan(GlCanvas& c, const robot::ScanView& scan);
/// Outlines of the obstacles perception tracked, and their velocity (1 s ahead).
bool draw_tracked(GlCanvas& c, const std::vector<controller::MovingBox>& boxes);
/// The estimated path as a band wider than the true path, drawn under it.
bool draw_estimate(GlCanvas& c, const std::vector<episode::TrajectorySample>& t);
/// The moving target's scripted track and where it was at the last sample.
bool draw_target(GlCanvas& c, const worlds::World& w,
                 const std::vector<episode::TrajectorySample>& t);
/// A wide band under the stretches driven in the wall-following state.
bool draw_wall_following(GlCanvas& c, const std::vector<episode::TrajectorySample>& t);
/// The driven path, each segment coloured by speed on cividis from 0 to `max_speed_mps`, broken
/// at each carry (a kidnap is no driving: draw_carries draws it).
bool draw_trajectory_by_speed(GlCanvas& c, const std::vector<episode::TrajectorySample>& t,
                              double max_speed_mps, std::size_t upto = static_cast<std::size_t>(-1),
                              const std::vector<episode::EpisodeResult::Carry>& carries = {});
/// Each kidnap's carry: dashed from where the robot was lifted (a small ring) to where it was set
/// down (a filled dot), in palette::kCarry. Returns whether there was one.
bool draw_carries(GlCanvas& c, const std::vector<episode::EpisodeResult::Carry>& carries);
/// The driven path's colour at its median speed: its legend swatch (a colour the path has).
Rgb speed_swatch(const std::vector<episode::TrajectorySample>& t, double max_speed_mps);
/// Rings where the robot stopped, replanned, recovered and backed off to retry, and crosses where
/// collisions began, a few pixels across at any scale.
void draw_events(GlCanvas& c, const std::vector<episode::EpisodeResult::Event>& events);
Rgb event_colour(episode::EpisodeResult::Event::Kind kind);
/// Footprint outlines every `every_s` seconds of the trajectory (never under 8 pixels across).
bool draw_footprints(GlCanvas& c, const worlds::RobotSpec& robot,
                     const std::vector<episode::TrajectorySample>& t, double every_s);
void draw_footprint(GlCanvas& c, const worlds::RobotSpec& robot, const geom::Pose2& pose,
                    Rgb colour, double width_px = 1.2);

}  // namespace plantsim::render
