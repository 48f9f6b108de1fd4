// Fuzzes robot_sim's service requests and velocity commands as the node takes them (issue 21):
// /sim/kidnap, /sim/set_door_state, /sim/sensor_fault, /sim/odometry_slip, /sim/add_obstacle
// and /cmd_vel built field by field from the fuzzer's bytes (NaN, infinities and any double
// included), converted (ros_conversions::FromRequest, FromMsg) and applied to one long-lived
// simulator (hilare_room with a B-12) as the node applies them, a few physics steps after each.
// Whatever is accepted, the robot's ground truth must stay finite and in the world's bounds.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <fuzzer/FuzzedDataProvider.h>

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
  int robot = 0;
  robot_sim::Rng rng{1};
};

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
    const auto spec = robot_sim::LoadRobotSpec(SPOTT_ROOT "/robot_sim/config/robots/b12.yaml",
                                               SPOTT_ROOT "/robot_sim/urdf/b12.urdf");
    if (!spec.ok()) std::abort();
    s.robot = *s.sim->AddRobot(*spec.spec, {2.0, 2.0, 0.0}, {}, nullptr);
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  Sim& s = TheSim();
  for (int n = 0; n < 4 && in.remaining_bytes() > 0; ++n) {
    if (in.ConsumeBool()) {
      geometry_msgs::Twist t;
      t.linear.x = AnyNumber<double>(in, -1.0, 1.0);
      t.angular.z = AnyNumber<double>(in, -2.0, 2.0);
      std::string error;
      s.sim->SetCommand(s.robot, conv::FromMsg(t), &error);
    } else {
      robot_sim::FaultEvent e;
      std::string error;
      if (NextEvent(in, e)) {
        if (std::getenv("SIM_REQUESTS_FUZZ_VERBOSE"))  // replaying a reported input
          std::fprintf(stderr, "apply: %s\n", robot_sim::Describe(e).c_str());
        robot_sim::ApplyFaultEvent(*s.sim, s.robot, e, &error);
      }
    }
    for (int k = 0; k < 3; ++k) s.sim->Step(0.02, s.rng);
    const spott_map::Pose2& at = s.sim->GroundTruth(s.robot);
    spott_fuzz::Check(std::isfinite(at.x) && std::isfinite(at.y) && std::isfinite(at.yaw),
                      "sim_requests_fuzz", "the robot's ground truth is not finite");
    spott_fuzz::Check(std::abs(at.x) < 1e3 && std::abs(at.y) < 1e3, "sim_requests_fuzz",
                      "the robot left the world");
  }
  return 0;
}
