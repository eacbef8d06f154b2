// NLopt (Debian's libnlopt-dev) driven through its C interface, and the random baseline.
#include "tune/search.h"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <random>
#include <stdexcept>

namespace plantsim::tune {

namespace {

nlopt_algorithm algorithm(Method m) {
  switch (m) {
    case Method::kSbplx:
    case Method::kSbplxStarts:
      return NLOPT_LN_SBPLX;
    case Method::kBobyqa:
      return NLOPT_LN_BOBYQA;
    case Method::kNelderMead:
      return NLOPT_LN_NELDERMEAD;
    case Method::kCrs2:
      return NLOPT_GN_CRS2_LM;
    case Method::kIsres:
      return NLOPT_GN_ISRES;
  }
  return NLOPT_LN_SBPLX;
}

bool local(Method m) { return m != Method::kCrs2 && m != Method::kIsres; }

/// What the C callback reaches: the evaluator, the count, and an exception it must not throw
/// through NLopt's C frames (kept, the optimiser stopped, and rethrown after).
struct Context {
  Context(const TuneSpec& s, const Evaluator& e) : spec(s), evaluate(e) {}
  const TuneSpec& spec;
  const Evaluator& evaluate;
  int used = 0;
  double best = -HUGE_VAL;
  std::vector<double> best_unit;
  std::exception_ptr failure;
  nlopt_opt opt = nullptr;
};

double objective(unsigned n, const double* x, double* gradient, void* data) {
  (void)gradient;  // derivative-free methods only
  Context& c = *static_cast<Context*>(data);
  if (c.used >= c.spec.budget || c.failure) {
    nlopt_force_stop(c.opt);
    return HUGE_VAL;
  }
  try {
    const std::vector<double> unit(x, x + n);
    const double value = c.evaluate("nlopt", c.used++, unscaled(c.spec.parameters, unit));
    if (value > c.best) c.best = value, c.best_unit = unit;
    return -value;  // NLopt minimises
  } catch (...) {
    c.failure = std::current_exception();
    nlopt_force_stop(c.opt);
    return HUGE_VAL;
  }
}

struct OptDeleter {
  void operator()(nlopt_opt o) const { nlopt_destroy(o); }
};

}  // namespace

std::vector<double> unscaled(const std::vector<TunedParameter>& parameters,
                             const std::vector<double>& unit) {
  std::vector<double> v(parameters.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const TunedParameter& p = parameters[i];
    const double u = std::clamp(i < unit.size() ? unit[i] : 0.0, 0.0, 1.0);
    v[i] = p.lo + u * (p.hi - p.lo);
    if (p.info.whole) v[i] = std::round(v[i]);
    v[i] = std::clamp(v[i], p.lo, p.hi);
  }
  return v;
}

std::vector<double> scaled(const std::vector<TunedParameter>& parameters,
                           const std::vector<double>& values) {
  std::vector<double> u(parameters.size());
  for (std::size_t i = 0; i < u.size(); ++i)
    u[i] = std::clamp((values[i] - parameters[i].lo) / (parameters[i].hi - parameters[i].lo), 0.0,
                      1.0);
  return u;
}

namespace {

/// sbplx-starts: 2n + 1 points (at most a third of the budget) drawn uniformly from the search's
/// own stream, the defaults among them as the first; Subplex then starts from the best of them.
/// A local search from the defaults alone stays in their basin (the speed showcase: sbplx lost to
/// random search by 1.9 s of 84 on validation); the design looks over the whole box first.
std::vector<double> best_of_design(Context& c, const std::vector<double>& defaults) {
  const std::size_t n = defaults.size();
  const int points = std::min<int>(2 * static_cast<int>(n) + 1, std::max(1, c.spec.budget / 3));
  std::mt19937_64 draw(c.spec.seed ^ 0x7374617274ULL);  // "start": apart from random search's
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> x = defaults;
  for (int k = 0; k < points && c.used < c.spec.budget; ++k) {
    if (k > 0)
      for (double& v : x) v = unit(draw);
    const double value = c.evaluate("nlopt", c.used++, unscaled(c.spec.parameters, x));
    if (value > c.best) c.best = value, c.best_unit = x;
  }
  return c.best_unit;
}

}  // namespace

void nlopt_search(const TuneSpec& spec, const std::vector<double>& start,
                  const Evaluator& evaluate) {
  const unsigned n = static_cast<unsigned>(spec.parameters.size());
  Context c(spec, evaluate);
  std::vector<double> x = scaled(spec.parameters, start);
  double step = 0.25;
  if (spec.method == Method::kSbplxStarts) {
    x = best_of_design(c, x);
    step = 0.125;  // from the best of the design: a finer first step than from the defaults
  }
  // The global methods draw from NLopt's own generator: seeded, so that a tuning repeats.
  nlopt_srand(spec.seed);
  while (c.used < spec.budget && !c.failure) {
    const int before = c.used;
    std::unique_ptr<nlopt_opt_s, OptDeleter> opt(nlopt_create(algorithm(spec.method), n));
    if (!opt) throw std::runtime_error("NLopt could not create its optimiser");
    c.opt = opt.get();
    const std::vector<double> lower(n, 0.0), upper(n, 1.0);
    nlopt_set_lower_bounds(c.opt, lower.data());
    nlopt_set_upper_bounds(c.opt, upper.data());
    nlopt_set_min_objective(c.opt, objective, &c);
    nlopt_set_maxeval(c.opt, spec.budget - c.used);
    // A step finer than a thousandth of a bound's span changes nothing an episode can show.
    nlopt_set_xtol_abs1(c.opt, 1e-3);
    if (local(spec.method)) nlopt_set_initial_step1(c.opt, step);
    double minimum = 0;
    nlopt_optimize(c.opt, x.data(),
                   &minimum);  // its status says why it stopped: budget or converged
    c.opt = nullptr;
    if (c.failure) std::rethrow_exception(c.failure);
    if (!local(spec.method) || c.used == before) break;
    // Converged early: again from the best point with a finer step, until the budget is spent.
    x = c.best_unit;
    step = std::max(step / 2, 0.01);
  }
}

void random_search(const TuneSpec& spec, const Evaluator& evaluate) {
  std::mt19937_64 draw(spec.seed ^ 0x72616e646f6dULL);  // a stream of its own ("random")
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < spec.budget; ++k) {
    std::vector<double> u(spec.parameters.size());
    for (double& v : u) v = unit(draw);
    evaluate("random", k, unscaled(spec.parameters, u));
  }
}

}  // namespace plantsim::tune
