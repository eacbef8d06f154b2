// The order problem's linear relaxation with subtour cuts (GLPK), and the reduced costs from its
// duals.
#include "planner/coverage/order_lp.h"

#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace plantsim::planner {

// A column of the relaxation: one way between sweeps. Outside the anonymous namespace because
// OrderRelaxation::Lp holds them.
struct OrderWay {
  int from_node, to_node;      // the start 0, sweeps, the end
  int from_region, to_region;  // -1 the start, n the end
  double cost;
};

namespace {

constexpr int kMaxCutRounds = 200;
// Max-flow capacities are integers in GLPK: shares scaled by this, rounded down, so a cut found
// below (1 - kCutSlack) is violated in the real numbers too.
constexpr double kFlowScale = 1e9;
constexpr double kCutSlack = 1e-5;

using Graph = std::unique_ptr<glp_graph, decltype(&glp_delete_graph)>;

// Sets of regions the relaxation leaves less than one unit out of: for every region, the source
// side of a minimum cut between it and the end in the graph of regions, if below one.
std::vector<std::vector<char>> violated_cuts(const std::vector<OrderWay>& ways,
                                             const std::vector<double>& x, int n) {
  std::vector<double> share(static_cast<std::size_t>(n) * (n + 1), 0.0);
  for (std::size_t k = 0; k < ways.size(); ++k)
    if (ways[k].from_region >= 0 && x[k] > 0)
      share[static_cast<std::size_t>(ways[k].from_region) * (n + 1) + ways[k].to_region] += x[k];
  struct ArcData {
    double cap;
  };
  struct VertexData {
    int cut;
  };
  Graph g(glp_create_graph(sizeof(VertexData), sizeof(ArcData)), &glp_delete_graph);
  glp_add_vertices(g.get(), n + 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double cap = std::floor(share[static_cast<std::size_t>(i) * (n + 1) + j] * kFlowScale);
      if (i == j || cap <= 0) continue;
      glp_arc* a = glp_add_arc(g.get(), i + 1, j + 1);
      static_cast<ArcData*>(a->data)->cap = cap;
    }
  std::vector<std::vector<char>> cuts;
  for (int source = 0; source < n; ++source) {
    double flow = 0;
    if (glp_maxflow_ffalg(g.get(), source + 1, n + 1, offsetof(ArcData, cap), &flow, -1,
                          offsetof(VertexData, cut)) != 0)
      continue;
    if (flow >= (1 - kCutSlack) * kFlowScale) continue;
    std::vector<char> side(n + 1, 0);
    for (int v = 0; v < n; ++v)
      side[v] = static_cast<char>(static_cast<VertexData*>(g->v[v + 1]->data)->cut != 0);
    if (std::find(cuts.begin(), cuts.end(), side) == cuts.end()) cuts.push_back(std::move(side));
  }
  return cuts;
}

}  // namespace

struct OrderRelaxation::Lp {
  glp_prob* problem = glp_create_prob();
  std::vector<OrderWay> ways;
  int n = 0, end = 0, start_row = 0;
  std::vector<std::vector<char>> cut_sides;
  std::vector<std::vector<int>> columns_out;  // per region + 1 (0: the start): its ways' columns
  std::vector<int> closed;                    // columns closed for the current prefix
  ~Lp() { glp_delete_prob(problem); }
};

OrderRelaxation::OrderRelaxation(const SweepModel& m) : lp_(std::make_unique<Lp>()) {
  const int n = m.regions();
  offset_.resize(n);
  nodes_ = 1;
  for (int i = 0; i < n; ++i) offset_[i] = nodes_, nodes_ += m.variants(i);
  Lp& lp = *lp_;
  lp.n = n;
  lp.end = static_cast<int>(nodes_);
  ++nodes_;
  for (int i = -1; i < n; ++i)
    for (int v = 0; v < (i < 0 ? 1 : m.variants(i)); ++v) {
      const int from = static_cast<int>(node(i, v));
      for (int j = 0; j < n; ++j)
        if (j != i)
          for (int w = 0; w < m.variants(j); ++w)
            lp.ways.push_back({from, static_cast<int>(node(j, w)), i, j, m.cost(i, v, j, w)});
      if (i >= 0) lp.ways.push_back({from, lp.end, i, n, m.cost_to_end(i, v)});
    }
  // Rows: one unit into each region (1..n), balance at each sweep (n + node), one unit out of the
  // start; then the cuts.
  glp_prob* p = lp.problem;
  glp_set_obj_dir(p, GLP_MIN);
  const int sweeps = lp.end - 1;
  lp.start_row = n + sweeps + 1;
  glp_add_rows(p, lp.start_row);
  for (int r = 1; r <= n; ++r) glp_set_row_bnds(p, r, GLP_FX, 1, 1);
  for (int s = 1; s <= sweeps; ++s) glp_set_row_bnds(p, n + s, GLP_FX, 0, 0);
  glp_set_row_bnds(p, lp.start_row, GLP_FX, 1, 1);
  glp_add_cols(p, static_cast<int>(lp.ways.size()));
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0};
  auto put = [&](int row, int col, double value) {
    ia.push_back(row), ja.push_back(col), ar.push_back(value);
  };
  lp.columns_out.assign(n + 1, {});
  for (std::size_t k = 0; k < lp.ways.size(); ++k) {
    const int col = static_cast<int>(k) + 1;
    const OrderWay& w = lp.ways[k];
    glp_set_col_bnds(p, col, GLP_DB, 0, 1);
    glp_set_obj_coef(p, col, w.cost);
    if (w.to_node != lp.end) put(w.to_region + 1, col, 1), put(n + w.to_node, col, 1);
    if (w.from_node == 0)
      put(lp.start_row, col, 1);
    else
      put(n + w.from_node, col, -1);
    lp.columns_out[w.from_region + 1].push_back(col);
  }
  if (n > 0) glp_load_matrix(p, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
}

