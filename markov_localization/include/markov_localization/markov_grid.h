// The position probability grid of Beetz et al. section 2: a belief P over (x, y, theta), the
// motion update, eq. (1), the sensor update, eq. (2), and the selective update, eqs. (3)/(4),
// with the partition into orientations: a part whose cells are all below the threshold theta is
// deactivated, keeps its accumulated normalizer alpha_pi and movement a_pi, and rejoins the
// update (movement applied as one combined motion) when alpha_pi exceeds 1.
//
// Not thread-safe. Takes no clock and no random generator: the caller passes each motion and
// each scan. On a machine with two cores or more a grid runs its large updates on the calling
// thread plus one worker thread of its own; the belief is the same as with one thread.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "markov_localization/lost_detector.h"
#include "markov_localization/map_model.h"
#include "markov_localization/sensor_model.h"
#include "spott_map/world.h"

namespace markov_localization {

using spott_map::Pose2;

class WorkerPool;

struct MotionModelParameters {
  double sigma_xy_per_m = 0.1;       ///< Position noise per metre travelled (m/m), >= 0.
  double sigma_xy_per_rad = 0.02;    ///< Position noise per radian turned (m/rad), >= 0.
  double sigma_theta_per_m = 0.035;  ///< Heading noise per metre travelled (rad/m), >= 0.
  double sigma_theta_per_rad = 0.1;  ///< Heading noise per radian turned (rad/rad), >= 0.
};

struct MarkovGridParameters {
  double angular_resolution_rad = 2.0 * M_PI / 180.0;  ///< Heading bin (rad); 2 pi / it must
                                                       ///< be an integer in [4, 3600].
  bool selective_update = true;  ///< Eq. (4) with the threshold; false: the full eq. (2).
  /// theta = threshold_fraction / |L| (footnote 1: 1% of the a priori probability), in (0, 1).
  double threshold_fraction = 0.01;
  /// After a sensor update no state of an updated part is below floor_fraction / |L|, in
  /// [0, threshold_fraction): a state ruled out by underflow could never come back after a
  /// kidnap. The floor holds at most floor_fraction of the mass.
  double floor_fraction = 1e-8;
  MotionModelParameters motion;
  /// Kidnap detection and recovery (see lost_detector.h): not in the paper, needed on sonar.
  LostDetectorParameters lost;
  /// The distance filter of Fox, Burgard, Thrun and Cremers ("Position estimation for mobile
  /// robots in dynamic environments", AAAI 1998), by the same group as the paper: a reading
  /// that the belief expects, with probability >= distance_filter_probability, to be shorter
  /// than the map's range by more than distance_filter_sigmas x sigma_hit was caused by
  /// something the map lacks (a person, furniture) and is left out of the update. Applied
  /// while at most distance_filter_max_parts orientation parts are active (the position is
  /// roughly known; a uniform belief expects nothing in particular). When more than
  /// distance_filter_max_fraction of a scan's beams would be left out, none is: that many
  /// surprises are no longer people in the way but a belief that may be wrong (a kidnap), and
  /// the lost detector must see the whole misfit -- unless the other beams confirm the pose:
  /// they fit at least distance_filter_confirm_ratio x as well as usual (the lost detector's
  /// slow average), as they do beside an object the map lacks and do not after a kidnap. A
  /// B-12 (12 sonars) by cim_office's unmapped partition and crate had 4-6 short beams; without
  /// the confirmation the whole misfit made the detector say lost with the pose right, and the
  /// relocalization settled on a place 4 m off where the partition read as the lab's wall.
  bool distance_filter = true;
  double distance_filter_max_fraction = 0.25;  ///< In [0, 1].
  double distance_filter_confirm_ratio = 0.8;  ///< In [0, 1); 0: never more than the cap.
  double distance_filter_probability = 0.99;   ///< In (0.5, 1].
  double distance_filter_sigmas = 2.0;         ///< >= 0
  int distance_filter_max_parts = 24;          ///< >= 1
};

std::vector<std::string> ValidateParameters(const MarkovGridParameters& params);

/// An odometry measurement: the motion since the last update in the robot's frame at its start
/// (m forward, m left, rad counter-clockwise).
struct Motion {
  double dx = 0.0;
  double dy = 0.0;
  double dtheta = 0.0;
};

/// The relative motion from odometry pose `from` to `to` (both in the odom frame).
Motion MotionBetween(const Pose2& from, const Pose2& to);

struct SensorUpdateStats {
  std::size_t states_evaluated = 0;  ///< States whose P(s|l) was computed.
  int active_parts = 0;              ///< Orientation parts updated.
  int parts_woken = 0;               ///< Parts whose alpha_pi exceeded 1 in this update.
  int beams = 0;                     ///< Beams of all readings of the update.
  int groups = 0;                    ///< Groups the beams were applied in (see SensorUpdate).
  double normalizer = 1.0;           ///< alpha of eq. (4) (product over the groups).
  double log_normalizer = 0.0;       ///< log alpha (finite for any number of beams).
  /// log(P(s | belief) / P~(s)) / beams = -log(alpha) / beams (nats): how well the belief
  /// predicted the scan, per beam.
  double log_likelihood_per_beam = 0.0;
  /// The scan's mean surprise per beam at the most likely state (nats; NaN when not computed).
  double surprise_per_beam = 0.0;
  /// The same without the unexpectedly short beams the update kept, when the lost detector
  /// checks it (LostDetectorParameters::judge_without_short_beams); NaN otherwise.
  double surprise_without_short_per_beam = std::numeric_limits<double>::quiet_NaN();
  /// The scan said the robot is lost: relocalization_mass of uniform probability was mixed in
  /// (the lost detector), or the belief was reset to uniform (nothing fitted any more).
  bool lost_detected = false;
  std::string lost_reason;  ///< Why, when lost_detected.
  /// Per beam of the readings (in order): 1 when used, 0 when the distance filter left it out
  /// or the beam dropped out.
  std::vector<std::uint8_t> beam_used;
  int beams_filtered = 0;
  int beams_dropped = 0;  ///< NaN readings (a sensor that dropped out), left out.
  /// More beams than distance_filter_max_fraction were left out because the others confirmed
  /// the pose (MarkovGridParameters::distance_filter_confirm_ratio).
  bool distance_filter_confirmed = false;
};

/// One reading of a range sensor for SensorUpdate: `ranges_m[b]` is the reading of beam b of
/// `sensor`: >= max range or +inf: no echo; NaN: the sensor dropped out, the beam is left out
/// (spott_msgs/RangeRing's convention; REP 117's for a laser). The sensor model must be built on
/// the grid's map and heading bins. Both pointers must stay valid during the call.
struct SensorReading {
  const SensorModel* sensor = nullptr;
  const std::vector<double>* ranges_m = nullptr;
  /// Whether the lost detector's surprise counts this reading's beams (a narrow view, a
  /// profile of 40 degrees across an unmapped desk, says little about a kidnap).
  bool judged = true;
  /// The transducers turned this far (rad) about the robot's centre from the model's beams (a
  /// turret: SPOTT's dense sonar scan). A ring of radial transducers turned by it reads what the
  /// model's ring reads from the heading + turn_rad: the update takes each beam's tables that
  /// many heading bins on (rounded: within half a bin, as the heading itself is).
  double turn_rad = 0.0;
};

class MarkovGrid {
 public:
  /// Throws std::invalid_argument on invalid parameters or a sensor model built for another
  /// number of headings. `map` and `sensor` must outlive the grid.
  MarkovGrid(const MapModel& map, const SensorModel& sensor, const MarkovGridParameters& params);

