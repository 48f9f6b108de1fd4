// The evaluation harness of markov_localization (no ROS): robot_sim's core simulator drives a
// B21 (sonars only, laser off, as in Beetz et al. section 2.3) through a spott_map world with a
// seeded generator; every sonar ring (the simulator's 10 Hz) the odometry since the previous ring
// becomes one motion update and the ring one sensor update of the markov core, as in the node.
// The harness knows the ground truth and scores the belief against it; the robot's behaviours
// (random wandering, wall following, a plain obstacle-avoiding go-to for the active localizer's
// targets) see only odometry, the sonar ring and the stall flag (a bumper would tell the same).
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "eval_picture.h"
#include "markov_localization/active_localization.h"
#include "markov_localization/certainty.h"
#include "markov_localization/localizer.h"
#include "markov_localization/markov_grid.h"
#include "robot_sim/simulator.h"
#include "spott_map/world.h"

namespace markov_localization {
namespace eval {

using robot_sim::Rng;
using robot_sim::Twist2;

struct Settings {
  double resolution_m = 0.25;
  int heading_bins = 72;
  double sigma_hit_m = 0.25;
  /// SensorModelParameters::critical_angle_rad: the node's 0.35 rad for sonar (pi/2: a single
  /// diffuse ray, the core's default before markov_kidnap's sonar physics).
  double critical_angle_rad = 0.35;
  bool lost_detector = true;   ///< MarkovGridParameters::lost.enabled (markov_kidnap's detector).
  double speed_mps = 0.5;      ///< Cruise speed of every behaviour (B21 limit 0.9 m/s).
  double physics_hz = 100.0;   ///< robot_sim's default physics rate.
  double sonar_hz = 10.0;      ///< robot_sim's default sensor rate: one update per ring.
  double certain = 0.8;        ///< Certainty threshold (issue: 0.8).
  double success_pos_m = 0.3;  ///< Success: certain and within 30 cm ...
  double success_rad = 10.0 * M_PI / 180.0;  ///< ... and 10 degrees.
  double wrong_pos_m = 0.5;                  ///< Confidently wrong: certain but > 0.5 m ...
  double wrong_rad = 15.0 * M_PI / 180.0;    ///< ... or > 15 degrees off.
  std::string robot_dir;                     ///< robot_sim's package directory.
  /// When set, the mixture weights and sigma_hit of the sensor model are fitted to readings of
  /// the simulator (see CalibrateSensorModel) before the runs; otherwise the core's defaults.
  bool calibrate = false;
  bool selective_update = true;
  /// MapModelParameters::state_clearance_m; < 0: the robot's radius (the B21's 0.2625 m), so
  /// that the active localizer's paths keep the body off the walls.
  double state_clearance_m = -1.0;  ///< false: the full eq. (2) on every state (diagnostic).
  int calibration_poses = 2000;
  std::uint64_t calibration_seed = 1000003;
  /// The robot of robot_sim's config/robots/ (b21, nomad200, hilare, b12).
  std::string robot_name = "b21";
  bool use_sonar = true;   ///< Localize on the sonar ring (the behaviours always use it).
  bool use_laser = false;  ///< Localize on the laser (the robot must have one).
  /// The laser's beams used: AMCL's laser_max_beams (every (n - 1) / (max - 1)-th beam).
  int laser_max_beams = 30;
  double laser_max_range_m = 25.0;  ///< The laser model's max range (capped by the laser's).
  double laser_range_bin_m = 0.1;
  double laser_sigma_hit_m = 0.15;
  double laser_exponent = 1.0;  ///< SensorModelParameters::likelihood_exponent of the laser.
  double motion_xy_per_m = -1;  ///< >= 0: MotionModelParameters::sigma_xy_per_m.
  double refine_cells = -1;     ///< > 0: the refinement's box; 0: no refinement; < 0: default.
  /// The node's motion gate (config/markov_localization.yaml: gate/*).
  MotionGateParameters gate;
  /// A map_server YAML to localize on instead of the world's CAD map (the simulator still runs
  /// the world); empty: the world.
  std::string map_file;
  int ray_cast_subdivision = 5;  ///< The node's map/ray_cast_subdivision.
  /// Lost detector parameters (the node's lost/*).
  LostDetectorParameters lost;
  /// >= 0: MarkovGridParameters::distance_filter_max_fraction (the node's
  /// grid/distance_filter_max_fraction); < 0: the core's default.
  double distance_filter_max_fraction = -1;
  /// >= 0: MarkovGridParameters::distance_filter_confirm_ratio; < 0: the core's default.
  double distance_filter_confirm_ratio = -1;
};

/// Everything that does not change between runs in one world: the world, the robot, the map,
/// the sensor model's tables and the active localizer.
struct Models {
  Settings settings;
  spott_map::World world;
  robot_sim::RobotSpec robot;
  const robot_sim::RangeRingSpec* ring = nullptr;
  std::shared_ptr<const MapModel> map_ptr;
  const MapModel& map;                  ///< *map_ptr
  SensorModelParameters sensor_params;  ///< The sonar's (also when only the laser is used).
  SensorModelParameters laser_params;
  std::vector<int> laser_beams;  ///< Indices of the laser's readings used.
  /// The localization's models as the node builds them: sonar (if used) then laser (if used).
  std::shared_ptr<const LocalizationModels> loc_models;
  LocalizerParameters loc_params;
  int sonar_sensor = -1;  ///< Index in loc_models->sensors, -1 unused.
  int laser_sensor = -1;
  const SensorModel* sensor = nullptr;  ///< The first sensor model (active localization's).
  MarkovGridParameters grid_params;
  CertaintyParameters certainty;
  ModeParameters modes;
  std::unique_ptr<ActiveLocalizer> active;
  double build_seconds = 0.0;
  std::string calibration_report;  ///< What the fit found (empty without calibration).

