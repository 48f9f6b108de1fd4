#include "conversions.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "rpl_executive/rpl/reader.h"
#include "spott_map/ros/conversions.h"
#include "spott_ros/markers.h"
#include "spott_ros/pose_conversions.h"
#include "spott_ros/range_readings.h"

namespace rpl_executive::ros_conversions {

namespace nc = noreils_chatila;

namespace {

rpl::Value DatumToValue(const rpl::Datum& d) {
  switch (d.kind) {
    case rpl::Datum::Kind::kNumber:
      return rpl::Value::Number(d.number);
    case rpl::Datum::Kind::kString:
      return rpl::Value::String(d.text);
    case rpl::Datum::Kind::kSymbol:
      return rpl::Value::Symbol(d.text);
    case rpl::Datum::Kind::kList: {
      std::vector<rpl::Value> items;
      for (const rpl::Datum& item : d.items) items.push_back(DatumToValue(item));
      return rpl::Value::List(std::move(items));
    }
  }
  return rpl::Value();
}

uint8_t TaskState(rpl::TaskInfo::State s) {
  switch (s) {
    case rpl::TaskInfo::State::kActive:
      return spott_msgs::PlanTask::ACTIVE;
    case rpl::TaskInfo::State::kWaitBlocked:
      return spott_msgs::PlanTask::WAIT_BLOCKED;
    case rpl::TaskInfo::State::kEvaporating:
      return spott_msgs::PlanTask::EVAPORATING;
  }
  return spott_msgs::PlanTask::ACTIVE;
}

const char* StateText(uint8_t s) {
  switch (s) {
    case spott_msgs::PlanTask::ACTIVE:
      return "active";
    case spott_msgs::PlanTask::WAIT_BLOCKED:
      return "wait-blocked";
    case spott_msgs::PlanTask::EVAPORATING:
      return "evaporating";
    case spott_msgs::PlanTask::DONE:
      return "done";
    case spott_msgs::PlanTask::FAILED:
      return "failed";
    case spott_msgs::PlanTask::EVAPORATED:
      return "evaporated";
  }
  return "?";
}

// A number of a mission value, or nullopt.
std::optional<double> Number(const nc::Value& v) {
  if (!v.IsNumber()) return std::nullopt;
  return v.number();
}

}  // namespace

// ---- RPL ----------------------------------------------------------------------------------------

spott_msgs::Fluent ToMsg(const rpl::FluentState& fluent) {
  spott_msgs::Fluent m;
  m.name = fluent.name;
  m.stamp = ros::Time(std::max(0.0, fluent.stamp_s));
  const rpl::Value& v = fluent.value;
  if (v.type() == rpl::Value::Type::kNil || v.type() == rpl::Value::Type::kTrue) {
    m.type = spott_msgs::Fluent::BOOL;
    m.bool_value = v.Truthy();
  } else if (v.IsNumber()) {
    m.type = spott_msgs::Fluent::NUMBER;
    m.number_value = v.number();
  } else {
    m.type = spott_msgs::Fluent::STRING;
    m.string_value = v.ToString();
  }
  return m;
}

std::vector<spott_msgs::PlanTask> ToMsgs(const std::vector<rpl::TaskInfo>& tasks,
                                         const std::string& file) {
  std::vector<spott_msgs::PlanTask> out;
  out.reserve(tasks.size());
  for (const rpl::TaskInfo& t : tasks) {
    spott_msgs::PlanTask m;
    m.id = t.id;
    m.parent = t.parent;
    m.depth = static_cast<uint16_t>(std::max(0, t.depth));
    m.label = t.label;
    m.state = TaskState(t.state);
    m.waiting_for = t.waiting_for;
    m.policy = t.policy;
    m.where = t.where.file.empty()
                  ? file + ":" + std::to_string(t.where.line) + ":" + std::to_string(t.where.column)
                  : t.where.ToString();
    out.push_back(m);
  }
  return out;
}

std::optional<spott_msgs::PlanTask> EndedThread(const rpl::Event& event) {
  if (event.kind != rpl::Event::Kind::kThreadEnded) return std::nullopt;
  spott_msgs::PlanTask m;
  m.id = -1;
  m.parent = -1;
  m.label = event.subject;
  m.stamp = ros::Time(std::max(0.0, event.time_s));
  if (event.detail == "done") {
    m.state = spott_msgs::PlanTask::DONE;
  } else if (event.detail == "evaporated") {
    m.state = spott_msgs::PlanTask::EVAPORATED;
  } else {
    m.state = spott_msgs::PlanTask::FAILED;
    const std::string prefix = "failed: ";
    m.detail = event.detail.compare(0, prefix.size(), prefix) == 0
                   ? event.detail.substr(prefix.size())
                   : event.detail;
  }
  return m;
}

std::string TaskTreeText(const std::vector<spott_msgs::PlanTask>& tasks,
                         const std::vector<spott_msgs::Fluent>& fluents) {
  std::ostringstream s;
  bool ended_header = false;
  for (const spott_msgs::PlanTask& t : tasks) {
    if (t.id < 0) {
      if (!ended_header) s << "ended:\n";
      ended_header = true;
      s << "  " << t.label << ": " << StateText(t.state)
        << (t.detail.empty() ? "" : " (" + t.detail + ")") << "\n";
      continue;
    }
    s << std::string(2 * t.depth, ' ') << t.label << (t.policy ? " [policy]" : "") << ": "
      << StateText(t.state) << (t.waiting_for.empty() ? "" : " on " + t.waiting_for) << "\n";
  }
  if (!fluents.empty()) s << "fluents:";
  for (const spott_msgs::Fluent& f : fluents) {
    s << " " << f.name << "=";
    if (f.type == spott_msgs::Fluent::BOOL) {
      s << (f.bool_value ? "T" : "NIL");
    } else if (f.type == spott_msgs::Fluent::NUMBER) {
      std::ostringstream n;
      n.precision(3);
      n << f.number_value;
      s << n.str();
    } else {
      s << f.string_value;
    }
  }
  return s.str();
}

// ---- input checks -------------------------------------------------------------------------------

namespace {

constexpr double kFar = 1e4;  // m: a map coordinate beyond 10 km is absurd (spott_map's bound)

bool Plausible(double v) { return std::isfinite(v) && std::abs(v) <= kFar; }
bool Plausible(double x, double y) { return Plausible(x) && Plausible(y); }

}  // namespace

std::string StatusProblem(const spott_msgs::LocalizationStatus& status) {
  if (!Plausible(status.estimate.x, status.estimate.y) || !std::isfinite(status.estimate.theta))
    return "estimate: not finite or beyond 10 km";
  if (!(status.certainty >= 0.0 && status.certainty <= 1.0))
    return "certainty: " + std::to_string(status.certainty) + " is not in [0, 1]";
  return "";
}

std::string GraphProblem(const spott_msgs::RoomDoorGraph& graph) {
  std::string error;
  if (!spott_map::ros_conversions::FromMsg(graph, &error)) return "rooms/doors: " + error;
  return "";
}

std::string TwistProblem(const geometry_msgs::Twist& t) {
  for (double v : {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z})
    if (!std::isfinite(v)) return "linear/angular: not finite";
  return "";
}

std::optional<std::pair<std::string, rpl::Value>> ParseBinding(const std::string& binding,
                                                               std::string* error) {
  const rpl::ReadResult r = rpl::ReadPlanText(binding, "binding '" + binding + "'");
  if (!r.ok()) {
    if (error) *error = rpl::FormatDiagnostics(r.diagnostics);
    return std::nullopt;
  }
  if (r.forms.size() != 2 || !r.forms[0].IsSymbol()) {
    if (error)
      *error = "binding '" + binding + "' must be a name and a value, e.g. DEST (19.6 6.0)";
    return std::nullopt;
  }
  rpl::Value value = DatumToValue(r.forms[1]);
  // (QUOTE x) as written in plans: the datum itself.
  if (r.forms[1].Head() == "QUOTE" && r.forms[1].items.size() == 2) {
    value = DatumToValue(r.forms[1].items[1]);
  }
  return std::make_pair(r.forms[0].text, value);
}

rpl::office::BuildingMap FromMsg(const spott_msgs::RoomDoorGraph& graph) {
  rpl::office::BuildingMap map;
  for (const spott_msgs::Room& r : graph.rooms) {
    rpl::office::BuildingRoom room;
    room.id = r.id;
    room.hallway = r.kind == spott_msgs::Room::HALLWAY;
    for (const auto& p : r.polygon.points) room.polygon.push_back({p.x, p.y});
    map.rooms.push_back(room);
  }
  for (const spott_msgs::Door& d : graph.doors) {
    rpl::office::BuildingDoor door;
    door.id = d.id;
    door.room_a = d.room_a;
    door.room_b = d.room_b;
    door.opening = d.kind == spott_msgs::Door::KIND_OPENING;
    door.open = door.opening || d.state != spott_msgs::Door::CLOSED;
    door.centre = {d.centre.x, d.centre.y};
    if (d.opening.size() == 2) {
      door.end_a = {d.opening[0].x, d.opening[0].y};
      door.end_b = {d.opening[1].x, d.opening[1].y};
    } else {
      door.end_a = door.end_b = door.centre;
    }
    map.doors.push_back(door);
  }
  return map;
}

// ---- Noreils-Chatila ----------------------------------------------------------------------------

nc::SonarRing RingFromMsg(const spott_msgs::RangeRing& ring) {
  nc::SonarRing r;
  for (const auto& m : ring.mounts) r.mounts.push_back({m.x, m.y, m.theta});
  r.half_field_of_view_rad = 0.5 * ring.field_of_view;
  r.max_range_m = ring.max_range;
  r.min_range_m = std::max(0.0f, ring.min_range);
  return r;
}

nc::SonarScan ScanFromMsg(const spott_msgs::RangeRing& ring, int* discarded) {
  nc::SonarScan s;
  s.ranges_m.assign(ring.ranges.begin(), ring.ranges.end());
  const int first = spott_ros::DiscardImpossibleRanges(ring.max_range, &s.ranges_m);
  if (discarded) *discarded = first;
  return s;
}

nc::LaserScan FromMsg(const sensor_msgs::LaserScan& scan, double yaw_in_base_rad) {
  nc::LaserScan s;
  s.angle_min_rad = scan.angle_min + yaw_in_base_rad;
  s.angle_increment_rad = scan.angle_increment;
  s.max_range_m = scan.range_max;
  s.ranges_m.assign(scan.ranges.begin(), scan.ranges.end());
  for (double& r : s.ranges_m) {
    if (r < scan.range_min) r = std::numeric_limits<double>::infinity();  // REP-117: no return
  }
  return s;
}

std::optional<nc::BatteryDatum> FromMsg(const sensor_msgs::BatteryState& battery) {
  if (!std::isfinite(battery.percentage)) return std::nullopt;
  nc::BatteryDatum d;
  d.level_percent = std::clamp(100.0 * battery.percentage, 0.0, 100.0);
  return d;
}

nc::Value PathToValue(const spott_msgs::NamedPath& path) {
  std::vector<nc::Value> points;
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    std::vector<nc::Value> p{nc::Value::Number(std::round(path.points[i].x * 1000.0) / 10.0),
                             nc::Value::Number(std::round(path.points[i].y * 1000.0) / 10.0)};
    if (i + 1 == path.points.size() && path.has_final_heading) {
      // Wrapped in radians first: degrees of a huge finite heading overflow to infinity (the
      // message fuzzer's finding).
      double deg = std::remainder(path.final_heading, 2.0 * M_PI) * 180.0 / M_PI;
      if (deg < 0) deg += 360.0;
      p.push_back(nc::Value::Number(std::round(deg * 10.0)));
    }
    points.push_back(nc::Value::List(std::move(p)));
  }
  return nc::Value::List(std::move(points));
}

