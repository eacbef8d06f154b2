// The Box2D side of a World: every static obstacle rectangle and the four floor walls as
// fixtures of one static body (about 6x faster than a body each at 1000 boxes), the charger
// as its own static body, and the robot as a dynamic disk with mass and inertia from its
// spec. Box2D types never leave sim/; the rest of plantsim sees poses and contact flags.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "geometry/vec2.h"
#include "robot/readings.h"
#include "worlds/surfaces.h"
#include "worlds/world.h"

class b2World;
class b2Body;

namespace plantsim::sim {

using robot::ActorState;
using worlds::RayHit;
using worlds::SurfaceKind;

using geom::Pose2;
using geom::Vec2;

struct StepSettings {
  double dt_s = 1.0 / 60.0;     ///< fixed time step
  int velocity_iterations = 8;  ///< Box2D solver iterations per step
  int position_iterations = 3;
};

struct ContactState {
  bool charger = false;               ///< robot touches the charger body
  bool obstacle = false;              ///< robot touches an obstacle, a wall or a moving obstacle
  std::vector<Vec2> obstacle_points;  ///< where it touches them (world frame)
};

class PhysicsWorld {
 public:
  explicit PhysicsWorld(const worlds::World& world);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// Moves the scripted obstacles one step along their scripts (through their velocity, so
  /// that Box2D sees them move) and advances the world by one fixed step.
  void step(const StepSettings& s);

  /// The scripted obstacles now (yielding ones may lag behind their script).
  std::vector<ActorState> actors() const;
  /// The moving target (a sensor body: it collides with nothing), if the world has one.
  std::optional<ActorState> target() const;

  Pose2 robot_pose() const;
  Vec2 robot_position() const;
  Vec2 robot_velocity() const;    ///< world frame, m/s
  double robot_yaw_rate() const;  ///< rad/s
  ContactState contacts() const;
  /// Nearest surface along the segment (obstacles, walls, charger, moving obstacles and the
  /// target; never the robot itself). For the sensors. The static parts are cast exactly by
  /// geometry through a grid built once (worlds/surfaces.h: the same boxes Box2D
  /// holds, in double precision), the moving bodies against their boxes as the physics has
  /// them now: no Box2D tree walk per beam.
  std::optional<RayHit> ray_cast(Vec2 from, Vec2 to) const;
  /// Box2D's own ray cast through its broad phase (single precision), the reference the exact
  /// casts are compared with in tests and `plantsim bench sim`; the sensors never use it.
  std::optional<RayHit> box2d_ray_cast(Vec2 from, Vec2 to) const;
  /// A lidar's fan: ray k from `from` along unit directions[k], whose angle is within 1e-6 rad of
  /// first_angle + k * increment, to `max_range_m`. ranges[k] is the range ray_cast finds along
  /// that direction, +infinity where it finds nothing (a lidar needs no more); the static parts
  /// are met in one pass over the boxes within reach.
  void ray_fan(Vec2 from, std::span<const Vec2> directions, double first_angle, double increment,
               double max_range_m, std::vector<double>& ranges) const;

  b2Body* robot_body() { return robot_; }  ///< for the drive model inside sim/
  /// Sets the robot's velocity directly (no tyre model): for baselines and tests.
  void set_robot_velocity(Vec2 linear_mps, double angular_radps);
  /// Moves the robot to `pose` at rest (a kidnap: carried off by hand, wheels off the floor).
  void place_robot(const Pose2& pose);
  double robot_mass() const;
  double robot_inertia() const;

 private:
  std::unique_ptr<b2World> world_;
  worlds::SurfaceGrid surfaces_;  // the static parts, for ray casts
  b2Body* robot_ = nullptr;
  double robot_radius_m_;  // circumscribed, for actors deciding whether the robot is in their way
  struct Actor {
    b2Body* body;
    worlds::MovingObstacle script;
    double script_time_s = 0;  // advances with the clock unless the actor yields
    Vec2 velocity;
  };
  std::vector<Actor> moving_;
  std::optional<Actor> target_;

  Actor make_actor(const worlds::MovingObstacle& m, bool sensor);
  void advance(Actor& a, double dt_s) const;  // one step along its script
  static ActorState state_of(const Actor& a);
};

}  // namespace plantsim::sim
