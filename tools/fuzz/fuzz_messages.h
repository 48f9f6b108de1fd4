// Messages the message fuzzers build field by field from the fuzzer's bytes (the targets that
// include this need a built workspace for spott_msgs' headers).
#pragma once

#include <spott_msgs/RangeRing.h>

#include <string>

#include "fuzz_values.h"

namespace spott_fuzz {

/// A ring of up to 24 transducers: its limits, mounts and readings each NaN, infinite, any value
/// or a plausible one; one reading per mount half the time, else 0 to 25 readings.
inline spott_msgs::RangeRing AnyRangeRing(FuzzedDataProvider& in) {
  spott_msgs::RangeRing ring;
  ring.field_of_view = AnyNumber<float>(in, -1.0f, 4.0f);
  ring.min_range = AnyNumber<float>(in, -1.0f, 2.0f);
  ring.max_range = AnyNumber<float>(in, -1.0f, 10.0f);
  const int n = in.ConsumeIntegralInRange<int>(0, 24);
  for (int i = 0; i < n; ++i) {
    geometry_msgs::Pose2D m;
    m.x = AnyNumber<double>(in, -1.0, 1.0);
    m.y = AnyNumber<double>(in, -1.0, 1.0);
    m.theta = AnyNumber<double>(in, -7.0, 7.0);
    ring.mounts.push_back(m);
  }
  const int ranges = in.ConsumeBool() ? n : in.ConsumeIntegralInRange<int>(0, 25);
  for (int i = 0; i < ranges; ++i) ring.ranges.push_back(AnyNumber<float>(in, -1.0f, 12.0f));
  return ring;
}

/// Whether a refusal names its field: "field: why".
inline bool NamesField(const std::string& problem) {
  const auto colon = problem.find(": ");
  return colon != std::string::npos && colon > 0;
}

}  // namespace spott_fuzz