OrderRelaxation::~OrderRelaxation() = default;

int OrderRelaxation::cuts() const { return static_cast<int>(lp_->cut_sides.size()); }

// Closes every way out of the start and the prefix's regions but the one the prefix takes
// (and opens again those the previous prefix closed).
void OrderRelaxation::close_all_but(const std::vector<int>& prefix) {
  Lp& lp = *lp_;
  for (int col : lp.closed) glp_set_col_bnds(lp.problem, col, GLP_DB, 0, 1);
  lp.closed.clear();
  for (std::size_t t = 0; t < prefix.size(); ++t) {
    const int from = t == 0 ? SweepModel::kStart : prefix[t - 1];
    for (int col : lp.columns_out[from + 1])
      if (lp.ways[col - 1].to_region != prefix[t])
        glp_set_col_bnds(lp.problem, col, GLP_FX, 0, 0), lp.closed.push_back(col);
  }
}

namespace {

// A subtour cut: at least one unit on the ways leaving the regions of `side`.
void add_cut(glp_prob* p, const std::vector<OrderWay>& ways, const std::vector<char>& side) {
  const int row = glp_add_rows(p, 1);
  glp_set_row_bnds(p, row, GLP_LO, 1, 0);
  std::vector<int> index{0};
  std::vector<double> ones{0};
  for (std::size_t k = 0; k < ways.size(); ++k)
    if (ways[k].from_region >= 0 && side[ways[k].from_region] && !side[ways[k].to_region])
      index.push_back(static_cast<int>(k) + 1), ones.push_back(1);
  glp_set_mat_row(p, row, static_cast<int>(index.size()) - 1, index.data(), ones.data());
}

}  // namespace

OrderRelaxation::Bound OrderRelaxation::solve(const std::vector<int>& prefix,
                                              std::chrono::steady_clock::time_point deadline) {
  Bound bound;
  Lp& lp = *lp_;
  const int n = lp.n;
  if (n == 0) return bound;
  glp_prob* p = lp.problem;
  close_all_but(prefix);

  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.meth = GLP_DUALP;
  std::vector<double> x(lp.ways.size());
  // Stopped early (time, rounds), the last optimum without the newest cuts still bounds: their
  // duals count as zero.
  std::size_t cuts_in_solution = 0;
  for (int round = 0;; ++round) {
    const double left =
        std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0 || round == kMaxCutRounds) break;
    parm.tm_lim = static_cast<int>(std::ceil(left * 1000));
    if (glp_simplex(p, &parm) != 0 || glp_get_status(p) != GLP_OPT) {
      // Infeasible with the prefix (no order continues it), or stopped: no bound from here.
      bound.solved = false;
      break;
    }
    bound.solved = true;
    bound.value = glp_get_obj_val(p);
    cuts_in_solution = lp.cut_sides.size();
    for (std::size_t k = 0; k < lp.ways.size(); ++k)
      x[k] = glp_get_col_prim(p, static_cast<int>(k) + 1);
    const std::vector<std::vector<char>> cuts = violated_cuts(lp.ways, x, n);
    if (cuts.empty()) break;
    for (const std::vector<char>& side : cuts) {
      add_cut(p, lp.ways, side);
      lp.cut_sides.push_back(side);
    }
  }
  if (bound.solved) reduce(bound, cuts_in_solution);
  return bound;
}

// The bound holds for any y and any z >= 0, so the reduced costs are computed here from them
// rather than taken from the solver. Closed ways are never on the orders it bounds.
void OrderRelaxation::reduce(Bound& bound, std::size_t cuts_in_solution) const {
  const Lp& lp = *lp_;
  const int n = lp.n;
  auto dual = [&](int row) { return glp_get_row_dual(lp.problem, row); };
  std::vector<double> z(lp.cut_sides.size());
  double base = 0, magnitude = 0;
  for (int r = 1; r <= n; ++r) base += dual(r);
  base += dual(lp.start_row);
  for (std::size_t c = 0; c < lp.cut_sides.size(); ++c) {
    z[c] = c < cuts_in_solution ? std::max(0.0, dual(lp.start_row + 1 + static_cast<int>(c))) : 0.0;
    base += z[c];
  }
  bound.reduced.assign(nodes_ * nodes_, 0.0);
  for (std::size_t k = 0; k < lp.ways.size(); ++k) {
    const OrderWay& w = lp.ways[k];
    double rc = w.cost;
    if (w.to_node != lp.end) rc -= dual(w.to_region + 1) + dual(n + w.to_node);
    rc -= w.from_node == 0 ? dual(lp.start_row) : -dual(n + w.from_node);
    for (std::size_t c = 0; c < lp.cut_sides.size(); ++c)
      if (w.from_region >= 0 && lp.cut_sides[c][w.from_region] && !lp.cut_sides[c][w.to_region])
        rc -= z[c];
    bound.reduced[static_cast<std::size_t>(w.from_node) * nodes_ + w.to_node] = rc;
    magnitude = std::max(magnitude, std::abs(rc) + std::abs(w.cost));
  }
  // Rounding in the duals' sums: a margin far below any cost difference the weights make.
  bound.base = base - 1e-9 * (1 + std::abs(base) + magnitude) * static_cast<double>(n + 1);
}

}  // namespace plantsim::planner
