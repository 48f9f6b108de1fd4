// Notices that the robot is lost (kidnapped, or its belief otherwise wrong) from how well the
// belief predicts the scans. The paper's selective update relies on the normalizer alpha of
// eq. (4) exceeding 1 to wake the parts it set aside; with a sonar model that has
// unexpected-obstacle and max-range terms a wrong room still explains a scan better than the
// average place, so alpha stays below 1 and a kidnapped robot stays certain at the old place.
// This detector compares the scan's predictive likelihood with its own recent history instead,
// as augmented MCL does with its w_fast / w_slow averages (Thrun, Burgard & Fox, Probabilistic
// Robotics, table 8.3): when the short-term average falls well below the long-term one, the
// scans no longer fit the belief.
//
// The caller passes one value per sensor update; no clock is read.
#pragma once

#include <string>
#include <vector>

namespace markov_localization {

struct LostDetectorParameters {
  bool enabled = true;
  /// Smoothing factors of the exponential averages per scan, 0 < slow < fast <= 1.
  double fast_rate = 0.5;
  double slow_rate = 0.05;
  /// Lost when fast < lost_ratio * slow, in (0, 1). The averages are of the geometric mean of
  /// the per-beam likelihood ratio P(s|belief) / P~(s), so 0.7 means every beam fits 0.7 times as
  /// well as it usually does (the scan 0.7^24 = 2e-4 times).
  double lost_ratio = 0.7;
  /// Scans after a reset or a detection before the detector may fire (again), >= 1.
  int hold_scans = 10;
  /// Uniform probability mass mixed into the belief when lost, in (0, 1). It must exceed the
  /// selective update's threshold_fraction, so that eq. (4) evaluates every state again.
  double relocalization_mass = 0.1;
};

std::vector<std::string> ValidateParameters(const LostDetectorParameters& params);

class LostDetector {
 public:
  explicit LostDetector(const LostDetectorParameters& params) : params_(params) {}

  /// One sensor update: `log_likelihood_per_beam` is log(P(s | belief) / P~(s)) divided by the
  /// number of beams (nats). Returns true when the scan says the robot is lost.
  bool Update(double log_likelihood_per_beam);
  /// Forgets the history (a new belief was set: uniform, initial pose, relocalization).
  void Reset();

  /// Exponential averages of the per-beam likelihood ratio.
  double fast() const { return fast_; }
  double slow() const { return slow_; }

 private:
  LostDetectorParameters params_;
  double fast_ = 0.0;
  double slow_ = 0.0;
  int scans_since_reset_ = 0;
};

}  // namespace markov_localization
