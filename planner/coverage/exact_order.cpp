// Branch and bound over sub-region orders, with dominance pruning.
#include "planner/coverage/exact_order.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <random>
#include <unordered_map>

#include "planner/coverage/order_lp.h"

namespace plantsim::planner {
namespace {

constexpr int kMaxVariants = 8;
constexpr int kMaxSearchedRegions = 63;  // the state key is a 64-bit set
constexpr int kMultiplierSteps = 1000;
constexpr int kRelaxedDepth = 2;     // prefixes up to this long solve the relaxation again
constexpr int kPerturbations = 100;  // of the starting order, before the search
constexpr std::uint64_t kPerturbationSeed = 4;
// Work of the local search before the search (regions in the orders evaluated; about 2 s on
// docs/seeds.md's machine): every perturbation on maps up to 31 regions (25 million), fewer on
// larger ones; a count, not a time, so that the result does not depend on the machine's load.
constexpr std::uint64_t kLocalSearchWork = 30'000'000;
using Costs = std::array<double, kMaxVariants>;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct StateKey {
  std::uint64_t done;
  int last;
  friend bool operator==(const StateKey&, const StateKey&) = default;
};
struct StateHash {
  std::size_t operator()(const StateKey& k) const {
    return std::hash<std::uint64_t>()(k.done * 0x9E3779B97F4A7C15ull ^ k.last);
  }
};

class Search {
 public:
  Search(const SweepModel& m, OrderRelaxation& relaxation, const ExactOrderOptions& o,
         std::vector<int> incumbent, double incumbent_cost)
      : m_(m),
        relaxation_(relaxation),
        options_(o),
        n_(m.regions()),
        best_order_(std::move(incumbent)),
        best_cost_(incumbent_cost),
        deadline_(std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                      std::chrono::duration<double>(o.time_limit_s))) {
    // Region-level cheapest costs (over all sweeps): between regions, from the start (row n) and
    // to the end (column n).
    cheapest_.assign(static_cast<std::size_t>(n_ + 1) * (n_ + 1), kInf);
    for (int i = -1; i < n_; ++i)
      for (int v = 0; v < (i < 0 ? 1 : m_.variants(i)); ++v) {
        const int row = i < 0 ? n_ : i;
        for (int j = 0; j < n_; ++j)
          if (j != i)
            for (int w = 0; w < m_.variants(j); ++w)
              at(row, j) = std::min(at(row, j), m_.cost(i, v, j, w));
        if (i >= 0) at(i, n_) = std::min(at(i, n_), m_.cost_to_end(i, v));
      }
    // Sweep-level tables for the split bound: travel (D without the next sweep's own turns)
    // into each sweep from each region's cheapest end, and out of each sweep to each region.
    into_.assign(static_cast<std::size_t>(n_ + 1) * n_ * kMaxVariants, kInf);
    out_of_.assign(static_cast<std::size_t>(n_) * kMaxVariants * (n_ + 1), kInf);
    for (int i = -1; i < n_; ++i)
      for (int v = 0; v < (i < 0 ? 1 : m_.variants(i)); ++v)
        for (int j = 0; j < n_; ++j)
          if (j != i)
            for (int w = 0; w < m_.variants(j); ++w) {
              const double t = m_.cost(i, v, j, w) - own(j, w);
              double& in = into_[(static_cast<std::size_t>(i + 1) * n_ + j) * kMaxVariants + w];
              in = std::min(in, t);
              if (i >= 0) {
                double& out =
                    out_of_[(static_cast<std::size_t>(i) * kMaxVariants + v) * (n_ + 1) + j];
                out = std::min(out, t);
              }
            }
    for (int i = 0; i < n_; ++i)
      for (int v = 0; v < m_.variants(i); ++v)
        out_of_[(static_cast<std::size_t>(i) * kMaxVariants + v) * (n_ + 1) + n_] =
            m_.has_end() ? m_.cost_to_end(i, v) : 0.0;
  }

