// An environment's episode seeds as Gymnasium gives an environment's resets their randomness
// (Env.np_random): a reset with a seed runs that seed's episode and restarts the environment's
// stream from it; a reset without one continues the stream (started from the machine's entropy
// if no reset ever had a seed), so that wrappers resetting without seeds never replay episodes.
// A VectorEnv's environment i is an Env: reset(seed=s) gives it s + i (or the i-th of a list),
// and each autoreset is a reset without a seed.
#pragma once

#include <cstdint>
#include <optional>
#include <random>

#include "util/random_stream.h"

namespace plantsim::python {

class EpisodeSeeds {
 public:
  /// The next episode's seed: `asked`, or the stream's next draw (63 bits: an episode id's seed
  /// reads back as a Python int, and two draws among millions practically never meet).
  std::uint64_t next(const std::optional<std::uint64_t>& asked) {
    return asked.has_value() ? restart(asked.value_or(0)) : draw();
  }
  /// Seed `seed`'s episode; the stream restarts from it.
  std::uint64_t restart(std::uint64_t seed) {
    stream_.emplace(mixed(seed));
    return seed;
  }
  /// The stream's next seed.
  std::uint64_t draw() {
    if (!stream_) {
      std::random_device entropy;
      stream_.emplace((std::uint64_t{entropy()} << 32) ^ entropy());
    }
    return stream_->bits() >> 1;
  }

 private:
  /// SplitMix64's finaliser: neighbouring seeds start unrelated streams.
  static std::uint64_t mixed(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  }
  std::optional<util::RandomStream> stream_;
};

}  // namespace plantsim::python
