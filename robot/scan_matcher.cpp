// The likelihood grid (an exact Euclidean distance transform of the mapped surfaces), its
// block maxima, and the windowed branch-and-bound search.
#include "robot/scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::robot {
namespace {

/// Squared distance to the nearest zero of f along one row (Felzenszwalb and Huttenlocher's
/// lower envelope of parabolas), in cells.
void distance_1d(const std::vector<double>& f, std::vector<double>& d, std::vector<long>& v,
                 std::vector<double>& z) {
  const long n = static_cast<long>(f.size());
  auto at = [](const auto& a, long i) -> decltype(auto) { return a[static_cast<std::size_t>(i)]; };
  auto meet = [&](long q, long p) {
    return ((at(f, q) + double(q) * q) - (at(f, p) + double(p) * p)) / (2.0 * (q - p));
  };
  long k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  for (long q = 1; q < n; ++q) {
    double s = meet(q, at(v, k));
    while (s <= at(z, k)) {
      --k;
      s = meet(q, at(v, k));
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k + 1)] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (long q = 0; q < n; ++q) {
    while (at(z, k + 1) < q) ++k;
    const long p = at(v, k);
    d[static_cast<std::size_t>(q)] = double(q - p) * (q - p) + at(f, p);
  }
}

}  // namespace

ScanMatcher::ScanMatcher(const worlds::World& map, ScanMatcherParams params) : p_(params) {
  const geom::Rect area = map.floor.inflated(1.0);
  res_ = std::max(p_.resolution_m, std::sqrt(area.width() * area.height() /
                                             static_cast<double>(std::max(1L, p_.max_cells))));
  origin_ = {area.xmin, area.ymin};
  nx_ = std::max(1L, static_cast<long>(std::ceil(area.width() / res_)));
  ny_ = std::max(1L, static_cast<long>(std::ceil(area.height() / res_)));
  const std::size_t cells = static_cast<std::size_t>(nx_ * ny_);
  // Surfaces: the outline of every mapped rectangle, wall and the charger, as the cells along
  // its edges whose centres lie in it. Only the outline: a lidar return lies on a surface, and a
  // return placed inside a solid block is as wrong as one in the open (a grid that scored a
  // wall's inside would let a scan of one long wall slide half a metre into it and fit
  // perfectly).
  const double far = 1e12;  // squared cells: far beyond any floor, and exact in the sums below
  std::vector<double> grid(cells, far);
  auto mark = [&](const geom::Rect& r) {
    const long first_i = static_cast<long>(std::ceil((r.xmin - origin_.x) / res_ - 0.5));
    const long last_i = static_cast<long>(std::floor((r.xmax - origin_.x) / res_ - 0.5));
    const long first_j = static_cast<long>(std::ceil((r.ymin - origin_.y) / res_ - 0.5));
    const long last_j = static_cast<long>(std::floor((r.ymax - origin_.y) / res_ - 0.5));
    const long i0 = std::max(0L, first_i), i1 = std::min(nx_ - 1, last_i);
    const long j0 = std::max(0L, first_j), j1 = std::min(ny_ - 1, last_j);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i)
        if (i == first_i || i == last_i || j == first_j || j == last_j)
          grid[static_cast<std::size_t>(j * nx_ + i)] = 0;
  };
  for (const geom::Rect& r : map.obstacles) mark(r);
  // The floor's walls one cell thick: their far side is never seen.
  for (const geom::Rect& r : geom::surrounding_walls(map.floor, res_)) mark(r);
  mark(worlds::charger_body(map).bounding_box());
  // Exact squared distances in cells: columns, then rows.
  const long longest = std::max(nx_, ny_);
  std::vector<double> f(static_cast<std::size_t>(longest)), d(static_cast<std::size_t>(longest));
  std::vector<long> v(static_cast<std::size_t>(longest));
  std::vector<double> z(static_cast<std::size_t>(longest) + 1);
  for (long i = 0; i < nx_; ++i) {
    f.resize(static_cast<std::size_t>(ny_));
    d.resize(static_cast<std::size_t>(ny_));
    for (long j = 0; j < ny_; ++j)
      f[static_cast<std::size_t>(j)] = grid[static_cast<std::size_t>(j * nx_ + i)];
    distance_1d(f, d, v, z);
    for (long j = 0; j < ny_; ++j)
      grid[static_cast<std::size_t>(j * nx_ + i)] = d[static_cast<std::size_t>(j)];
  }
  f.resize(static_cast<std::size_t>(nx_));
  d.resize(static_cast<std::size_t>(nx_));
  for (long j = 0; j < ny_; ++j) {
    for (long i = 0; i < nx_; ++i)
      f[static_cast<std::size_t>(i)] = grid[static_cast<std::size_t>(j * nx_ + i)];
    distance_1d(f, d, v, z);
    for (long i = 0; i < nx_; ++i)
      grid[static_cast<std::size_t>(j * nx_ + i)] = d[static_cast<std::size_t>(i)];
  }
  mark_standable(map);
  fine_.resize(cells);
  const double k = res_ * res_ / (2.0 * p_.hit_sigma_m * p_.hit_sigma_m);
  for (std::size_t c = 0; c < cells; ++c) fine_[c] = std::exp(-k * grid[c]);
  // Block maxima: max over [i, i + b) first along x, then along y.
  const long b = std::max(1, p_.block);
  std::vector<double> along_x(cells);
  for (long j = 0; j < ny_; ++j)
    for (long i = 0; i < nx_; ++i) {
      double m = 0;
      for (long a = 0; a < b && i + a < nx_; ++a)
        m = std::max(m, fine_[static_cast<std::size_t>(j * nx_ + i + a)]);
      along_x[static_cast<std::size_t>(j * nx_ + i)] = m;
    }
  coarse_.resize(cells);
  for (long j = 0; j < ny_; ++j)
    for (long i = 0; i < nx_; ++i) {
      double m = 0;
      for (long a = 0; a < b && j + a < ny_; ++a)
        m = std::max(m, along_x[static_cast<std::size_t>((j + a) * nx_ + i)]);
      coarse_[static_cast<std::size_t>(j * nx_ + i)] = m;
    }
}

