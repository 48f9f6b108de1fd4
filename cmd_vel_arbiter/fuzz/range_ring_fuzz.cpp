// The arbiter's RangeRing conversion (ros_conversions::RingBounds) on rings built field by
// field from the fuzzer's bytes: any sizes, NaN, infinities, huge and negative numbers.
// Whatever it accepts gives bounds that are never NaN nor negative (a NaN cap would let the
// arbiter pass any speed; a negative one would reverse the robot).
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "cmd_vel_arbiter/ros/conversions.h"
#include "fuzz_values.h"
#include "speed_bounds_check.h"

namespace {

float AnyFloat(FuzzedDataProvider& in) { return spott_fuzz::AnyNumber<float>(in, -1.0f, 6.0f); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  spott_msgs::RangeRing ring;
  ring.field_of_view = AnyFloat(in);
  ring.min_range = AnyFloat(in);
  ring.max_range = AnyFloat(in);
  const int mounts = in.ConsumeIntegralInRange<int>(0, 32);
  for (int i = 0; i < mounts; ++i) {
    geometry_msgs::Pose2D m;
    m.x = AnyFloat(in);
    m.y = AnyFloat(in);
    m.theta = AnyFloat(in);
    ring.mounts.push_back(m);
  }
  const int ranges = in.ConsumeBool() ? mounts : in.ConsumeIntegralInRange<int>(0, 33);
  for (int i = 0; i < ranges; ++i) ring.ranges.push_back(AnyFloat(in));
  cmd_vel_arbiter::ClearanceParameters p;
  p.footprint_radius_m = in.ConsumeBool() ? 0.0 : in.ConsumeFloatingPointInRange<double>(0, 10);
  p.min_range_at_face = in.ConsumeBool();
  std::string error;
  const auto b = cmd_vel_arbiter::ros_conversions::RingBounds(ring, p, &error);
  spott_fuzz::CheckSpeedBounds(b, error, "range_ring_fuzz");
  return 0;
}