std::vector<nc::Point2> PolygonFromMsg(const geometry_msgs::Polygon& polygon) {
  std::vector<nc::Point2> out;
  for (const auto& p : polygon.points) out.push_back({p.x, p.y});
  return out;
}

spott_msgs::MonitorEvent ToMsg(const nc::MonitorEvent& event, const std::string& mission,
                               const std::string& frame, const ros::Time& stamp) {
  spott_msgs::MonitorEvent m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.mission = event.o_surveillance ? "O-surveillance" : mission;
  m.monitor_id = std::to_string(event.id) + ": " + event.label;
  m.kind = event.is_static  ? spott_msgs::MonitorEvent::STATIC
           : event.terminal ? spott_msgs::MonitorEvent::TERMINAL
                            : spott_msgs::MonitorEvent::NON_TERMINAL;
  m.condition = event.condition;
  if (!event.reflex.empty()) m.reflex_actions.push_back(event.reflex);
  m.control_action = event.control;
  m.command = event.command;
  return m;
}

geometry_msgs::Twist ToTwist(const nc::VelocityCommand& command) {
  geometry_msgs::Twist t;
  t.linear.x = command.linear_mps;
  t.angular.z = command.angular_rps;
  return t;
}

visualization_msgs::MarkerArray DrawToMarkers(const nc::DrawCommand& draw,
                                              const nc::SonarRing& ring, const std::string& frame,
                                              const ros::Time& stamp, int* next_id) {
  visualization_msgs::MarkerArray out;
  // r-position first: the echoes are placed from it.
  std::optional<nc::Pose2> pose;
  for (std::size_t i = 0; i < draw.formats.size() && i < draw.data.size(); ++i) {
    if (draw.formats[i] != "G_pos" || !draw.data[i].IsList()) continue;
    const auto& l = draw.data[i].list();
    if (l.size() >= 3 && Number(l[0]) && Number(l[1]) && Number(l[2])) {
      pose = nc::Pose2{*Number(l[0]) / 100.0, *Number(l[1]) / 100.0,
                       *Number(l[2]) / 10.0 * M_PI / 180.0};
    }
  }
  for (std::size_t i = 0; i < draw.formats.size() && i < draw.data.size(); ++i) {
    const std::string& format = draw.formats[i];
    const nc::Value& value = draw.data[i];
    if (format == "G_pos" && pose) {
      auto m = spott_ros::MakeMarker("draw/G_pos", (*next_id)++, visualization_msgs::Marker::ARROW,
                                     frame, stamp);
      m.pose.position.x = pose->x;
      m.pose.position.y = pose->y;
      m.pose.orientation = spott_ros::YawToQuaternion(pose->yaw);
      m.scale.x = 0.3;
      m.scale.y = 0.05;
      m.scale.z = 0.05;
      m.color = spott_ros::Colour(0.1f, 0.4f, 1.0f);
      out.markers.push_back(m);
    } else if (format == "G_echoes" && value.IsList() && pose) {
      auto m = spott_ros::MakeMarker("draw/G_echoes", (*next_id)++,
                                     visualization_msgs::Marker::SPHERE_LIST, frame, stamp);
      m.scale.x = m.scale.y = m.scale.z = 0.06;
      m.color = spott_ros::Colour(1.0f, 0.5f, 0.0f);
      for (const nc::Value& echo : value.list()) {
        if (!echo.IsList() || echo.list().size() != 2) continue;
        const auto id = Number(echo.list()[0]);
        const auto range_cm = Number(echo.list()[1]);
        if (!id || !range_cm || *id < 1 || *id > static_cast<double>(ring.mounts.size())) continue;
        const nc::SonarMount& s = ring.mounts[static_cast<std::size_t>(*id) - 1];
        const double r = *range_cm / 100.0;
        const double bx = s.x_m + r * std::cos(s.yaw_rad), by = s.y_m + r * std::sin(s.yaw_rad);
        geometry_msgs::Point p;
        p.x = pose->x + bx * std::cos(pose->yaw) - by * std::sin(pose->yaw);
        p.y = pose->y + bx * std::sin(pose->yaw) + by * std::cos(pose->yaw);
        p.z = 0.3;
        m.points.push_back(p);
      }
      out.markers.push_back(m);
    } else {
      auto m = spott_ros::MakeMarker("draw/" + format, (*next_id)++,
                                     visualization_msgs::Marker::TEXT_VIEW_FACING, frame, stamp);
      if (pose) {
        m.pose.position.x = pose->x;
        m.pose.position.y = pose->y;
      }
      m.pose.position.z = 1.5;
      m.scale.z = 0.2;
      m.color = spott_ros::Colour(1.0f, 1.0f, 1.0f);
      m.text = format + " " + value.ToText();
      out.markers.push_back(m);
    }
  }
  return out;
}

// ---- both ---------------------------------------------------------------------------------------

visualization_msgs::Marker TextViewMarker(const std::string& text, const std::string& frame,
                                          double x_m, double y_m, const ros::Time& stamp) {
  auto m =
      spott_ros::MakeMarker("plan", 0, visualization_msgs::Marker::TEXT_VIEW_FACING, frame, stamp);
  m.pose.position.x = x_m;
  m.pose.position.y = y_m;
  m.pose.position.z = 2.0;
  m.scale.z = 0.18;
  m.color = spott_ros::Colour(1.0f, 1.0f, 1.0f);
  m.text = text;
  return m;
}

}  // namespace rpl_executive::ros_conversions
