// Fuzzes the Navigate goal conversion (FromGoal), where a NaN quaternion, an infinite tolerance
// or a 1e300 m target entered (issue 21): a goal built field by field from the fuzzer's bytes is
// either refused with a reason or gives a request whose every number is finite, so that nothing
// downstream can put a non-finite value on /cmd_vel.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "spott_harmonic_planner/ros/conversions.h"

namespace {

class Bytes {
 public:
  Bytes(const uint8_t* d, size_t n) : d_(d), n_(n) {}
  uint8_t U8() { return i_ < n_ ? d_[i_++] : 0; }
  double Double() {  // a small number most of the time, any bit pattern otherwise
    if (U8() < 160) return (static_cast<int>(U8()) - 128) / 16.0;
    uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits = bits << 8 | U8();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

 private:
  const uint8_t* d_;
  size_t n_, i_ = 0;
};

bool Finite(double v) { return std::isfinite(v); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using spott_harmonic_planner::DirectionBias;
  Bytes b(data, size);
  spott_msgs::NavigateGoal g;
  g.target.header.frame_id = b.U8() < 200 ? "map" : (b.U8() < 128 ? "" : "odom");
  g.target.pose.position.x = b.Double();
  g.target.pose.position.y = b.Double();
  g.target.pose.orientation.x = b.U8() < 200 ? 0.0 : b.Double();
  g.target.pose.orientation.y = b.U8() < 200 ? 0.0 : b.Double();
  g.target.pose.orientation.z = b.Double();
  g.target.pose.orientation.w = b.Double();
  g.ignore_heading = b.U8() & 1;
  g.speed_mode = b.U8() % 4;
  g.position_tolerance = b.Double();
  g.heading_tolerance = b.Double();
  g.bias_kind = b.U8() % 7;
  g.direction_bias = b.Double();
  g.bias_point.x = b.Double();
  g.bias_point.y = b.Double();
  g.bias_radius = b.Double();
  g.bias_sense = b.U8() < 128 ? (b.U8() & 1 ? 1.0 : -1.0) : b.Double();
  std::string error;
  const auto r = spott_harmonic_planner::ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error);
  if (!r) {
    if (error.empty()) std::abort();  // a refusal says why
    return 0;
  }
  if (!Finite(r->target.x()) || !Finite(r->target.y())) std::abort();
  if (!Finite(r->tolerance_m) || r->tolerance_m <= 0.0) std::abort();
  if (!Finite(r->heading_tolerance_rad) || r->heading_tolerance_rad <= 0.0) std::abort();
  if (r->yaw && !Finite(*r->yaw)) std::abort();
  // The direction the planner would be biased towards, anywhere the robot could be.
  for (const auto& at : {r->target, spott_map::Vec2(0.0, 0.0), r->bias.point}) {
    const auto heading = r->bias.HeadingAt(at);
    if (heading && !Finite(*heading)) std::abort();
  }
  return 0;
}
