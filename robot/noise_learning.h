// Sensor noise learnt online (covariance matching), shared by the estimators: a variance
// averaged over samples (the plain mean of the first ones, then a moving average that forgets,
// so that a sensor degrading during the run is followed), used in place of the told value only
// when clearly above it; and the gyro's noise from its readings at rest.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

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

/// A gyro reading `innovation` from the bias's estimate, whose spread (noise and the bias's
/// uncertainty) has variance `variance`, is what a robot at rest reads; farther, it turns.
inline bool at_rest(double innovation, double variance) {
  constexpr double kRestGateSigmas = 5.0;
  return innovation * innovation <= kRestGateSigmas * kRestGateSigmas * variance;
}

/// The gyro's white noise from its readings at rest: two readings in a row at rest differ by
/// the noise alone (the bias cancels, whatever its estimate), so half their squared difference
/// is a sample of its variance. The readings themselves measure the bias; until the noise is
/// learnt from `min_samples` of them they are held back, then all weighed by what was learnt.
/// (Weighed by the told noise as they came, the first readings of a gyro four times as noisy as
/// its datasheet counted sixteen times what they are worth: after the start's calibration the bias
/// was off by several of the filter's own sigmas, and on the open plants of wet_levers.yaml the
/// heading drifted across open ground while the filter reported itself ok.)
class GyroRestNoise {
 public:
  GyroRestNoise(double rate, int min_samples) : variance_(rate), min_samples_(min_samples) {}
  /// Every reading, moving or not (call before at_rest for a reading at rest).
  void reading() { ++since_rest_; }
  void at_rest(double gyro_yaw_rate_radps) {
    if (last_rest_ && since_rest_ == 1) {
      const double d = gyro_yaw_rate_radps - *last_rest_;
      variance_.add(0.5 * d * d);
    }
    last_rest_ = gyro_yaw_rate_radps;
    since_rest_ = 0;
    held_.push_back(gyro_yaw_rate_radps);
  }
  const LearntVariance& variance() const { return variance_; }
  /// The 1-sigma noise to weigh readings by: the learnt one when clearly above `told` and learnt
  /// from at least `min_samples`, else `told`. A variance from n samples scatters as chi-square
  /// with n degrees: weighed by its inverse, readings would count n / (n - 2) times what they
  /// are worth on average, and the bias would look surer than it is.
  double sigma(double told) const {
    const int n = variance_.samples();
    if (n < min_samples_ || n < 3) return told;
    const double learnt = std::sqrt(variance_.variance() * n / (n - 2.0));
    return learnt > kClearlyAbove * told ? learnt : told;
  }
  /// The readings at rest not yet used for the bias, once the noise is learnt (none before),
  /// each to be weighed by sigma(told); taking them empties the store.
  std::vector<double> take_readings() {
    if (variance_.samples() < min_samples_) return {};
    std::vector<double> out;
    out.swap(held_);
    return out;
  }

 private:
  LearntVariance variance_;
  int min_samples_;
  std::optional<double> last_rest_;
  int since_rest_ = 0;
  std::vector<double> held_;
};

}  // namespace plantsim::robot
