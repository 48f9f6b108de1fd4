#include "spott_global_planner/planning_session.h"

#include <cmath>

#include <gtest/gtest.h>

#include "spott_global_planner/window_tracker.h"
#include "test_building.h"

namespace spott_global_planner {
namespace {

using spott_map::Box;
using spott_map::Vec2;
using Ids = std::vector<std::string>;

TEST(WindowTracker, WindowIsCentredOnTheLatticeAndMovesNearItsBorder) {
  EXPECT_TRUE(WindowAround(Vec2(3, 5), 4.0, 0.2).min.isApprox(Vec2(1, 3)));
  EXPECT_TRUE(WindowAround(Vec2(3, 5), 4.0, 0.2).max.isApprox(Vec2(5, 7)));
  WindowParameters params;
  params.window_size_m = 4.0;
  params.resolution_m = 0.2;
  params.recentre_margin_m = 1.0;
  WindowTracker tracker(params);
  EXPECT_TRUE(tracker.Update(Vec2(3, 5), nullptr));
  // Inside [2,4]x[4,6] (1 m from the border): the window stays.
  EXPECT_FALSE(tracker.Update(Vec2(3.9, 5.9), nullptr));
  EXPECT_TRUE(tracker.window().min.isApprox(Vec2(1, 3)));
  // Past it: re-centred on the robot.
  EXPECT_TRUE(tracker.Update(Vec2(4.2, 5), nullptr));
  EXPECT_TRUE(tracker.window().min.isApprox(Vec2(2.2, 3)));
  EXPECT_TRUE(tracker.window().max.isApprox(Vec2(6.2, 7)));
}

TEST(WindowTracker, FitNodeGrowsTheWindowToHoldTheRobotsNodeUpToTheMaximum) {
  // The paper's remedy for cases 1 and 2: the robot's node A = [0,4]^2 lies wholly inside.
  WindowParameters params;
  params.window_size_m = 2.0;
  params.resolution_m = 0.2;
  params.recentre_margin_m = 0.5;
  params.fit_node = true;
  params.max_window_size_m = 10.0;
  const spott_map::Polygon a = test::MakeRoom("A", 0, 0, 4, 4).polygon;
  WindowTracker tracker(params);
  tracker.Update(Vec2(2, 2), &a);
  const Box& w = tracker.window();
  EXPECT_TRUE(w.Contains(Vec2(0, 0)) && w.Contains(Vec2(4, 4)));
  // At most one spare cell on each side beyond the 4 m the node needs.
  EXPECT_LE((w.max - w.min).x(), 4.0 + 4 * 0.2 + 1e-9);
  params.max_window_size_m = 3.0;
  WindowTracker capped(params);
  capped.Update(Vec2(2, 2), &a);
  EXPECT_NEAR((capped.window().max - capped.window().min).x(), 3.0, 1e-9);
}

TEST(WindowTracker, EveryViolatedParameterIsNamed) {
  WindowParameters p;
  p.window_size_m = -1.0;
  p.resolution_m = 0.0;
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0], "window_size_m must be > 0 (got -1)");
  EXPECT_EQ(v[1], "resolution_m must be > 0 (got 0)");
  WindowParameters q;
  q.recentre_margin_m = 4.0;  // window 7 m: the margin must stay below 3.5 m
  EXPECT_EQ(ValidateParameters(q),
            (std::vector<std::string>{"recentre_margin_m must be < window_size_m / 2 (got 4)"}));
  GlobalPlannerParameters all;
  all.window = p;
  all.passage.padding_m = -2.0;
  const auto named = ValidateParameters(all);
  ASSERT_EQ(named.size(), 3u);
  EXPECT_EQ(named[0], "window/window_size_m must be > 0 (got -1)");
  EXPECT_EQ(named[2], "passage/padding_m must be >= 0 (got -2)");
  EXPECT_THROW(PlanningSession{all}, std::invalid_argument);
}

// The partition across H at x in [3.5,4.5] of the passage tests.
spott_map::MapFeature Partition() {
  spott_map::MapFeature partition;
  partition.id = "p";
  partition.type = spott_map::FeatureType::kRectangle;
  partition.pose = spott_map::Pose2{4.0, 5.0, 0.0};
  partition.size_x = 1.0;
  partition.size_y = 3.0;
  return partition;
}

