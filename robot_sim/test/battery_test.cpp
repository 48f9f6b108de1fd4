// The battery's drain model (battery.h) on hand-computed cases.
#include "robot_sim/battery.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace robot_sim {
namespace {

BatteryParameters Small() {
  BatteryParameters p;
  p.capacity_wh = 100.0;
  p.initial_percent = 50.0;
  p.idle_power_w = 36.0;
  p.power_per_mps_w = 72.0;
  p.power_per_rps_w = 18.0;
  p.full_voltage_v = 26.0;
  p.empty_voltage_v = 22.0;
  return p;
}

TEST(Battery, StandingStillDrainsTheIdlePowerOnly) {
  Battery b(Small());
  EXPECT_DOUBLE_EQ(b.percent(), 50.0);
  // 36 W for 100 s = 1 Wh of 100 Wh: one percent.
  for (int i = 0; i < 1000; ++i) b.Step(0.1, 0.0, 0.0);
  EXPECT_NEAR(b.percent(), 49.0, 1e-9);
  EXPECT_NEAR(b.remaining_wh(), 49.0, 1e-9);
}

TEST(Battery, DrivingAndTurningDrawTractionPowerInEitherDirection) {
  Battery forward(Small()), backward(Small());
  // 36 + 72 * 0.5 + 18 * 1.0 = 90 W for 40 s = 1 Wh.
  for (int i = 0; i < 400; ++i) {
    forward.Step(0.1, 0.5, 1.0);
    backward.Step(0.1, -0.5, -1.0);
  }
  EXPECT_NEAR(forward.power_w(), 90.0, 1e-12);
  EXPECT_NEAR(forward.percent(), 49.0, 1e-9);
  EXPECT_NEAR(backward.percent(), forward.percent(), 1e-12);
}

TEST(Battery, VoltageAndCurrentFollowTheCharge) {
  Battery b(Small());
  EXPECT_DOUBLE_EQ(b.voltage_v(), 24.0);            // half charged: half way from 22 to 26 V
  EXPECT_DOUBLE_EQ(b.current_a(), 36.0 / 24.0);     // idle before the first step
  EXPECT_DOUBLE_EQ(b.capacity_ah(), 100.0 / 24.0);  // at the nominal 24 V
  EXPECT_DOUBLE_EQ(b.charge_ah(), 50.0 / 24.0);
}

TEST(Battery, NeverFallsBelowEmptyAndIgnoresBadSteps) {
  BatteryParameters p = Small();
  p.initial_percent = 0.01;  // 0.01 Wh
  Battery b(p);
  b.Step(10.0, 0.0, 0.0);  // 0.1 Wh asked
  EXPECT_DOUBLE_EQ(b.percent(), 0.0);
  EXPECT_DOUBLE_EQ(b.voltage_v(), 22.0);
  Battery c(Small());
  c.Step(-1.0, 0.0, 0.0);
  c.Step(std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0);
  c.Step(1.0, std::numeric_limits<double>::quiet_NaN(), 0.0);  // NaN speed counts as standing
  EXPECT_NEAR(c.remaining_wh(), 50.0 - 36.0 / 3600.0, 1e-12);
}

TEST(Battery, BadParametersAreNamed) {
  BatteryParameters p;
  p.capacity_wh = 0.0;
  p.initial_percent = 120.0;
  p.idle_power_w = -1.0;
  p.full_voltage_v = 20.0;  // below empty
  const auto e = ValidateParameters(p);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[0], "battery/capacity_wh must be in (0, 1e6]");
  EXPECT_EQ(e[1], "battery/initial_percent must be in [0, 100]");
  EXPECT_EQ(e[2], "battery/idle_power_w must be in [0, 1e5]");
  EXPECT_NE(e[3].find("battery/full_voltage_v"), std::string::npos);
  EXPECT_THROW(Battery{p}, std::invalid_argument);
}

}  // namespace
}  // namespace robot_sim