  bool run() {
    Costs none{};
    none.fill(kInf);
    none[0] = 0;
    root_bound_ = still_to_come(0, SweepModel::kStart);
    tune_multipliers(none);
    root_bound_ = std::max(root_bound_, split_bound(0, SweepModel::kStart, none));
    prefix_.clear();
    OrderRelaxation::Bound root = relaxation_.solve(prefix_, deadline_);
    if (root.solved)
      root_bound_ = std::max(root_bound_, root.value), relaxed_.push_back(relaxed(std::move(root)));
    expand(0, SweepModel::kStart, none, none);
    return !timed_out_;
  }

  const std::vector<int>& order() const { return best_order_; }
  double cost() const { return best_cost_; }
  double root_bound() const { return root_bound_; }
  std::uint64_t prefixes() const { return prefixes_; }

 private:
  double& at(int i, int j) { return cheapest_[static_cast<std::size_t>(i) * (n_ + 1) + j]; }
  double at(int i, int j) const { return cheapest_[static_cast<std::size_t>(i) * (n_ + 1) + j]; }

  // A lower bound of what follows a prefix over `done` ending at `last`: every region left is
  // entered from the last one or from another region left, and every one of them and the last
  // is left for a region left or the end; the larger of the two sums.
  double still_to_come(std::uint64_t done, int last) const {
    const int last_row = last == SweepModel::kStart ? n_ : last;
    double in = 0, out = 0;
    bool any_left = false;
    for (int j = 0; j < n_; ++j) {
      if (done >> j & 1) continue;
      any_left = true;
      double best_in = at(last_row, j), best_out = m_.has_end() ? at(j, n_) : 0.0;
      for (int i = 0; i < n_; ++i)
        if (i != j && !(done >> i & 1))
          best_in = std::min(best_in, at(i, j)), best_out = std::min(best_out, at(j, i));
      in += best_in;
      out += best_out;
    }
    if (last != SweepModel::kStart && m_.has_end()) {
      double best_out = any_left ? kInf : at(last, n_);
      for (int j = 0; j < n_; ++j)
        if (!(done >> j & 1)) best_out = std::min(best_out, at(last, j));
      out += best_out;
    }
    return std::max(in, out);
  }

  // The relaxation solved for a prefix: its reduced costs, and the cheapest of them between
  // regions (over all sweeps), laid out as cheapest_.
  struct Relaxed {
    double base;
    std::vector<double> reduced, cheapest;
  };
  Relaxed relaxed(OrderRelaxation::Bound&& b) const {
    Relaxed r{b.base, std::move(b.reduced), std::vector<double>(cheapest_.size(), kInf)};
    for (int i = -1; i < n_; ++i)
      for (int v = 0; v < (i < 0 ? 1 : m_.variants(i)); ++v) {
        double* row = &r.cheapest[static_cast<std::size_t>(i < 0 ? n_ : i) * (n_ + 1)];
        for (int j = 0; j < n_; ++j)
          if (j != i)
            for (int w = 0; w < m_.variants(j); ++w)
              row[j] = std::min(row[j], r.reduced[relaxation_.way(i, v, j, w)]);
        if (i >= 0) row[n_] = std::min(row[n_], r.reduced[relaxation_.way_to_end(i, v)]);
      }
    return r;
  }
  double reduced(int i, int v, int j, int w) const {
    return relaxed_.back().reduced[relaxation_.way(i, v, j, w)];
  }
  double reduced_to_end(int i, int v) const {
    return relaxed_.back().reduced[relaxation_.way_to_end(i, v)];
  }

  // The current prefix's cheapest reduced cost for every sweep of its last region.
  Costs prefix_reduced() const {
    Costs at{};
    at.fill(kInf);
    at[0] = 0;
    int from = SweepModel::kStart;
    for (int r : prefix_) {
      Costs next{};
      next.fill(kInf);
      for (int w = 0; w < m_.variants(r); ++w)
        for (int v = 0; v < (from == SweepModel::kStart ? 1 : m_.variants(from)); ++v)
          next[w] = std::min(next[w], at[v] + reduced(from, v, r, w));
      at = next, from = r;
    }
    return at;
  }

