// The simulator core: robots in a SimWorld, stepped by the caller with its own dt and random
// generator (no clock is read here). Each robot's body is a Bullet cylinder that collides with
// the world: a step that would make it penetrate is cut at the contact and the base stops
// (its motors stall); contacts press the bumper segments that face them. Sensor faults and
// odometry slip last a given time of simulated time. Not thread-safe.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robot_sim/drive.h"
#include "robot_sim/range_sensors.h"
#include "robot_sim/robot_spec.h"
#include "robot_sim/sim_world.h"

namespace robot_sim {

enum class FaultKind { kDropout, kStuck, kNoise };

struct SensorFault {
  FaultKind kind = FaultKind::kDropout;
  double noise_stddev = 0.0;  ///< (m) for kNoise
  double until = 0.0;         ///< Simulated time (s) it ends; infinity = until cleared.
};

class Simulator {
 public:
  explicit Simulator(std::unique_ptr<SimWorld> world);

  /// Adds a robot at `start` (map frame; odometry starts at the origin of odom = start).
  /// Returns its index, or nullopt with `error` when the start pose is blocked.
  std::optional<int> AddRobot(const RobotSpec& spec, const spott_map::Pose2& start,
                              const OdometryErrorModel& odometry, std::string* error);

  /// Sets the velocity command; a NaN, infinite or absurd command is refused (false, with a
  /// message) and the robot is commanded to stop.
  bool SetCommand(int robot, const Twist2& cmd, std::string* error);

  /// Advances every robot by `dt` seconds (> 0).
  void Step(double dt, Rng& rng);

  /// Readings of ring `ring` of `robot` (m), faults applied (NaN for a dropped-out sensor).
  std::vector<double> SenseRing(int robot, const RangeRingSpec& ring, Rng& rng);
  /// Laser readings (m, +inf for no return; NaN when dropped out), empty without a laser.
  std::vector<double> SenseLaser(int robot, Rng& rng);
  /// A profile of pan-tilt head `index` (robot's range_profilers order), faults applied.
  std::vector<double> SenseProfile(int robot, int index, bool horizontal, Rng& rng,
                                   std::vector<double>* angles);
  /// Points head `index` (pan about z, tilt positive down, rad); false for a bad index or a
  /// value that is not finite.
  bool PointHead(int robot, int index, double pan, double tilt);
  /// Current pan and tilt of head `index` (rad).
  std::pair<double, double> Head(int robot, int index) const {
    return robots_.at(robot).heads.at(index);
  }
  /// Bumper segments pressed after the last step (all false when dropped out).
  std::vector<bool> Bumper(int robot);
  /// Ground truth, for evaluation only: the directions (robot frame, rad) in which the body
  /// touches a solid (within kBodyTouchM of its shell) after the last step, whatever sensors the
  /// robot has and whatever their faults (a B-12 has no bumper; a bumper may drop out).
  std::vector<double> BodyContacts(int robot) const;
  static constexpr double kBodyTouchM = 0.005;

  /// Moves the robot without the odometry seeing it. `relative`: `target` is a displacement
  /// in the robot frame. Refused (false, message) when the target is outside the map or
  /// inside a solid; nothing changes then.
  bool Kidnap(int robot, const spott_map::Pose2& target, bool relative, std::string* error);
  /// Injects a fault on "sonar", "sonar/3" (transducer 3, numbered from 1), "laser", "bumper"...
  bool InjectFault(int robot, const std::string& sensor, const SensorFault& fault,
                   std::string* error);
  bool ClearFault(int robot, const std::string& sensor, std::string* error);
  /// Odometry measures `linear_scale` / `angular_scale` of the true motion for `duration` s.
  bool Slip(int robot, double linear_scale, double angular_scale, double duration,
            std::string* error);
  /// Replaces the building by `world`, keeping the robots, their odometry and faults. Refused
  /// (false, message; nothing changes) when a robot would stand inside a solid or outside
  /// every room of the new world.
  bool ReplaceWorld(const spott_map::World& world, std::string* error);
  /// Turns the sensor turret (synchro drives) towards `yaw` (rad) relative to the base, at the
  /// robot's max_turret_rps (the shorter way round).
  void SetTurretYaw(int robot, double yaw);

  const spott_map::Pose2& GroundTruth(int robot) const { return robots_.at(robot).pose; }
  const Twist2& Velocity(int robot) const { return robots_.at(robot).twist; }
  const Odometry& odometry(int robot) const { return robots_.at(robot).odometry; }
  const RobotSpec& spec(int robot) const { return robots_.at(robot).spec; }
  double turret_yaw(int robot) const { return robots_.at(robot).turret_yaw; }
  /// True when the robot's body, grown by `margin_m`, overlaps a solid of the world (a door
  /// leaf or an obstacle just put where it stands).
  bool Overlapped(int robot, double margin_m = 0.0) const;
  /// True when the last step was cut short by a contact.
  bool Stalled(int robot) const { return robots_.at(robot).stalled; }
  int robot_count() const { return static_cast<int>(robots_.size()); }
  double time() const { return time_; }
  SimWorld& world() { return *world_; }
  const SimWorld& world() const { return *world_; }

 private:
  struct Robot {
    RobotSpec spec;
    spott_map::Pose2 pose;
    Twist2 twist;
    Twist2 command;
    Odometry odometry;
    btCollisionObject* body = nullptr;
    double turret_yaw = 0.0;
    double turret_target = 0.0;
    bool stalled = false;
    std::vector<bool> bumper;
    std::vector<std::pair<double, double>> heads;  ///< Pan and tilt of each range profiler.
    std::map<std::string, SensorFault> faults;
    std::map<std::string, std::vector<double>> last;  ///< Last readings, for stuck faults.
    double slip_until = -1.0;
    double slip_linear = 1.0;
    double slip_angular = 1.0;
  };
  bool Collides(const Robot& r, double x, double y) const;
  const SensorFault* ActiveFault(Robot& r, const std::string& key);
  /// Dropout, stuck and noise faults of sensor `name`; a noisy reading stays within what the
  /// sensor can measure, [min_range, max_range] (REP 117: anything else would read as valid).
  void ApplyFaults(Robot& r, const std::string& name, double min_range, double max_range,
                   std::vector<double>& values, Rng& rng);
  bool KnownSensor(const Robot& r, const std::string& sensor) const;

  std::unique_ptr<SimWorld> world_;
  std::vector<Robot> robots_;
  double time_ = 0.0;
};

}  // namespace robot_sim