  explicit Models(std::shared_ptr<const MapModel> m) : map_ptr(std::move(m)), map(*map_ptr) {}
  /// Throws std::runtime_error with the file's errors.
  static std::unique_ptr<Models> Load(const std::string& world_file, const Settings& settings);
  /// The id of the room containing `p`, or "outside".
  std::string RoomAt(const Vec2& p) const;
};

/// Fits the sensor model to the simulator as [BFH97] fitted theirs to real data: the robot is
/// placed at `poses` random states (uniform over the state cells, continuous position and
/// heading), fires its ring, and every reading is paired with the expected range bin that the
/// model's table gives for that state and beam. EM then estimates the mixture weights z_hit,
/// z_short, z_max, z_rand (the model's own component shapes, per bin), for each sigma_hit of a
/// grid (0.1 to 0.6 m); the pair with the highest likelihood wins. Returns the parameters and
/// a report (log-likelihood per reading of the defaults and of the fit).
SensorModelParameters CalibrateSensorModel(const Models& m, int poses, std::uint64_t seed,
                                           std::string* report);

/// What the belief says after one update, scored against the ground truth.
struct Status {
  double time = 0.0;  ///< Simulated seconds since the episode started.
  double certainty = 0.0;
  Pose2 estimate;
  Pose2 truth;
  double pos_error = 0.0;
  double yaw_error = 0.0;
  bool lost_detector = false;  ///< The update of this tick found the robot lost.
  std::string lost_reason;
  double update_ms = 0.0;  ///< Localization CPU time of this tick (ms, all threads).
  bool updated = false;    ///< The gate let an update through this tick.
  std::size_t states_evaluated = 0;
  int groups = 0;  ///< Beam groups of the sensor update (numerically safe products).
};

/// A second filter fed the same odometry and readings (the particle-filter peer).
class PeerFilter {
 public:
  virtual ~PeerFilter() = default;
  /// A reading of the sonar ring (`laser` false) or the laser (subsampled beams as the grid's,
  /// angles and origins in `params`), taken at odometry pose `odom`.
  virtual void OnReading(bool laser, const std::vector<double>& ranges, const Pose2& odom,
                         double now_s) = 0;
  /// The published estimate at odometry pose `odom`.
  virtual Pose2 Estimate(const Pose2& odom) const = 0;
  virtual void SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad) = 0;
};

/// One robot in one fresh simulator, and its belief.
class Episode {
 public:
  /// `start`: the true start pose. Uniform belief unless `known_start`, then a Gaussian around
  /// it (10 cm, 3 degrees). Throws std::runtime_error when the start is blocked.
  Episode(const Models& models, const Pose2& start, std::uint64_t seed, bool known_start);

  /// Drives with `cmd` until the next sonar ring, then updates and scores the belief.
  const Status& Tick(const Twist2& cmd);

  const Status& status() const { return status_; }
  const std::vector<double>& ranges() const { return ranges_; }
  const Pose2& odom() const { return sim_->odometry(robot_).pose(); }
  const Pose2& truth() const { return sim_->GroundTruth(robot_); }
  bool stalled() const { return stalled_; }
  /// Bumper segments pressed during the last sonar period (segment 0 ahead, counter-clockwise).
  const std::vector<bool>& bumper() const { return bumper_; }
  double distance() const { return distance_; }
  double time() const { return status_.time; }
  double tick_seconds() const { return 1.0 / models_.settings.sonar_hz; }
  MarkovGrid& grid() { return localizer_->grid(); }
  Localizer& localizer() { return *localizer_; }
  /// A peer filter fed the same data from now on (its CPU time kept apart).
  void SetPeer(std::unique_ptr<PeerFilter> peer);
  PeerFilter* peer() { return peer_.get(); }
  double peer_cpu_ms() const { return peer_cpu_ms_; }
  double cpu_ms() const { return cpu_ms_; }  ///< Localization CPU time so far (ms).
  int updates() const { return localizer_->updates(); }
  const std::vector<double>& laser() const { return laser_; }
  robot_sim::Simulator& sim() { return *sim_; }
  int robot() const { return robot_; }
  Rng& rng() { return rng_; }
  const Models& models() const { return models_; }
  /// Success and confidently-wrong tests of the last status.
  bool Success() const;
  bool ConfidentlyWrong() const;
  std::vector<Mode> Modes() const;