  // The relaxation's bound of the orders that start with a prefix: its base, the prefix's
  // reduced cost and the larger of two sums of reduced ways: into every region left (from the
  // last region or another one left) and to the end from one left; or out of every region left
  // (to another one or the end) and out of the last region.
  double reduced_bound(std::uint64_t done, int last, const Costs& prefix_reduced) const {
    const Relaxed& r = relaxed_.back();
    const int last_variants = last == SweepModel::kStart ? 1 : m_.variants(last);
    double prefix = kInf;
    for (int v = 0; v < last_variants; ++v) prefix = std::min(prefix, prefix_reduced[v]);
    const int last_row = last == SweepModel::kStart ? n_ : last;
    auto rc = [&](int row, int j) {
      return r.cheapest[static_cast<std::size_t>(row) * (n_ + 1) + j];
    };
    double rest_in = 0, to_end = kInf, rest_out = 0, last_out = kInf;
    bool any_left = false;
    for (int j = 0; j < n_; ++j) {
      if (done >> j & 1) continue;
      any_left = true;
      double in = rc(last_row, j), out = rc(j, n_);
      for (int i = 0; i < n_; ++i)
        if (i != j && !(done >> i & 1)) in = std::min(in, rc(i, j)), out = std::min(out, rc(j, i));
      rest_in += in;
      rest_out += out;
      to_end = std::min(to_end, rc(j, n_));
      last_out = std::min(last_out, rc(last_row, j));
    }
    if (!any_left) {
      double whole = kInf;
      for (int v = 0; v < last_variants; ++v)
        whole = std::min(whole, prefix_reduced[v] + reduced_to_end(last, v));
      return r.base + whole;
    }
    return r.base + prefix + std::max(rest_in + to_end, rest_out + last_out);
  }

  double own(int j, int w) const { return m_.weights().turns * m_.variant(j, w).turns; }

  double into(int i, int j, int w) const {
    return into_[(static_cast<std::size_t>(i + 1) * n_ + j) * kMaxVariants + w];
  }
  double out_of(int j, int w, int k) const {
    return out_of_[(static_cast<std::size_t>(j) * kMaxVariants + w) * (n_ + 1) + k];
  }
  // Multiplier of the way from i (kStart: the start) to j (n_: the end).
  double& pi(int i, int j) { return pi_[static_cast<std::size_t>(i + 1) * (n_ + 1) + j]; }
  double pi(int i, int j) const { return pi_[static_cast<std::size_t>(i + 1) * (n_ + 1) + j]; }