void ScanMatcher::mark_standable(const worlds::World& map) {
  // Cells whose centre the robot's centre could occupy: on the floor, off every mapped box, with
  // a cell of slack for the grid. (A scan of one long wall fits as well from the wall's far
  // side, outside the plant, as from where the robot stands: no such pose is an answer.)
  const double body = std::max(0.0, map.robot.radius_m - res_);
  standable_.assign(static_cast<std::size_t>(nx_ * ny_), 0);
  auto fill = [&](const geom::Rect& r, std::uint8_t value) {
    const long i0 = std::max(0L, static_cast<long>(std::ceil((r.xmin - origin_.x) / res_ - 0.5)));
    const long i1 =
        std::min(nx_ - 1, static_cast<long>(std::floor((r.xmax - origin_.x) / res_ - 0.5)));
    const long j0 = std::max(0L, static_cast<long>(std::ceil((r.ymin - origin_.y) / res_ - 0.5)));
    const long j1 =
        std::min(ny_ - 1, static_cast<long>(std::floor((r.ymax - origin_.y) / res_ - 0.5)));
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) standable_[static_cast<std::size_t>(j * nx_ + i)] = value;
  };
  fill(map.floor.inflated(-body), 1);
  for (const geom::Rect& r : map.obstacles) fill(r.inflated(body), 0);
}

bool ScanMatcher::standable(const geom::Vec2& p) const {
  const long i = static_cast<long>(std::floor((p.x - origin_.x) / res_));
  const long j = static_cast<long>(std::floor((p.y - origin_.y) / res_));
  return inside(i, j) && standable_[static_cast<std::size_t>(j * nx_ + i)] != 0;
}

double ScanMatcher::likelihood(geom::Vec2 p) const {
  return fine(static_cast<long>(std::floor((p.x - origin_.x) / res_)),
              static_cast<long>(std::floor((p.y - origin_.y) / res_)));
}