 private:
  const Models& models_;
  std::unique_ptr<robot_sim::Simulator> sim_;
  int robot_ = 0;
  Rng rng_;
  std::unique_ptr<Localizer> localizer_;
  std::unique_ptr<PeerFilter> peer_;
  double peer_cpu_ms_ = 0.0;
  double cpu_ms_ = 0.0;
  std::vector<double> ranges_;
  std::vector<double> laser_;
  Status status_;
  bool stalled_ = false;
  std::vector<bool> bumper_;
  double distance_ = 0.0;
};

/// Smallest reading of the beams whose mount heading is within [from, to] (rad, robot frame).
double MinRange(const Models& m, const std::vector<double>& ranges, double from, double to);

/// Stall recovery shared by the behaviours: after a stall the robot turns on the spot until it
/// faces away from the contact (the pressed bumper segments; the nearest sonar reading when none
/// is pressed), then drives 0.16 m that way.
class Escape {
 public:
  /// True while escaping; `cmd` is then the command to send.
  bool Step(Episode& e, Twist2* cmd);

 private:
  int phase_ = 0;  ///< 0 idle, 1 turning, 2 driving away
  double target_yaw_ = 0.0;
  double until_ = 0.0;
};

/// A behaviour: the command for the next sonar period from what the robot senses.
class Behaviour {
 public:
  virtual ~Behaviour() = default;
  virtual Twist2 Command(Episode& e) = 0;
};

/// Random wandering: straight ahead until the front sonars see an obstacle, then a turn on the
/// spot by a random angle (60-180 degrees) to the freer side; Escape after a stall.
class RandomWander : public Behaviour {
 public:
  Twist2 Command(Episode& e) override;

 private:
  double turn_left_ = 0.0;  ///< Rotation (rad) still to make; sign = direction.
  Escape escape_;
};

/// Wall following: keeps a wall on one side at 0.6 m by the side sonars, turns away from
/// obstacles ahead, curves towards the wall side when it is lost.
class WallFollow : public Behaviour {
 public:
  explicit WallFollow(bool right) : right_(right) {}
  Twist2 Command(Episode& e) override;

 private:
  bool right_;
  Escape escape_;
};

/// A plain obstacle-avoiding go-to (not a planner: the integrator's stand-in for the suite's
/// Navigate action): follows waypoints given in the odom frame, turning on the spot towards the
/// next, slowing and turning away when the front sonars see something close, steering away from
/// a side closer than 0.25 m; Escape after a stall. Done when the last waypoint is within 0.25 m
/// (odometry), or after `timeout_s` or 8 stalls (then timed_out()).
class GoTo : public Behaviour {
 public:
  void Set(std::vector<Vec2> odom_waypoints, double now, double timeout_s);
  Twist2 Command(Episode& e) override;
  bool done() const { return done_; }
  bool timed_out() const { return timed_out_; }

 private:
  std::vector<Vec2> wp_;
  std::size_t next_ = 0;
  double deadline_ = 0.0;
  bool done_ = true;
  bool timed_out_ = false;
  Escape escape_;
  int stalls_ = 0;
};

/// Active localization as in the issue: ActiveLocalizer chooses a* from the modes, GoTo drives
/// the hill-climbed path there, then it chooses again. `chosen` collects a* in the world under
/// the true pose at each choice.
class ActiveDriver : public Behaviour {
 public:
  Twist2 Command(Episode& e) override;
  int choices() const { return choices_; }
  const std::vector<Vec2>& targets_true() const { return targets_true_; }
  double choose_ms_total() const { return choose_ms_; }
  bool verbose = false;  ///< Log each choice and how the go-to ended (stderr).

 private:
  GoTo goto_;
  RandomWander fallback_;
  double fallback_until_ = -1.0;
  int choices_ = 0;
  double choose_ms_ = 0.0;
  std::vector<Vec2> targets_true_;
};

/// A point `rel` (ahead, left) of a robot at `pose`, in the pose's frame.
Vec2 Compose(const Pose2& pose, const Vec2& rel);
/// `p` (map frame) in the odom frame, given that the robot's map pose is `estimate` while its
/// odometry reads `odom`.
Vec2 MapToOdom(const Pose2& estimate, const Pose2& odom, const Vec2& p);

double Elapsed(std::chrono::steady_clock::time_point since);
/// CPU time of the process (s): every thread, the grid's worker included.
double ProcessCpuSeconds();

/// Logs every go-to step (stderr; debugging only).
extern bool verbose_trace;

}  // namespace eval
}  // namespace markov_localization
