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

#include <limits>
#include <string>
#include <vector>

namespace markov_localization {

struct LostDetectorParameters {
  bool enabled = true;
  /// What the averages are of. false: the per-beam predictive fit (P(s | belief) / P~(s))^(1 /
  /// beams). It also falls when the view becomes common rather than wrong (facing a plain wall
  /// at the end of crossing_corridors' hallway a single scan fit 0.12 x its usual: a false
  /// "kidnap", then a look-alike place 23 m away won). true: the surprise of the scan at the
  /// belief's most likely state, exp(mean over the used beams of log P(z_b | e_b) - E[log P(z |
  /// e_b)]), the expectation under the model itself: about 1 wherever the robot is right,
  /// whatever it looks at; far below after a kidnap. Computed while at most
  /// distance_filter_max_parts orientation parts are active (the position roughly known);
  /// otherwise the detector waits.
  bool surprise = true;
  /// Smoothing factors of the exponential averages per scan, 0 < slow < fast <= 1.
  double fast_rate = 0.5;
  double slow_rate = 0.05;
  /// Lost when fast < lost_ratio * slow, in (0, 1). The averages are of the geometric mean of
  /// the per-beam likelihood ratio P(s|belief) / P~(s), so 0.3 means every beam fits 0.3
  /// times as well as it usually does. Chosen on the evaluation with the motion gate
  /// (README): 0.55 (the choice before the gate, when every scan updated) fired on entering
  /// cim_office's cluttered lab and at doorways, and the relocalization then went up to 10 m
  /// wrong; at 0.3 and 0.2 the tracking runs on the three worlds (B21 laser and sonar, Nomad
  /// sonar) raise no alarm of this rule; kidnaps are caught by the single-scan collapse and
  /// the certainty drop.
  double lost_ratio = 0.3;
  /// Lost at once when a single scan's fit falls below scan_lost_ratio * slow, in
  /// (0, lost_ratio]: the signature of a kidnap (about 0.07 x on robot_sim; the lowest single
  /// scan while driving was 0.34 x).
  double scan_lost_ratio = 0.15;
  /// A detection by the averages or by the single-scan collapse stands only if the scan judged
  /// without its unexpectedly short beams (those the belief expects, with the distance filter's
  /// probability, to read longer; whether or not the update could leave them out) fits below
  /// without_short_lost_ratio x the slow average too: an object the map lacks can only shorten
  /// a reading, so the beams it cannot explain must misfit as well. Checked while at least
  /// short_beams_min_others other judged beams remain (fewer: the whole scan decides).
  /// Without it the unmapped clutter in cim_office's lab (half a B-12's sonars short with the
  /// pose right) raised false kidnaps that relocalized the robot up to 24 m off; leaving the short
  /// beams out of the rules altogether noticed real kidnaps late. The measurements: README, "The
  /// lab's clutter and the lost detector".
  bool judge_without_short_beams = true;
  double without_short_lost_ratio = 0.15;  ///< In (0, 1].
  /// Fewest other judged beams for the check above, >= 1.
  int short_beams_min_others = 3;
  /// A fall of POS-CERTAINTY below its threshold after hold_scans scans above it, while the
  /// fast fit is below certainty_drop_ratio * slow is lost too, in [lost_ratio, 1): after a 70
  /// degree turn in the corridor a single scan fits 0.15-0.55 x, and within a few scans the
  /// paper's wake-up finds a wrong place that fits again (the caller reports the certainty:
  /// MarkovGrid::ReportCertainty). 0.6, not 0.7: in cim_office's lab the Nomad turning in place
  /// by the partition dipped below the certainty threshold with the fit at 0.70 x (twice, each
  /// time the fast average just crossing 0.7); the relocalization then settled certain on a
  /// place 4.5 m off, turned 180 deg. The evaluation's kidnap (19 of 20) and global (20 of 20
  /// active) rows are the same at 0.6 and 0.7; 0.5 loses a kidnap, 0.3 four.
  double certainty_drop_ratio = 0.6;
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
  /// number of beams (nats), or the surprise (LostDetectorParameters::surprise). Returns true
  /// when the scan says the robot is lost. `without_short_per_beam` (optional, the same without
  /// the unexpectedly short beams): when finite, a detection also needs it below
  /// without_short_lost_ratio x the slow average (see judge_without_short_beams).
  bool Update(double log_likelihood_per_beam,
              double without_short_per_beam = std::numeric_limits<double>::quiet_NaN());
  /// After the scan's Update: the belief's POS-CERTAINTY. True when it fell from above
  /// `threshold` to below it while the fit dropped (see certainty_drop_ratio).
  bool OnCertainty(double certainty, double threshold);
  /// Forgets the history (a new belief was set: uniform, initial pose, relocalization).
  void Reset();

  /// Exponential averages of the per-beam likelihood ratio.
  double fast() const { return fast_; }
  double slow() const { return slow_; }
  /// Which rule fired last (a sentence with the fits), empty before any detection.
  const std::string& reason() const { return reason_; }

 private:
  std::string Describe(const char* what, double fit) const;

  LostDetectorParameters params_;
  double fast_ = 0.0;
  double slow_ = 0.0;
  int scans_since_reset_ = 0;
  bool was_certain_ = false;
  int certain_scans_ = 0;  // consecutive scans above the certainty threshold
  std::string reason_;
};

}  // namespace markov_localization
