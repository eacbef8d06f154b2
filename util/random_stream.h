// A stream of random draws for one sensor or estimator: O'Neill's PCG engine (pcg64, Debian's
// libpcg-cpp-dev) with Boost.Random's ziggurat normal. Each owner has its own stream, seeded from
// the episode's seed and its own constant, so that one owner's draws never shift another's.
// Replaces std::mt19937_64 with std::normal_distribution (Marsaglia's polar method: two
// uniforms, a log and a square root per pair), which drew a fifth of a sensing episode's time.
#pragma once

#include <boost/random/normal_distribution.hpp>
#include <cstdint>
#include <pcg_random.hpp>

namespace plantsim::util {

/// The double nearest `x` (ties to even), as `static_cast<double>(x)` gives it, without a branch:
/// each 32-bit half converts exactly and their sum rounds once.
inline double nearest_double(std::uint64_t x) {
  return static_cast<double>(static_cast<std::int64_t>(x >> 32)) * 0x1p32 +
         static_cast<double>(static_cast<std::int64_t>(x & 0xffffffffULL));
}

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}
  /// A draw of the standard normal N(0, 1).
  double gaussian() { return normal_(engine_); }
  /// The engine's next 64 bits, for a caller that turns many into draws at once (MPPI's noise).
  std::uint64_t bits() { return engine_(); }
  /// A draw uniform in [0, 1): bit for bit Boost's uniform_01 on this engine (the 64-bit draw
  /// to the nearest double, times 2^-64, drawn again when that rounds to 1), without its
  /// unsigned-to-double conversion, whose branch on the draw's top bit the CPU mispredicts half
  /// the time (it cost two thirds of the lidar's noise).
  double uniform() {
    for (;;)
      if (const double u = nearest_double(engine_()) * 0x1p-64; u < 1.0) return u;
  }

 private:
  pcg64 engine_;
  boost::random::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace plantsim::util
