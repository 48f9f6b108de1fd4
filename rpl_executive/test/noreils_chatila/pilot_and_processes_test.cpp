// The pilot's path tracking, the two processes' control laws and the on-board modules, driven
// on a unicycle model (x += v cos(yaw) dt, ...) at 10 Hz with a ray-casting sonar belt.
#include <cmath>

#include <gtest/gtest.h>

#include "rpl_executive/noreils_chatila/on_board_modules.h"
#include "rpl_executive/noreils_chatila/pilot.h"
#include "rpl_executive/noreils_chatila/processes.h"
#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::HilareRing;
using testing::Scan;
using testing::Segment;
using testing::SimulateSonar;

void Integrate(Pose2* pose, const VelocityCommand& cmd, double dt) {
  pose->yaw = WrapAngle(pose->yaw + cmd.angular_rps * dt / 2);
  pose->x += cmd.linear_mps * std::cos(pose->yaw) * dt;
  pose->y += cmd.linear_mps * std::sin(pose->yaw) * dt;
  pose->yaw = WrapAngle(pose->yaw + cmd.angular_rps * dt / 2);
}

// Distance from p to the broken line through `v`.
double DistanceToBrokenLine(const Point2& p, const std::vector<Point2>& v) {
  double best = 1e300;
  for (size_t i = 0; i + 1 < v.size(); ++i) {
    const double dx = v[i + 1].x - v[i].x, dy = v[i + 1].y - v[i].y;
    const double t =
        std::clamp(((p.x - v[i].x) * dx + (p.y - v[i].y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, std::hypot(p.x - v[i].x - t * dx, p.y - v[i].y - t * dy));
  }
  return best;
}

TEST(Pilot, FollowsExample2sPathToItsEndAndFinalHeading) {
  Pilot pilot{PilotParameters()};
  Pose2 pose{0.8, 5.2, 0.0};
  const std::vector<Point2> vertices = {{1.8, 5.2}, {3.5, 5.2}, {3.6, 3.2}};
  pilot.Start(pose, vertices, -kPi / 2);
  pilot.SetSpeed(0.2);  // set-speed 20
  double worst = 0.0;
  int steps = 0;
  for (; steps < 2000 && pilot.state() != Pilot::State::kDone; ++steps) {
    const VelocityCommand cmd = pilot.Update(pose);
    EXPECT_LE(cmd.linear_mps, 0.2 + 1e-9 + PilotParameters().k_x * 0.5);
    Integrate(&pose, cmd, 0.1);
    worst = std::max(worst, DistanceToBrokenLine({pose.x, pose.y},
                                                 {{0.8, 5.2}, {1.8, 5.2}, {3.5, 5.2}, {3.6, 3.2}}));
  }
  ASSERT_EQ(pilot.state(), Pilot::State::kDone);
  EXPECT_LT(std::hypot(pose.x - 3.6, pose.y - 3.2), 0.06);
  EXPECT_LT(std::fabs(WrapAngle(pose.yaw + kPi / 2)), 0.06);
  // The corner at (3.5, 5.2) is cut by the clothoids (d = 0.5 m), never by more.
  EXPECT_LT(worst, 0.25);
  // 4.7 m at 0.2 m/s with a slow end and two turns: about 25-30 s.
  EXPECT_GT(steps, 230);
  EXPECT_LT(steps, 400);
}

TEST(Pilot, StopAndResumeGoOnAlongWhatIsLeft) {
  Pilot pilot{PilotParameters()};
  Pose2 pose{0.0, 0.0, 0.0};
  pilot.Start(pose, {{2.0, 0.0}, {2.0, 2.0}}, std::nullopt);
  for (int i = 0; i < 30; ++i) Integrate(&pose, pilot.Update(pose), 0.1);
  pilot.Stop();
  EXPECT_EQ(pilot.state(), Pilot::State::kIdle);
  EXPECT_DOUBLE_EQ(pilot.Update(pose).linear_mps, 0.0);
  pose.y += 0.3;  // pushed aside (an avoidance)
  ASSERT_TRUE(pilot.Resume(pose));
  int steps = 0;
  for (; steps < 1000 && pilot.state() != Pilot::State::kDone; ++steps) {
    Integrate(&pose, pilot.Update(pose), 0.1);
  }
  EXPECT_EQ(pilot.state(), Pilot::State::kDone);
  EXPECT_LT(std::hypot(pose.x - 2.0, pose.y - 2.0), 0.06);
}

TEST(Pilot, TurnsInPlaceTowardsAPathBehindIt) {
  Pilot pilot{PilotParameters()};
  const Pose2 pose{0.0, 0.0, kPi};
  pilot.Start(pose, {{2.0, 0.0}}, std::nullopt);
  const VelocityCommand cmd = pilot.Update(pose);
  EXPECT_DOUBLE_EQ(cmd.linear_mps, 0.0);
  EXPECT_GT(std::fabs(cmd.angular_rps), 0.5);
}

TEST(WallFollowing, KeepsTwentyFiveCentimetresFromAWallOnItsRight) {
  const SonarRing ring = HilareRing();
  WallFollowingProcess process(WallFollowingParameters(), ring, SonarInterpretationParameters());
  process.Activate(WallSide::kRight, 0.25);  // (right-side 25)
  const std::vector<Segment> world = {Segment{{-5, 0}, {30, 0}}};
  Pose2 pose{0.0, 0.4 + 0.5, 0.1};  // 50 cm from the wall, turned slightly away
  for (int i = 0; i < 300; ++i) {
    const ProcessOutput out = process.Update(SimulateSonar(world, pose, ring), 0.3);
    ASSERT_FALSE(out.failed) << "step " << i;
    Integrate(&pose, out.command, 0.1);
  }
  EXPECT_NEAR(pose.y - 0.4, 0.25, 0.03);  // the robot's side 25 cm from the wall
  EXPECT_NEAR(pose.yaw, 0.0, 0.05);
  EXPECT_GT(pose.x, 4.0);
}

TEST(WallFollowing, TurnsAwayFromAWallAheadAndFailsOnlyWhenTheWallIsRepeatedlyLost) {
  const SonarRing ring = HilareRing();
  WallFollowingParameters p;
  WallFollowingProcess process(p, ring, SonarInterpretationParameters());
  process.Activate(WallSide::kRight, 0.25);
  const ProcessOutput corner = process.Update(Scan({{1, 0.3}}), 0.3);
  EXPECT_DOUBLE_EQ(corner.command.linear_mps, 0.0);
  EXPECT_GT(corner.command.angular_rps, 0.0);  // left, away from the right-hand wall
  for (int i = 1; i < p.insufficient_data_limit; ++i) {
    const ProcessOutput out = process.Update(Scan(), 0.3);
    EXPECT_TRUE(out.insufficient);
    EXPECT_FALSE(out.failed) << i;
  }
  EXPECT_TRUE(process.Update(Scan(), 0.3).failed);
}

TEST(ObstacleAvoidance, TurnsTowardsTheFreerSideAndHasNothingToDoWithoutObstacle) {
  const SonarRing ring = HilareRing();
  ObstacleAvoidanceParameters p;
  ObstacleAvoidanceProcess process(p, ring);
  process.Activate();
  const ProcessOutput left_obstacle = process.Update(Scan({{2, 0.3}, {3, 0.35}}), 0.3);
  EXPECT_LT(left_obstacle.command.angular_rps, 0.0);  // turn right
  EXPECT_LT(left_obstacle.command.linear_mps, p.speed_mps);
  const ProcessOutput right_obstacle = process.Update(Scan({{16, 0.3}}), 0.3);
  EXPECT_GT(right_obstacle.command.angular_rps, 0.0);
  EXPECT_DOUBLE_EQ(process.Update(Scan({{1, 0.2}}), 0.3).command.linear_mps, 0.0);  // stop dist.
  for (int i = 1; i < p.insufficient_data_limit; ++i) {
    EXPECT_FALSE(process.Update(Scan({{9, 0.3}}), 0.3).failed);  // behind: not an obstacle
  }
  EXPECT_TRUE(process.Update(Scan(), 0.3).failed);
}

TEST(OnBoardModules, StopReportsTheInterruptionOnTheNextCycleAndHaltDoesNot) {
  OnBoardModules modules(OnBoardParameters(), HilareRing());
  modules.OnPose(testing::At(0, 0));
  SmoothMoveCommand move;
  move.path_m = {{2, 0}};
  EXPECT_EQ(modules.Send(1, move, 0.0).status, OperatorStatus::kRunning);
  EXPECT_EQ(modules.wheels_holder(), "smooth-move");
  EXPECT_GT(modules.Update(0.1).linear_mps, 0.0);
  EXPECT_EQ(modules.Send(2, StopCommand{}, 0.2).status, OperatorStatus::kCompleted);
  EXPECT_DOUBLE_EQ(modules.Update(0.3).linear_mps, 0.0);
  const auto reports = modules.TakeReports();
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].first, 1u);
  EXPECT_EQ(reports[0].second.status, OperatorStatus::kInterrupted);
  modules.Send(3, move, 0.4);
  modules.Halt(3, 0.5);
  EXPECT_TRUE(modules.TakeReports().empty());
  EXPECT_EQ(modules.wheels_holder(), "");
}

