// The localization pipeline of the node, ROS-free, so that the evaluation (eval/) measures what
// the node runs: the motion gate (AMCL's update_min_d / update_min_a), one motion update with
// the odometry since the last update followed by one sensor update with the newest reading of
// every sensor (sonar ring, laser scan), the lost handling, POS-CERTAINTY and the modes, and the
// published estimate (sticky_estimate.h) as a map -> odom transform that stays fixed between
// updates (the estimate then follows the odometry, as AMCL's does).
//
// Why the gate: a grid updated at every 10 Hz scan re-peaks the belief at cell centres after
// each sub-cell motion (a 5 cm step moves a third of a 15 cm cell's mass, the next scan pulls it
// back), and consecutive scans are far from independent; in a corridor the estimate then sat on
// one cell while the robot drove metres (the "corridor lock"). Updating after
// update_min_d of travel moves the mass by more than a cell between scans.
//
// Not thread-safe; no clock (the caller passes each reading's time) and no random generator.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "markov_localization/certainty.h"
#include "markov_localization/markov_grid.h"
#include "markov_localization/pose_refinement.h"
#include "markov_localization/sticky_estimate.h"

namespace markov_localization {

struct MotionGateParameters {
  /// AMCL's update_min_d: odometry translation (m) since the last update before the next one,
  /// >= 0 (0: every reading updates). Measured in the evaluation (README): 0.2 m.
  double update_min_d_m = 0.2;
  /// AMCL's update_min_a: odometry rotation (rad) since the last update, >= 0.
  double update_min_a_rad = M_PI / 6.0;
  /// A robot that stands still (slower than 2 cm/s and 3 deg/s between two readings) updates
  /// again after this long (s), so that a kidnap of a standing robot is noticed and a standing
  /// robot localizes globally; 0 = never (AMCL). >= 0. Between near-mirror places a standing
  /// robot's repeated scans make the belief overconfident, so this is slow.
  double standing_interval_s = 0.5;
  /// Once the gate is open, how long (s) the update waits for a reading of every sensor taken
  /// since it opened, [0, 5]; only such readings join it (one taken before was taken elsewhere).
  /// 0: the update waits until the sensor that found the gate open delivers again (two 10 Hz
  /// sensors, a ring and a scan). A slow sensor needs its period: the QUADRIS profiles (about
  /// 2 Hz from both heads) 0.6 s. Giving it updates of its own instead (each profile at once)
  /// brought the corridor lock back: at 0.3 m/s the belief was updated every 0.1-0.15 m and the
  /// estimate fell 5 m behind twice along cim_office's hallway.
  double join_s = 0.0;
};

std::vector<std::string> ValidateParameters(const MotionGateParameters& params);

struct LocalizerParameters {
  MarkovGridParameters grid;
  MotionGateParameters gate;
  CertaintyParameters certainty;
  ModeParameters modes;
  StickyEstimateParameters sticky;
  PoseRefinementParameters refine;  ///< The published pose below the cell size.
  /// Indices of sensors with a narrow view (a QUADRIS profile's 40 degrees): used in the
  /// updates, not by the lost detector (a profile across an unmapped desk collapsed its fit in
  /// the lab and the robot was relocalized elsewhere).
  std::vector<int> unjudged_sensors;
};

/// Every violation by parameter name (core names: "gate.update_min_d_m ...").
std::vector<std::string> ValidateParameters(const LocalizerParameters& params);

/// The map and the sensor models built on it: the expensive part (ray-cast tables, seconds on
/// a large map), built once and shared; rebuilt when the map changes.
struct LocalizationModels {
  std::shared_ptr<const MapModel> map;
  std::vector<std::unique_ptr<SensorModel>> sensors;  ///< In the order of `sensor_params`.
  int num_headings = 0;

  /// Throws std::invalid_argument naming the problem.
  static std::shared_ptr<const LocalizationModels> Build(
      std::shared_ptr<const MapModel> map, const std::vector<SensorModelParameters>& sensor_params,
      int num_headings);
  /// The models of `map` from `previous` (same sensors and headings), whose map has the same
  /// raster: only the rays the map's changes can reach are cast again (a door's state: 7 % of
  /// them for the Nomad's sonar on cim_office). Otherwise a full build.
  static std::shared_ptr<const LocalizationModels> Build(
      std::shared_ptr<const MapModel> map, const std::vector<SensorModelParameters>& sensor_params,
      int num_headings, const std::shared_ptr<const LocalizationModels>& previous);
};

/// What one reading did.
struct LocalizerStep {
  bool updated = false;     ///< The gate let a motion + sensor update through.
  SensorUpdateStats stats;  ///< Of the sensor update (when updated).
  int sensors_used = 0;     ///< Readings in the sensor update.
  bool lost = false;        ///< The update found the robot lost (detector or forced reset).
  std::string lost_reason;
  bool switched = false;  ///< The published estimate left the mode it followed.
};

class Localizer {
 public:
  /// Starts uniform. Throws std::invalid_argument on invalid parameters or models.
  Localizer(std::shared_ptr<const LocalizationModels> models, const LocalizerParameters& params);

