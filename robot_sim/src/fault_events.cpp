#include "robot_sim/fault_events.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include "spott_map/yaml_reader.h"

namespace robot_sim {

using spott_map::NumberRule;
using spott_map::YamlReader;

namespace {

// Whoever closes a door or puts a box down leaves the robot this much room (m): more than a
// bumper's travel, so that the leaf does not brush it as it passes.
constexpr double kKeepClearM = 0.1;

std::vector<bool> Overlaps(const Simulator& sim) {
  std::vector<bool> v;
  for (int i = 0; i < sim.robot_count(); ++i) v.push_back(sim.Overlapped(i, kKeepClearM));
  return v;
}

// The name of a robot the world overlaps now but did not `before`, or "".
std::string NewlyOverlapped(const Simulator& sim, const std::vector<bool>& before) {
  for (int i = 0; i < sim.robot_count(); ++i)
    if (sim.Overlapped(i, kKeepClearM) && !before[i]) return sim.spec(i).name;
  return "";
}

}  // namespace

bool ApplyFaultEvent(Simulator& sim, int robot, const FaultEvent& e, std::string* error,
                     bool* blocked) {
  if (blocked) *blocked = false;
  const bool closes = e.kind == FaultEvent::Kind::kDoor && e.closed &&
                      sim.world().DoorClosed(e.name) == std::optional<bool>(false);
  if (closes || e.kind == FaultEvent::Kind::kAddObstacle) {
    const std::vector<bool> before = Overlaps(sim);
    const bool added = closes ? sim.world().SetDoorClosed(e.name, true, error)
                              : sim.world().AddObstacle(e.obstacle, error);
    if (!added) return false;
    const std::string in_the_way = NewlyOverlapped(sim, before);
    if (in_the_way.empty()) return true;
    if (closes)
      sim.world().SetDoorClosed(e.name, false, nullptr);
    else
      sim.world().RemoveObstacle(e.obstacle.id, nullptr);
    if (error)
      *error = closes ? "robot " + in_the_way + " stands in the doorway"
                      : "robot " + in_the_way + " stands where the obstacle would be";
    if (blocked) *blocked = true;
    return false;
  }
  switch (e.kind) {
    case FaultEvent::Kind::kKidnap:
      return sim.Kidnap(robot, e.pose, e.relative, error);
    case FaultEvent::Kind::kDoor:
      return sim.world().SetDoorClosed(e.name, e.closed, error);
    case FaultEvent::Kind::kSensor: {
      SensorFault f;
      f.kind = e.sensor_fault;
      f.noise_stddev = e.noise_stddev;
      if (!(e.duration >= 0) || !std::isfinite(e.duration)) {
        if (error) *error = "fault duration must be finite and >= 0";
        return false;
      }
      f.until = e.duration > 0 ? sim.time() + e.duration : std::numeric_limits<double>::infinity();
      return sim.InjectFault(robot, e.name, f, error);
    }
    case FaultEvent::Kind::kClearSensor:
      return sim.ClearFault(robot, e.name, error);
    case FaultEvent::Kind::kSlip:
      return sim.Slip(robot, e.linear_scale, e.angular_scale, e.duration, error);
    case FaultEvent::Kind::kAddObstacle:
      return sim.world().AddObstacle(e.obstacle, error);
    case FaultEvent::Kind::kRemoveObstacle:
      return sim.world().RemoveObstacle(e.name, error);
  }
  return false;
}

const char* KindName(FaultEvent::Kind kind) {
  switch (kind) {
    case FaultEvent::Kind::kKidnap:
      return "kidnap";
    case FaultEvent::Kind::kDoor:
      return "door";
    case FaultEvent::Kind::kSensor:
    case FaultEvent::Kind::kClearSensor:
      return "sensor";
    case FaultEvent::Kind::kSlip:
      return "slip";
    case FaultEvent::Kind::kAddObstacle:
      return "add_obstacle";
    case FaultEvent::Kind::kRemoveObstacle:
      return "remove_obstacle";
  }
  return "?";
}

std::string Describe(const FaultEvent& e) {
  char text[256];
  std::snprintf(text, sizeof(text), " for %g s", e.duration);
  const std::string lasting = e.duration > 0 ? text : " until cleared";
  switch (e.kind) {
    case FaultEvent::Kind::kKidnap:
      std::snprintf(text, sizeof(text), "kidnap %s (%.2f m, %.2f m, %.2f rad)%s",
                    e.relative ? "by" : "to", e.pose.x, e.pose.y, e.pose.yaw,
                    e.relative ? " in the robot frame" : " in the map frame");
      return text;
    case FaultEvent::Kind::kDoor:
      return "door " + e.name + (e.closed ? " closed" : " open");
    case FaultEvent::Kind::kSensor: {
      const char* fault = e.sensor_fault == FaultKind::kDropout ? "dropout"
                          : e.sensor_fault == FaultKind::kStuck ? "stuck"
                                                                : "noise";
      std::string out = "sensor " + e.name + " " + fault;
      if (e.sensor_fault == FaultKind::kNoise) {
        std::snprintf(text, sizeof(text), " (%.3f m)", e.noise_stddev);
        out += text;
      }
      return out + lasting;
    }
    case FaultEvent::Kind::kClearSensor:
      return "sensor " + e.name + " faults cleared";
    case FaultEvent::Kind::kSlip:
      std::snprintf(text, sizeof(text), "wheel slip x%.2f linear, x%.2f angular for %.1f s",
                    e.linear_scale, e.angular_scale, e.duration);
      return text;
    case FaultEvent::Kind::kAddObstacle:
      std::snprintf(text, sizeof(text), "%s %s %.2f x %.2f x %.2f m added at (%.2f, %.2f)",
                    e.obstacle.cylinder ? "cylinder" : "cuboid", e.obstacle.id.c_str(),
                    e.obstacle.size_x, e.obstacle.size_y, e.obstacle.height, e.obstacle.pose.x,
                    e.obstacle.pose.y);
      return text;
    case FaultEvent::Kind::kRemoveObstacle:
      return "obstacle " + e.name + " removed";
  }
  return "?";
}

namespace {

std::optional<FaultEvent> ReadEvent(YamlReader& in, const YAML::Node& item,
                                    const std::string& what) {
  if (!in.ExpectMap(
          item, what,
          {"time", "kind", "pose", "relative", "door", "state", "sensor", "fault", "noise_stddev",
           "duration", "linear_scale", "angular_scale", "id", "shape", "size"})) {
    return std::nullopt;
  }
  FaultEvent e;
  e.where = in.Where(item);
  const auto time = in.Number(item, "time", what, true, NumberRule::kNonNegative);
  const auto kind = in.String(item, "kind", what, true);
  if (!time || !kind) return std::nullopt;
  e.time = *time;
  const std::size_t errors_before = in.errors().size();
  if (*kind == "kidnap") {
    e.kind = FaultEvent::Kind::kKidnap;
    e.pose = in.Pose(item, "pose", what, true).value_or(spott_map::Pose2{});
    e.relative = in.Bool(item, "relative", what, false).value_or(false);
  } else if (*kind == "door") {
    e.kind = FaultEvent::Kind::kDoor;
    e.name = in.String(item, "door", what, true).value_or("");
    const std::string state = in.String(item, "state", what, true).value_or("closed");
    if (state != "open" && state != "closed") {
      in.Error(item["state"], what + ": state must be open or closed, got '" + state + "'");
    }
    e.closed = state == "closed";
  } else if (*kind == "sensor") {
    e.kind = FaultEvent::Kind::kSensor;
    e.name = in.String(item, "sensor", what, true).value_or("");
    const std::string fault = in.String(item, "fault", what, true).value_or("dropout");
    if (fault == "dropout") {
      e.sensor_fault = FaultKind::kDropout;
    } else if (fault == "stuck") {
      e.sensor_fault = FaultKind::kStuck;
    } else if (fault == "noise") {
      e.sensor_fault = FaultKind::kNoise;
      e.noise_stddev =
          in.Number(item, "noise_stddev", what, true, NumberRule::kPositive).value_or(0.0);
    } else if (fault == "clear") {
      e.kind = FaultEvent::Kind::kClearSensor;
    } else {
      in.Error(item["fault"],
               what + ": fault must be dropout, stuck, noise or clear, got '" + fault + "'");
    }
    e.duration = in.Number(item, "duration", what, false, NumberRule::kNonNegative).value_or(0.0);
  } else if (*kind == "slip") {
    e.kind = FaultEvent::Kind::kSlip;
    e.linear_scale =
        in.Number(item, "linear_scale", what, false, NumberRule::kNonNegative).value_or(1.0);
    e.angular_scale =
        in.Number(item, "angular_scale", what, false, NumberRule::kNonNegative).value_or(1.0);
    e.duration = in.Number(item, "duration", what, true, NumberRule::kPositive).value_or(1.0);
  } else if (*kind == "add_obstacle") {
    e.kind = FaultEvent::Kind::kAddObstacle;
    e.obstacle.id = in.String(item, "id", what, true).value_or("");
    const std::string shape = in.String(item, "shape", what, false).value_or("cuboid");
    if (shape != "cuboid" && shape != "cylinder") {
      in.Error(item["shape"], what + ": shape must be cuboid or cylinder, got '" + shape + "'");
    }
    e.obstacle.cylinder = shape == "cylinder";
    e.obstacle.pose = in.Pose(item, "pose", what, true).value_or(spott_map::Pose2{});
    if (auto size = in.Numbers(item, "size", what, true, 3, NumberRule::kPositive)) {
      e.obstacle.size_x = (*size)[0];
      e.obstacle.size_y = (*size)[1];
      e.obstacle.height = (*size)[2];
    }
  } else if (*kind == "remove_obstacle") {
    e.kind = FaultEvent::Kind::kRemoveObstacle;
    e.name = in.String(item, "id", what, true).value_or("");
  } else {
    in.Error(item["kind"], what +
                               ": kind must be kidnap, door, sensor, slip, add_obstacle or "
                               "remove_obstacle, got '" +
                               *kind + "'");
  }
  if (in.errors().size() != errors_before) return std::nullopt;
  return e;
}

}  // namespace

std::vector<FaultEvent> ReadFaultEvents(YamlReader& in, const YAML::Node& list,
                                        const std::string& what) {
  std::vector<FaultEvent> events;
  if (!list || list.IsNull() || !in.ExpectSequence(list, what)) return events;
  for (std::size_t i = 0; i < list.size(); ++i) {
    auto e = ReadEvent(in, list[i], what + "[" + std::to_string(i) + "]");
    if (e) events.push_back(*e);
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const FaultEvent& a, const FaultEvent& b) { return a.time < b.time; });
  return events;
}

FaultScheduleResult ParseFaultSchedule(const std::string& yaml, const std::string& source_name) {
  FaultScheduleResult result;
  YamlReader in(source_name);
  const YAML::Node root = in.Parse(yaml);
  if (in.errors().empty() && root && !root.IsNull()) {
    if (in.ExpectMap(root, "fault schedule", {"faults"}) && root["faults"]) {
      result.events = ReadFaultEvents(in, root["faults"], "faults");
    }
  }
  result.errors = in.errors();
  if (!result.ok()) result.events.clear();
  return result;
}

}  // namespace robot_sim