class Session : public ::testing::Test {
 protected:
  Session() : session_(Params()) { session_.SetGraph(test::MakeTestBuilding()); }
  static GlobalPlannerParameters Params() {
    GlobalPlannerParameters p;
    p.window.window_size_m = 3.0;
    p.window.resolution_m = 0.5;
    p.window.recentre_margin_m = 0.5;
    return p;
  }
  PlanningSession session_;
  const Box window_{Vec2(0.5, 0.5), Vec2(3.5, 3.5)};  // around the robot at (2,2) in A
};

TEST_F(Session, NoGoalMeansNothingPlanned) {
  const SessionUpdate u = session_.Update(Vec2(2, 2), &window_);
  EXPECT_EQ(u.state, SessionState::kNoGoal);
  EXPECT_FALSE(u.path);
  EXPECT_FALSE(u.projection);
}

TEST_F(Session, GoalOutsideEveryRoomIsRefusedAndThePreviousGoalKept) {
  ASSERT_EQ(session_.SetGoal(Vec2(11, 1)).error, PlanError::kNone);
  const PlanResult refused = session_.SetGoal(Vec2(30, 1));
  EXPECT_EQ(refused.error, PlanError::kGoalOutsideRooms);
  EXPECT_EQ(refused.message,
            "goal (30.000, 1.000) is outside every room of the graph: goal refused");
  ASSERT_TRUE(session_.goal());
  EXPECT_TRUE(session_.goal()->isApprox(Vec2(11, 1)));
}

TEST_F(Session, ClosingADoorOnThePathReplansAndCountsIt) {
  ASSERT_EQ(session_.SetGoal(Vec2(11, 1)).error, PlanError::kNone);
  SessionUpdate u = session_.Update(Vec2(2, 2), &window_);
  ASSERT_EQ(u.state, SessionState::kPlanned);
  EXPECT_EQ(u.path->doors, (Ids{"dAB", "dBC"}));
  // Case 3: e_k = dAB (x = 4, outside [0.5,3.5]), n_k = A; the line y = 2 leaves at (3.5,2).
  ASSERT_TRUE(u.projection);
  EXPECT_EQ(u.projection->projection_case, ProjectionCase::kGeneral);
  EXPECT_EQ(u.projection->edge_id, "dAB");
  EXPECT_TRUE(u.projection->projected_point.isApprox(Vec2(3.5, 2)));
  EXPECT_TRUE(u.path_changed);
  EXPECT_FALSE(u.replanned);

  u = session_.Update(Vec2(2, 2), &window_);
  EXPECT_FALSE(u.path_changed);
  EXPECT_FALSE(u.projection_changed);

  ASSERT_TRUE(session_.SetDoorState("dBC", spott_map::DoorState::kClosed));
  u = session_.Update(Vec2(2, 2), &window_);
  ASSERT_EQ(u.state, SessionState::kPlanned);
  EXPECT_EQ(u.path->doors, (Ids{"dAH", "dCH"}));
  EXPECT_TRUE(u.replanned);
  EXPECT_EQ(u.replans, 1u);
  // The new first edge dAH (y = 4) is above the window: p_k = (2,3.5) on the top side.
  EXPECT_EQ(u.projection->edge_id, "dAH");
  EXPECT_TRUE(u.projection->projected_point.isApprox(Vec2(2, 3.5)));
  EXPECT_TRUE(u.projection_changed);

  // Closing a door off the path changes nothing and is not a replan.
  ASSERT_TRUE(session_.SetDoorState("dBH", spott_map::DoorState::kClosed));
  u = session_.Update(Vec2(2, 2), &window_);
  EXPECT_FALSE(u.replanned);
  EXPECT_EQ(u.replans, 1u);
}

TEST_F(Session, NoPathLeftFailsNamingTheClosedDoorsAndRecoversWhenOneOpens) {
  session_.SetGoal(Vec2(11, 1));
  ASSERT_EQ(session_.Update(Vec2(2, 2), &window_).state, SessionState::kPlanned);
  session_.SetDoorState("dBC", spott_map::DoorState::kClosed);
  session_.SetDoorState("dCH", spott_map::DoorState::kClosed);
  SessionUpdate u = session_.Update(Vec2(2, 2), &window_);
  ASSERT_EQ(u.state, SessionState::kFailed);
  EXPECT_EQ(u.failure.closed_doors, (Ids{"dBC", "dCH"}));
  EXPECT_EQ(u.failure.message, "no path from node 'A' to node 'C': doors dBC, dCH are closed");
  EXPECT_FALSE(u.projection);
  session_.SetDoorState("dCH", spott_map::DoorState::kOpen);
  u = session_.Update(Vec2(2, 2), &window_);
  ASSERT_EQ(u.state, SessionState::kPlanned);
  EXPECT_EQ(u.path->doors, (Ids{"dAH", "dCH"}));
}

