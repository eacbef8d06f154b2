// A stream of random draws for one sensor or estimator: O'Neill's PCG engine (pcg64, Debian's
// libpcg-cpp-dev) with Boost.Random's ziggurat normal. Each owner has its own stream, seeded from
// the episode's seed and its own constant, so that one owner's draws never shift another's.
// Replaces std::mt19937_64 with std::normal_distribution (Marsaglia's polar method: two
// uniforms, a log and a square root per pair), which drew a fifth of a sensing episode's time.
#pragma once

#include <boost/random/normal_distribution.hpp>
#include <boost/random/uniform_01.hpp>
#include <cstdint>
#include <pcg_random.hpp>

namespace plantsim::util {

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}
  /// A draw of the standard normal N(0, 1).
  double gaussian() { return normal_(engine_); }
  /// A draw uniform in [0, 1).
  double uniform() { return uniform_(engine_); }

 private:
  pcg64 engine_;
  boost::random::normal_distribution<double> normal_{0.0, 1.0};
  boost::random::uniform_01<double> uniform_;
};

}  // namespace plantsim::util
