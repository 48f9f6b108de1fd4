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

namespace {

void Check(bool ok, const char* what) { spott_fuzz::Check(ok, "range_ring_fuzz", what); }

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
