#include "markov_localization/lost_detector.h"

#include <cmath>
#include <cstdio>

namespace markov_localization {

std::vector<std::string> ValidateParameters(const LostDetectorParameters& p) {
  std::vector<std::string> errors;
  if (!(p.fast_rate > 0.0 && p.fast_rate <= 1.0)) errors.push_back("fast_rate must be in (0, 1]");
  if (!(p.slow_rate > 0.0 && p.slow_rate < p.fast_rate))
    errors.push_back("slow_rate must be in (0, fast_rate)");
  if (!(p.lost_ratio > 0.0 && p.lost_ratio < 1.0)) errors.push_back("lost_ratio must be in (0, 1)");
  if (!(p.scan_lost_ratio > 0.0 && p.scan_lost_ratio <= p.lost_ratio))
    errors.push_back("scan_lost_ratio must be in (0, lost_ratio]");
  const double lost_ratio = p.lost_ratio > 0.0 && p.lost_ratio < 1.0 ? p.lost_ratio : 0.0;
  if (!(p.certainty_drop_ratio >= lost_ratio && p.certainty_drop_ratio < 1.0))
    errors.push_back("certainty_drop_ratio must be in [lost_ratio, 1)");
  if (!(p.hold_scans >= 1)) errors.push_back("hold_scans must be >= 1");
  if (!(p.without_short_lost_ratio > 0.0 && p.without_short_lost_ratio <= 1.0))
    errors.push_back("without_short_lost_ratio must be in (0, 1]");
  if (!(p.short_beams_min_others >= 1)) errors.push_back("short_beams_min_others must be >= 1");
  if (!(p.relocalization_mass > 0.0 && p.relocalization_mass < 1.0))
    errors.push_back("relocalization_mass must be in (0, 1)");
  return errors;
}

std::string LostDetector::Describe(const char* what, double fit) const {
  char text[160];
  std::snprintf(text, sizeof text, "%s (per-beam fit %.3g = %.2f x its usual %.3g)", what, fit,
                slow_ > 0.0 ? fit / slow_ : 0.0, slow_);
  return text;
}

void LostDetector::Reset() {
  fast_ = slow_ = 0.0;
  scans_since_reset_ = 0;
  was_certain_ = false;
  certain_scans_ = 0;
}

bool LostDetector::OnCertainty(double certainty, double threshold) {
  // Only a robot that was certain for a while can be kidnapped out of its certainty; dips of a
  // belief that is just becoming certain (a long hallway) are not a kidnap.
  const bool dropped = certain_scans_ >= params_.hold_scans && certainty < threshold;
  was_certain_ = certainty > threshold;
  certain_scans_ = was_certain_ ? certain_scans_ + 1 : 0;
  if (!params_.enabled || !dropped || scans_since_reset_ <= params_.hold_scans) return false;
  if (fast_ >= params_.certainty_drop_ratio * slow_) return false;
  reason_ = Describe("the certainty fell below its threshold while the fit dropped", fast_);
  scans_since_reset_ = 1;  // the hold starts again, as after any detection
  return true;
}

bool LostDetector::Update(double log_likelihood_per_beam, double without_short_per_beam) {
  if (!params_.enabled || !std::isfinite(log_likelihood_per_beam)) return false;
  const double r = std::exp(log_likelihood_per_beam);
  const bool collapsed = scans_since_reset_ > 0 && r < params_.scan_lost_ratio * slow_;
  if (scans_since_reset_ == 0) {
    fast_ = slow_ = r;
  } else {
    fast_ += params_.fast_rate * (r - fast_);
    slow_ += params_.slow_rate * (r - slow_);
  }
  ++scans_since_reset_;
  if (scans_since_reset_ <= params_.hold_scans) return false;
  if (!collapsed && fast_ >= params_.lost_ratio * slow_) return false;
  // The beams an unmapped object cannot explain (it only shortens readings) fit: not lost.
  if (std::isfinite(without_short_per_beam) &&
      std::exp(without_short_per_beam) >= params_.without_short_lost_ratio * slow_)
    return false;
  // Lost. The averages are kept: if the relocalization does not restore the usual fit the
  // detector fires again after the hold, while a lasting change of scene (clutter) is absorbed
  // by the slow average.
  reason_ =
      collapsed ? Describe("one scan's fit collapsed", r) : Describe("the scans' fit fell", fast_);
  scans_since_reset_ = 1;
  return true;
}

}  // namespace markov_localization
