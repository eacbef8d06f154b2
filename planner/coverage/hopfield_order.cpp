// The Hopfield-Tank network integrated by Euler steps, restarted from random inputs.
#include "planner/coverage/hopfield_order.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace plantsim::planner {
namespace {

double path_cost(const RegionDistances& d, const std::vector<int>& order) {
  double c = d.from_start[order.front()] + d.to_end[order.back()];
  for (std::size_t k = 1; k < order.size(); ++k) c += d.between[order[k - 1]][order[k]];
  return c;
}

// The order a permutation matrix stands for, if the outputs are one.
std::optional<std::vector<int>> read_permutation(const Eigen::MatrixXd& v) {
  const int n = static_cast<int>(v.rows());
  std::vector<int> order(n, -1);
  for (int k = 0; k < n; ++k)
    for (int x = 0; x < n; ++x)
      if (v(x, k) > 0.5) {
        if (order[k] >= 0) return std::nullopt;
        order[k] = x;
      }
  std::vector<int> seen(n, 0);
  for (int x : order) {
    if (x < 0 || seen[x]++) return std::nullopt;
  }
  return order;
}

// Steps before a still network counts as settled (the first steps move slowly everywhere).
constexpr int kWarmUpSteps = 100;

}  // namespace

HopfieldResult hopfield_order(const RegionDistances& dist, const HopfieldParams& p) {
  const int n = static_cast<int>(dist.between.size());
  HopfieldResult result;
  if (n == 0) return result;
  if (n == 1) {
    result.order = std::vector<int>{0};
    result.valid = result.restarts = result.settled = 1;
    return result;
  }
  const double dmax = distance_scale(dist);
  Eigen::MatrixXd d(n, n);
  Eigen::VectorXd from_start(n), to_end(n);
  for (int x = 0; x < n; ++x) {
    from_start[x] = dist.from_start[x] / dmax;
    to_end[x] = dist.to_end[x] / dmax;
    for (int y = 0; y < n; ++y)
      d(x, y) = x == y ? 0.0 : 0.5 * (dist.between[x][y] + dist.between[y][x]) / dmax;
  }
  std::mt19937_64 rng(p.seed);
  std::uniform_real_distribution<double> noise(-p.init_noise * p.u0, p.init_noise * p.u0);
  // Inputs that give every output 1/n, so that the activity starts at n.
  const double u_even = p.u0 * std::atanh(2.0 / n - 1.0);
  double best_cost = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd u(n, n), v(n, n), neighbours(n, n), grad(n, n);
  for (int restart = 0; restart < p.restarts; ++restart) {
    ++result.restarts;
    for (int x = 0; x < n; ++x)
      for (int k = 0; k < n; ++k) u(x, k) = u_even + noise(rng);
    v = (0.5 * (1.0 + (u.array() / p.u0).tanh())).matrix();
    bool settled = false;
    for (int step = 0; step < p.max_steps && !settled; ++step) {
      // dE/dV for E = alpha/2 sum_x sum_k sum_{l!=k} V_xk V_xl + beta/2 sum_k sum_x sum_{y!=x} V_xk
      // V_yk
      //   + gamma/2 (sum V - target)^2 + eta/2 sum_x sum_y sum_k d_xy V_xk (V_y,k+1 + V_y,k-1)
      //   + eta (sum_x d_start,x V_x,0 + sum_x d_x,end V_x,n-1)
      const Eigen::VectorXd row = v.rowwise().sum(), column = v.colwise().sum().transpose();
      const double total = v.sum();
      neighbours.setZero();
      neighbours.leftCols(n - 1) += v.rightCols(n - 1);  // V_y,k+1
      neighbours.rightCols(n - 1) += v.leftCols(n - 1);  // V_y,k-1
      grad = p.eta * (d * neighbours);
      grad.col(0) += p.eta * from_start;
      grad.col(n - 1) += p.eta * to_end;
      for (int x = 0; x < n; ++x)
        for (int k = 0; k < n; ++k)
          grad(x, k) += p.alpha * (row[x] - v(x, k)) + p.beta * (column[k] - v(x, k)) +
                        p.gamma * (total - p.target_ratio * n);
      u += p.dt * (-u / p.tau - grad);
      const Eigen::MatrixXd next = (0.5 * (1.0 + (u.array() / p.u0).tanh())).matrix();
      settled = step >= kWarmUpSteps && (next - v).cwiseAbs().maxCoeff() < p.settle_change;
      v = next;
    }
    result.settled += settled;
    if (const auto order = read_permutation(v)) {
      ++result.valid;
      const double c = path_cost(dist, *order);
      if (c < best_cost) best_cost = c, result.order = *order;
    }
  }
  return result;
}

}  // namespace plantsim::planner