  int nx() const { return map_.width(); }
  int ny() const { return map_.height(); }
  int nt() const { return nt_; }
  double angular_resolution() const { return 2.0 * M_PI / nt_; }
  const MapModel& map() const { return map_; }
  const SensorModel& sensor() const { return sensor_; }
  std::size_t NumStates() const { return map_.NumStateCells() * static_cast<std::size_t>(nt_); }
  /// theta of the selective update.
  double threshold() const { return threshold_; }

  /// Global localization: every state equally likely.
  void SetUniform();
  /// A Gaussian around `pose` (tracking start, /initialpose).
  void SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad);
  /// Sets P from a dense belief (index (k * ny + iy) * nx + ix, like Dense()), normalized;
  /// cells that are not states get 0, every part is active. A belief without mass on any
  /// state resets to uniform (lost, with the reason). Throws std::invalid_argument on a size
  /// mismatch.
  void SetBelief(const std::vector<float>& dense);
  /// P <- (1 - mass) P + mass / |L| over every state, all parts active (their stored movement
  /// applied). With mass / |L| above theta the next sensor update evaluates every state.
  void MixUniform(double mass);
  /// After a sensor update: its POS-CERTAINTY (and the threshold). A fall below the threshold
  /// while the fit dropped is lost too (LostDetector::OnCertainty): mixes relocalization_mass
  /// in as SensorUpdate does. Returns lost().
  bool ReportCertainty(double certainty, double threshold);
  /// Whether the last sensor update (or ReportCertainty) detected that the robot is lost.
  bool lost() const { return lost_; }
  const LostDetector& lost_detector() const { return detector_; }
  /// Why the robot was last found lost (lost detector, or a reset of a belief that vanished).
  const std::string& lost_reason() const { return lost_reason_; }
  /// Resets to uniform forced by a belief that vanished or left the float range (never silent:
  /// each sets lost() and lost_reason()).
  int forced_resets() const { return resets_; }

  /// Eq. (1) with the odometry noise model: each orientation part is shifted by the motion as
  /// seen from its heading (split bilinearly between cells), blurred by the motion's noise and
  /// turned; mass pushed into obstacles is removed. Parts that are inactive store the motion.
  void MotionUpdate(const Motion& motion);

