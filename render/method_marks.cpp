// Seed 003's annotations: dashed search walks and the junction letters.
#include "render/method_marks.h"

#include <algorithm>

#include "render/layers.h"
#include "render/palette.h"

namespace plantsim::render {

namespace {

bool draw_tried_walks(GlCanvas& c, const std::vector<std::vector<Vec2>>& walks) {
  bool drawn = false;
  const double px = 1.0 / c.transform().scale;
  for (std::size_t k = 0; k < walks.size(); ++k) {
    // Walks share their first corridors and the route drawn over them: each lies beside the
    // route, 4 px off along the diagonal, and 2.5 px beyond the walk before it.
    const double shift = (4.0 + 2.5 * static_cast<double>(k)) * px;
    std::vector<Vec2> moved;
    moved.reserve(walks[k].size());
    for (const Vec2& p : walks[k]) moved.push_back(p + Vec2{shift, -shift});
    drawn = draw_dashed(c, moved, 1.5, 6.0, palette::kTried) || drawn;
  }
  return drawn;
}

}  // namespace

std::vector<LegendEntry> draw_walks_before_answer(GlCanvas& c, const episode::EpisodeLog& run) {
  std::vector<LegendEntry> legend;
  const planner::PlanTrace& trace = run.plan_trace;
  if (!trace.explored.empty()) {
    c.polyline(trace.explored, 5.0, palette::kExplored);
    legend.push_back({palette::kExplored, trace.explored_label});
  }
  if (draw_tried_walks(c, trace.tried)) legend.push_back({palette::kTried, "ring search walks"});
  return legend;
}

std::vector<LegendEntry> draw_plan_marks(Figure& fig, const PixelTransform& t,
                                         const std::vector<planner::PlanMark>& marks) {
  using Kind = planner::PlanMark::Kind;
  bool placed[3] = {false, false, false};
  // A dot where each letter was recorded (the text sits beside it, where it has room).
  for (const auto& m : marks)
    if (m.kind != Kind::kTriedEnd)
      fig.canvas().fill_disk(
          m.at, 2.5 / t.scale,
          m.kind == Kind::kRouteLetters ? palette::kPlan : palette::kExploredText);
  for (const auto& m : marks) {
    const Vec2 p = t.to_pixel(m.at);
    bool ok = false;
    switch (m.kind) {
      case Kind::kExplorationLetters:
        ok = fig.text_if_free(m.text, p.x - 5, p.y - 7, 11, palette::kExploredText, Anchor::kRight);
        break;
      case Kind::kRouteLetters:
        ok = fig.text_if_free(m.text, p.x + 5, p.y + 15, 11, palette::kPlan);
        break;
      case Kind::kTriedEnd:
        ok = fig.text_if_free(m.text, p.x + 7, p.y - 7, 11, palette::kTried);
        break;
    }
    placed[static_cast<int>(m.kind)] = placed[static_cast<int>(m.kind)] || ok;
  }
  std::vector<LegendEntry> legend;
  if (placed[0]) legend.push_back({palette::kExploredText, "letters explored"});
  if (placed[1]) legend.push_back({palette::kPlan, "letters driven"});  // dots on the plan's line
  return legend;
}

}  // namespace plantsim::render
