// The arbiter's LaserScan conversion (ros_conversions::ScanBounds) on scans built field by field
// from the fuzzer's bytes: any sizes, NaN, infinities, huge and negative numbers, any mount and
// radius. Whatever it accepts gives bounds that are never NaN nor negative (a NaN cap would let
// the arbiter pass any speed; a negative one would reverse the robot).
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "cmd_vel_arbiter/ros/conversions.h"
#include "fuzz_values.h"
#include "speed_bounds_check.h"

namespace {

float AnyFloat(FuzzedDataProvider& in) { return spott_fuzz::AnyNumber<float>(in, -4.0f, 30.0f); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  sensor_msgs::LaserScan scan;
  scan.angle_min = AnyFloat(in);
  scan.angle_increment = AnyFloat(in);
  scan.angle_max = AnyFloat(in);
  scan.range_min = AnyFloat(in);
  scan.range_max = AnyFloat(in);
  const int ranges = in.ConsumeIntegralInRange<int>(0, 400);
  for (int i = 0; i < ranges; ++i) scan.ranges.push_back(AnyFloat(in));
  cmd_vel_arbiter::Transducer mount;
  mount.x = AnyFloat(in);
  mount.y = AnyFloat(in);
  mount.yaw = AnyFloat(in);
  const double radius = AnyFloat(in);
  cmd_vel_arbiter::ClearanceParameters p;
  p.footprint_radius_m = in.ConsumeBool() ? 0.0 : in.ConsumeFloatingPointInRange<double>(0, 10);
  std::string error;
  const auto b = cmd_vel_arbiter::ros_conversions::ScanBounds(scan, mount, radius, p, &error);
  spott_fuzz::CheckSpeedBounds(b, error, "laser_scan_fuzz");
  return 0;
}
