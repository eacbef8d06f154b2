// Sweeps of each region and the table of D between them.
#include "planner/coverage/sweep_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace plantsim::planner {
double distance_scale(const RegionDistances& d) {
  double largest = 0;
  auto take = [&](double v) {
    if (std::isfinite(v)) largest = std::max(largest, v);
  };
  for (std::size_t x = 0; x < d.between.size(); ++x) {
    take(d.from_start[x]);
    take(d.to_end[x]);
    for (double v : d.between[x]) take(v);
  }
  return largest > 0 ? largest : 1.0;
}

SweepModel::SweepModel(const CoverageGrid& grid, std::vector<CellRect> regions, Cell start,
                       std::optional<Cell> end, CoverageWeights weights)
    : grid_(grid), regions_(std::move(regions)), start_(start), end_(end), weights_(weights) {
  if (regions_.size() > static_cast<std::size_t>(kMaxRegions))
    throw std::invalid_argument(std::to_string(regions_.size()) +
                                " sub-regions: more than the coverage planners' limit of " +
                                std::to_string(kMaxRegions) +
                                " (use larger cells or a smaller work area)");
  // Up to eight sweeps per region; a one-cell-wide region has fewer distinct ones.
  for (const CellRect& r : regions_) {
    std::vector<SweepVariant> vs;
    for (bool along_x : {true, false})
      for (int corner = 0; corner < 4; ++corner) {
        SweepVariant v{sweep(r, corner, along_x), 0};
        v.turns = turns_along(v.cells);
        if (std::none_of(vs.begin(), vs.end(),
                         [&](const SweepVariant& o) { return o.cells == v.cells; }))
          vs.push_back(std::move(v));
      }
    offset_.push_back(nodes_);
    nodes_ += vs.size();
    variants_.push_back(std::move(vs));
  }
  const double inf = std::numeric_limits<double>::infinity();
  cost_.assign(nodes_ * nodes_, inf);
  to_end_.assign(nodes_, 0.0);
  // One breadth-first search per distinct first cell of a sweep, then every sweep's end runs
  // down it.
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> by_first_cell;
  for (int j = 0; j < this->regions(); ++j)
    for (int w = 0; w < variants(j); ++w) {
      const Cell c = variants_[j][w].cells.front();
      by_first_cell[{c.column, c.row}].push_back({j, w});
    }
  for (const auto& [cell, sweeps] : by_first_cell) {
    const std::vector<int> dist = grid_.distances_from({Cell{cell.first, cell.second}});
    for (int i = kStart; i < this->regions(); ++i)
      for (int v = 0; v < (i == kStart ? 1 : variants(i)); ++v) {
        const std::vector<Cell> way = grid_.descend(dist, end_cell(i, v), end_heading(i, v));
        if (way.empty()) continue;
        for (const auto& [j, w] : sweeps)
          if (j != i)
            cost_[node(i, v) * nodes_ + node(j, w)] = junction_cost(i, v, way, &variants_[j][w]);
      }
  }
  if (end_) {
    const std::vector<int> dist = grid_.distances_from({*end_});
    for (int i = 0; i < this->regions(); ++i)
      for (int v = 0; v < variants(i); ++v) {
        const std::vector<Cell> way = grid_.descend(dist, end_cell(i, v), end_heading(i, v));
        to_end_[node(i, v)] = way.empty() ? inf : junction_cost(i, v, way, nullptr);
      }
  }
}

Cell SweepModel::end_cell(int i, int v) const {
  return i == kStart ? start_ : variants_[i][v].cells.back();
}

int SweepModel::end_heading(int i, int v) const {
  if (i == kStart || variants_[i][v].cells.size() < 2) return -1;
  const auto& c = variants_[i][v].cells;
  return heading_between(c[c.size() - 2], c.back());
}

double SweepModel::junction_cost(int i, int v, const std::vector<Cell>& way,
                                 const SweepVariant* next) const {
  // Turns where the way leaves the last lane and where it enters the next one count too.
  std::vector<Cell> joined;
  if (i != kStart && variants_[i][v].cells.size() >= 2)
    joined.push_back(variants_[i][v].cells[variants_[i][v].cells.size() - 2]);
  joined.insert(joined.end(), way.begin(), way.end());
  if (next && next->cells.size() >= 2) joined.push_back(next->cells[1]);
  const int turns = turns_along(joined) + (next ? next->turns : 0);
  return weights_.cells * static_cast<double>(way.size() - 1) + weights_.turns * turns;
}

std::vector<Cell> SweepModel::travel(int i, int v, int j, int w) const {
  return grid_.descend(grid_.distances_from({variants_[j][w].cells.front()}), end_cell(i, v),
                       end_heading(i, v));
}

std::vector<Cell> SweepModel::travel_to_end(int i, int v) const {
  if (!end_) return {end_cell(i, v)};
  return grid_.descend(grid_.distances_from({*end_}), end_cell(i, v), end_heading(i, v));
}

RegionDistances SweepModel::region_distances() const {
  const int n = regions();
  const double inf = std::numeric_limits<double>::infinity();
  RegionDistances d;
  d.between.assign(n, std::vector<double>(n, 0.0));
  d.from_start.assign(n, inf);
  d.to_end.assign(n, end_ ? inf : 0.0);
  for (int j = 0; j < n; ++j)
    for (int w = 0; w < variants(j); ++w)
      d.from_start[j] = std::min(d.from_start[j], cost(kStart, 0, j, w));
  for (int i = 0; i < n; ++i) {
    if (end_)
      for (int v = 0; v < variants(i); ++v) d.to_end[i] = std::min(d.to_end[i], cost_to_end(i, v));
    for (int j = 0; j < n; ++j) {
      if (i == j) continue;
      double best = inf;
      for (int v = 0; v < variants(i); ++v)
        for (int w = 0; w < variants(j); ++w) best = std::min(best, cost(i, v, j, w));
      d.between[i][j] = best;
    }
  }
  return d;
}

SweepModel::Sweeps SweepModel::best_sweeps(const std::vector<int>& order) const {
  Sweeps out;
  if (order.empty()) return out;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<int>> from(order.size());
  std::vector<double> best(variants(order[0]));
  for (int w = 0; w < variants(order[0]); ++w) best[w] = cost(kStart, 0, order[0], w);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const int i = order[k - 1], j = order[k];
    std::vector<double> next(variants(j), inf);
    from[k].assign(variants(j), 0);
    for (int w = 0; w < variants(j); ++w)
      for (int v = 0; v < variants(i); ++v) {
        const double c = best[v] + cost(i, v, j, w);
        if (c < next[w]) next[w] = c, from[k][w] = v;
      }
    best = std::move(next);
  }
  int last = 0;
  for (int v = 0; v < variants(order.back()); ++v) {
    best[v] += cost_to_end(order.back(), v);
    if (best[v] < best[last]) last = v;
  }
  out.cost = best[last];
  out.variants.assign(order.size(), 0);
  for (std::size_t k = order.size(); k-- > 0;) {
    out.variants[k] = last;
    if (k > 0) last = from[k][last];
  }
  return out;
}

}  // namespace plantsim::planner
