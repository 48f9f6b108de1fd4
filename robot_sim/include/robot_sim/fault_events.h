// Faults as events: what a fault service asks for and what a fault schedule lists, applied to a
// Simulator by one function. A schedule is YAML (a list under `faults:`), read with errors that
// name the file, line and column:
//   faults:
//     - {time: 30, kind: kidnap, pose: [0, 0, -1.22], relative: true}   # RHINO's 70 deg turn
//     - {time: 45, kind: door, door: d_102, state: open}
//     - {time: 60, kind: sensor, sensor: sonar/3, fault: dropout, duration: 10}
//     - {time: 70, kind: sensor, sensor: laser, fault: noise, noise_stddev: 0.2, duration: 5}
//     - {time: 80, kind: slip, linear_scale: 0.8, angular_scale: 1.0, duration: 3}
//     - {time: 90, kind: add_obstacle, id: box, shape: cuboid, pose: [3, 8, 0], size: [0.5, 0.5,
//     1]}
//     - {time: 99, kind: remove_obstacle, id: box}
#pragma once

#include <string>
#include <vector>

#include "robot_sim/simulator.h"
#include "spott_map/source_location.h"
#include "spott_map/yaml_reader.h"

namespace robot_sim {

struct FaultEvent {
  enum class Kind { kKidnap, kDoor, kSensor, kClearSensor, kSlip, kAddObstacle, kRemoveObstacle };
  Kind kind = Kind::kKidnap;
  double time = 0.0;      ///< Simulated time it happens (s); schedules only.
  spott_map::Pose2 pose;  ///< Kidnap target or obstacle pose (map frame / robot frame).
  bool relative = false;  ///< Kidnap: pose is a displacement in the robot frame.
  std::string name;       ///< Door id, sensor name or obstacle id.
  bool closed = false;    ///< Door state.
  FaultKind sensor_fault = FaultKind::kDropout;
  double noise_stddev = 0.0;   ///< (m)
  double duration = 0.0;       ///< (s); 0 = until cleared (sensor faults).
  double linear_scale = 1.0;   ///< Slip.
  double angular_scale = 1.0;  ///< Slip.
  Solid obstacle;              ///< AddObstacle.
  spott_map::SourceLocation where;
};

/// Applies `event` to robot `robot` now; false with a message (and nothing changed) when the
/// simulator refuses it. A door does not close, nor an obstacle appear, through a robot
/// standing there: refused, and `*blocked` (when given) set, so that a schedule can wait
/// until the place is clear (a real door cannot be shut on a robot in the doorway).
bool ApplyFaultEvent(Simulator& sim, int robot, const FaultEvent& event, std::string* error,
                     bool* blocked = nullptr);

struct FaultScheduleResult {
  std::vector<FaultEvent> events;  ///< Sorted by time (stable).
  std::vector<spott_map::SourceError> errors;
  bool ok() const { return errors.empty(); }
};

/// The event in a user's words: "kidnap by (0, 0, -1.22 rad) in the robot frame",
/// "door d_102 closed", "sensor sonar/3 dropout for 10 s", ... (logs, /sim/faults, reports).
std::string Describe(const FaultEvent& event);

/// "kidnap", "door", "sensor", "slip", "add_obstacle", "remove_obstacle": the schedule's `kind`.
const char* KindName(FaultEvent::Kind kind);

/// Reads the list `list` of fault events (a YAML sequence; null = none) named `what` in errors,
/// sorted by time (stable); errors go to `in`. A scenario file's `faults:` uses it.
std::vector<FaultEvent> ReadFaultEvents(spott_map::YamlReader& in, const YAML::Node& list,
                                        const std::string& what);

/// Parses a schedule; an empty document is an empty schedule.
FaultScheduleResult ParseFaultSchedule(const std::string& yaml, const std::string& source_name);

}  // namespace robot_sim
