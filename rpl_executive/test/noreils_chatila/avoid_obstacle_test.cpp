// avoid-obstacle as an elementary task (avoid_obstacle.h), driven in closed loop: a unicycle
// robot of HILARE's radius takes the task's commands at 10 Hz, its sonar belt simulated on a
// world of segments (test_support.h), a cylinder approximated by a 16-sided polygon.
#include <cmath>

#include <gtest/gtest.h>

#include "rpl_executive/noreils_chatila/avoid_obstacle.h"
#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::HilareRing;
using testing::Segment;

constexpr double kRobotRadius = 0.4;

std::vector<Segment> Cylinder(Point2 c, double radius) {
  std::vector<Segment> out;
  const int sides = 16;
  for (int k = 0; k < sides; ++k) {
    const double a0 = 2.0 * kPi * k / sides, a1 = 2.0 * kPi * (k + 1) / sides;
    out.push_back(Segment{{c.x + radius * std::cos(a0), c.y + radius * std::sin(a0)},
                          {c.x + radius * std::cos(a1), c.y + radius * std::sin(a1)}});
  }
  return out;
}

struct Outcome {
  AvoidObstacleTask::Step last;
  Pose2 pose;
  double closest_m = 1e9;  // robot centre to the cylinder's centre
  int cycles = 0;
};

// Drives the task from `start` until it ends (or 1,000 cycles).
Outcome Drive(const Pose2& start, std::vector<Point2> way, Point2 obstacle) {
  std::vector<Segment> world = testing::HilareRoomWalls();
  for (const Segment& s : Cylinder(obstacle, 0.15)) world.push_back(s);
  AvoidObstacleTask task(ObstacleAvoidanceParameters(), HilareRing());
  task.Start(way);
  Outcome run;
  run.pose = start;
  for (; run.cycles < 1000; ++run.cycles) {
    run.last = task.Update(run.pose, testing::SimulateSonar(world, run.pose, HilareRing()), 0.5);
    if (run.last.status != AvoidObstacleTask::Status::kRunning) break;
    const double dt = 0.1;
    run.pose.yaw += run.last.command.angular_rps * dt;
    run.pose.x += run.last.command.linear_mps * dt * std::cos(run.pose.yaw);
    run.pose.y += run.last.command.linear_mps * dt * std::sin(run.pose.yaw);
    run.closest_m = std::min(run.closest_m, Distance({run.pose.x, run.pose.y}, obstacle));
  }
  return run;
}

// The hilare_example2_obstacle_after_zone scenario: stopped by S_us-threshold 0.75 m before a
// cylinder on PATH's last leg, heading for its end (3.6, 3.2). Before, the task ended as soon as
// the robot had turned away and resume-order drove it back at the cylinder, five times, into it.
TEST(AvoidObstacle, GoesRoundACylinderUntilTheWayToTheNextVertexIsClear) {
  for (const double start_x : {3.35, 3.45, 3.55, 3.65, 3.75}) {
    const Point2 cylinder{3.58, 3.9};
    const Point2 vertex{3.6, 3.2};
    const Pose2 start{start_x, 4.65, -kPi / 2 + 0.1 * (start_x - 3.55)};
    const Outcome run = Drive(start, {vertex}, cylinder);
    ASSERT_EQ(run.last.status, AvoidObstacleTask::Status::kCompleted)
        << "from x " << start_x << ": " << run.last.message;
    EXPECT_GT(run.closest_m, 0.15 + kRobotRadius) << "touched, from x " << start_x;
    const Point2 at{run.pose.x, run.pose.y};
    EXPECT_GT(DistanceToSegment(cylinder, at, vertex), 0.15 + kRobotRadius + 0.05)
        << DistanceToSegment(cylinder, at, vertex) << " at " << at.x << ", " << at.y
        << "the way back still meets the cylinder, from x " << start_x;
    EXPECT_GT(Distance(at, {start.x, start.y}), 0.3) << "it has to move off, from " << start_x;
    EXPECT_NE(run.last.message.find("is clear"), std::string::npos) << run.last.message;
  }
}

TEST(AvoidObstacle, AnObstacleOnTheVertexFailsAfterMaxTravelWithoutTouchingIt) {
  const Outcome run = Drive(Pose2{3.6, 4.1, -kPi / 2}, {Point2{3.6, 3.2}}, Point2{3.6, 3.25});
  EXPECT_EQ(run.last.status, AvoidObstacleTask::Status::kFailed);
  EXPECT_NE(run.last.message.find("max_travel_m"), std::string::npos) << run.last.message;
  EXPECT_GT(run.closest_m, 0.15 + kRobotRadius);
}

TEST(AvoidObstacle, AnEchoABeamLaterReadsPastIsForgotten) {
  AvoidObstacleTask task(ObstacleAvoidanceParameters(), HilareRing());
  task.Start({Point2{0.9, 0.0}});
  const Pose2 at{0.0, 0.0, 0.0};
  auto step = task.Update(at, testing::Scan({{1, 0.3}}), 0.5);  // 0.7 m ahead, on the way
  EXPECT_EQ(step.status, AvoidObstacleTask::Status::kRunning);
  ASSERT_EQ(task.remembered().size(), 1u);
  EXPECT_NEAR(task.remembered()[0].at.x, 0.7, 1e-9);
  // The obstacle went away: the beam reads the wall behind it, 1.2 m off, five times.
  for (int i = 0; i < 4; ++i) step = task.Update(at, testing::Scan({{1, 1.2}}), 0.5);
  EXPECT_EQ(task.remembered().size(), 2u) << "kept while a grazing beam may read past it";
  step = task.Update(at, testing::Scan({{1, 1.2}}), 0.5);
  ASSERT_EQ(task.remembered().size(), 1u);
  EXPECT_NEAR(task.remembered()[0].at.x, 1.6, 1e-9) << "only the wall is left";
  EXPECT_EQ(step.status, AvoidObstacleTask::Status::kCompleted) << step.message;
}

TEST(AvoidObstacle, WithoutAnOrderToReturnToItEndsWhenNothingIsInFront) {
  const ObstacleAvoidanceParameters p;
  AvoidObstacleTask task(p, HilareRing());
  task.Start({});
  const Pose2 at{0.0, 0.0, 0.0};
  EXPECT_GT(std::fabs(task.Update(at, testing::Scan({{1, 0.3}}), 0.5).command.angular_rps), 0.0);
  AvoidObstacleTask::Step step;
  for (int i = 0; i < p.insufficient_data_limit; ++i) step = task.Update(at, testing::Scan(), 0.5);
  EXPECT_EQ(step.status, AvoidObstacleTask::Status::kCompleted);
  EXPECT_EQ(step.message, "nothing left to avoid");
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