namespace {

/// The valid returns in the robot frame, at most `max_points` spread evenly over the scan, and
/// the farthest one's distance; none when fewer than 10 are valid.
std::optional<std::vector<geom::Vec2>> returns_in_robot(const LidarScan& scan, int max_points,
                                                        double& reach) {
  std::vector<geom::Vec2> points;
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i)
    if (scan.valid(i)) valid.push_back(i);
  if (valid.size() < 10) return std::nullopt;
  const std::size_t stride =
      std::max<std::size_t>(1, valid.size() / static_cast<std::size_t>(std::max(1, max_points)));
  reach = 0;
  for (std::size_t k = 0; k < valid.size(); k += stride) {
    const std::size_t i = valid[k];
    const geom::Vec2 in_sensor = scan.ranges[i] * geom::unit_from_angle(scan.angle(i));
    points.push_back(
        geom::compose(scan.mount, geom::Pose2{in_sensor.x, in_sensor.y, 0}).position());
    reach = std::max(reach, geom::norm(points.back()));
  }
  return points;
}

}  // namespace

ScanMatcher::SearchSteps ScanMatcher::search_steps(const MatchWindow& window, double reach) const {
  // Rotation steps that move the farthest return by about one cell.
  const long b = std::max(1, p_.block);
  long n_xy = static_cast<long>(std::ceil(window.xy_m / res_));
  auto blocks = [&](long n) { return (2 * n / b + 1) * (2 * n / b + 1); };
  // The work is bounded: coarser rotation steps for wide windows, then a narrower window.
  double dyaw = std::clamp(res_ / std::max(reach, 1.0), 0.002, p_.max_yaw_step_rad);
  const long budget = std::max(1L, p_.max_candidates);
  // 2 n_yaw + 1 rotations fit the budget: n_yaw = ceil(yaw / dyaw) rounds up by one step each
  // way, hence the two spare. (Without them a window of +-3.5 m at all headings came out one
  // rotation over, and was narrowed to +-2.6 m: tiles of reseeding searches 7 m apart left gaps.)
  const double rotations = std::floor(double(budget) / double(blocks(n_xy)));
  dyaw = std::min(p_.max_yaw_step_rad,
                  std::max(dyaw, 2.0 * window.yaw_rad / std::max(1.0, rotations - 2.0)));
  const long n_yaw = static_cast<long>(std::ceil(window.yaw_rad / dyaw));
  while ((2 * n_yaw + 1) * blocks(n_xy) > budget && n_xy > b) n_xy = n_xy * 3 / 4;
  return {b, n_xy, n_yaw, dyaw};
}

Eigen::Matrix3d ScanMatcher::near_best_spread(const std::vector<Scored>& good,
                                              const ScanMatch& best, const geom::Pose2& prior,
                                              double dyaw) const {
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  int near = 0;
  for (const Scored& g : good) {
    if (g.score < p_.max_ambiguity * best.score) continue;
    const Eigen::Vector3d d(prior.x + g.i * res_ - best.pose.x, prior.y + g.j * res_ - best.pose.y,
                            geom::wrap_angle(prior.yaw + g.s * dyaw - best.pose.yaw));
    spread += d * d.transpose();
    ++near;
  }
  spread /= std::max(1, near);
  spread.diagonal() += Eigen::Vector3d(res_ * res_, res_ * res_, dyaw * dyaw);
  return spread;
}

void ScanMatcher::rank_apart(const std::vector<Scored>& good, const geom::Pose2& prior, double dyaw,
                             ScanMatch& best) const {
  auto apart = [&](const geom::Pose2& a, const geom::Pose2& c) {
    return geom::distance(a.position(), c.position()) > p_.apart_m ||
           std::fabs(geom::wrap_angle(a.yaw - c.yaw)) > p_.apart_rad;
  };
  std::vector<Scored> by_score = good;  // `good` keeps its order: the spread sums over it
  std::stable_sort(by_score.begin(), by_score.end(),
                   [](const Scored& a, const Scored& c) { return a.score > c.score; });
  for (const Scored& g : by_score) {
    const geom::Pose2 at{prior.x + g.i * res_, prior.y + g.j * res_,
                         geom::wrap_angle(prior.yaw + g.s * dyaw)};
    if (apart(at, best.pose)) best.runner_up = std::max(best.runner_up, g.score);
    if (g.score < p_.max_ambiguity * best.score ||
        static_cast<int>(best.alternatives.size()) >= p_.max_alternatives)
      continue;
    if (std::all_of(best.alternatives.begin(), best.alternatives.end(),
                    [&](const auto& taken) { return apart(at, taken.first); }))
      best.alternatives.emplace_back(at, g.score);
  }
}

