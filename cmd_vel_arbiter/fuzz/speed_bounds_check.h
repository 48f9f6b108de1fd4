// What the fuzz targets of the clearance conversions (a range ring, a laser scan) assert of an
// answer: a refusal says why; accepted bounds are never NaN nor negative (a NaN cap would let the
// arbiter pass any speed; a negative one would reverse the robot).
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "cmd_vel_arbiter/clearance.h"
#include "fuzz_values.h"

namespace spott_fuzz {

inline void CheckSpeedBounds(const std::optional<cmd_vel_arbiter::SpeedBounds>& b,
                             const std::string& error, const char* target) {
  const auto check = [target](bool ok, const char* what) { Check(ok, target, what); };
  if (!b) {
    check(!error.empty(), "refused without a reason");
    return;
  }
  check(!std::isnan(b->forward_mps) && b->forward_mps >= 0.0, "forward bound NaN or negative");
  check(!std::isnan(b->backward_mps) && b->backward_mps >= 0.0, "backward bound NaN or negative");
  check(!std::isnan(b->forward_gap_m) && b->forward_gap_m >= 0.0, "forward gap NaN or negative");
  check(!std::isnan(b->backward_gap_m) && b->backward_gap_m >= 0.0, "backward gap NaN or negative");
}

}  // namespace spott_fuzz
