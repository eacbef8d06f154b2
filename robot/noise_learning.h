// Sensor noise learnt online (covariance matching), shared by the estimators: a variance
// averaged over samples (the plain mean of the first ones, then a moving average that forgets,
// so that a sensor degrading during the run is followed), used in place of the told value only
// when clearly above it; and the gyro's noise from its readings at rest.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

namespace plantsim::robot {

// A learnt noise replaces the told one only when clearly above it: an estimate from a few
// hundred residuals scatters by some per cent about the truth, and the larger of the two
// alone would be biased above a told value that is right.
inline constexpr double kClearlyAbove = 1.2;

class LearntVariance {
 public:
  explicit LearntVariance(double rate) : rate_(rate) {}
  void add(double variance) {
    ++samples_;
    variance_ += std::max(rate_, 1.0 / samples_) * (variance - variance_);
  }
  int samples() const { return samples_; }
  double variance() const { return variance_; }
  /// The 1-sigma noise to use: the learnt one when clearly above `told` and learnt from at
  /// least `min_samples`, else `told`.
  double sigma(double told, int min_samples = 1) const {
    if (samples_ < min_samples) return told;
    const double learnt = std::sqrt(variance_);
    return learnt > kClearlyAbove * told ? learnt : told;
  }

 private:
  double rate_;
  double variance_ = 0;
  int samples_ = 0;
};

/// The gyro's white noise from its readings at rest: two readings in a row at rest differ by
/// the noise alone (the bias cancels, whatever its estimate), so half their squared difference
/// is a sample of its variance.
class GyroRestNoise {
 public:
  explicit GyroRestNoise(double rate) : variance_(rate) {}
  /// Every reading, moving or not (call before at_rest for a reading at rest).
  void reading() { ++since_rest_; }
  void at_rest(double gyro_yaw_rate_radps) {
    if (last_rest_ && since_rest_ == 1) {
      const double d = gyro_yaw_rate_radps - *last_rest_;
      variance_.add(0.5 * d * d);
    }
    last_rest_ = gyro_yaw_rate_radps;
    since_rest_ = 0;
  }
  const LearntVariance& variance() const { return variance_; }

 private:
  LearntVariance variance_;
  std::optional<double> last_rest_;
  int since_rest_ = 0;
};

}  // namespace plantsim::robot
