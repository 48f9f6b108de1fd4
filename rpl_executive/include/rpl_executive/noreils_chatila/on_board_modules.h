// HILARE's on-board modules (section 6.1.1) in one object that implements RobotModules: the
// Pilot (smooth-move, set-speed, stop), the ultrasonic and odometer modules (read-all-us-data,
// read-pos), the graphics interface's input (draw) and the two processes, built once (section
// 3.3) and activated by the executive's operators. A node feeds it the robot's pose and sonar
// scans, calls Update once per control cycle, sends the returned velocity to the wheels (through
// the stack's arbiter), passes TakeReports() to Executive::OnOperatorReport and publishes
// TakeDrawings() as markers. Tests drive it the same way, in process.
//
// The Pilot is the only effector: whatever runs (path, wall following, avoidance) holds the
// wheels, and a new movement interrupts the one before (reported kInterrupted). `stop`
// halts the wheels' holder and reports its interruption on the next Update (Fig. 5, message 7).
// avoid-obstacle completes when the way back to the interrupted order is clear
// (avoid_obstacle.h); a RUN process that repeatedly lacks data fails.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rpl_executive/noreils_chatila/avoid_obstacle.h"
#include "rpl_executive/noreils_chatila/pilot.h"
#include "rpl_executive/noreils_chatila/processes.h"
#include "rpl_executive/noreils_chatila/robot_modules.h"
#include "rpl_executive/noreils_chatila/sensor_data.h"

namespace rpl_executive::noreils_chatila {

struct OnBoardParameters {
  PilotParameters pilot;
  WallFollowingParameters wall_following;
  ObstacleAvoidanceParameters obstacle_avoidance;
  SonarInterpretationParameters sonar;
};
std::vector<std::string> ValidateParameters(const OnBoardParameters& p);

class OnBoardModules : public RobotModules {
 public:
  /// Parameters must be valid (std::invalid_argument otherwise).
  OnBoardModules(const OnBoardParameters& parameters, const SonarRing& ring);

  OperatorReply Send(OperatorHandle handle, const OperatorCommand& command, double now) override;
  void Halt(OperatorHandle handle, double now) override;
  /// The Pilot's speed back to its default.
  void OnMissionStart(double now) override;

  void OnPose(const PoseDatum& pose);
  /// Processes run on each new scan.
  void OnSonar(const SonarScan& scan);
  /// One control cycle: the wheels' command.
  VelocityCommand Update(double now);

  /// Reports on long operators since the last call, in order.
  std::vector<std::pair<OperatorHandle, OperatorReply>> TakeReports();
  std::vector<DrawCommand> TakeDrawings();

  const Pilot& pilot() const { return pilot_; }
  /// The operator holding the wheels (empty when none).
  std::string wheels_holder() const;

 private:
  enum class Holder { kNone, kPilot, kWallFollowing, kAvoidance };
  void Release(OperatorStatus status, const std::string& message);
  void Report(OperatorHandle handle, OperatorStatus status, const std::string& message);

  OnBoardParameters parameters_;
  SonarRing ring_;
  Pilot pilot_;
  WallFollowingProcess wall_following_;
  ObstacleAvoidanceProcess avoidance_;
  AvoidObstacleTask avoid_obstacle_;
  Holder holder_ = Holder::kNone;
  OperatorHandle handle_ = 0;
  bool elementary_task_ = false;  // avoid-obstacle rather than RUN (obstacle-avoidance)
  std::optional<PoseDatum> pose_;
  std::optional<SonarScan> sonar_;
  ProcessOutput process_output_;
  std::vector<std::pair<OperatorHandle, OperatorReply>> reports_;
  std::vector<DrawCommand> drawings_;
};

/// r-us-data as read-all-us-data returns it: ((sensor range_cm)...) for the echoes.
Value SonarToValue(const SonarScan& scan, const SonarRing& ring);
/// r-position: (x_cm y_cm heading_tenths_of_a_degree).
Value PoseToValue(const Pose2& pose);

}  // namespace rpl_executive::noreils_chatila
