// Example 1 (section 6.2.1) in closed loop: HILARE's on-board modules drive a unicycle model in
// hilare_room's walls, the belt simulated by ray casting. smooth-move goes to the east wall
// until the wall is perceived as a line 80 cm ahead, then the wall-following process keeps the
// wall on the right at 25 cm until the goal line y = 7 m is crossed.
#include <cmath>

#include <gtest/gtest.h>

#include "rpl_executive/noreils_chatila/on_board_modules.h"
#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::HilareRing;

TEST(Example1, SmoothMoveUntilTheWallIsPerceivedThenWallFollowingUntilTheGoalLine) {
  const SonarRing ring = HilareRing();
  OnBoardModules kit(OnBoardParameters(), ring);
  Executive exec(ExecutiveParameters(), SurveillanceParameters(), ring, &kit);
  exec.SetRobotState("motors", Value::Symbol("ON"));
  const auto walls = testing::HilareRoomWalls();
  Pose2 pose{6.0, 2.5, 0.0};  // hilare_room's wall_follow_start
  double t = 0.0;
  kit.OnPose(PoseDatum{pose});
  exec.OnPose(PoseDatum{pose}, t);
  ASSERT_TRUE(exec.StartMission(testing::ParseFile("example1_wall_following.nc"), t).accepted);
  Pose2 perceived_at{};
  double worst_side = 0.0;
  for (int i = 0; i < 3000 && exec.state() == MissionState::kRunning; ++i) {
    t += 0.1;
    const SonarScan scan = testing::SimulateSonar(walls, pose, ring);
    kit.OnPose(PoseDatum{pose});
    kit.OnSonar(scan);
    exec.OnPose(PoseDatum{pose}, t);
    exec.OnSonar(scan, t);
    const VelocityCommand v = kit.Update(t);
    for (const auto& [h, reply] : kit.TakeReports()) exec.OnOperatorReport(h, reply, t);
    exec.Step(t);
    if (exec.fired().size() == 1 && perceived_at.x == 0.0) perceived_at = pose;
    if (exec.fired().size() == 1 && pose.y > 3.5) {
      worst_side = std::max(worst_side, std::fabs((7.925 - pose.x - 0.4) - 0.25));
    }
    pose.yaw = WrapAngle(pose.yaw + v.angular_rps * 0.05);
    pose.x += v.linear_mps * std::cos(pose.yaw) * 0.1;
    pose.y += v.linear_mps * std::sin(pose.yaw) * 0.1;
    pose.yaw = WrapAngle(pose.yaw + v.angular_rps * 0.05);
  }
  ASSERT_EQ(exec.state(), MissionState::kSucceeded) << exec.log().ToString();
  ASSERT_EQ(exec.fired().size(), 2u);
  EXPECT_EQ(exec.fired()[0].condition, "(S_us-perception line (ρ θ))");
  EXPECT_EQ(exec.fired()[1].condition, "(S_straight-line (x y φ))");
  // The line is perceived at rho = 80 +- 10 cm: the centre 0.7 to 0.9 m from the wall's face.
  EXPECT_GT(7.925 - perceived_at.x, 0.7);
  EXPECT_LT(7.925 - perceived_at.x, 0.9);
  // Wall following: the side 25 cm from the wall (within 5 cm once settled), heading north,
  // stopped on the goal line y = 7 m.
  EXPECT_LT(worst_side, 0.05);
  EXPECT_NEAR(7.925 - pose.x - 0.4, 0.25, 0.03);
  EXPECT_NEAR(pose.yaw, kPi / 2, 0.1);
  EXPECT_NEAR(pose.y, 7.0, 0.05);
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
