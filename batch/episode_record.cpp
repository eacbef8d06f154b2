// One episode's record (see the header).
#include "batch/episode_record.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "batch/record_builds.h"
#include "episode/episode_json.h"
#include "geometry/predicates.h"
#include "util/fingerprint.h"

namespace plantsim::batch {

using nlohmann::json;

std::string episode_key(const std::string& scenario_fingerprint, const std::string& id) {
  return util::Fingerprint()
      .add(std::string_view("plantsim episode key v1"))
      .add(scenario_fingerprint)
      .add(id)
      .hex();
}

std::string record_line(const Episode& e, const BatchSpec& spec, const ScenarioIdentity& scenario,
                        const worlds::World& plant, const episode::EpisodeResult& r,
                        double optimal_m, std::optional<double> shortest_possible_m) {
  const std::string& world_name = plant.name;
  const geom::Pose2& start = plant.start;
  nlohmann::ordered_json j;
  j["index"] = e.index;
  j["id"] = e.id;
  j["scenario"] = scenario.fingerprint;
  j["scenario_episodes"] = scenario.episodes;
  j["scenario_file"] = scenario.file;
  j["build"] = this_build();  // which build ran it: a resume or a merge may mix builds
  j["key"] = episode_key(scenario.fingerprint, e.id);
  j["world"] = world_name;
  j["planner"] = spec.planners[e.planner];
  j["controller"] = spec.controllers[e.controller].name;
  j["fault"] = spec.faults[e.fault].name;
  if (!spec.faults[e.fault].sweep_parameter.empty()) {
    j["sweep_parameter"] = spec.faults[e.fault].sweep_parameter;
    j["sweep_value"] = spec.faults[e.fault].sweep_value;
  }
  j["seed"] = e.seed;
  j["start"] = {start.x, start.y, start.yaw};
  j["goal"] = plant.target ? "catch" : "dock";
  j["succeeded"] = r.succeeded();
  episode::add_episode_metrics(j, r);
  j["optimal_length_m"] = optimal_m;
  // What no robot can drive less than (issue 52: the planning optimum with its margin, plus the
  // approach, was beaten by most docked episodes, so it measured nothing).
  if (shortest_possible_m) j["shortest_possible_m"] = *shortest_possible_m;
  // The driven path for the report's overlay of every episode, in millimetres, thinned to a
  // point every 0.5 m (further apart on long drives: at most about 400 points, 3 kB a record).
  auto path = json::array();
  geom::Vec2 last{NAN, NAN};
  const double spacing = std::max(0.5, r.driven_length_m / 400.0);
  for (std::size_t i = 0; i < r.trajectory.size(); ++i) {
    const geom::Vec2 p = r.trajectory[i].truth.position();
    if (i + 1 < r.trajectory.size() && i > 0 && geom::distance(p, last) < spacing) continue;
    path.push_back(std::lround(p.x * 1000));
    path.push_back(std::lround(p.y * 1000));
    last = p;
  }
  j["path_mm"] = path;
  if (!plant.unmapped.empty()) {  // the plant as this episode met it, to replay it
    auto boxes = json::array();
    for (const geom::Rect& u : plant.unmapped) boxes.push_back({u.xmin, u.ymin, u.xmax, u.ymax});
    j["unmapped"] = boxes;
  }
  return j.dump();
}

}  // namespace plantsim::batch
