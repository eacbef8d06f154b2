// Seed 004's sub-regions as the order solvers see them. Each region can be swept in up to eight
// ways (a start corner, lanes along x or along y); going from the end of one region's sweep to
// the start of the next and sweeping it costs the document's distance D = w1 * cells travelled
// + w2 * turns (on the way, where the way meets the sweeps, and inside the next sweep). The
// document's D_ij only names the cell distance and the turns; which corner a sweep ends at, and
// so where the next one can start, is plantsim's reading of it. The path runs from the start
// cell through every region once to the end cell (the document: from the start region to the
// end region), when there is one.
#pragma once

#include <optional>
#include <vector>

#include "planner/coverage/coverage_grid.h"

namespace plantsim::planner {

/// The document's weights of D (its experiment: w1 = 0.8, w2 = 0.2).
struct CoverageWeights {
  double cells = 0.8;
  double turns = 0.2;
};

struct SweepVariant {
  std::vector<Cell> cells;  ///< the region's cells in sweeping order
  int turns = 0;            ///< turns inside the sweep
};

/// Region-level distances for solvers that order regions only (the networks): the cheapest way
/// between two regions over all their sweeps.
struct RegionDistances {
  std::vector<std::vector<double>> between;  ///< [from][to]
  std::vector<double> from_start, to_end;    ///< to_end is all zero without an end cell
};

/// The largest finite distance (1 if none is positive): the networks scale by it, so that their
/// constants mean the same on every map.
double distance_scale(const RegionDistances& d);

class SweepModel {
 public:
  /// Throws std::invalid_argument when the regions are too many to tabulate (over 400).
  SweepModel(const CoverageGrid& grid, std::vector<CellRect> regions, Cell start,
             std::optional<Cell> end, CoverageWeights weights = {});

  static constexpr int kStart = -1;  ///< "region" index of the start cell (one variant, 0)
  static constexpr int kMaxRegions = 400;

  int regions() const { return static_cast<int>(regions_.size()); }
  const CellRect& region(int i) const { return regions_[i]; }
  int variants(int i) const { return static_cast<int>(variants_[i].size()); }
  const SweepVariant& variant(int i, int v) const { return variants_[i][v]; }
  bool has_end() const { return end_.has_value(); }
  const CoverageWeights& weights() const { return weights_; }

  /// D from the end of region i's sweep v (i = kStart: the start cell) to region j's sweep w,
  /// including sweeping it.
  double cost(int i, int v, int j, int w) const { return cost_[node(i, v) * nodes_ + node(j, w)]; }
  /// D from the end of region i's sweep v to the end cell; 0 without an end.
  double cost_to_end(int i, int v) const { return to_end_[node(i, v)]; }
  /// The cells travelled between them (both ends included), as the costs counted them.
  std::vector<Cell> travel(int i, int v, int j, int w) const;
  std::vector<Cell> travel_to_end(int i, int v) const;

  RegionDistances region_distances() const;

  struct Sweeps {
    double cost = 0;            ///< sum of D along the order, with the end
    std::vector<int> variants;  ///< per position in the order
  };
  /// The best sweep of each region for a given order (dynamic programming along it).
  Sweeps best_sweeps(const std::vector<int>& order) const;

 private:
  std::size_t node(int i, int v) const { return i == kStart ? 0 : offset_[i] + v; }
  Cell end_cell(int i, int v) const;
  int end_heading(int i, int v) const;
  double junction_cost(int i, int v, const std::vector<Cell>& way, const SweepVariant* next) const;

  const CoverageGrid& grid_;
  std::vector<CellRect> regions_;
  Cell start_;
  std::optional<Cell> end_;
  CoverageWeights weights_;
  std::vector<std::vector<SweepVariant>> variants_;
  std::vector<std::size_t> offset_;
  std::size_t nodes_ = 1;
  std::vector<double> cost_, to_end_;
};

}  // namespace plantsim::planner
