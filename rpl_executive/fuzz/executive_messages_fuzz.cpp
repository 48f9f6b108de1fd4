// rpl_executive's inbound messages (src/ros/conversions.h) built field by field from the
// fuzzer's bytes (any sizes, NaN, infinities, huge and negative numbers, any text), taken as the
// node takes them: the edge's check first (RingProblem, LaserScanProblem, StatusProblem,
// GraphProblem, PlacesProblem), then the conversion and the core. Whatever is accepted must be
// usable: a sonar ring gives the Noreils-Chatila modules finite wheel commands, readings that
// are dropped out (NaN) or in [0, max_range]; a scan finite angles; a graph a building whose
// navigation plans have finite target points; places mission values without NaN or infinity; a
// battery a charge in [0, 100] %; a Mission goal's binding a value or an error that says why.
// A refusal must name its field ("field: why").
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "conversions.h"
#include "fuzz_messages.h"
#include "fuzz_values.h"
#include "rpl_executive/noreils_chatila/on_board_modules.h"
#include "spott_map/ros/conversions.h"
#include "spott_ros/range_readings.h"

namespace conv = rpl_executive::ros_conversions;
namespace nc = rpl_executive::noreils_chatila;
namespace office = rpl_executive::rpl::office;

namespace {

using spott_fuzz::AnyNumber;
void Check(bool ok, const char* what) { spott_fuzz::Check(ok, "executive_messages_fuzz", what); }
void CheckRefusal(const std::string& problem) {
  Check(spott_fuzz::NamesField(problem), "a refusal without 'field: why'");
}
bool Finite(const std::string& text) {
  return text.find("nan") == std::string::npos && text.find("inf") == std::string::npos;
}

void Ring(FuzzedDataProvider& in) {
  const spott_msgs::RangeRing ring = spott_fuzz::AnyRangeRing(in);
  const std::string problem = spott_ros::RangeRingProblem(ring);
  if (!problem.empty()) return CheckRefusal(problem);
  const nc::SonarRing belt = conv::RingFromMsg(ring);
  Check(belt.mounts.size() == ring.ranges.size(), "not one mount per reading");
  int discarded = -2;
  const nc::SonarScan scan = conv::ScanFromMsg(ring, &discarded);
  Check(discarded >= -1 && discarded < static_cast<int>(ring.ranges.size()), "a discarded index");
  for (double r : scan.ranges_m)
    Check(std::isnan(r) || (r >= 0.0 && r <= belt.max_range_m * 1.001),
          "a reading neither dropped out nor in [0, max_range]");
  // The belt on the modules as the node builds them, driving from a pose with that scan.
  try {
    nc::OnBoardModules kit(nc::OnBoardParameters(), belt);
    nc::PoseDatum pose;
    pose.pose.x = AnyNumber<double>(in, -5.0, 5.0);
    pose.pose.y = AnyNumber<double>(in, -5.0, 5.0);
    pose.pose.yaw = AnyNumber<double>(in, -4.0, 4.0);
    if (!std::isfinite(pose.pose.x) || !std::isfinite(pose.pose.y) || !std::isfinite(pose.pose.yaw))
      return;  // the node's poses come from tf, finite (spott_ros::ToPose2D)
    kit.OnMissionStart(0.0);
    kit.OnPose(pose);
    kit.OnSonar(scan);
    const nc::VelocityCommand c = kit.Update(0.1);
    Check(std::isfinite(c.linear_mps) && std::isfinite(c.angular_rps),
          "an accepted ring gave a wheel command that is not finite");
  } catch (const std::invalid_argument& e) {
    Check(std::string(e.what()).size() > 0, "the modules refused the belt without a reason");
  }
}

void Laser(FuzzedDataProvider& in) {
  sensor_msgs::LaserScan scan;
  scan.angle_min = AnyNumber<float>(in, -4.0f, 4.0f);
  scan.angle_increment = AnyNumber<float>(in, -0.1f, 0.1f);
  scan.range_min = AnyNumber<float>(in, -1.0f, 1.0f);
  scan.range_max = AnyNumber<float>(in, -1.0f, 40.0f);
  const int n = in.ConsumeIntegralInRange<int>(0, 400);
  for (int i = 0; i < n; ++i) scan.ranges.push_back(AnyNumber<float>(in, -1.0f, 50.0f));
  const std::string problem = spott_ros::LaserScanProblem(scan);
  if (!problem.empty()) return CheckRefusal(problem);
  const double yaw = in.ConsumeFloatingPointInRange<double>(-M_PI, M_PI);  // from tf
  const nc::LaserScan s = conv::FromMsg(scan, yaw);
  Check(std::isfinite(s.angle_min_rad) && std::isfinite(s.angle_increment_rad) &&
            s.angle_increment_rad != 0.0,
        "an accepted scan with angles not finite");
  Check(std::isfinite(s.max_range_m) && s.max_range_m > 0.0, "an accepted scan without a range");
  Check(s.ranges_m.size() == scan.ranges.size(), "not one reading per beam");
}

void Status(FuzzedDataProvider& in) {
  spott_msgs::LocalizationStatus st;
  st.estimate.x = AnyNumber<double>(in, -50.0, 50.0);
  st.estimate.y = AnyNumber<double>(in, -50.0, 50.0);
  st.estimate.theta = AnyNumber<double>(in, -7.0, 7.0);
  st.certainty = AnyNumber<double>(in, -0.5, 1.5);
  const std::string problem = conv::StatusProblem(st);
  if (!problem.empty()) return CheckRefusal(problem);
  Check(std::isfinite(st.estimate.x) && std::isfinite(st.estimate.y) &&
            std::isfinite(st.estimate.theta) && st.certainty >= 0.0 && st.certainty <= 1.0,
        "an accepted status that is not finite or not a probability");
}

geometry_msgs::Point32 Point32(FuzzedDataProvider& in) {
  geometry_msgs::Point32 p;
  p.x = AnyNumber<float>(in, -2.0f, 12.0f);
  p.y = AnyNumber<float>(in, -2.0f, 12.0f);
  return p;
}
geometry_msgs::Point Point(FuzzedDataProvider& in) {
  geometry_msgs::Point p;
  p.x = AnyNumber<double>(in, -2.0, 12.0);
  p.y = AnyNumber<double>(in, -2.0, 12.0);
  return p;
}

void Graph(FuzzedDataProvider& in) {
  spott_msgs::RoomDoorGraph g;
  const int rooms = in.ConsumeIntegralInRange<int>(0, 4);
  for (int i = 0; i < rooms; ++i) {
    spott_msgs::Room r;
    r.id = "r" + std::to_string(in.ConsumeIntegralInRange<int>(0, 4));
    r.kind = in.ConsumeIntegralInRange<std::uint8_t>(0, 2);
    const int points = in.ConsumeIntegralInRange<int>(0, 6);
    for (int k = 0; k < points; ++k) r.polygon.points.push_back(Point32(in));
    g.rooms.push_back(r);
  }
  const int doors = in.ConsumeIntegralInRange<int>(0, 4);
  for (int i = 0; i < doors; ++i) {
    spott_msgs::Door d;
    d.id = "d" + std::to_string(i);
    d.room_a = "r" + std::to_string(in.ConsumeIntegralInRange<int>(0, 4));
    d.room_b = "r" + std::to_string(in.ConsumeIntegralInRange<int>(0, 4));
    d.kind = in.ConsumeIntegralInRange<std::uint8_t>(0, 2);
    d.state = in.ConsumeIntegralInRange<std::uint8_t>(0, 3);
    d.width = AnyNumber<double>(in, 0.0, 2.0);
    d.centre = Point(in);
    const int ends = in.ConsumeIntegralInRange<int>(0, 3);
    for (int k = 0; k < ends; ++k) d.opening.push_back(Point(in));
    g.doors.push_back(d);
  }
  const std::string problem = conv::GraphProblem(g);
  if (!problem.empty()) return CheckRefusal(problem);
  const office::BuildingMap map = conv::FromMsg(g);
  Check(map.rooms.size() == g.rooms.size() && map.doors.size() == g.doors.size(),
        "rooms or doors lost in the conversion");
  const office::Point from{in.ConsumeFloatingPointInRange<double>(-2.0, 12.0),
                           in.ConsumeFloatingPointInRange<double>(-2.0, 12.0)};
  const office::Point to{in.ConsumeFloatingPointInRange<double>(-2.0, 12.0),
                         in.ConsumeFloatingPointInRange<double>(-2.0, 12.0)};
  std::string error;
  const auto plan =
      office::PlanNavigation(map, from, to, office::NavigationPlanParameters(), &error);
  if (!plan) return Check(!error.empty(), "no navigation plan and no reason");
  Check(!plan->targets.empty(), "a navigation plan without a target");
  for (const office::Point& t : plan->targets)
    Check(std::isfinite(t.x_m) && std::isfinite(t.y_m), "a target point that is not finite");
}

void Places(FuzzedDataProvider& in) {
  spott_msgs::WorldPlaces places;
  const int n = in.ConsumeIntegralInRange<int>(0, 3);
  for (int i = 0; i < n; ++i) {
    spott_msgs::NamedPlace p;
    p.name = in.ConsumeRandomLengthString(12);
    p.pose.x = AnyNumber<double>(in, -5.0, 5.0);
    p.pose.y = AnyNumber<double>(in, -5.0, 5.0);
    p.pose.theta = AnyNumber<double>(in, -4.0, 4.0);
    places.places.push_back(p);
  }
  const int zones = in.ConsumeIntegralInRange<int>(0, 2);
  for (int i = 0; i < zones; ++i) {
    spott_msgs::Zone z;
    z.id = "Z" + std::to_string(i);
    const int points = in.ConsumeIntegralInRange<int>(0, 5);
    for (int k = 0; k < points; ++k) z.polygon.points.push_back(Point32(in));
    places.zones.push_back(z);
  }
  const int paths = in.ConsumeIntegralInRange<int>(0, 2);
  for (int i = 0; i < paths; ++i) {
    spott_msgs::NamedPath path;
    path.id = "P" + std::to_string(i);
    const int points = in.ConsumeIntegralInRange<int>(0, 5);
    for (int k = 0; k < points; ++k) path.points.push_back(Point(in));
    path.has_final_heading = in.ConsumeBool();
    path.final_heading = AnyNumber<double>(in, -7.0, 7.0);
    places.paths.push_back(path);
  }
  const std::string problem = spott_map::ros_conversions::PlacesProblem(places);
  if (!problem.empty()) return CheckRefusal(problem);
  for (const auto& z : places.zones) {
    const auto polygon = conv::PolygonFromMsg(z.polygon);
    Check(polygon.size() >= 3, "an accepted zone of fewer than 3 points");
    for (const auto& p : polygon)
      Check(std::isfinite(p.x) && std::isfinite(p.y), "a zone point that is not finite");
  }
  for (const auto& p : places.paths)
    Check(Finite(conv::PathToValue(p).ToText()), "a path value with NaN or infinity");
}

void Battery(FuzzedDataProvider& in) {
  sensor_msgs::BatteryState b;
  b.percentage = AnyNumber<float>(in, -0.5f, 1.5f);
  const auto d = conv::FromMsg(b);
  if (d) Check(d->level_percent >= 0.0 && d->level_percent <= 100.0, "a charge beyond [0, 100] %");
}

void Binding(FuzzedDataProvider& in) {
  const std::string text = in.ConsumeRandomLengthString(200);
  std::string error;
  const auto b = conv::ParseBinding(text, &error);
  if (!b) return Check(!error.empty(), "a binding refused without a reason");
  Check(!b->first.empty(), "a binding without a name");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  switch (in.ConsumeIntegralInRange<int>(0, 6)) {
    case 0:
      Ring(in);
      break;
    case 1:
      Laser(in);
      break;
    case 2:
      Status(in);
      break;
    case 3:
      Graph(in);
      break;
    case 4:
      Places(in);
      break;
    case 5:
      Battery(in);
      break;
    default:
      Binding(in);
      break;
  }
  return 0;
}