  // Another lower bound, of the whole order, that keeps each sweep's way in and way out
  // together: every way joins two sweeps, so half of it is charged to each end of it; each
  // region left pays its own turns, half its cheapest way in (from the last region or one left)
  // and half its cheapest way out (to one left or the end) for the same sweep; the last region
  // pays half its way out for the sweep its prefix ended with, the end half its way in. A
  // multiplier pi(a, b) is added to the way a -> b where b pays for it and taken off where a
  // does: on any order the two cancel, so every choice of them gives a bound, and the root's
  // are raised by subgradient steps until the bound stops rising (Lagrangian relaxation of
  // "the way b was entered by is the way a left by"). Without an end the end is a free node.
  struct Choices {
    std::vector<int> in, out;  // per region left: where its cheapest way came from, went to
    int last_out = -1, end_in = -1;
  };
  double split_bound(std::uint64_t done, int last, const Costs& costs,
                     Choices* chosen = nullptr) const {
    bool any_left = false;
    double total = 0, end_in = kInf;
    int end_from = -1;
    const int last_variants = last == SweepModel::kStart ? 1 : m_.variants(last);
    if (chosen) chosen->in.assign(n_, -2), chosen->out.assign(n_, -2);
    for (int j = 0; j < n_; ++j) {
      if (done >> j & 1) continue;
      any_left = true;
      double best = kInf;
      for (int w = 0; w < m_.variants(j); ++w) {
        double in = 0.5 * into(last, j, w) + pi(last, j), out = 0.5 * out_of(j, w, n_) - pi(j, n_);
        int from = last, to = n_;
        for (int i = 0; i < n_; ++i)
          if (i != j && !(done >> i & 1)) {
            const double a = 0.5 * into(i, j, w) + pi(i, j), b = 0.5 * out_of(j, w, i) - pi(j, i);
            if (a < in) in = a, from = i;
            if (b < out) out = b, to = i;
          }
        const double e = 0.5 * out_of(j, w, n_) + pi(j, n_);
        if (e < end_in) end_in = e, end_from = j;
        if (own(j, w) + in + out < best) {
          best = own(j, w) + in + out;
          if (chosen) chosen->in[j] = from, chosen->out[j] = to;
        }
      }
      total += best;
    }
    if (!any_left) {  // only the way to the end is left, whole
      double whole = kInf;
      for (int v = 0; v < last_variants; ++v)
        whole = std::min(whole, costs[v] + m_.cost_to_end(last, v));
      return whole;
    }
    double prefix = kInf;
    for (int v = 0; v < last_variants; ++v) {
      double out = kInf;
      int to = -1;
      for (int k = 0; k < n_; ++k) {
        if (done >> k & 1) continue;
        double way = kInf;
        if (last == SweepModel::kStart) {
          for (int w = 0; w < m_.variants(k); ++w)
            way = std::min(way, into(SweepModel::kStart, k, w));
        } else {
          way = out_of(last, v, k);
        }
        if (0.5 * way - pi(last, k) < out) out = 0.5 * way - pi(last, k), to = k;
      }
      if (costs[v] + out < prefix) {
        prefix = costs[v] + out;
        if (chosen) chosen->last_out = to;
      }
    }
    if (chosen) chosen->end_in = end_from;
    return prefix + total + end_in;
  }

  // Raises the root's multipliers (Polyak steps towards the incumbent, halved when the bound
  // stalls) and keeps those of the best bound.
  void tune_multipliers(const Costs& root) {
    pi_.assign(static_cast<std::size_t>(n_ + 1) * (n_ + 1), 0.0);
    std::vector<double> best_pi = pi_;
    double best = split_bound(0, SweepModel::kStart, root), theta = 1.0;
    int stalled = 0;
    Choices c;
    for (int step = 0; step < kMultiplierSteps && std::chrono::steady_clock::now() < deadline_;
         ++step) {
      const double bound = split_bound(0, SweepModel::kStart, root, &c);
      if (bound > best + 1e-12)
        best = bound, best_pi = pi_, stalled = 0;
      else if (++stalled > 20)
        theta *= 0.5, stalled = 0;
      // d bound / d pi(a, b): +1 where b's way in came from a, -1 where a's way out went to b.
      std::vector<double> g(pi_.size(), 0.0);
      auto add = [&](int a, int b, double x) {
        g[static_cast<std::size_t>(a + 1) * (n_ + 1) + b] += x;
      };
      for (int j = 0; j < n_; ++j) add(c.in[j], j, 1.0), add(j, c.out[j], -1.0);
      add(SweepModel::kStart, c.last_out, -1.0);
      add(c.end_in, n_, 1.0);
      double norm = 0;
      for (double x : g) norm += x * x;
      if (norm == 0 || !(best_cost_ > bound)) break;  // consistent choices: the bound is an order
      const double length = theta * (best_cost_ - bound) / norm;
      for (std::size_t k = 0; k < pi_.size(); ++k) pi_[k] += length * g[k];
    }
    pi_ = best_pi;
  }