TEST_F(Session, ObstacleBlockingAPassageReplansThroughAnotherDoorOfTheNode) {
  session_.SetDoorState("dBC", spott_map::DoorState::kClosed);
  session_.SetGoal(Vec2(11, 1));
  SessionUpdate u = session_.Update(Vec2(2, 2), &window_);
  ASSERT_EQ(u.path->doors, (Ids{"dAH", "dCH"}));
  EXPECT_EQ(session_.SetFeatures({Partition()}), (Ids{"H"}));
  u = session_.Update(Vec2(2, 2), &window_);
  ASSERT_EQ(u.state, SessionState::kPlanned);
  EXPECT_EQ(u.path->doors, (Ids{"dAB", "dBH", "dCH"}));
  EXPECT_TRUE(u.replanned);
}

TEST(SessionWithoutGraph, GoalBeforeTheGraphIsKeptAndPlannedWhenTheGraphArrives) {
  GlobalPlannerParameters params;
  PlanningSession session(params);
  const PlanResult early = session.SetGoal(Vec2(11, 1));
  EXPECT_EQ(early.error, PlanError::kNone);
  EXPECT_EQ(early.message, "no room/door graph yet: the goal waits for one");
  EXPECT_EQ(session.SetGoal(Vec2(std::nan(""), 1)).error, PlanError::kInvalidPoint);
  session.SetGraph(test::MakeTestBuilding());
  const SessionUpdate u = session.Update(Vec2(1, 1));
  ASSERT_EQ(u.state, SessionState::kPlanned);
  EXPECT_EQ(u.path->doors, (Ids{"dAB", "dBC"}));
}

TEST_F(Session, RobotOnTheFarSideOfAnObstacleInItsNodeLeavesByTheDoorsOnItsSide) {
  // The robot stands in H at (2.5,5), left of the partition: of H's doors it reaches only dAH.
  // With dBC closed the way to C is H-dAH-A-dAB-B-dBH-H-dCH-C (H twice, on either side):
  // (sqrt(17) + 2) + 4 + 3 + (sqrt(17) + 2) = 11 + 2 sqrt(17).
  session_.SetDoorState("dBC", spott_map::DoorState::kClosed);
  session_.SetFeatures({Partition()});
  session_.SetGoal(Vec2(11, 1));
  const SessionUpdate u = session_.Update(Vec2(2.5, 5));
  ASSERT_EQ(u.state, SessionState::kPlanned) << u.failure.message;
  EXPECT_EQ(u.path->rooms, (Ids{"H", "A", "B", "H", "C"}));
  EXPECT_EQ(u.path->doors, (Ids{"dAH", "dAB", "dBH", "dCH"}));
  EXPECT_NEAR(u.path->cost, 11.0 + 2.0 * test::kSqrt17, 1e-9);
}

TEST_F(Session, GoalBehindAnObstacleInTheRobotsOwnNodeIsReachedAroundIt) {
  // Robot (2.5,5) and goal (10,5) both in H, the partition between them: out by dAH, through A
  // and B, back into H by dBH, which is on the goal's side: (sqrt(17) + 2) + 4 + 3.
  session_.SetFeatures({Partition()});
  session_.SetGoal(Vec2(10, 5));
  const SessionUpdate u = session_.Update(Vec2(2.5, 5));
  ASSERT_EQ(u.state, SessionState::kPlanned) << u.failure.message;
  EXPECT_EQ(u.path->doors, (Ids{"dAH", "dAB", "dBH"}));
  EXPECT_NEAR(u.path->cost, 9.0 + test::kSqrt17, 1e-9);
  // Not case 2 (the straight line to the goal crosses the obstacle) but case 3: in the tracked
  // window [1,4]x[3.5,6.5] dAH is inside, dAB (y in [1.5,2.5]) is not: e_k = dAB, n_k = A.
  ASSERT_TRUE(u.projection);
  EXPECT_EQ(u.projection->projection_case, ProjectionCase::kGeneral);
  EXPECT_EQ(u.projection->edge_id, "dAB");
  EXPECT_EQ(u.projection->node_id, "A");
  // On the goal's side the robot goes straight there.
  EXPECT_TRUE(session_.Update(Vec2(9, 5)).path->doors.empty());
}

