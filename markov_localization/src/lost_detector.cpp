#include "markov_localization/lost_detector.h"

#include <cmath>

namespace markov_localization {

std::vector<std::string> ValidateParameters(const LostDetectorParameters& p) {
  std::vector<std::string> errors;
  if (!(p.fast_rate > 0.0 && p.fast_rate <= 1.0)) errors.push_back("fast_rate must be in (0, 1]");
  if (!(p.slow_rate > 0.0 && p.slow_rate < p.fast_rate))
    errors.push_back("slow_rate must be in (0, fast_rate)");
  if (!(p.lost_ratio > 0.0 && p.lost_ratio < 1.0)) errors.push_back("lost_ratio must be in (0, 1)");
  if (!(p.hold_scans >= 1)) errors.push_back("hold_scans must be >= 1");
  if (!(p.relocalization_mass > 0.0 && p.relocalization_mass < 1.0))
    errors.push_back("relocalization_mass must be in (0, 1)");
  return errors;
}

void LostDetector::Reset() {
  fast_ = slow_ = 0.0;
  scans_since_reset_ = 0;
}

bool LostDetector::Update(double log_likelihood_per_beam) {
  if (!params_.enabled || !std::isfinite(log_likelihood_per_beam)) return false;
  const double r = std::exp(log_likelihood_per_beam);
  if (scans_since_reset_ == 0) {
    fast_ = slow_ = r;
  } else {
    fast_ += params_.fast_rate * (r - fast_);
    slow_ += params_.slow_rate * (r - slow_);
  }
  ++scans_since_reset_;
  if (scans_since_reset_ <= params_.hold_scans) return false;
  if (fast_ >= params_.lost_ratio * slow_) return false;
  // Lost. The averages are kept: if the relocalization does not restore the usual fit the
  // detector fires again after the hold, while a lasting change of scene (clutter) is absorbed
  // by the slow average.
  scans_since_reset_ = 1;
  return true;
}

}  // namespace markov_localization
