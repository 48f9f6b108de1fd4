// Fuzzes robot_sim's service requests and velocity commands as the node takes them (issue 21):
// /sim/kidnap, /sim/set_door_state, /sim/sensor_fault, /sim/odometry_slip, /sim/add_obstacle
// and /cmd_vel built field by field from the fuzzer's bytes (NaN, infinities and any double
// included), converted (ros_conversions::FromRequest, FromMsg) and applied to one long-lived
// simulator (hilare_room with a B-12, a Nomad 200 and a B21) as the node applies them, a few
// physics steps after each. Whatever is accepted, each robot's ground truth must stay finite and
// in the world's bounds, and what the node would publish then (the outbound conversions: range
// rings, sensor_msgs/Range, LaserScan, QUADRIS profiles, bumper, odometry) must keep its
// message's contract: sizes that agree, ranges NaN (dropped out), +inf (no return, where the
// sensor has that) or within [min, max] (REP 117), finite angles and unit quaternions, and the
// message must serialize and read back to the same length.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>
#include <ros/serialization.h>

#include "fuzz_values.h"
#include "robot_sim/fault_events.h"
#include "robot_sim/ros/conversions.h"
#include "robot_sim/simulator.h"
#include "spott_map/world_loader.h"

namespace {

namespace conv = robot_sim::ros_conversions;
using spott_fuzz::AnyNumber;

struct Sim {
  std::unique_ptr<robot_sim::Simulator> sim;
  std::vector<int> robots;  // B-12 (sonar only), Nomad 200 (sonar, infrared, QUADRIS, bumper), B21
  robot_sim::Rng rng{1};
};

void AddRobot(Sim& s, const std::string& name, const spott_map::Pose2& at) {
  const auto spec =
      robot_sim::LoadRobotSpec(SPOTT_ROOT "/robot_sim/config/robots/" + name + ".yaml",
                               SPOTT_ROOT "/robot_sim/urdf/" + name + ".urdf");
  if (!spec.ok()) std::abort();
  const auto id = s.sim->AddRobot(*spec.spec, at, {}, nullptr);
  if (!id) std::abort();
  s.robots.push_back(*id);
}

Sim& TheSim() {
  static Sim s = [] {
    Sim s;
    const auto world = spott_map::LoadWorldFile(SPOTT_ROOT "/spott_worlds/worlds/hilare_room.yaml");
    if (!world.ok()) std::abort();
    robot_sim::SimWorldParameters p;
    p.octomap_resolution_m = 0.1;
    auto sim_world = std::make_unique<robot_sim::SimWorld>(p);
    sim_world->Build(*world.world);
    s.sim = std::make_unique<robot_sim::Simulator>(std::move(sim_world));
    AddRobot(s, "b12", {2.0, 2.0, 0.0});
    AddRobot(s, "nomad200", {5.0, 2.0, 0.0});
    AddRobot(s, "b21", {2.0, 6.5, 0.0});
    return s;
  }();
  return s;
}

geometry_msgs::Pose2D AnyPose(FuzzedDataProvider& in) {
  geometry_msgs::Pose2D p;
  p.x = AnyNumber<double>(in, -2.0, 12.0);
  p.y = AnyNumber<double>(in, -2.0, 11.0);
  p.theta = AnyNumber<double>(in, -7.0, 7.0);
  return p;
}

std::string AnyName(FuzzedDataProvider& in, std::initializer_list<const char*> known) {
  const auto k = in.ConsumeIntegralInRange<std::size_t>(0, known.size());
  if (k < known.size()) return *(known.begin() + k);
  return in.ConsumeRandomLengthString(12);
}

// One request of any kind, converted; false when the conversion refuses it.
bool NextEvent(FuzzedDataProvider& in, robot_sim::FaultEvent& e) {
  std::string error;
  switch (in.ConsumeIntegralInRange<int>(0, 4)) {
    case 0: {
      spott_msgs::Kidnap::Request r;
      r.relative = in.ConsumeBool();
      r.pose = AnyPose(in);
      return conv::FromRequest(r, e, &error);
    }
    case 1: {
      spott_msgs::SetDoorState::Request r;
      r.door_id = AnyName(in, {"door_room", "door_corridor", "d1"});
      r.state = in.ConsumeIntegral<std::uint8_t>();
      return conv::FromRequest(r, e, &error);
    }
    case 2: {
      spott_msgs::SensorFault::Request r;
      r.sensor = AnyName(in, {"sonar", "sonar/3", "infrared", "laser", "bumper", "sonar/99"});
      r.fault = in.ConsumeIntegral<std::uint8_t>();
      r.noise_stddev = AnyNumber<double>(in, 0.0, 1.0);
      r.duration = AnyNumber<double>(in, 0.0, 30.0);
      return conv::FromRequest(r, e, &error);
    }
    case 3: {
      spott_msgs::OdometrySlip::Request r;
      r.linear_scale = AnyNumber<double>(in, 0.0, 2.0);
      r.angular_scale = AnyNumber<double>(in, 0.0, 2.0);
      r.duration = AnyNumber<double>(in, 0.0, 30.0);
      return conv::FromRequest(r, e, &error);
    }
    default: {
      spott_msgs::AddObstacle::Request r;
      r.id = AnyName(in, {"box", "chair_1", "wall_1"});
      r.kind = AnyName(in, {"chair", "desk", "partition", "cuboid", "cylinder"});
      r.pose = AnyPose(in);
      r.size.x = AnyNumber<double>(in, 0.0, 3.0);
      r.size.y = AnyNumber<double>(in, 0.0, 3.0);
      r.size.z = AnyNumber<double>(in, 0.0, 3.0);
      return conv::FromRequest(r, e, &error);
    }
  }
}

constexpr const char* kName = "sim_requests_fuzz";

template <class M>
void RoundTrips(const M& msg) {
  const std::uint32_t n = ros::serialization::serializationLength(msg);
  std::vector<std::uint8_t> buffer(n);
  ros::serialization::OStream out(buffer.data(), n);
  ros::serialization::serialize(out, msg);
  M back;
  ros::serialization::IStream in(buffer.data(), n);
  ros::serialization::deserialize(in, back);
  spott_fuzz::Check(ros::serialization::serializationLength(back) == n, kName,
                    "a published message does not read back to its length");
}

// A published range: NaN (dropped out), +inf when `inf_ok` (no return), else within [lo, hi].
bool ValidRange(double r, double lo, double hi, bool inf_ok) {
  if (std::isnan(r)) return true;
  if (r == std::numeric_limits<double>::infinity()) return inf_ok;
  // float32 fields (RangeRing, Range, LaserScan) round the bounds themselves by up to 6e-8.
  const double slack = 1e-6 * (1.0 + std::abs(hi));
  return r >= lo - slack && r <= hi + slack;
}

bool Unit(const geometry_msgs::Quaternion& q) {
  const double n = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  return std::abs(n - 1.0) < 1e-9;
}

// What the node would publish for `robot` now, checked against each message's contract.
void CheckOutbound(Sim& s, int robot) {
  const ros::Time stamp(100.0);
  const robot_sim::RobotSpec& spec = s.sim->spec(robot);
  for (const robot_sim::RangeRingSpec& ring : spec.rings) {
    const std::vector<double> ranges = s.sim->SenseRing(robot, ring, s.rng);
    const auto msg = conv::ToRangeRing(ring, ranges, "base_link", stamp, 0.3);
    spott_fuzz::Check(msg.ranges.size() == ring.mounts.size() &&
                          msg.mounts.size() == ring.mounts.size() &&
                          msg.frame_ids.size() == ring.mounts.size(),
                      kName, "a range ring's ranges, mounts and frames differ in number");
    for (std::size_t i = 0; i < msg.ranges.size(); ++i) {
      if (!ValidRange(msg.ranges[i], ring.min_range, ring.max_range, false)) {
        std::fprintf(stderr, "%s %zu: %.9g outside [%g, %g]\n", ring.name.c_str(), i + 1,
                     msg.ranges[i], ring.min_range, ring.max_range);
        spott_fuzz::Check(false, kName, "a ring's range is outside [min_range, max_range]");
      }
      spott_fuzz::Check(std::abs(msg.mounts[i].theta) <= M_PI + 1e-12, kName,
                        "a ring mount's heading is not normalized");
      const auto one = conv::ToRange(ring, i, ranges[i], stamp);
      spott_fuzz::Check(ValidRange(one.range, static_cast<float>(ring.min_range),
                                   static_cast<float>(ring.max_range), true),
                        kName, "a sensor_msgs/Range is outside [min_range, max_range]");
      spott_fuzz::Check(!one.header.frame_id.empty(), kName, "a Range has no frame");
      RoundTrips(one);
    }
    RoundTrips(msg);
  }
  if (spec.laser) {
    const robot_sim::LaserSpec& laser = *spec.laser;
    const auto msg = conv::ToLaserScan(laser, s.sim->SenseLaser(robot, s.rng), 0.1, stamp);
    spott_fuzz::Check(static_cast<int>(msg.ranges.size()) == laser.beams, kName,
                      "a scan's ranges are not its beams");
    const double last = msg.angle_min + msg.angle_increment * (laser.beams - 1);
    spott_fuzz::Check(std::abs(last - msg.angle_max) < 1e-4, kName,
                      "a scan's angle_increment does not reach angle_max");
    for (float r : msg.ranges) {
      spott_fuzz::Check(ValidRange(r, msg.range_min, msg.range_max, true), kName,
                        "a scan's range is outside [range_min, range_max]");
    }
    RoundTrips(msg);
  }
  for (std::size_t h = 0; h < spec.profilers.size(); ++h) {
    const robot_sim::ProfilerSpec& p = spec.profilers[h];
    const bool horizontal = h % 2 == 0;
    std::vector<double> angles;
    const std::vector<double> ranges =
        s.sim->SenseProfile(robot, static_cast<int>(h), horizontal, s.rng, &angles);
    spott_fuzz::Check(angles.size() == ranges.size(), kName,
                      "a profile's angles are not its ranges");
    const auto [pan, tilt] = s.sim->Head(robot, static_cast<int>(h));
    const auto msg = conv::ToRangeProfile(p, horizontal, pan, tilt, angles, ranges, stamp);
    spott_fuzz::Check(
        msg.points.size() == msg.ranges.size() && msg.angles.size() == msg.ranges.size(), kName,
        "a profile's points, angles and ranges differ in number");
    for (std::size_t k = 0; k < msg.ranges.size(); ++k) {
      const double r = msg.ranges[k];
      spott_fuzz::Check(ValidRange(r, p.min_range, p.max_range, true), kName,
                        "a profile's range is outside [min_range, max_range]");
      const auto& q = msg.points[k];
      const bool finite = std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
      spott_fuzz::Check(finite == std::isfinite(r), kName,
                        "a profile's point is finite exactly when its range is not");
      if (finite) {
        const double n = std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z);
        spott_fuzz::Check(std::abs(n - r) < 1e-3 * (1.0 + r), kName,
                          "a profile's point is not at its range");
      }
    }
    RoundTrips(msg);
  }
  if (spec.bumper) {
    const std::vector<bool> pressed = s.sim->Bumper(robot);
    const auto msg = conv::ToBumperRing(*spec.bumper, pressed, "base_link", stamp);
    spott_fuzz::Check(msg.pressed.size() == msg.segment_angles.size() &&
                          static_cast<int>(msg.pressed.size()) == spec.bumper->segments,
                      kName, "a bumper ring's segments and angles differ in number");
    for (double a : msg.segment_angles) {
      spott_fuzz::Check(std::abs(a) <= M_PI + 1e-12, kName, "a bumper angle is not normalized");
    }
    RoundTrips(msg);
  }
  const robot_sim::Odometry& odo = s.sim->odometry(robot);
  const auto odom = conv::ToOdometry(odo.pose(), odo.twist(), "odom", "base_link", stamp);
  const auto truth = conv::ToOdometry(s.sim->GroundTruth(robot), s.sim->Velocity(robot), "map",
                                      "base_link", stamp);
  spott_fuzz::Check(Unit(odom.pose.pose.orientation) && Unit(truth.pose.pose.orientation), kName,
                    "odometry's quaternion is not unit");
  RoundTrips(odom);
  RoundTrips(truth);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  Sim& s = TheSim();
  for (int n = 0; n < 4 && in.remaining_bytes() > 0; ++n) {
    const int robot = s.robots[in.ConsumeIntegralInRange<std::size_t>(0, s.robots.size() - 1)];
    if (in.ConsumeBool()) {
      geometry_msgs::Twist t;
      t.linear.x = AnyNumber<double>(in, -1.0, 1.0);
      t.angular.z = AnyNumber<double>(in, -2.0, 2.0);
      std::string error;
      s.sim->SetCommand(robot, conv::FromMsg(t), &error);
    } else {
      robot_sim::FaultEvent e;
      std::string error;
      if (NextEvent(in, e)) {
        if (std::getenv("SIM_REQUESTS_FUZZ_VERBOSE"))  // replaying a reported input
          std::fprintf(stderr, "apply: %s\n", robot_sim::Describe(e).c_str());
        robot_sim::ApplyFaultEvent(*s.sim, robot, e, &error);
      }
    }
    for (int k = 0; k < 3; ++k) s.sim->Step(0.02, s.rng);
    for (int r : s.robots) {
      const spott_map::Pose2& at = s.sim->GroundTruth(r);
      spott_fuzz::Check(std::isfinite(at.x) && std::isfinite(at.y) && std::isfinite(at.yaw), kName,
                        "the robot's ground truth is not finite");
      spott_fuzz::Check(std::abs(at.x) < 1e3 && std::abs(at.y) < 1e3, kName,
                        "the robot left the world");
    }
    CheckOutbound(s, robot);
  }
  return 0;
}