TEST_F(Session, RobotCutOffFromEveryOpenDoorFailsNamingTheObstacleAndTheClosedDoor) {
  session_.SetDoorState("dAH", spott_map::DoorState::kClosed);
  session_.SetFeatures({Partition()});
  session_.SetGoal(Vec2(11, 1));
  const SessionUpdate u = session_.Update(Vec2(2.5, 5));
  ASSERT_EQ(u.state, SessionState::kFailed);
  EXPECT_EQ(u.failure.closed_doors, (Ids{"dAH"}));
  EXPECT_EQ(u.failure.message,
            "no path from node 'H' to node 'C': door dAH is closed; node 'H' is blocked between "
            "the robot and door dBH; node 'H' is blocked between the robot and door dCH");
}

TEST_F(Session, UnknownDoorIsRefusedWithoutChangingAnything) {
  EXPECT_FALSE(session_.SetDoorState("nope", spott_map::DoorState::kClosed));
  session_.SetGoal(Vec2(11, 1));
  EXPECT_EQ(session_.Update(Vec2(2, 2), &window_).path->doors, (Ids{"dAB", "dBC"}));
}

TEST(SessionFitNode, WindowHoldingTheRobotsNodeTurnsCase2IntoCase1) {
  // The paper's remedy: with fit_node the window grows to hold the robot's node H = [0,12]x[4,6]
  // around the robot (3,5), so a goal (10,5) in H is inside the window: case 1, not case 2.
  GlobalPlannerParameters params;
  params.window.window_size_m = 4.0;
  params.window.resolution_m = 0.2;
  params.window.recentre_margin_m = 0.5;
  params.window.max_window_size_m = 30.0;
  PlanningSession plain(params);
  params.window.fit_node = true;
  PlanningSession fitted(params);
  for (PlanningSession* s : {&plain, &fitted}) {
    s->SetGraph(test::MakeTestBuilding());
    s->SetGoal(Vec2(10, 5));
  }
  EXPECT_EQ(plain.Update(Vec2(3, 5)).projection->projection_case,
            ProjectionCase::kSameNodeOutsideWindow);
  const SessionUpdate u = fitted.Update(Vec2(3, 5));
  EXPECT_EQ(u.projection->projection_case, ProjectionCase::kSameNodeInWindow);
  EXPECT_TRUE(u.projection->window.Contains(Vec2(0, 4)) &&
              u.projection->window.Contains(Vec2(12, 6)));
}

TEST_F(Session, StaleLocalWindowThatNoLongerHoldsTheRobotIsNotUsed) {
  session_.SetGoal(Vec2(11, 1));
  // window_ is [0.5,3.5]^2; the robot at (6,2) in B has left it: the modelled 3 m window on the
  // 0.5 m lattice around (6,2), [4.5,7.5]x[0.5,3.5], is used instead.
  const SessionUpdate u = session_.Update(Vec2(6, 2), &window_);
  ASSERT_TRUE(u.projection);
  EXPECT_TRUE(u.projection->window.min.isApprox(Vec2(4.5, 0.5)));
  EXPECT_TRUE(u.projection->window.max.isApprox(Vec2(7.5, 3.5)));
  EXPECT_EQ(u.projection->edge_id, "dBC");
}

TEST_F(Session, TrackedWindowIsUsedWhenTheLocalPlannerGivesNone) {
  session_.SetGoal(Vec2(11, 1));
  const SessionUpdate u = session_.Update(Vec2(2, 2));
  ASSERT_TRUE(u.projection);
  // 3 m window on a 0.5 m lattice around (2,2): [0.5,3.5]^2.
  EXPECT_TRUE(u.projection->window.min.isApprox(Vec2(0.5, 0.5)));
  EXPECT_TRUE(u.projection->window.max.isApprox(Vec2(3.5, 3.5)));
}

}  // namespace
}  // namespace spott_global_planner
