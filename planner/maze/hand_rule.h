// Seed 003's walks through a tunnel lattice. A walk leaves the entrance and, at every junction
// (a node offering more than one way on), either takes the next letter of a script or, once
// the script is used up, the hand rule's choice (left hand: L before S before R; right hand:
// R, S, L); at a dead end it turns back (U). Bends and straight runs record nothing; the
// entrance and the exit are not junctions. Letters are recorded as the document does.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "planner/maze/maze_strings.h"
#include "worlds/tunnel_maze.h"

namespace plantsim::planner {

using worlds::Heading;
using worlds::LatticeNode;
using worlds::TunnelMaze;

enum class WalkEnd { kExit, kBackAtEntrance, kBlocked, kStepLimit };
std::string_view to_string(WalkEnd e);

struct MazeWalk {
  std::vector<LatticeNode> nodes;    ///< entrance .. where it ended
  std::string turns;                 ///< L/R/S/U at each junction and dead end
  std::vector<std::size_t> turn_at;  ///< turns[i] was recorded at nodes[turn_at[i]]
  WalkEnd end = WalkEnd::kStepLimit;
  double length_m(const TunnelMaze& maze) const {
    return nodes.empty() ? 0.0 : maze.pitch_m() * (nodes.size() - 1.0);
  }
};

/// Walks from `entrance` (leaving along `heading`, or by the hand's priority when that corridor
/// is closed) following `script`, then `hand`, until the exit, the entrance again, a scripted
/// letter whose corridor is closed (kBlocked), or a step limit.
MazeWalk walk_maze(const TunnelMaze& maze, LatticeNode entrance, Heading heading, LatticeNode exit,
                   Hand hand, std::string_view script = "");

/// The shortest corridor route (breadth-first; every edge is one pitch), empty if none.
std::vector<LatticeNode> shortest_route(const TunnelMaze& maze, LatticeNode from, LatticeNode to);

/// What the next inspections drive after a ring search. The document stores the third string
/// as recorded and drives it (its Fig. 25 keeps "SRRRUSURRRR", dead ends and all);
/// re-simplifying it by the second step's rules is plantsim's option, shorter where it works.
enum class ThirdString { kAsRecorded, kResimplified };

/// The document's whole procedure: explore by the hand rule (first string), simplify (second
/// string) and drive it; when the exploration came back to the entrance (the exit inside a
/// ring of tunnels), change the N-th L or S marker (right hand: R or S) of the second string,
/// N = 1, 2, ..., to each of its untried directions, continue by either hand rule, and keep the
/// first walk that reaches the exit (third string).
struct MazeSolution {
  MazeWalk exploration;      ///< first string
  std::string simplified;    ///< second string
  std::string third;         ///< ring search: the record of the first walk that reached the exit
  MazeWalk route;            ///< what is driven: the second string's walk, or the third string's
                             ///< (as recorded, or simplified again when asked and that still works)
  bool ring_search = false;  ///< the exploration came back to the entrance
  std::vector<MazeWalk> attempts;           ///< the ring search's walks, in the order tried
  std::vector<std::string> attempt_labels;  ///< "marker 1 L->R, then left hand: exit"
  std::string search_log;                   ///< the labels joined
  bool solved() const { return route.end == WalkEnd::kExit; }
};
MazeSolution solve_maze(const TunnelMaze& maze, LatticeNode entrance, Heading heading,
                        LatticeNode exit, Hand hand,
                        ThirdString third_string = ThirdString::kAsRecorded);

}  // namespace plantsim::planner
