#include "markov_localization/resume_spread.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace markov_localization {
namespace {

TEST(ResumeSpread, GrowsAsTheTrackingsOwnUpdatesWouldNotAsOneLongMotion) {
  MotionModelParameters motion;           // 0.1 m/m, 0.02 m/rad, 0.035 rad/m, 0.1 rad/rad
  MotionGateParameters gate;              // updates every 0.2 m or 30 degrees
  const double bin = 0.5 * M_PI / 180.0;  // finer than the spreads here: no floor
  const Spread saved{0.05, 0.02};
  // node_kill.test: about 3 m driven east while the respawned node built its models.
  const Spread s =
      ResumeSpread(saved, Pose2{5.0, 8.25, 0.0}, Pose2{8.0, 8.25, 0.0}, motion, gate, 0.15, bin);
  // 15 updates of 0.1 x 0.2 m in quadrature: 0.077 m; with the saved 0.05: 0.092 m. One motion
  // update of 3 m would have said 0.3 m (the initial sigma the node used to resume with).
  EXPECT_NEAR(s.xy_m, std::hypot(0.05, 0.1 * std::sqrt(0.2 * 3.0)), 1e-9);
  EXPECT_LT(s.xy_m, 0.1);
  EXPECT_NEAR(s.theta_rad, std::hypot(0.02, 0.035 * std::sqrt(0.2 * 3.0)), 1e-9);
  // Turning grows it too; more driving, more spread.
  const Spread turned =
      ResumeSpread(saved, Pose2{5.0, 8.25, 0.0}, Pose2{8.0, 8.25, M_PI}, motion, gate, 0.15, bin);
  EXPECT_GT(turned.xy_m, s.xy_m);
  EXPECT_GT(turned.theta_rad, s.theta_rad);
  const Spread far =
      ResumeSpread(saved, Pose2{0.0, 0.0, 0.0}, Pose2{30.0, 0.0, 0.0}, motion, gate, 0.15, bin);
  EXPECT_GT(far.xy_m, 0.2);
}

TEST(ResumeSpread, NeverFinerThanTheGridAndSpreadOfRefusesABadCovariance) {
  const Spread s = ResumeSpread(Spread{0.0, 0.0}, Pose2{}, Pose2{}, MotionModelParameters{},
                                MotionGateParameters{}, 0.15, 0.035);
  EXPECT_DOUBLE_EQ(s.xy_m, 0.075);
  EXPECT_DOUBLE_EQ(s.theta_rad, 0.035);
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  c(0, 0) = 0.04;  // 0.2 m along the corridor
  c(1, 1) = 0.01;
  c(2, 2) = 0.0025;
  const auto spread = SpreadOf(c);
  ASSERT_TRUE(spread);
  EXPECT_DOUBLE_EQ(spread->xy_m, 0.2);
  EXPECT_DOUBLE_EQ(spread->theta_rad, 0.05);
  c(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(SpreadOf(c));
  c(1, 1) = -1.0;
  EXPECT_FALSE(SpreadOf(c));
}

}  // namespace
}  // namespace markov_localization