TEST(OnBoardModules, AvoidObstacleCompletesWhenNothingIsLeftToAvoidAndRunFails) {
  OnBoardModules modules(OnBoardParameters(), HilareRing());
  modules.OnPose(testing::At(0, 0));
  modules.Send(1, AvoidObstacleCommand{}, 0.0);
  modules.OnSonar(Scan({{1, 0.3}}));
  EXPECT_GT(std::fabs(modules.Update(0.1).angular_rps), 0.0);
  for (int i = 0; i < ObstacleAvoidanceParameters().insufficient_data_limit; ++i) {
    modules.OnSonar(Scan());
  }
  auto reports = modules.TakeReports();
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].second.status, OperatorStatus::kCompleted);
  modules.Send(2, ObstacleAvoidanceCommand{}, 1.0);  // RUN (obstacle-avoidance)
  for (int i = 0; i < ObstacleAvoidanceParameters().insufficient_data_limit; ++i) {
    modules.OnSonar(Scan());
  }
  reports = modules.TakeReports();
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].second.status, OperatorStatus::kFailed);
  EXPECT_NE(reports[0].second.message.find("repeatedly insufficient data"), std::string::npos);
}

TEST(OnBoardModules, ReadAllUsDataReturnsEchoesAndPositionInMissionUnits) {
  OnBoardModules modules(OnBoardParameters(), HilareRing());
  modules.OnPose(testing::At(2.0, 5.2, -kPi / 2));
  modules.OnSonar(Scan({{1, 1.234}, {5, 0.5}}));
  const OperatorReply r = modules.Send(1, ReadAllUsDataCommand{}, 0.0);
  ASSERT_EQ(r.results.size(), 2u);
  EXPECT_EQ(r.results[0].first, "r-us-data");
  EXPECT_EQ(r.results[0].second.ToText(), "((1 123.4) (5 50))");
  EXPECT_EQ(r.results[1].second.ToText(), "(200 520 2700)");
  modules.Send(2, DrawCommand{{"G_pos"}, {r.results[1].second}}, 0.0);
  ASSERT_EQ(modules.TakeDrawings().size(), 1u);
}

TEST(OnBoardModules, ParametersAreValidatedByName) {
  OnBoardParameters p;
  p.pilot.default_speed_mps = 1.0;  // above max_speed_mps
  p.obstacle_avoidance.detect_distance_m = 0.1;
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0], "pilot.default_speed_mps: must be in (0, max_speed_mps]");
  EXPECT_EQ(v[1], "obstacle_avoidance.detect_distance_m: must be above stop_distance_m");
  EXPECT_THROW(OnBoardModules(p, HilareRing()), std::invalid_argument);
}

// The parameter fuzzer's finding (corpus side_window_above_half_pi): the wall window's range is
// (0, pi], as validated; the header said (0, pi/2].
TEST(OnBoardModules, TheWallWindowMayBeWiderThanAQuarterTurnButNotAboveAHalfTurn) {
  OnBoardParameters p;
  p.wall_following.side_window_rad = 2.1;
  EXPECT_TRUE(ValidateParameters(p).empty());
  p.wall_following.side_window_rad = 3.2;
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0], "wall_following.side_window_rad: must be in (0, pi]");
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