  const LocalizationModels& models() const { return *models_; }
  std::shared_ptr<const LocalizationModels> shared_models() const { return models_; }
  const LocalizerParameters& parameters() const { return params_; }

  /// New models (a door closed, a /map message): the belief is carried over state by state
  /// (P at the same place and heading; mass on places that are no longer states is dropped).
  /// The models must have the same heading count.
  void ReplaceModels(std::shared_ptr<const LocalizationModels> models);

  /// Global localization; the next reading updates whatever the gate says.
  void SetUniform();
  /// A Gaussian belief (initial pose); the next reading updates whatever the gate says.
  /// `at_odom`: the odometry when the robot was at `pose`; the next update moves the belief by
  /// the odometry since then (a respawned node builds its models for seconds while the robot
  /// drives on). Without it the belief holds at the next reading's odometry.
  void SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad,
                   const std::optional<Pose2>& at_odom = std::nullopt);

  /// A reading of sensor `sensor` (index into models().sensors) taken when odometry read `odom`
  /// at time `now_s` (any epoch, non-decreasing). When the robot moved update_min_d /
  /// update_min_a since the last update (or standing_interval_s passed, or the belief was just
  /// set), the update runs once every sensor has a reading newer than the last update (or this
  /// sensor delivered twice meanwhile): one motion update with the odometry since the last
  /// update, one sensor update with the newest reading of each sensor. Throws
  /// std::invalid_argument for a bad sensor index or a reading of the wrong size. `turn_rad`:
  /// the transducers turned about the robot's centre (SensorReading::turn_rad).
  LocalizerStep OnReading(int sensor, const std::vector<double>& ranges_m, const Pose2& odom,
                          double now_s, double turn_rad = 0.0);

  /// Whether an update has happened since the belief was set (map_to_odom is valid).
  bool has_estimate() const { return has_estimate_; }
  /// The published estimate's map -> odom (REP-105), fixed between updates.
  const Pose2& map_to_odom() const { return map_to_odom_; }
  /// The published estimate for odometry pose `odom`: map_to_odom * odom.
  Pose2 Estimate(const Pose2& odom) const { return Compose(map_to_odom_, odom); }
  /// The refined pose of the global maximum at the last update (what the status reports), moved
  /// by the odometry since, like Estimate; differs from it while the estimate follows another
  /// mode (sticky_estimate.h).
  Pose2 BestEstimate(const Pose2& odom) const { return Compose(best_map_to_odom_, odom); }
  /// Certainty and modes after the last update.
  const BeliefSummary& summary() const { return summary_; }
  bool certain() const { return summary_.certainty.certainty > params_.certainty.threshold; }
  /// The grid was found lost at its last update.
  bool lost() const { return grid_->lost(); }
  const MarkovGrid& grid() const { return *grid_; }
  MarkovGrid& grid() { return *grid_; }
  int updates() const { return updates_; }

 private:
  struct Pending {
    std::vector<double> ranges;
    Pose2 odom;
    double turn_rad = 0.0;
    bool fresh = false;  // received after the last update
    double time_s = 0.0;
  };
  bool GateOpen(const Pose2& odom, double now_s) const;
  /// With the fresh readings (taken since the gate opened when join_s > 0).
  LocalizerStep Update(const Pose2& odom, double now_s);
  /// Whether pending reading `s` joins the update the open gate waits for.
  bool Joins(std::size_t s) const;

  std::shared_ptr<const LocalizationModels> models_;
  LocalizerParameters params_;
  std::unique_ptr<MarkovGrid> grid_;
  std::vector<Pending> pending_;
  std::vector<char> judged_;  // per sensor: the lost detector sees its readings
  // When a reading first found the gate open (join_s > 0); < 0: not yet.
  double gate_opened_s_ = -1.0;
  // The previous reading (any sensor), to tell a standing robot.
  bool has_last_reading_ = false, standing_ = true;
  double last_reading_s_ = 0.0;
  Pose2 last_reading_odom_;
  int opener_ = -1;  // the sensor whose reading found the gate open while others were missing
  bool force_ = true;
  bool has_update_odom_ = false;
  Pose2 update_odom_;
  double update_time_s_ = 0.0;
  bool has_estimate_ = false;
  Pose2 map_to_odom_;
  Pose2 best_map_to_odom_;
  BeliefSummary summary_;
  StickyEstimate sticky_;
  int updates_ = 0;
};

}  // namespace markov_localization
