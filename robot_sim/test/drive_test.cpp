#include <gtest/gtest.h>

#include <cmath>

#include "robot_sim/drive.h"

namespace robot_sim {
namespace {

DriveSpec Nomad() {
  DriveSpec d;
  d.max_linear_mps = 0.5;
  d.max_angular_rps = 0.8;
  d.max_linear_accel = 0.5;
  d.max_angular_accel = 1.5;
  return d;
}

TEST(DriveTest, AccelerationAndSpeedLimits) {
  Twist2 v = LimitVelocity({}, {1.0, 2.0}, Nomad(), 0.1);
  EXPECT_NEAR(v.v, 0.05, 1e-12);  // 0.5 m/s^2 * 0.1 s
  EXPECT_NEAR(v.w, 0.15, 1e-12);
  for (int i = 0; i < 100; ++i) v = LimitVelocity(v, {1.0, 2.0}, Nomad(), 0.1);
  EXPECT_DOUBLE_EQ(v.v, 0.5);
  EXPECT_DOUBLE_EQ(v.w, 0.8);
}

TEST(DriveTest, DifferentialDriveLimitsEachWheelAndKeepsCurvature) {
  DriveSpec d = Nomad();
  d.kind = DriveKind::kDifferential;
  d.max_linear_mps = 0.4;
  d.max_angular_rps = 5.0;
  d.wheel_separation_m = 0.6;
  d.max_linear_accel = d.max_angular_accel = 1e6;
  // Wheels would turn at 0.1 and 0.7 m/s: scaled by 0.4 / 0.7.
  const Twist2 v = LimitVelocity({}, {0.4, 1.0}, d, 1.0);
  EXPECT_NEAR(v.v, 0.4 * 0.4 / 0.7, 1e-12);
  EXPECT_NEAR(v.w, 1.0 * 0.4 / 0.7, 1e-12);
}

TEST(DriveTest, IntegrationFollowsTheArc) {
  // 1 m/s and pi/2 rad/s for 1 s: a quarter circle of radius 2/pi.
  const spott_map::Pose2 p = Integrate({0, 0, 0}, {1.0, M_PI / 2}, 1.0);
  EXPECT_NEAR(p.x, 2 / M_PI, 1e-12);
  EXPECT_NEAR(p.y, 2 / M_PI, 1e-12);
  EXPECT_NEAR(p.yaw, M_PI / 2, 1e-12);
}

TEST(DriveTest, InsaneCommandsAreRecognized) {
  EXPECT_TRUE(CommandIsSane({0.5, 0.0}, Nomad()));
  EXPECT_TRUE(CommandIsSane({1.0, 0.0}, Nomad()));  // over the limit: clamped, not refused
  EXPECT_FALSE(CommandIsSane({NAN, 0.0}, Nomad()));
  EXPECT_FALSE(CommandIsSane({0.0, INFINITY}, Nomad()));
  EXPECT_FALSE(CommandIsSane({100.0, 0.0}, Nomad()));
}

TEST(OdometryTest, SystematicScaleAndDriftPerMetre) {
  OdometryErrorModel m;
  m.linear_scale = 1.1;
  m.drift_rad_per_m = 0.01;
  Odometry odo(m);
  Rng rng(1);
  odo.Update(1.0, 0.0, rng);
  EXPECT_NEAR(odo.pose().x, 1.1 * std::cos(0.005), 1e-12);
  EXPECT_NEAR(odo.pose().y, 1.1 * std::sin(0.005), 1e-12);
  EXPECT_NEAR(odo.pose().yaw, 0.01, 1e-12);
}

TEST(OdometryTest, DriftPerRadian) {
  OdometryErrorModel m;
  m.angular_scale = 1.02;
  Odometry odo(m);
  Rng rng(1);
  for (int i = 0; i < 4; ++i) odo.Update(0.0, M_PI / 4, rng);
  EXPECT_NEAR(odo.pose().yaw, 1.02 * M_PI - 2 * M_PI, 1e-9);  // wrapped into (-pi, pi]
}

TEST(OdometryTest, RandomDriftIsReproducibleWithASeedAndGrowsWithDistance) {
  OdometryErrorModel m;
  m.linear_noise = 0.05;
  m.angular_noise_per_m = 0.02;
  auto run = [&](std::uint64_t seed, int steps) {
    Odometry odo(m);
    Rng rng(seed);
    for (int i = 0; i < steps; ++i) odo.Update(0.01, 0.0, rng);
    return odo.pose();
  };
  const auto a = run(7, 1000), b = run(7, 1000), c = run(8, 1000);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.yaw, b.yaw);
  EXPECT_NE(a.x, c.x);
  // Over 10 m the distance error has stddev 0.05 * sqrt(10) = 0.158 m: check the spread over
  // many seeds.
  double sum2 = 0;
  const int runs = 300;
  for (int s = 0; s < runs; ++s) {
    const auto p = run(100 + s, 1000);
    const double e = std::hypot(p.x, p.y) - 10.0;
    sum2 += e * e;
  }
  EXPECT_NEAR(std::sqrt(sum2 / runs), 0.05 * std::sqrt(10.0), 0.03);
}

TEST(OdometryTest, ParametersAreValidatedByName) {
  OdometryErrorModel m;
  m.linear_scale = 3;
  m.angular_noise = -1;
  const auto e = ValidateParameters(m);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_NE(e[0].find("linear_scale"), std::string::npos);
  EXPECT_NE(e[1].find("angular_noise"), std::string::npos);
}

}  // namespace
}  // namespace robot_sim
