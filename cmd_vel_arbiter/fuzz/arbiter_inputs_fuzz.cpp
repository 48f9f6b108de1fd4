// Everything that reaches the arbiter from outside, in any order, built from the fuzzer's bytes:
// Twists of three sources and of an unknown one (ros_conversions::FromTwist), bumper rings
// (PressedAngles), sonar rings (RingBounds), takes, releases, run-time speed limits, timeouts,
// any numbers (NaN, infinities, huge, negative), time that jumps. Whatever the arbiter
// publishes must be safe for the wheels: finite; within the robot's and the run-time limits;
// no push towards a pressed bumper segment; within the sonar's bounds unless the driver is
// exempt (the reflex).
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "cmd_vel_arbiter/arbiter.h"
#include "cmd_vel_arbiter/ros/conversions.h"
#include "fuzz_values.h"

namespace conv = cmd_vel_arbiter::ros_conversions;

namespace {

using spott_fuzz::AnyNumber;
void Check(bool ok, const char* what) { spott_fuzz::Check(ok, "arbiter_inputs_fuzz", what); }

const char* kSources[] = {"planner", "teleop", "reflex", "nobody"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  cmd_vel_arbiter::ArbiterParameters params;
  params.sources = {{"planner", 10, 0.5}, {"teleop", 50, 0.5}, {"reflex", 100, 0.3}};
  params.max_linear_mps = 0.5;
  params.max_angular_rps = 1.0;
  cmd_vel_arbiter::Arbiter arbiter(params);
  cmd_vel_arbiter::ClearanceParameters clearance;
  std::vector<double> contacts;
  double forward_cap = std::numeric_limits<double>::infinity();
  double backward_cap = std::numeric_limits<double>::infinity();
  double now = 0.0;
  std::string message, other;
  for (int step = 0; step < 64 && in.remaining_bytes() > 0; ++step) {
    now +=
        in.ConsumeIntegralInRange<int>(0, 3) == 0 ? in.ConsumeFloatingPointInRange(0.0, 5.0) : 0.05;
    const std::string source = kSources[in.ConsumeIntegralInRange<int>(0, 3)];
    cmd_vel_arbiter::Output out;
    switch (in.ConsumeIntegralInRange<int>(0, 6)) {
      case 0:
      case 1: {
        geometry_msgs::Twist t;
        t.linear.x = AnyNumber(in, -0.7, 0.7);
        t.angular.z = AnyNumber(in, -1.5, 1.5);
        if (in.ConsumeBool()) t.linear.y = AnyNumber(in, -1.0, 1.0);
        bool ignored = false;
        out = arbiter.Command(source, conv::FromTwist(t, &ignored), now, &message);
        break;
      }
      case 2: {
        spott_msgs::BumperRing ring;
        const int n = in.ConsumeIntegralInRange<int>(0, 24);
        for (int i = 0; i < n; ++i) {
          ring.segment_angles.push_back(AnyNumber<float>(in, -7.0f, 7.0f));
          ring.pressed.push_back(in.ConsumeIntegralInRange<int>(0, 3) == 0);
        }
        if (in.ConsumeIntegralInRange<int>(0, 7) == 0) ring.pressed.push_back(true);
        const auto angles = conv::PressedAngles(ring, &message);
        if (!angles) {
          Check(!message.empty(), "a bumper ring refused without a reason");
          continue;
        }
        contacts = *angles;
        out = arbiter.SetContacts(contacts, now);
        break;
      }
      case 3: {
        spott_msgs::RangeRing ring;
        ring.field_of_view = AnyNumber<float>(in, 0.0f, 0.6f);
        ring.min_range = AnyNumber<float>(in, 0.0f, 0.5f);
        ring.max_range = AnyNumber<float>(in, 0.0f, 6.0f);
        const int n = in.ConsumeIntegralInRange<int>(0, 16);
        for (int i = 0; i < n; ++i) {
          geometry_msgs::Pose2D m;
          m.x = AnyNumber<double>(in, -0.3, 0.3);
          m.y = AnyNumber<double>(in, -0.3, 0.3);
          m.theta = AnyNumber<double>(in, -3.2, 3.2);
          ring.mounts.push_back(m);
          ring.ranges.push_back(AnyNumber<float>(in, -0.5f, 7.0f));
        }
        const auto bounds = conv::RingBounds(ring, clearance, &message);
        if (!bounds) {
          Check(!message.empty(), "a range ring refused without a reason");
          continue;
        }
        forward_cap = bounds->forward_mps;
        backward_cap = bounds->backward_mps;
        out = arbiter.SetClearance(forward_cap, backward_cap, now);
        break;
      }
      case 4:
        if (in.ConsumeBool()) {
          arbiter.Take(source, now, &message, &other, &out);
        } else {
          arbiter.Release(source, now, &message, &out);
        }
        break;
      case 5:
        arbiter.SetSpeedLimits(AnyNumber(in, 0.0, 0.6), AnyNumber(in, 0.0, 1.2), "fuzz", &message,
                               now, &out);
        break;
      default:
        out = arbiter.Update(now);
        break;
    }
    if (!out.publish) continue;
    const double v = out.command.linear_mps, w = out.command.angular_rps;
    Check(std::isfinite(v) && std::isfinite(w), "a command that is not finite");
    Check(std::abs(v) <= arbiter.max_linear_mps() + 1e-9, "faster than the linear limit");
    Check(std::abs(w) <= arbiter.max_angular_rps() + 1e-9, "faster than the angular limit");
    Check(arbiter.max_linear_mps() <= params.max_linear_mps + 1e-9 &&
              arbiter.max_angular_rps() <= params.max_angular_rps + 1e-9,
          "run-time limits above the robot's");
    for (double phi : contacts)
      Check(v * std::cos(phi) <= 1e-6, "a push towards a pressed bumper segment");
    if (arbiter.driver() != "reflex") {
      Check(v <= forward_cap + 1e-9 && -v <= backward_cap + 1e-9, "beyond the sonar's bound");
    }
  }
  return 0;
}
