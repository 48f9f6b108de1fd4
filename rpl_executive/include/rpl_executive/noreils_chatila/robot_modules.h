// The robot's modules as the executive and the surveillance manager see them (section 3): the
// execution operators they send, and the interface a node (or the in-process OnBoardModules,
// on_board_modules.h) implements to carry them out. Arguments arrive decoded and in SI units:
// the mission's centimetres, tenths of a degree and cm/s are converted by the vocabulary.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rpl_executive/noreils_chatila/geometry.h"
#include "rpl_executive/noreils_chatila/value.h"

namespace rpl_executive::noreils_chatila {

/// Names one run of an operator in later reports. Never 0.
using OperatorHandle = std::uint64_t;

enum class WallSide { kLeft, kRight };

/// smooth-move(PATH): move along the broken line, smoothing the orientation changes by clothoid
/// curves (section 6.2.1; path_smoothing.h). The robot's own position is the line's first point.
struct SmoothMoveCommand {
  std::vector<Point2> path_m;
  std::optional<double> final_yaw_rad;  ///< Tpath's last point (x y heading)
  bool resume = false;                  ///< resume-order: go on along what is left of the same path
};

/// RUN (wall-following (right-side 25)): the Docking process (section 6.1.1).
struct WallFollowingCommand {
  WallSide side = WallSide::kRight;
  double distance_m = 0.25;  ///< from the robot's side (its sonar ring) to the wall
};

/// RUN (obstacle-avoidance): the Local Obstacle Avoidance process, which never stops by itself.
struct ObstacleAvoidanceCommand {};

/// avoid-obstacle: the elementary task that "includes the avoidance process" (Example 2). It
/// ends when the process reports that it repeatedly has nothing to avoid (section 4.2's
/// "an obstacle avoidance has terminated").
struct AvoidObstacleCommand {};

/// set-speed v: the pilot's linear speed.
struct SetSpeedCommand {
  double speed_mps = 0.0;
};

/// stop: the pilot stops the movement (and any process driving the wheels), then reports the
/// interruption of the running operator (Fig. 5, message 7).
struct StopCommand {};

/// read-all-us-data: returns the belt's echoes (result r-us-data) and where they were read
/// (r-position).
struct ReadAllUsDataCommand {};

/// read-pos: returns the odometer's position (result r-position).
struct ReadPosCommand {};

/// draw %G_pos%G_echoes r-position r-us-data: sends data to the graphics interface, each
/// value with its format (G_pos, G_echoes).
struct DrawCommand {
  std::vector<std::string> formats;
  std::vector<Value> data;
};

using OperatorCommand =
    std::variant<SmoothMoveCommand, WallFollowingCommand, ObstacleAvoidanceCommand,
                 AvoidObstacleCommand, SetSpeedCommand, StopCommand, ReadAllUsDataCommand,
                 ReadPosCommand, DrawCommand>;

/// The operator's name as missions write it (smooth-move, wall-following, ...).
std::string OperatorName(const OperatorCommand& command);
/// The module it goes to, as Fig. 5 names them: PILOT, US, ODOMETER, GRAPHICS,
/// WALL-FOLLOWING, OBSTACLE-AVOIDANCE.
std::string ModuleName(const OperatorCommand& command);
/// One line: "smooth-move 3 points" / "set-speed 0.20 m/s".
std::string Describe(const OperatorCommand& command);

enum class OperatorStatus {
  kRunning,      ///< accepted; a report follows (Executive::OnOperatorReport)
  kCompleted,    ///< done
  kInterrupted,  ///< stopped (by stop or Halt) before it was done
  kFailed,       ///< the module could not do it (module failure, repeated insufficient data)
};
const char* StatusName(OperatorStatus status);

struct OperatorReply {
  OperatorStatus status = OperatorStatus::kCompleted;
  std::string message;  ///< why, for kFailed
  /// Results the executive stores in variables (read-all-us-data: r-us-data, r-position),
  /// in mission units.
  std::vector<std::pair<std::string, Value>> results;
};

/// The robot's modules. Calls come from the executive and the surveillance manager in one
/// thread; implementations must not call back into the executive from inside these calls
/// except through Executive::OnOperatorReport, which queues.
class RobotModules {
 public:
  virtual ~RobotModules() = default;
  /// Sends an execution operator. Instant operators (set-speed, stop, read-all-us-data,
  /// read-pos, draw) answer kCompleted or kFailed at once; the others answer kRunning and
  /// report their end later with the same handle.
  virtual OperatorReply Send(OperatorHandle handle, const OperatorCommand& command, double now) = 0;
  /// Halts a running operator (the executive's own decision: NEXT, FAIL, an ENV that no longer
  /// holds). No report is expected afterwards; one that comes is ignored.
  virtual void Halt(OperatorHandle handle, double now) = 0;
  /// A mission has been accepted and starts: settings an earlier mission's operators left
  /// (set-speed) return to the robot's defaults, so that no mission inherits them.
  virtual void OnMissionStart(double /*now*/) {}
};

}  // namespace rpl_executive::noreils_chatila
