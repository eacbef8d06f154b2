// Hand-rule walks, the shortest route and the ring search.
#include "planner/maze/hand_rule.h"

#include <deque>
#include <map>

namespace plantsim::planner {
namespace {

Heading turned(Heading h, char letter) {
  const int rel = letter == 'L' ? 1 : letter == 'U' ? 2 : letter == 'R' ? 3 : 0;
  return static_cast<Heading>((static_cast<int>(h) + rel) % 4);
}

const char* priority(Hand hand) { return hand == Hand::kLeft ? "LSR" : "RSL"; }

}  // namespace

std::string_view to_string(WalkEnd e) {
  switch (e) {
    case WalkEnd::kExit:
      return "exit";
    case WalkEnd::kBackAtEntrance:
      return "back at the entrance";
    case WalkEnd::kBlocked:
      return "scripted corridor closed";
    case WalkEnd::kStepLimit:
      return "step limit";
  }
  return "?";
}

MazeWalk walk_maze(const TunnelMaze& maze, LatticeNode entrance, Heading heading, LatticeNode exit,
                   Hand hand, std::string_view script) {
  MazeWalk w;
  w.nodes.push_back(entrance);
  if (!maze.open(entrance, heading)) {
    bool found = false;
    for (const char* p = "SLRU"; *p && !found; ++p)
      if (maze.open(entrance, turned(heading, *p))) heading = turned(heading, *p), found = true;
    if (!found) {
      w.end = WalkEnd::kBlocked;
      return w;
    }
  }
  std::size_t next_letter = 0;
  const std::size_t limit = 4 * static_cast<std::size_t>(maze.open_edges()) + 4;
  LatticeNode at = entrance;
  for (std::size_t steps = 0; steps < limit; ++steps) {
    at = TunnelMaze::step(at, heading);
    w.nodes.push_back(at);
    if (at == exit) {
      w.end = WalkEnd::kExit;
      return w;
    }
    if (at == entrance) {
      w.end = WalkEnd::kBackAtEntrance;
      return w;
    }
    std::string ways;  // the ways on, in the hand's priority
    for (const char* p = priority(hand); *p; ++p)
      if (maze.open(at, turned(heading, *p))) ways += *p;
    char letter;
    if (ways.empty()) {
      letter = 'U';  // dead end
    } else if (ways.size() == 1) {
      heading = turned(heading, ways[0]);  // a bend or a straight run: no choice, no letter
      continue;
    } else if (next_letter < script.size()) {
      letter = script[next_letter++];
      if (!maze.open(at, turned(heading, letter))) {
        w.turns += letter;
        w.turn_at.push_back(w.nodes.size() - 1);
        w.end = WalkEnd::kBlocked;
        return w;
      }
    } else {
      letter = ways[0];
    }
    w.turns += letter;
    w.turn_at.push_back(w.nodes.size() - 1);
    heading = turned(heading, letter);
  }
  w.end = WalkEnd::kStepLimit;
  return w;
}

std::vector<LatticeNode> shortest_route(const TunnelMaze& maze, LatticeNode from, LatticeNode to) {
  auto key = [](LatticeNode n) { return std::pair{n.column, n.row}; };
  std::map<std::pair<int, int>, LatticeNode> parent;
  std::deque<LatticeNode> queue{from};
  parent[key(from)] = from;
  while (!queue.empty()) {
    const LatticeNode n = queue.front();
    queue.pop_front();
    if (n == to) break;
    for (int h = 0; h < 4; ++h) {
      if (!maze.open(n, static_cast<Heading>(h))) continue;
      const LatticeNode m = TunnelMaze::step(n, static_cast<Heading>(h));
      if (parent.emplace(key(m), n).second) queue.push_back(m);
    }
  }
  if (!parent.count(key(to))) return {};
  std::vector<LatticeNode> route{to};
  while (!(route.back() == from)) route.push_back(parent.at(key(route.back())));
  return {route.rbegin(), route.rend()};
}

MazeSolution solve_maze(const TunnelMaze& maze, LatticeNode entrance, Heading heading,
                        LatticeNode exit, Hand hand, ThirdString third_string) {
  MazeSolution s;
  s.exploration = walk_maze(maze, entrance, heading, exit, hand);
  s.simplified = simplify_turns(s.exploration.turns, hand);
  s.route = walk_maze(maze, entrance, heading, exit, hand, s.simplified);
  if (s.exploration.end != WalkEnd::kBackAtEntrance) return s;

  // The exit lies inside a ring: the document's search over the second string's markers.
  s.ring_search = true;
  const char turn_marker = hand == Hand::kLeft ? 'L' : 'R';
  const Hand other = hand == Hand::kLeft ? Hand::kRight : Hand::kLeft;
  int n = 0;
  for (std::size_t i = 0; i < s.simplified.size(); ++i) {
    const char c = s.simplified[i];
    if (c != turn_marker && c != 'S') continue;
    ++n;
    // Left hand: L -> S or R, S -> R (the ways not yet taken there); right hand mirrored.
    const std::string changes = c == 'S' ? std::string(1, hand == Hand::kLeft ? 'R' : 'L')
                                         : std::string(hand == Hand::kLeft ? "SR" : "SL");
    for (char change : changes)
      for (Hand then : {hand, other}) {
        std::string script = s.simplified.substr(0, i);
        script += change;
        const MazeWalk w = walk_maze(maze, entrance, heading, exit, then, script);
        s.attempts.push_back(w);
        s.attempt_labels.push_back("marker " + std::to_string(n) + " " + c + "->" + change +
                                   ", then " + (then == Hand::kLeft ? "left" : "right") +
                                   " hand: " + std::string(to_string(w.end)));
        s.search_log += s.attempt_labels.back() + "; ";
        if (w.end == WalkEnd::kExit) {
          s.third = w.turns;
          s.route = w;
          if (third_string == ThirdString::kResimplified) {
            // The third string is a record like the first: the second step's rules drop the
            // dead ends it still visits, when the shorter string still reaches the exit.
            const MazeWalk shorter =
                walk_maze(maze, entrance, heading, exit, then, simplify_turns(w.turns, then));
            if (shorter.end == WalkEnd::kExit && shorter.nodes.size() < w.nodes.size())
              s.route = shorter;
          }
          return s;
        }
      }
  }
  return s;
}

}  // namespace plantsim::planner
