// From points to lattice nodes and back, with the strings in the result's note.
#include "planner/maze/maze_planner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "geometry/polyline.h"
#include "util/c_number.h"
#include "util/stopwatch.h"

namespace plantsim::planner {

MazePlanner::MazePlanner(const PlannerInput& input, Hand hand, bool drive_exploration,
                         ThirdString third_string)
    : maze_(input.maze),
      hand_(hand),
      drive_exploration_(drive_exploration),
      third_string_(third_string) {}

namespace {

// Whether p lies inside the corridor between two lattice nodes (not at either end).
bool in_corridor(const TunnelMaze& maze, Vec2 p, LatticeNode a, LatticeNode b) {
  const Vec2 pa = maze.position(a), pb = maze.position(b), d = pb - pa;
  const double t = geom::dot(p - pa, d) / geom::dot(d, d);
  return t > 0 && t < 1 &&
         std::fabs(geom::cross(d, p - pa)) / std::sqrt(geom::dot(d, d)) < 0.5 * maze.corridor_m();
}

// Start and goal lie in corridors near their nodes; a point already on the first (last) corridor
// of the route joins it there instead of doubling back from the node.
std::vector<Vec2> lattice_path(const TunnelMaze& maze, const std::vector<LatticeNode>& nodes,
                               Vec2 start, Vec2 goal, bool to_goal) {
  std::vector<Vec2> p{start};
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (i == 0 && nodes.size() > 1 && in_corridor(maze, start, nodes[0], nodes[1])) continue;
    if (to_goal && i + 1 == nodes.size() && nodes.size() > 1 &&
        in_corridor(maze, goal, nodes[i - 1], nodes[i]))
      continue;
    p.push_back(maze.position(nodes[i]));
  }
  if (to_goal) p.push_back(goal);
  return p;
}

// Every search walk drawn, and where each ended: "tries 1, 2: closed" where several ended alike
// in one place.
void add_tries(const TunnelMaze& maze, const MazeSolution& s, Vec2 start, Vec2 goal,
               PlanResult& r) {
  std::map<std::pair<std::pair<int, int>, WalkEnd>, std::vector<std::size_t>> ended_at;
  for (std::size_t k = 0; k < s.attempts.size(); ++k) {
    const MazeWalk& w = s.attempts[k];
    r.trace.tried.push_back(lattice_path(maze, w.nodes, start, goal, false));
    ended_at[{{w.nodes.back().column, w.nodes.back().row}, w.end}].push_back(k + 1);
  }
  for (const auto& [where, tries] : ended_at) {
    const WalkEnd end = where.second;
    std::string text = tries.size() > 1 ? "tries " : "try ";
    for (std::size_t i = 0; i < tries.size(); ++i)
      text += (i ? ", " : "") + std::to_string(tries[i]);
    text += end == WalkEnd::kExit             ? ": exit"
            : end == WalkEnd::kBackAtEntrance ? ": back"
            : end == WalkEnd::kBlocked        ? ": closed"
                                              : ": step limit";
    r.trace.marks.push_back(
        {maze.position({where.first.first, where.first.second}), text, PlanMark::Kind::kTriedEnd});
  }
}

// One label per junction and walk: the letters recorded there in the order they were ("S U L"
// where the walk came back from a dead end).
void label_junctions(const TunnelMaze& maze, const MazeWalk& w, PlanMark::Kind kind,
                     std::vector<PlanMark>& marks) {
  std::map<std::pair<int, int>, std::size_t> label_of;
  for (std::size_t i = 0; i < w.turns.size() && i < w.turn_at.size(); ++i) {
    const LatticeNode n = w.nodes[w.turn_at[i]];
    const auto [it, fresh] = label_of.try_emplace({n.column, n.row}, marks.size());
    if (fresh)
      marks.push_back({maze.position(n), std::string(1, w.turns[i]), kind});
    else
      marks[it->second].text += std::string(" ") + w.turns[i];
  }
}

}  // namespace

// The strings of the document: explored, simplified, the ring search's, the route's, and the
// shortest corridor route beside them.
std::string MazePlanner::note(const MazeSolution& s, double shortest_m) const {
  char line[512];
  util::c_snprintf(line, sizeof line, "%s hand: explored %s (%s, %.1f m) -> simplified %s; ",
                   hand_ == Hand::kLeft ? "left" : "right", s.exploration.turns.c_str(),
                   std::string(to_string(s.exploration.end)).c_str(),
                   s.exploration.length_m(*maze_), s.simplified.c_str());
  std::string text = line;
  if (s.ring_search)
    text += "ring search: " + s.search_log + "third string " + s.third +
            (third_string_ == ThirdString::kResimplified
                 ? " (simplified again where that still reaches the exit)"
                 : " (driven as recorded)") +
            "; ";
  util::c_snprintf(line, sizeof line, "route %s %.1f m (%s); shortest corridor route %.1f m",
                   s.route.turns.c_str(), s.route.length_m(*maze_),
                   std::string(to_string(s.route.end)).c_str(), shortest_m);
  return text + line;
}

PlanResult MazePlanner::plan(Vec2 start, Vec2 goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult r;
  if (!maze_) {
    r.note = name() + " needs a world with a tunnel_maze lattice";
    return r;
  }
  const auto entrance = maze_->nearest_node(start), exit = maze_->nearest_node(goal);
  if (!entrance || !exit) {
    r.note = "the lattice has no corridor";
    return r;
  }
  const MazeSolution s = solve_maze(*maze_, *entrance, Heading::kEast, *exit, hand_, third_string_);
  const std::vector<LatticeNode> best = shortest_route(*maze_, *entrance, *exit);
  r.trace.explored = lattice_path(*maze_, s.exploration.nodes, start, goal, false);
  add_tries(*maze_, s, start, goal, r);
  label_junctions(*maze_, s.exploration, PlanMark::Kind::kExplorationLetters, r.trace.marks);
  if (s.solved()) label_junctions(*maze_, s.route, PlanMark::Kind::kRouteLetters, r.trace.marks);
  r.note = note(s, best.empty() ? -1.0 : maze_->pitch_m() * (best.size() - 1.0));
  if (s.solved()) {
    r.status = PlanStatus::kOk;
    std::vector<LatticeNode> nodes = s.route.nodes;
    if (drive_exploration_) {
      nodes = s.exploration.nodes;
      if (s.exploration.end != WalkEnd::kExit)
        nodes.insert(nodes.end(), s.route.nodes.begin() + 1, s.route.nodes.end());
    }
    r.path = lattice_path(*maze_, nodes, start, goal, true);
    r.length = geom::polyline_length(r.path);
  }
  r.stats.vertices = static_cast<std::int64_t>(maze_->columns()) * maze_->rows();
  r.stats.edges = maze_->open_edges();
  r.stats.query_ms = util::ms_since(t0);
  return r;
}

}  // namespace plantsim::planner
