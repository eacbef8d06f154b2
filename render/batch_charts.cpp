// Layout of the batch charts on linear axes of their own (categorical rows or numeric values).
#include "render/batch_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "render/chart_axes.h"
#include "render/colormap.h"
#include "render/layers.h"
#include "render/method_strips.h"
#include "render/palette.h"
#include "util/c_number.h"

namespace plantsim::render {
/// The tallest chart drawn: figures hold 16,384 pixels a side; a chart that would need more
/// shows what fits and says so.
constexpr double kMaxChartHeight_px = 12000;

namespace {

constexpr Rgb kBand{185, 212, 238};  // a light tint of the success line's blue

}  // namespace

Image draw_success_chart(const std::vector<RateRow>& all_rows, const std::string& title,
                         int width_px, FigureLayout* layout_out) {
  constexpr std::size_t kMaxRows = 80;
  const std::vector<RateRow> rows(all_rows.begin(),
                                  all_rows.begin() + std::min(all_rows.size(), kMaxRows));
  const double row_h = 22;
  const int height = static_cast<int>(120 + row_h * std::max<std::size_t>(rows.size(), 1) + 60);
  Figure fig(width_px, height);
  fig.text_fitted(title, 20, 28, 18, palette::kAxis, width_px - 40.0, true);
  std::string sub = "success rate per configuration with its Wilson 95 % interval";
  if (all_rows.size() > rows.size())
    sub += " (first " + std::to_string(rows.size()) + " of " + std::to_string(all_rows.size()) +
           " configurations)";
  fig.text(sub, 20, 48, 13, palette::kAxis);
  const PixelBox box{520, 100, width_px - 110.0,
                     100 + row_h * std::max<std::size_t>(rows.size(), 1)};
  const Axes a{box, 0, 1, 0, 1};
  axis(fig, a, true, "success rate", 100.0, " %");
  GlCanvas& c = fig.canvas();
  bool any_gate = false, any_below = false, any_pass = false, any_unsure = false;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RateRow& r = rows[i];
    const double y = box.top + (i + 0.5) * row_h;
    const double rate = r.episodes ? static_cast<double>(r.successes) / r.episodes : 0.0;
    const bool below = r.gate >= 0 && rate < r.gate;
    // At or above its gate by the point estimate, yet the interval's lower bound is below it: the
    // sample cannot tell that it meets the gate (10 of 10 against 0.9: lower bound 0.72).
    const bool unsure = r.gate >= 0 && !below && r.low < r.gate;
    // Listed only when a bar is drawn (a rate of 0 draws none).
    any_below = any_below || (below && rate > 0);
    any_unsure = any_unsure || (unsure && rate > 0);
    any_pass = any_pass || (!below && !unsure && rate > 0);
    const Rgb bar = below ? palette::kFailure : unsure ? palette::kUnsureBar : palette::kCharger;
    if (rate > 0) c.pixel_line({a.px(0), y}, {a.px(rate), y}, row_h * 0.6, bar);
    c.pixel_line({a.px(r.low), y}, {a.px(r.high), y}, 1.6, palette::kAxis);
    c.pixel_line({a.px(r.low), y - 5}, {a.px(r.low), y + 5}, 1.6, palette::kAxis);
    c.pixel_line({a.px(r.high), y - 5}, {a.px(r.high), y + 5}, 1.6, palette::kAxis);
    if (r.gate >= 0) {
      any_gate = true;
      c.pixel_line({a.px(r.gate), y - 0.5 * row_h}, {a.px(r.gate), y + 0.5 * row_h}, 2.0,
                   palette::kOkabeBlack);
    }
    fig.text(fig.fit(r.label, 12, box.left - 20), box.left - 10, y + 4, 12, palette::kAxis,
             Anchor::kRight);
    fig.text(std::to_string(r.successes) + "/" + std::to_string(r.episodes), box.right + 8, y + 4,
             12, palette::kAxis);
  }
  std::vector<LegendEntry> legend;
  if (any_pass)
    legend.push_back({palette::kCharger, any_gate ? "success rate (meets gate)" : "success rate"});
  if (any_unsure) legend.push_back({palette::kUnsureBar, "meets gate, 95 % low below it"});
  if (any_below) legend.push_back({palette::kFailure, "success rate (below gate)"});
  legend.push_back({palette::kAxis, "Wilson 95 %"});
  if (any_gate) legend.push_back({palette::kOkabeBlack, "gate"});
  fig.legend(20, 76, legend, static_cast<int>(legend.size()), 270);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

Image draw_error_strips(const std::vector<EpisodeOutcome>& episodes, const DockingGates& gates,
                        int width_px, FigureLayout* layout_out) {
  const std::vector<std::string> methods = methods_of(episodes);
  std::vector<std::vector<double>> pos(methods.size()), heading(methods.size());
  std::vector<std::size_t> counts(methods.size(), 0);
  for (const auto& e : episodes) {
    if (!e.docked) continue;
    const std::size_t m = method_index(methods, e.method);
    pos[m].push_back(e.position_error_m);
    heading[m].push_back(e.heading_error_deg);
    ++counts[m];
  }
  const double row_h = 60;
  const int height = static_cast<int>(130 + row_h * std::max<std::size_t>(methods.size(), 1) + 60);
  Figure fig(width_px, height);
  fig.text("Docking errors of the docked episodes", 20, 28, 18, palette::kAxis, Anchor::kLeft,
           true);
  fig.text("one dot per episode (spread vertically to be seen); red lines: the gates", 20, 48, 13,
           palette::kAxis);
  const double label_w = 260, gap = 60;
  const double panel_w = (width_px - label_w - gap - 40) / 2.0;
  const PixelBox left{label_w, 110, label_w + panel_w,
                      110 + row_h * std::max<std::size_t>(methods.size(), 1)};
  const PixelBox right{left.right + gap, left.top, left.right + gap + panel_w, left.bottom};
  method_labels(fig, left, methods, counts);
  char head[120];
  util::c_snprintf(head, sizeof head, "Position error (gate %.0f mm)", 1000 * gates.position_m);
  strip_panel(fig, left, methods, pos, gates.position_m, head, "mm", 1000.0);
  util::c_snprintf(head, sizeof head, "Heading error (gate %.0f deg)", gates.heading_deg);
  strip_panel(fig, right, methods, heading, gates.heading_deg, head, "deg", 1.0);
  // Each row is named in its dots' colour; the legend says what the red lines are.
  fig.legend(20, 76, {{palette::kCollisionMark, "gate"}}, 1, 200);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

Image draw_localization_chart(const std::vector<EpisodeOutcome>& episodes, int width_px,
                              FigureLayout* layout_out) {
  constexpr double kShownUpTo_m =
      1.0;  // a few lost episodes tens of metres off must not squash the rest
  const std::vector<std::string> methods = methods_of(episodes);
  std::vector<std::vector<double>> worst(methods.size());
  std::vector<std::vector<bool>> failed(methods.size());
  std::vector<std::size_t> counts(methods.size(), 0), not_ok(methods.size(), 0),
      beyond(methods.size(), 0);
  bool any_failed = false, any_docked = false;
  for (const auto& e : episodes) {
    if (e.localization_error_max_m < 0) continue;
    const std::size_t m = method_index(methods, e.method);
    worst[m].push_back(std::min(e.localization_error_max_m, kShownUpTo_m));
    failed[m].push_back(!e.docked);
    any_failed = any_failed || !e.docked;
    any_docked = any_docked || e.docked;
    beyond[m] += e.localization_error_max_m > kShownUpTo_m;
    not_ok[m] += !e.localization_ok;
    ++counts[m];
  }
  const double row_h = 60;
  const int height = static_cast<int>(130 + row_h * std::max<std::size_t>(methods.size(), 1) + 60);
  Figure fig(width_px, height);
  fig.text("Localisation: each episode's worst error, true against estimated", 20, 28, 18,
           palette::kAxis, Anchor::kLeft, true);
  fig.text(
      "one mark per episode: a dot if it docked, a cross if it failed (spread vertically to be "
      "seen); errors past 1 m drawn at 1 m; right: episodes whose estimator reported worse than ok",
      20, 48, 13, palette::kAxis);
  const double label_w = 260, right_w = 300;
  const PixelBox box{label_w, 110, width_px - right_w,
                     110 + row_h * std::max<std::size_t>(methods.size(), 1)};
  method_labels(fig, box, methods, counts);
  strip_panel(fig, box, methods, worst, 0.10, "Worst position error (red line: 100 mm)", "mm",
              1000.0, &failed);
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::string note = std::to_string(not_ok[m]) + " of " + std::to_string(counts[m]) + " not ok";
    if (beyond[m]) note += ", " + std::to_string(beyond[m]) + " past 1 m";
    fig.text(note, box.right + 16, box.top + (m + 0.5) * row_h + 4, 12, palette::kAxis);
  }
  std::vector<LegendEntry> legend = {{palette::kCollisionMark, "100 mm"}};
  if (any_docked)
    legend.push_back({method_colour(0), "docked (dot, its method's colour)", Swatch::kDot});
  if (any_failed) legend.push_back({kFailedMark, "failed (black cross)", Swatch::kDot});
  fig.legend(20, 76, legend, static_cast<int>(legend.size()), 330);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

Image draw_efficiency_chart(const std::vector<EpisodeOutcome>& episodes, int width_px,
                            FigureLayout* layout_out) {
  const std::vector<std::string> methods = methods_of(episodes);
  std::vector<std::vector<double>> ratio(methods.size()), times(methods.size());
  std::vector<std::size_t> counts(methods.size(), 0);
  for (const auto& e : episodes) {
    if (!e.docked) continue;
    const std::size_t m = method_index(methods, e.method);
    if (e.driven_over_shortest > 0) ratio[m].push_back(e.driven_over_shortest);
    times[m].push_back(e.time_s);
    ++counts[m];
  }
  // The legend names every method's ECDF line, six a row.
  std::size_t listed = 0;
  for (const auto& v : ratio) listed += !v.empty();
  const int legend_rows = static_cast<int>((std::max<std::size_t>(listed, 1) + 5) / 6);
  const double top = 110 + 19.0 * (legend_rows - 1);
  const int height = static_cast<int>(560 + top - 110);
  Figure fig(width_px, height);
  fig.text("How far and how long, docked episodes", 20, 28, 18, palette::kAxis, Anchor::kLeft,
           true);
  fig.text(
      "left: share of episodes driving at most x times the shortest path their robot's centre "
      "could take (a lower bound); right: time to dock",
      20, 48, 13, palette::kAxis);
  const double half = (width_px - 120) / 2.0;
  const PixelBox left{80, top, 80 + half - 40, height - 60.0};
  // From 1 (the bound) unless a value falls below it, so every step is drawn inside the axes.
  double lo = 1.0, hi = 1.1;
  for (auto& v : ratio) {
    std::sort(v.begin(), v.end());
    if (!v.empty()) lo = std::min(lo, v.front()), hi = std::max(hi, v.back() * 1.02);
  }
  const Axes a{left, lo, hi, 0, 1};
  axis(fig, a, true, "driven length / shortest possible");
  axis(fig, a, false, "", 100.0, " %");
  GlCanvas& c = fig.canvas();
  std::vector<LegendEntry> legend;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    if (ratio[m].empty()) continue;
    std::vector<Vec2> steps{{a.px(lo), a.py(0)}};
    for (std::size_t i = 0; i < ratio[m].size(); ++i) {
      steps.push_back({a.px(ratio[m][i]), steps.back().y});
      steps.push_back({a.px(ratio[m][i]), a.py(static_cast<double>(i + 1) / ratio[m].size())});
    }
    steps.push_back({a.px(hi), steps.back().y});
    c.pixel_polyline(steps, 2.2, method_colour(m));
    legend.push_back({method_colour(m), methods[m]});
  }
  fig.text("ECDF of driven length over the shortest possible", left.left, left.top - 10, 14,
           palette::kAxis, Anchor::kLeft, true);
  const PixelBox right{80 + half + 180, top, width_px - 40.0, height - 60.0};
  method_labels(fig, right, methods, counts);
  double tmax = 1;
  for (const auto& v : times)
    for (double t : v) tmax = std::max(tmax, t * 1.05);
  const double row_h = right.height() / std::max<std::size_t>(methods.size(), 1);
  const Axes b{right, 0, tmax, 0, 1};
  axis(fig, b, true, "time to dock (s)");
  c.pixel_line({right.left, right.bottom}, {right.left, right.top}, 1.0, palette::kAxis);
  for (std::size_t m = 0; m < methods.size(); ++m)
    for (std::size_t i = 0; i < times[m].size(); ++i) {
      const double x = b.px(times[m][i]),
                   y = right.top + (m + 0.5) * row_h + 0.3 * row_h * jitter(i);
      c.pixel_line({x - 2.5, y}, {x + 2.5, y}, 5.0, method_colour(m));
    }
  fig.text("Time to dock", right.left, right.top - 10, 14, palette::kAxis, Anchor::kLeft, true);
  fig.legend(20, 76, legend, std::max(1, std::min(6, static_cast<int>(legend.size()))),
             (width_px - 40.0) / 6);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

Image draw_time_by_world(const std::vector<EpisodeOutcome>& episodes, int width_px,
                         FigureLayout* layout_out) {
  const std::vector<std::string> methods = methods_of(episodes);
  std::vector<std::string> worlds;  // in first-met order, as the methods
  for (const auto& e : episodes)
    if (std::find(worlds.begin(), worlds.end(), e.world) == worlds.end()) worlds.push_back(e.world);
  const double row_h = 34, panel_gap = 74, top = 100;
  const double panel_h = row_h * static_cast<double>(std::max<std::size_t>(methods.size(), 1));
  // As many worlds as a figure can hold (16,384 pixels a side; 12,000 kept): 30 worlds of 14
  // configurations stopped a batch's report after its episodes. The tables list every world.
  const std::size_t all_worlds = worlds.size();
  const auto fit = static_cast<std::size_t>(
      std::max(1.0, std::floor((kMaxChartHeight_px - top - 10) / (panel_h + panel_gap))));
  if (worlds.size() > fit) worlds.resize(fit);
  const int height = static_cast<int>(
      std::min(kMaxChartHeight_px, top + worlds.size() * (panel_h + panel_gap) + 10));
  Figure fig(width_px, height);
  fig.text(worlds.size() < all_worlds
               ? "Time to dock, world by world: the first " + std::to_string(worlds.size()) +
                     " of " + std::to_string(all_worlds) + " worlds (the tables list every one)"
               : std::string("Time to dock, world by world"),
           20, 28, 18, palette::kAxis, Anchor::kLeft, true);
  fig.text(
      "docked episodes, one dot each (spread vertically to be seen); each world on its own "
      "scale, as worlds differ in size",
      20, 48, 13, palette::kAxis);
  std::vector<LegendEntry> legend;
  for (std::size_t m = 0; m < methods.size(); ++m) legend.push_back({method_colour(m), methods[m]});
  fig.legend(20, 62, legend, std::max(1, std::min(6, static_cast<int>(legend.size()))),
             (width_px - 40.0) / 6);
  GlCanvas& c = fig.canvas();
  for (std::size_t w = 0; w < worlds.size(); ++w) {
    std::vector<std::vector<double>> times(methods.size());
    std::vector<std::size_t> counts(methods.size(), 0);
    double tmax = 1;
    for (const auto& e : episodes)
      if (e.world == worlds[w] && e.docked) {
        const std::size_t m = method_index(methods, e.method);
        times[m].push_back(e.time_s);
        ++counts[m];
        tmax = std::max(tmax, e.time_s * 1.05);
      }
    const double y0 = top + 30 + w * (panel_h + panel_gap);
    const PixelBox box{300, y0, width_px - 40.0, y0 + panel_h};
    const Axes a{box, 0, tmax, 0, 1};
    axis(fig, a, true, "time to dock (s)");
    c.pixel_line({box.left, box.bottom}, {box.left, box.top}, 1.0, palette::kAxis);
    method_labels(fig, box, methods, counts);
    for (std::size_t m = 0; m < methods.size(); ++m)
      for (std::size_t i = 0; i < times[m].size(); ++i) {
        const double x = a.px(times[m][i]),
                     y = box.top + (m + 0.5) * row_h + 0.3 * row_h * jitter(i);
        c.pixel_line({x - 2.5, y}, {x + 2.5, y}, 5.0, method_colour(m));
      }
    fig.text_fitted(worlds[w], 20, box.top - 10, 14, palette::kAxis, width_px - 40.0, true);
  }
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

Image draw_episode_paths(const worlds::World& world, const std::vector<EpisodePath>& paths,
                         const std::string& title, const std::string& success_word, int width_px,
                         int height_px, FigureLayout* layout_out) {
  Figure fig(width_px, height_px);
  const double column = width_px - 230.0;
  const PixelTransform t = fig.world_panel(world.floor, {70, 76, column - 20, height_px - 50.0});
  GlCanvas& c = fig.canvas();
  draw_floor(c, world);
  const bool obstacles = draw_obstacles(c, world);
  // At most kMaxDrawn of each kind, evenly chosen: a figure's cost must not grow with a
  // million-episode batch.
  constexpr std::size_t kMaxDrawn = 2000;
  std::vector<const EpisodePath*> ok, bad;
  for (const EpisodePath& p : paths) (p.succeeded ? ok : bad).push_back(&p);
  auto chosen = [](const std::vector<const EpisodePath*>& all) {
    std::vector<const EpisodePath*> out;
    const std::size_t step = (all.size() + kMaxDrawn - 1) / kMaxDrawn;
    for (std::size_t i = 0; i < all.size(); i += std::max<std::size_t>(step, 1))
      out.push_back(all[i]);
    return out;
  };
  const std::vector<const EpisodePath*> ok_drawn = chosen(ok), bad_drawn = chosen(bad);
  const std::size_t succeeded = ok.size(), failed = bad.size();
  for (const EpisodePath* p : ok_drawn)
    if (p->points.size() > 1) c.polyline(p->points, 1.2, palette::kTrajectory);
  for (const EpisodePath* p : bad_drawn)
    if (p->points.size() > 1) c.polyline(p->points, 2.2, palette::kFailure);
  const double dot = 3.0 / t.scale;
  for (const auto* set : {&ok_drawn, &bad_drawn})
    for (const EpisodePath* p : *set)
      if (!p->points.empty()) c.fill_disk(p->points.front(), dot, palette::kStart);
  draw_charger(c, world);
  fig.world_axes(world.floor, t);
  fig.text_fitted(title, 70, 26, 18, palette::kAxis, width_px - 90.0, true);
  std::string sub = std::to_string(paths.size()) + " episodes: " + std::to_string(succeeded) + " " +
                    success_word + ", " + std::to_string(failed) + " failed (drawn on top)";
  if (ok_drawn.size() < ok.size() || bad_drawn.size() < bad.size())
    sub += "; drawn: " + std::to_string(ok_drawn.size()) + " " + success_word + " and " +
           std::to_string(bad_drawn.size()) + " failed, evenly chosen";
  fig.text_fitted(sub, 70, 46, 13, palette::kAxis, width_px - 90.0);
  std::vector<LegendEntry> legend;
  if (obstacles) legend.push_back({palette::kObstacle, "obstacle"});
  if (obstacles && world.planning_inflation_m() > 0)
    legend.push_back({palette::kInflation, "margin"});
  if (succeeded) legend.push_back({palette::kTrajectory, success_word});
  if (failed) legend.push_back({palette::kFailure, "failed"});
  if (!paths.empty()) legend.push_back({palette::kStart, "starts"});
  legend.push_back({palette::kCharger, "charger"});
  fig.legend(column, 100, legend);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

Image draw_sweep_chart(const std::string& parameter, const std::vector<double>& values,
                       const std::vector<RateRow>& rows, int width_px, FigureLayout* layout_out) {
  const int height = 560;
  Figure fig(width_px, height);
  fig.text_fitted("Success against " + parameter, 20, 28, 18, palette::kAxis, width_px - 40.0,
                  true);
  fig.text("every value's success rate, its Wilson 95 % band and the gate", 20, 48, 13,
           palette::kAxis);
  const PixelBox box{90, 110, width_px - 40.0, height - 70.0};
  double lo = values.empty() ? 0 : *std::min_element(values.begin(), values.end());
  double hi = values.empty() ? 1 : *std::max_element(values.begin(), values.end());
  if (!(hi > lo)) lo -= 0.5, hi += 0.5;
  const double pad = 0.04 * (hi - lo);
  const Axes a{box, lo - pad, hi + pad, 0, 1.0};
  GlCanvas& c = fig.canvas();
  // The band, one pixel column at a time between consecutive values.
  for (std::size_t i = 0; i + 1 < values.size() && i + 1 < rows.size(); ++i) {
    const double x0 = a.px(values[i]), x1 = a.px(values[i + 1]);
    for (double x = x0; x < x1; x += 1.0) {
      const double f = (x - x0) / (x1 - x0);
      const double l = rows[i].low + f * (rows[i + 1].low - rows[i].low),
                   h = rows[i].high + f * (rows[i + 1].high - rows[i].high);
      c.pixel_line({x + 0.5, a.py(l)}, {x + 0.5, a.py(h)}, 1.0, kBand);
    }
  }
  axis(fig, a, true, parameter);
  axis(fig, a, false, "", 100.0, " %");
  std::vector<Vec2> line;
  double gate = -1;
  for (std::size_t i = 0; i < values.size() && i < rows.size(); ++i) {
    const double rate =
        rows[i].episodes ? static_cast<double>(rows[i].successes) / rows[i].episodes : 0.0;
    line.push_back({a.px(values[i]), a.py(rate)});
    gate = std::max(gate, rows[i].gate);
  }
  c.pixel_polyline(line, 2.2, palette::kOkabeBlue);
  for (const Vec2& p : line) c.pixel_line({p.x - 3, p.y}, {p.x + 3, p.y}, 6.0, palette::kOkabeBlue);
  std::vector<LegendEntry> legend = {{palette::kOkabeBlue, "success rate"},
                                     {kBand, "Wilson 95 % band"}};
  if (gate >= 0) {
    c.pixel_line({box.left, a.py(gate)}, {box.right, a.py(gate)}, 2.0, palette::kCollisionMark);
    legend.push_back({palette::kCollisionMark, "gate"});
  }
  fig.legend(20, 76, legend, static_cast<int>(legend.size()), 200);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