  // `costs[v]`: the prefix's cheapest cost ending with its last region swept as v; `prefix_rc[v]`
  // the same in the relaxation's reduced costs.
  void expand(std::uint64_t done, int last, const Costs& costs, Costs prefix_rc) {
    if (timed_out_) return;
    if (++prefixes_ > options_.max_prefixes ||
        (prefixes_ % 1024 == 0 && std::chrono::steady_clock::now() > deadline_)) {
      timed_out_ = true;
      return;
    }
    const int last_variants = last == SweepModel::kStart ? 1 : m_.variants(last);
    if (static_cast<int>(prefix_.size()) == n_) {
      double total = kInf;
      for (int v = 0; v < last_variants; ++v)
        total = std::min(total, costs[v] + m_.cost_to_end(last, v));
      if (total < best_cost_ - 1e-12) best_cost_ = total, best_order_ = prefix_;
      return;
    }
    double so_far = kInf;
    for (int v = 0; v < last_variants; ++v) so_far = std::min(so_far, costs[v]);
    if (so_far + still_to_come(done, last) >= best_cost_ - 1e-12) return;
    if (split_bound(done, last, costs) >= best_cost_ - 1e-12) return;
    // Near the root, the relaxation solved again for this prefix (its subtree is large).
    bool own_relaxation = false;
    if (!relaxed_.empty() && !prefix_.empty() &&
        static_cast<int>(prefix_.size()) <= kRelaxedDepth) {
      OrderRelaxation::Bound b = relaxation_.solve(prefix_, deadline_);
      if (b.solved) {
        if (b.value >= best_cost_ - 1e-12) return;
        relaxed_.push_back(relaxed(std::move(b)));
        own_relaxation = true;
        prefix_rc = prefix_reduced();
      }
    }
    struct Pop {
      std::vector<Relaxed>& stack;
      bool own;
      ~Pop() {
        if (own) stack.pop_back();
      }
    } pop{relaxed_, own_relaxation};
    if (!relaxed_.empty() && reduced_bound(done, last, prefix_rc) >= best_cost_ - 1e-12) return;
    struct Child {
      int region;
      double bound;
      Costs costs, reduced;
    };
    std::vector<Child> children;
    for (int j = 0; j < n_; ++j) {
      if (done >> j & 1) continue;
      Child c{j, kInf, {}, {}};
      c.costs.fill(kInf);
      c.reduced.fill(kInf);
      double low = kInf;
      for (int w = 0; w < m_.variants(j); ++w) {
        for (int v = 0; v < last_variants; ++v) {
          c.costs[w] = std::min(c.costs[w], costs[v] + m_.cost(last, v, j, w));
          if (!relaxed_.empty())
            c.reduced[w] = std::min(c.reduced[w], prefix_rc[v] + reduced(last, v, j, w));
        }
        low = std::min(low, c.costs[w]);
      }
      c.bound = low;
      if (c.bound < best_cost_ - 1e-12) children.push_back(c);
    }
    std::sort(children.begin(), children.end(),
              [](const Child& a, const Child& b) { return a.bound < b.bound; });
    for (const Child& c : children) {
      if (c.bound >= best_cost_ - 1e-12) break;
      const std::uint64_t next = done | (std::uint64_t{1} << c.region);
      if (dominated(next, c.region, c.costs)) continue;
      prefix_.push_back(c.region);
      expand(next, c.region, c.costs, c.reduced);
      prefix_.pop_back();
      if (timed_out_) return;
    }
  }

  // Another prefix over the same regions ending at the same one was at most as dear for every
  // sweep of it: whatever follows this one followed that one too. Records this one otherwise.
  bool dominated(std::uint64_t done, int last, const Costs& costs) {
    const StateKey key{done, last};
    auto it = seen_.find(key);
    if (it == seen_.end()) {
      if (seen_.size() < options_.max_table_states) seen_.emplace(key, costs);
      return false;
    }
    bool beaten = true;
    for (int w = 0; w < m_.variants(last); ++w) beaten = beaten && it->second[w] <= costs[w];
    if (beaten) return true;
    for (int w = 0; w < m_.variants(last); ++w) it->second[w] = std::min(it->second[w], costs[w]);
    return false;
  }

  const SweepModel& m_;
  OrderRelaxation& relaxation_;
  std::vector<Relaxed> relaxed_;  // the innermost prefix's relaxation last
  ExactOrderOptions options_;
  int n_;
  std::vector<int> best_order_, prefix_;
  double best_cost_;
  std::chrono::steady_clock::time_point deadline_;
  std::vector<double> cheapest_, into_, out_of_, pi_;
  double root_bound_ = 0;
  std::unordered_map<StateKey, Costs, StateHash> seen_;
  std::uint64_t prefixes_ = 0;
  bool timed_out_ = false;
};

}  // namespace

