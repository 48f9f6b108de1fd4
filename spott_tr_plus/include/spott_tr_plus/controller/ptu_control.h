// Where CONTROL_THE_PTU's scanning pattern (Fig. 10: set by room or hallway) points the QUADRIS
// heads. In a room the heads sweep across it; in a hallway they look ahead, one to each side,
// and a head turns to a door in its side's wall as the robot comes to it: looking only ahead,
// QUADRIS saw a side door's leaf once the robot had turned into the doorway (door.test: the
// robot touched the closed d_lab_w 0.3 s after its state was sensed), and once profiles arrive
// the sonar no longer votes on doors (DoorSensingParameters::sonar_with_profiles). ROS-free; the
// caller owns time.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_map/map_database.h"

namespace spott_tr_plus::controller {

struct PtuParameters {
  double sweep_rad = 0.8;        ///< "room": pan sweep amplitude (rad).
  double sweep_period_s = 8.0;   ///< "room": sweep period (s), > 0.
  double hallway_pan_rad = 0.3;  ///< "hallway": the heads look ahead, this far apart (rad).
  /// "hallway": a door whose opening's middle lies this close (m) and ahead of or beside the
  /// robot is looked at by the head on its side; 0 = never.
  double door_watch_m = 3.0;
  double max_pan_rad = 1.5;  ///< The heads' pan range (+-, rad).
  double head_height_m =
      0.85;                   ///< The heads' height above the floor (m), > 0 (the Nomad's QUADRIS).
  double max_tilt_rad = 0.5;  ///< The most a head tilts down (rad), in [0, pi/2).
};

std::vector<std::string> ValidateParameters(const PtuParameters& p);

/// The pan angle (rad, about the base's z, 0 ahead) of each of `heads` heads (even indices the
/// left ones, odd the right) for `pattern` ("room", "hallway"; anything else: ahead) at `now`
/// (s), the robot at `robot` (map frame) in `map`. In a room, head 0 turns to `look_at` (an
/// object recognition needs a vertical profile of) while the others sweep.
/// The tilt (rad, positive down, within [0, max_tilt_rad]) that points a head of the robot at
/// `robot` at `height` (m) above the floor at `at` (map).
double TiltToward(const spott_map::Pose2& robot, const spott_map::Vec2& at, double height,
                  const PtuParameters& p);

std::vector<double> PanHeads(const std::string& pattern, std::size_t heads, double now,
                             const std::optional<spott_map::Pose2>& robot,
                             const spott_map::MapDatabase& map, const PtuParameters& p,
                             const std::optional<spott_map::Vec2>& look_at = std::nullopt);

}  // namespace spott_tr_plus::controller