std::optional<ScanMatch> ScanMatcher::match(const LidarScan& scan, const geom::Pose2& prior,
                                            const MatchWindow& window) const {
  double reach = 0;
  const std::optional<std::vector<geom::Vec2>> returns =
      returns_in_robot(scan, p_.max_points, reach);
  if (!returns) return std::nullopt;
  const std::vector<geom::Vec2>& points = *returns;
  const double n_points = static_cast<double>(points.size());
  const SearchSteps steps = search_steps(window, reach);
  const long b = steps.b, n_xy = steps.n_xy, n_yaw = steps.n_yaw;
  const double dyaw = steps.dyaw;
  struct Candidate {
    double bound;
    long yaw_step, i, j;  // block's first translation
  };
  std::vector<Candidate> candidates;
  std::vector<std::vector<std::pair<long, long>>> cells_by_yaw(
      static_cast<std::size_t>(2 * n_yaw + 1));
  for (long s = -n_yaw; s <= n_yaw; ++s) {
    const double yaw = prior.yaw + s * dyaw;
    auto& cells = cells_by_yaw[static_cast<std::size_t>(s + n_yaw)];
    cells.reserve(points.size());
    for (const geom::Vec2& p : points) {
      const geom::Vec2 q = prior.position() + geom::rotate(p, yaw);
      cells.emplace_back(static_cast<long>(std::floor((q.x - origin_.x) / res_)),
                         static_cast<long>(std::floor((q.y - origin_.y) / res_)));
    }
    for (long i = -n_xy; i <= n_xy; i += b)
      for (long j = -n_xy; j <= n_xy; j += b) {
        double bound = 0;
        for (const auto& [ci, cj] : cells) bound += coarse(ci + i, cj + j);
        candidates.push_back({bound / n_points, s, i, j});
      }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& c) { return a.bound > c.bound; });

  ScanMatch best;
  best.score = -1;
  std::vector<Scored> good;  // every exact score close enough to the best to matter for ambiguity
  for (const Candidate& c : candidates) {
    // Nothing left can beat the best, or come close enough to make it ambiguous.
    if (c.bound < p_.max_ambiguity * std::max(best.score, p_.min_score)) break;
    const auto& cells = cells_by_yaw[static_cast<std::size_t>(c.yaw_step + n_yaw)];
    for (long i = c.i; i < c.i + b && i <= n_xy; ++i)
      for (long j = c.j; j < c.j + b && j <= n_xy; ++j) {
        if (!standable({prior.x + i * res_, prior.y + j * res_})) continue;
        double score = 0;
        for (const auto& [ci, cj] : cells) score += fine(ci + i, cj + j);
        score /= n_points;
        ++best.scored;
        if (score >= p_.max_ambiguity * std::max(best.score, p_.min_score))
          good.push_back({score, c.yaw_step, i, j});
        if (score > best.score) {
          best.score = score;
          best.pose = {prior.x + i * res_, prior.y + j * res_,
                       geom::wrap_angle(prior.yaw + c.yaw_step * dyaw)};
        }
      }
  }
  if (best.score < 0) {
    best.score = 0;
    best.pose = prior;
    return best;
  }
  rank_apart(good, prior, dyaw, best);
  best.accepted = best.score >= p_.min_score && best.runner_up < p_.max_ambiguity * best.score;
  best.spread = near_best_spread(good, best, prior, dyaw);
  return best;
}

}  // namespace plantsim::robot