namespace {

// Moves single regions and short stretches and reverses stretches while that lowers the cost;
// `work` counts the regions of every order evaluated.
std::vector<int> local_search(const SweepModel& model, std::vector<int> order,
                              std::uint64_t& work) {
  const int n = static_cast<int>(order.size());
  auto cost_of = [&](const std::vector<int>& o) {
    work += static_cast<std::uint64_t>(n);
    return model.best_sweeps(o).cost;
  };
  double cost = cost_of(order);
  for (bool better = true; better;) {
    better = false;
    // Reverse a stretch.
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        std::reverse(order.begin() + a, order.begin() + b + 1);
        const double c = cost_of(order);
        if (c < cost - 1e-12)
          cost = c, better = true;
        else
          std::reverse(order.begin() + a, order.begin() + b + 1);
      }
    // Move a stretch of one to three regions elsewhere.
    for (int length = 1; length <= 3; ++length)
      for (int a = 0; a + length <= n; ++a)
        for (int b = 0; b + length <= n; ++b) {
          if (a == b) continue;
          std::vector<int> moved = order;
          const std::vector<int> stretch(moved.begin() + a, moved.begin() + a + length);
          moved.erase(moved.begin() + a, moved.begin() + a + length);
          moved.insert(moved.begin() + b, stretch.begin(), stretch.end());
          const double c = cost_of(moved);
          if (c < cost - 1e-12) cost = c, order = std::move(moved), better = true;
        }
  }
  return order;
}

// The local search, then perturbations (double bridge: A B C D -> A C B D, which its moves
// cannot undo in one step) each followed by it, keeping the best, until the rounds or the work
// budget are spent.
std::vector<int> perturbed_search(const SweepModel& model, std::vector<int> order) {
  std::uint64_t work = 0;
  order = local_search(model, std::move(order), work);
  double cost = model.best_sweeps(order).cost;
  const int n = static_cast<int>(order.size());
  if (n < 8) return order;
  std::mt19937_64 random(kPerturbationSeed);
  for (int round = 0; round < kPerturbations && work < kLocalSearchWork; ++round) {
    std::array<int, 3> cut{};
    for (int& c : cut) c = 1 + static_cast<int>(random() % static_cast<std::uint64_t>(n - 1));
    std::sort(cut.begin(), cut.end());
    if (cut[0] == cut[1] || cut[1] == cut[2]) continue;
    std::vector<int> next(order.begin(), order.begin() + cut[0]);
    next.insert(next.end(), order.begin() + cut[1], order.begin() + cut[2]);
    next.insert(next.end(), order.begin() + cut[0], order.begin() + cut[1]);
    next.insert(next.end(), order.begin() + cut[2], order.end());
    next = local_search(model, std::move(next), work);
    const double c = model.best_sweeps(next).cost;
    if (c < cost - 1e-12) cost = c, order = std::move(next);
  }
  return order;
}

}  // namespace

ExactOrder exact_order(const SweepModel& model,
                       const std::vector<std::vector<int>>& starting_orders,
                       const ExactOrderOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  ExactOrder out;
  out.cost = kInf;
  const bool searched = model.regions() <= kMaxSearchedRegions;
  for (const std::vector<int>& o : starting_orders) {
    std::vector<int> better = searched ? perturbed_search(model, o) : o;
    const double c = model.best_sweeps(better).cost;
    if (c < out.cost) out.cost = c, out.order = std::move(better);
  }
  out.searched = searched;
  if (searched) {
    OrderRelaxation relaxation(model);
    Search search(model, relaxation, options, out.order, out.cost);
    out.proven = search.run();
    out.order = search.order();
    out.cost = search.cost();
    out.lower_bound = out.proven ? out.cost : search.root_bound();
    out.prefixes = search.prefixes();
  } else {
    out.lower_bound = 0;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace plantsim::planner
