// robot_sim's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h): Read and the
// reader's Finish, as main() does (spott_ros::ReadNodeParameters), then the `faults` parameter
// as the node hands it to ParseFaultSchedule (FaultScheduleYaml). Whatever the node accepts must
// lie in the ranges its config file and headers document and leave the simulator's loop
// well-defined: every ros::WallDuration it makes, every publishing period in steps, and an octree
// that holds the building and the walls' height.
#include <cmath>
#include <stdexcept>

#include "parameter_fuzz.h"
#include "robot_sim/battery.h"
#include "robot_sim/consumer_pacer.h"
#include "robot_sim/fault_events.h"
#include "robot_sim/ros/parameters.h"

using namespace robot_sim;
using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(
      CONFIG_FILE, {{"world_file", "spott_worlds/worlds/cim_office.yaml"}},
      {"faults", "faults/time", "faults/kind", "faults/pose", "faults/relative", "faults/door",
       "faults/state", "faults/sensor", "faults/fault", "faults/duration", "faults/id",
       "faults/shape", "faults/size"},
      {"nomad200", "b21",      "b12",          "hilare",
       "kidnap",   "door",     "open",         "closed",
       "sensor",   "sonar/3",  "laser",        "dropout",
       "noise",    "slip",     "add_obstacle", "remove_obstacle",
       "cuboid",   "cylinder", "1 2 0.5",      "/tmp/world.yaml"});
  FuzzedDataProvider in(data, size);
  const XmlRpc::XmlRpcValue tree = spott_fuzz::BuildParameters(in, vocabulary);
  spott_ros::ParameterReader r(tree);
  SimNodeParameters p;
  ros_parameters::Read(r, p);
  const bool accepted = r.Finish().empty();
  // The schedule is parsed after the reader accepted everything else; parse it regardless (it
  // must never crash, whatever the tree holds).
  if (tree.getType() == XmlRpc::XmlRpcValue::TypeStruct && tree.hasMember("faults")) {
    XmlRpc::XmlRpcValue copy = tree;
    ParseFaultSchedule(ros_parameters::FaultScheduleYaml(copy["faults"]), "~faults");
  }
  if (!accepted) return 0;  // the node stops, naming every problem

  Expect(!p.world_file.empty(), "an empty world_file accepted");
  Expect(p.seed >= 0, "seed < 0 accepted");
  ExpectIn("physics_rate_hz", p.physics_rate_hz, "[10, 10000]");
  const double dt = 1.0 / p.physics_rate_hz;
  for (const auto& [name, rate] :
       {std::pair<const char*, double>{"sensor_rate_hz", p.sensor_rate_hz},
        {"laser_rate_hz", p.laser_rate_hz},
        {"odom_rate_hz", p.odom_rate_hz},
        {"profile_rate_hz", p.profile_rate_hz},
        {"battery_rate_hz", p.battery_rate_hz}}) {
    ExpectIn(name, rate, "[0.01, inf)");
    Expect(rate <= p.physics_rate_hz, std::string(name) + " > physics_rate_hz accepted");
    // Run(): published every lround(physics_rate_hz / rate) steps, which a long must hold.
    Expect(p.physics_rate_hz / rate < 9.2e18,
           std::string("the publishing period of ") + name + " in steps overflows a long");
  }
  if (p.real_time_factor != 0) {
    ExpectIn("real_time_factor", p.real_time_factor, "[0.01, 1e4]");
    // Run() paces the loop with ros::WallDuration(step * dt / real_time_factor): a simulated
    // day must make one.
    spott_fuzz::ExpectRosDuration("the wall time of a simulated day (86400 / real_time_factor)",
                                  86400.0 / p.real_time_factor);
    spott_fuzz::ExpectRosDuration("the wall time of a step", dt / p.real_time_factor);
  }
  ExpectIn("cmd_vel_timeout_s", p.cmd_vel_timeout_s, "[0, inf)");
  Expect(!p.map_frame.empty() && !p.odom_frame.empty() && !p.base_frame.empty(),
         "an empty frame accepted");
  ExpectIn("wall_height_m", p.world.wall_height_m, "(0, 10]");
  ExpectIn("door_leaf_thickness_m", p.world.door_leaf_thickness_m, "(0, inf)");
  ExpectIn("octomap_resolution_m", p.world.octomap_resolution_m, "[0.01, 1]");
  // The octree has 16 levels: it reaches +-32768 voxels from the origin. SimWorld::Voxelize steps
  // through every voxel of a solid, up to its height, and a key beyond the tree is dropped
  // silently: the tree must hold a building (+-100 m) and the walls' height.
  Expect(32768.0 * p.world.octomap_resolution_m >= 100.0,
         "an octomap_resolution_m whose tree does not reach 100 m from the origin accepted (the "
         "simulator drops every voxel beyond it, and its loops barely advance)");
  Expect(p.world.wall_height_m <= 32768.0 * p.world.octomap_resolution_m,
         "walls taller than the octree accepted (wall_height_m)");
  ExpectIn("consumers/max_lag_s", p.consumers.max_lag_s, "(0, inf)");
  ExpectIn("consumers/max_hold_s", p.consumers.max_hold_s, "(0, inf)");
  for (const std::string& t : p.consumers.topics) Expect(!t.empty(), "an empty consumer topic");
  const auto& o = p.odometry;
  ExpectIn("odometry/linear_scale", o.linear_scale, "(0.5, 1.5)");
  ExpectIn("odometry/angular_scale", o.angular_scale, "(0.5, 1.5)");
  ExpectIn("odometry/drift_rad_per_m", o.drift_rad_per_m, "(-1, 1)");
  ExpectIn("odometry/linear_noise", o.linear_noise, "[0, inf)");
  ExpectIn("odometry/angular_noise", o.angular_noise, "[0, inf)");
  ExpectIn("odometry/angular_noise_per_m", o.angular_noise_per_m, "[0, inf)");
  const auto& b = p.battery;
  ExpectIn("battery/capacity_wh", b.capacity_wh, "(0, 1e6]");
  ExpectIn("battery/initial_percent", b.initial_percent, "[0, 100]");
  ExpectIn("battery/idle_power_w", b.idle_power_w, "[0, 1e5]");
  ExpectIn("battery/power_per_mps_w", b.power_per_mps_w, "[0, 1e5]");
  ExpectIn("battery/power_per_rps_w", b.power_per_rps_w, "[0, 1e5]");
  ExpectIn("battery/empty_voltage_v", b.empty_voltage_v, "(0, inf)");
  Expect(b.full_voltage_v > b.empty_voltage_v, "battery/full_voltage_v <= empty_voltage_v");
  try {
    Battery battery(b);
    ConsumerPacer pacer(p.consumers);
  } catch (const std::exception& e) {
    Expect(false, std::string("the node accepted parameters its core refuses: ") + e.what());
  }
  return 0;
}
