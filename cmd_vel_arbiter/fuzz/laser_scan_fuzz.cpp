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

namespace {

void Check(bool ok, const char* what) { spott_fuzz::Check(ok, "laser_scan_fuzz", what); }

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
  if (!b) {
    Check(!error.empty(), "refused without a reason");
    return 0;
  }
  Check(!std::isnan(b->forward_mps) && b->forward_mps >= 0.0, "forward bound NaN or negative");
  Check(!std::isnan(b->backward_mps) && b->backward_mps >= 0.0, "backward bound NaN or negative");
  Check(!std::isnan(b->forward_gap_m) && b->forward_gap_m >= 0.0, "forward gap NaN or negative");
  Check(!std::isnan(b->backward_gap_m) && b->backward_gap_m >= 0.0, "backward gap NaN or negative");
  return 0;
}
