#include "spott_tr_plus/controller/ptu_control.h"

#include <algorithm>
#include <cmath>

#include "violation.h"

namespace spott_tr_plus::controller {

std::vector<std::string> ValidateParameters(const PtuParameters& p) {
  std::vector<std::string> v;
  if (!(std::isfinite(p.sweep_rad) && p.sweep_rad >= 0))
    v.push_back(Violation("sweep_rad", ">= 0", p.sweep_rad));
  if (!(std::isfinite(p.sweep_period_s) && p.sweep_period_s > 0))
    v.push_back(Violation("sweep_period_s", "> 0", p.sweep_period_s));
  if (!(std::isfinite(p.hallway_pan_rad) && std::abs(p.hallway_pan_rad) <= M_PI))
    v.push_back(Violation("hallway_pan_rad", "in [-pi, pi]", p.hallway_pan_rad));
  if (!(std::isfinite(p.door_watch_m) && p.door_watch_m >= 0))
    v.push_back(Violation("door_watch_m", ">= 0", p.door_watch_m));
  if (!(p.max_pan_rad > 0 && p.max_pan_rad <= M_PI))
    v.push_back(Violation("max_pan_rad", "in (0, pi]", p.max_pan_rad));
  if (!(p.head_height_m > 0 && std::isfinite(p.head_height_m)))
    v.push_back(Violation("head_height_m", "> 0", p.head_height_m));
  if (!(p.max_tilt_rad >= 0 && p.max_tilt_rad < M_PI / 2))
    v.push_back(Violation("max_tilt_rad", "in [0, pi/2)", p.max_tilt_rad));
  return v;
}

namespace {

// The door (with a leaf) of the robot's room nearest it within `reach`, ahead of it or beside
// it: its bearing from the robot's heading (rad).
std::optional<double> DoorToWatch(const spott_map::Pose2& robot, const spott_map::MapDatabase& map,
                                  double reach) {
  const spott_map::Room* room = map.graph().RoomContaining(robot.Position());
  if (!room) return std::nullopt;
  const spott_map::Vec2 heading(std::cos(robot.yaw), std::sin(robot.yaw));
  std::optional<double> bearing;
  double nearest = reach;
  for (const spott_map::Door& door : map.graph().doors()) {
    if (door.kind != spott_map::DoorKind::kDoor) continue;
    if (door.room_a != room->id && door.room_b != room->id) continue;
    const spott_map::Vec2 d = door.opening.Midpoint() - robot.Position();
    const double distance = d.norm();
    // Passed (more than half a door's width behind): the next one matters.
    if (distance > nearest || d.dot(heading) < -0.3) continue;
    nearest = distance;
    bearing = spott_map::NormalizeAngle(std::atan2(d.y(), d.x()) - robot.yaw);
  }
  return bearing;
}

}  // namespace

double TiltToward(const spott_map::Pose2& robot, const spott_map::Vec2& at, double height,
                  const PtuParameters& p) {
  const double tilt = std::atan2(p.head_height_m - height, (at - robot.Position()).norm());
  return std::isfinite(tilt) ? std::clamp(tilt, 0.0, p.max_tilt_rad) : 0.0;
}

std::vector<double> PanHeads(const std::string& pattern, std::size_t heads, double now,
                             const std::optional<spott_map::Pose2>& robot,
                             const spott_map::MapDatabase& map, const PtuParameters& p,
                             const std::optional<spott_map::Vec2>& look_at) {
  std::vector<double> pan(heads, 0.0);
  for (std::size_t i = 0; i < heads; ++i) {
    const double side = i % 2 == 0 ? 1.0 : -1.0;
    if (pattern == "room") {  // sweep across the room
      pan[i] = side * p.sweep_rad * std::sin(2 * M_PI * now / p.sweep_period_s);
    } else if (pattern == "hallway") {  // ahead
      pan[i] = side * p.hallway_pan_rad;
    }
  }
  if (pattern == "room" && heads > 0 && robot && look_at) {
    const spott_map::Vec2 d = *look_at - robot->Position();
    const double bearing = spott_map::NormalizeAngle(std::atan2(d.y(), d.x()) - robot->yaw);
    pan[0] = std::clamp(bearing, -p.max_pan_rad, p.max_pan_rad);
    return pan;
  }
  if (pattern != "hallway" || heads == 0 || !robot || p.door_watch_m <= 0) return pan;
  const std::optional<double> bearing = DoorToWatch(*robot, map, p.door_watch_m);
  if (!bearing) return pan;
  // The head on the door's side (the only one if there is one) turns to it.
  const std::size_t head = heads == 1 || *bearing >= 0 ? 0 : 1;
  pan[head] = std::clamp(*bearing, -p.max_pan_rad, p.max_pan_rad);
  return pan;
}

}  // namespace spott_tr_plus::controller
