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
#include <memory>
#include <string>
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
  double normalizer = 1.0;           ///< alpha of eq. (4).
  /// log(P(s | belief) / P~(s)) / beams = -log(alpha) / beams (nats): how well the belief
  /// predicted the scan, per beam.
  double log_likelihood_per_beam = 0.0;
  /// The scan said the robot is lost: relocalization_mass of uniform probability was mixed in.
  bool lost_detected = false;
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

  /// Eq. (1) with the odometry noise model: each orientation part is shifted by the motion as
  /// seen from its heading (split bilinearly between cells), blurred by the motion's noise and
  /// turned; mass pushed into obstacles is removed. Parts that are inactive store the motion.
  void MotionUpdate(const Motion& motion);

  /// Eq. (2) (full) or eq. (4) (selective) for one scan: `ranges_m[b]` is the reading of beam b
  /// of the sensor model (NaN or >= max range: no echo). Throws std::invalid_argument when the
  /// number of readings differs from the number of beams.
  SensorUpdateStats SensorUpdate(const std::vector<double>& ranges_m);

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
  // Runs [begin, end) of cells (pairs) covering every state cell: the loops skip the rest.
  std::vector<std::uint32_t> spans_;
  // Two threads (the caller and one worker) when the machine has two cores; shared by copies.
  std::shared_ptr<WorkerPool> pool_;
};

}  // namespace markov_localization