  /// Eq. (2) (full) or eq. (4) (selective) for one scan: `ranges_m[b]` is the reading of beam b
  /// of the sensor model (NaN or >= max range: no echo). Throws std::invalid_argument when the
  /// number of readings differs from the number of beams.
  SensorUpdateStats SensorUpdate(const std::vector<double>& ranges_m);
  /// One sensor update with the readings of several sensors (e.g. a sonar ring and a laser
  /// scan), their beams treated as independent. Safe for any number of beams: the beams are
  /// applied in groups small enough that no float product underflows (each group an exact
  /// eq. (2) / (4) with its own normalization); the belief never becomes non-finite. When no
  /// state fits at all the belief is reset to uniform, lost() is set and lost_reason() and the
  /// stats say why. Throws std::invalid_argument for a reading of the wrong size or a model
  /// built for another map or heading count.
  SensorUpdateStats SensorUpdateWith(const std::vector<SensorReading>& readings);

  /// P(l) of state (ix, iy, heading bin k), normalized over all states.
  double Probability(int ix, int iy, int k) const;
  /// The whole belief, index (k * ny + iy) * nx + ix, normalized.
  std::vector<float> Dense() const;
  /// Whether orientation part (heading bin) k is updated.
  bool PartActive(int k) const { return active_[Layer(k)] != 0; }
  /// P of heading bin k's states, index iy * nx + ix; normalized only while PartActive(k).
  const float* PartData(int k) const { return LayerData(Layer(k)); }
  int ActiveParts() const;
  /// Centre of heading bin k (rad).
  double Heading(int k) const { return k * angular_resolution(); }
  int HeadingBin(double yaw) const;

 private:
  std::size_t LayerSize() const { return map_.NumCells(); }
  int Layer(int k) const { return ((k - rotation_) % nt_ + nt_) % nt_; }
  int HeadingOfLayer(int j) const { return (j + rotation_) % nt_; }
  float* LayerData(int j) { return belief_.data() + static_cast<std::size_t>(j) * LayerSize(); }
  const float* LayerData(int j) const {
    return belief_.data() + static_cast<std::size_t>(j) * LayerSize();
  }
  // scratch: one layer (default: scratch_); out: where the result goes (default: layer j).
  void ShiftLayer(int j, double sx_cells, double sy_cells, double var_cells,
                  float* scratch = nullptr, float* out = nullptr);
  double LayerSum(int j) const;
  void WakeLayer(int j);
  void MaterializeLayer(int j);
  void Normalize();
  void Normalize(const double* active_sums);  // sums of the active parts when known
  // One group of beams of SensorUpdate: eq. (4) and the normalization; false after a reset.
  // A beam as the update reads its tables: its model, index, and the heading-bin offset of its
  // direction (the model's beam_offset, plus the reading's turn).
  struct BeamTables {
    const SensorModel* model;
    int beam;
    int offset;
  };
  bool SensorGroup(const float* columns, int stride, const std::vector<BeamTables>& beams,
                   double log_unlikely_factor, SensorUpdateStats* stats, double* alpha);
  void ResetUniform(const std::string& reason);  // SetUniform, lost, the reason kept
  // Marks in `unexpected` the beams the belief expects to be shorter than the map says (the
  // distance filter's candidates, see MarkovGridParameters) and returns how many.
  template <typename TablesOf, typename BinOf>
  std::size_t DistanceFilter(std::size_t n, TablesOf tables_of, BinOf bin_of,
                             std::vector<std::uint8_t>* unexpected) const;

  const MapModel& map_;
  const SensorModel& sensor_;
  MarkovGridParameters params_;
  int nt_ = 0;
  double threshold_ = 0.0;
  float floor_ = 0.0f;
  int rotation_ = 0;                     // Layer j holds heading bin (j + rotation_) mod nt_.
  double rotation_residual_ = 0.0;       // Turn (rad) not yet applied to the heading bins.
  std::vector<float> belief_;            // [layer][iy][ix]; inactive layers hold P / alpha_pi.
  std::vector<float> scratch_;           // 6 layers per segment of the motion update (see there)
  std::vector<std::uint8_t> evaluated_;  // Cells the last sensor update computed P(s|l) for.
  std::vector<std::uint8_t> active_;
  std::vector<double> alpha_;       // alpha_pi of each inactive layer.
  std::vector<double> stored_sum_;  // Sum of an inactive layer's stored values.
  std::vector<double> moved_x_m_;   // a_pi: accumulated world displacement (m) ...
  std::vector<double> moved_y_m_;
  std::vector<double> moved_var_m2_;  // ... and accumulated position noise variance (m^2).
  LostDetector detector_;
  bool lost_ = false;
  std::string lost_reason_;
  int resets_ = 0;
  std::vector<float> layer_max_;  // each active layer's maximum after the last sensor group
  // Runs [begin, end) of cells (pairs) covering every state cell: the loops skip the rest.
  std::vector<std::uint32_t> spans_;
  // Two threads (the caller and one worker) when the machine has two cores; shared by copies.
  std::shared_ptr<WorkerPool> pool_;
};

}  // namespace markov_localization
