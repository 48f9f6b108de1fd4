// The three cases of SPOTT Fig. 14 (and the goal-itself case) on the building of
// test_building.h, with the windows given explicitly so every answer is computed by hand.
#include "spott_global_planner/goal_projection.h"

#include <gtest/gtest.h>

#include "test_building.h"

namespace spott_global_planner {
namespace {

using spott_map::Box;
using spott_map::Vec2;

class GoalProjection : public ::testing::Test {
 protected:
  GoalProjection() : planner_(test::MakeTestBuilding()) {}

  ProjectedGoal Project(const Vec2& robot, const Vec2& goal, const Box& window) {
    const PlanResult r = planner_.Plan(robot, goal);
    EXPECT_TRUE(r.ok()) << r.message;
    path_ = *r.path;
    return ProjectGoalOntoWindow(planner_.graph(), path_, robot, goal, window);
  }

  GlobalPlanner planner_;
  GlobalPath path_;
};

// Segment equality regardless of direction.
::testing::AssertionResult SameSegment(const spott_map::Segment& s, const Vec2& a, const Vec2& b) {
  const double tol = 1e-9;
  if (((s.a - a).norm() < tol && (s.b - b).norm() < tol) ||
      ((s.a - b).norm() < tol && (s.b - a).norm() < tol)) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "segment (" << s.a.transpose() << ") - (" << s.b.transpose() << "), expected ("
         << a.transpose() << ") - (" << b.transpose() << ")";
}

TEST_F(GoalProjection, Case1GoalInWindowAndRobotNodeIsLeftAlone) {
  // Robot (3,5) in H, window [1,5]x[3,7], goal (4,5.5) in H and in the window.
  const ProjectedGoal p = Project(Vec2(3, 5), Vec2(4, 5.5), Box{Vec2(1, 3), Vec2(5, 7)});
  EXPECT_EQ(p.projection_case, ProjectionCase::kSameNodeInWindow);
  EXPECT_FALSE(p.on_border);
  EXPECT_TRUE(p.goal.isApprox(Vec2(4, 5.5)));
}

TEST_F(GoalProjection, GoalExactlyOnTheBorderCountsAsInsideTheWindow) {
  // Goal (5,5) lies on the right side x = 5 of the window: case 1, the goal itself.
  const ProjectedGoal p = Project(Vec2(3, 5), Vec2(5, 5), Box{Vec2(1, 3), Vec2(5, 7)});
  EXPECT_EQ(p.projection_case, ProjectionCase::kSameNodeInWindow);
  EXPECT_FALSE(p.on_border);
}

TEST_F(GoalProjection, Case2ProjectsOntoThePartOfTheSideInsideTheRobotNode) {
  // Robot (3,5) in H, window [1,5]x[3,7], goal (10,5) in H outside the window. The line robot ->
  // goal leaves by the right side x = 5 at (5,5); that side runs y in [3,7], of which H (y in
  // [4,6]) holds [4,6].
  const ProjectedGoal p = Project(Vec2(3, 5), Vec2(10, 5), Box{Vec2(1, 3), Vec2(5, 7)});
  EXPECT_EQ(p.projection_case, ProjectionCase::kSameNodeOutsideWindow);
  ASSERT_TRUE(p.on_border);
  EXPECT_EQ(p.side, WindowSide::kRight);
  EXPECT_TRUE(SameSegment(p.border, Vec2(5, 4), Vec2(5, 6)));
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(5, 5)));
  EXPECT_EQ(p.node_id, "H");
  EXPECT_EQ(p.rule, "");
}

TEST_F(GoalProjection, Case2AtAWindowCornerTakesTheSideWithTheLongerPortionInTheNode) {
  // One room R = [0,10]x[2,10]; robot (3,3), window [1,5]x[1,5], goal (7,7): the line leaves
  // through the corner (5,5). The right side x = 5 has y in [2,5] in R (3 m), the top side
  // y = 5 has x in [1,5] in R (4 m): the top side wins.
  GlobalPlanner planner(spott_map::RoomDoorGraph({test::MakeRoom("R", 0, 2, 10, 10)}, {}));
  const PlanResult r = planner.Plan(Vec2(3, 3), Vec2(7, 7));
  ASSERT_TRUE(r.ok());
  const ProjectedGoal p = ProjectGoalOntoWindow(planner.graph(), *r.path, Vec2(3, 3), Vec2(7, 7),
                                                Box{Vec2(1, 1), Vec2(5, 5)});
  EXPECT_EQ(p.projection_case, ProjectionCase::kSameNodeOutsideWindow);
  EXPECT_EQ(p.side, WindowSide::kTop);
  EXPECT_TRUE(SameSegment(p.border, Vec2(1, 5), Vec2(5, 5)));
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(5, 5)));
}

TEST_F(GoalProjection, Case3ProjectsWhereTheLineFromNodeCentreToFirstOutsideEdgeCrosses) {
  // Robot (2,2) in A, window [0.5,3.5]^2, goal (10,5) in H: the path is A-dAH-H. dAH's opening
  // (1.5..2.5, 4) is above the window, so e_k = dAH and n_k = A. The line from A's centre (2,2)
  // to dAH's centre (2,4) crosses the top side y = 3.5 at p_k = (2,3.5); that side lies wholly
  // in A.
  const ProjectedGoal p = Project(Vec2(2, 2), Vec2(10, 5), Box{Vec2(0.5, 0.5), Vec2(3.5, 3.5)});
  EXPECT_EQ(path_.doors, (std::vector<std::string>{"dAH"}));
  EXPECT_EQ(p.projection_case, ProjectionCase::kGeneral);
  ASSERT_TRUE(p.on_border);
  EXPECT_EQ(p.edge_id, "dAH");
  EXPECT_EQ(p.node_id, "A");
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(2, 3.5)));
  EXPECT_EQ(p.side, WindowSide::kTop);
  EXPECT_TRUE(SameSegment(p.border, Vec2(0.5, 3.5), Vec2(3.5, 3.5)));
  EXPECT_EQ(p.rule, "");
}

TEST_F(GoalProjection, Case3SkipsEdgesInsideTheWindowAndClipsTheSideToNodeK) {
  // Robot (3,3) in A, window [1,5]x[1,5], goal (10,2) in C: path A-dAB-B-dBC-C. dAB's opening
  // x = 4, y in [1.5,2.5] is inside the window; dBC (x = 8) is not: e_k = dBC, n_k = B. The
  // line through B's centre (6,2) and dBC's centre (8,2) is y = 2; B's centre is already right
  // of the window, so the crossing nearer the edge is p_k = (5,2). The right side x = 5 runs y
  // in [1,5], of which B (y <= 4) holds [1,4].
  const ProjectedGoal p = Project(Vec2(3, 3), Vec2(10, 2), Box{Vec2(1, 1), Vec2(5, 5)});
  EXPECT_EQ(path_.doors, (std::vector<std::string>{"dAB", "dBC"}));
  EXPECT_EQ(p.projection_case, ProjectionCase::kGeneral);
  EXPECT_EQ(p.edge_id, "dBC");
  EXPECT_EQ(p.node_id, "B");
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(5, 2)));
  EXPECT_EQ(p.side, WindowSide::kRight);
  EXPECT_TRUE(SameSegment(p.border, Vec2(5, 1), Vec2(5, 4)));
}

TEST_F(GoalProjection, Case3SlopedLineClipsTheSideToNodeK) {
  // Robot (6,5) in H, window [4.5,7.5]x[3.5,6.5], goal (11,1) in C. Path: H-dCH-C
  // (sqrt(17) + 2 = 6.12; via dBH-B-dBC it is 3 + 4 = 7). e_k = dCH (x in [9.5,10.5]), n_k = H.
  // The line from H's centre (6,5) to dCH's centre (10,4) has slope -1/4 and meets x = 7.5 at
  // y = 4.625: p_k = (7.5, 4.625), on the right side (y in [3.5,6.5]); H holds y in [4,6] of it.
  const ProjectedGoal p = Project(Vec2(6, 5), Vec2(11, 1), Box{Vec2(4.5, 3.5), Vec2(7.5, 6.5)});
  EXPECT_EQ(path_.doors, (std::vector<std::string>{"dCH"}));
  EXPECT_EQ(p.edge_id, "dCH");
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(7.5, 4.625)));
  EXPECT_EQ(p.side, WindowSide::kRight);
  EXPECT_TRUE(SameSegment(p.border, Vec2(7.5, 4), Vec2(7.5, 6)));
}

TEST_F(GoalProjection, Case3LineThroughAWindowCornerTakesTheSideWithTheLongerPortionInNodeK) {
  // Robot (6.5,5.5) in H, window [5,8]x[4.5,7.5], goal (11,1) in C: e_k = dCH, n_k = H. The line
  // (6,5) + t (4,-1) leaves the window at t = 0.5 through the corner (8,4.5). The right side
  // x = 8 (y in [4.5,7.5]) has y in [4.5,6] in H (1.5 m); the bottom side y = 4.5 (x in [5,8])
  // lies wholly in H (3 m): the bottom side wins.
  const ProjectedGoal p = Project(Vec2(6.5, 5.5), Vec2(11, 1), Box{Vec2(5, 4.5), Vec2(8, 7.5)});
  EXPECT_EQ(p.edge_id, "dCH");
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(8, 4.5)));
  EXPECT_EQ(p.side, WindowSide::kBottom);
  EXPECT_TRUE(SameSegment(p.border, Vec2(5, 4.5), Vec2(8, 4.5)));
}

TEST_F(GoalProjection, GoalInWindowInAnotherNodeWithEveryEdgeInsideIsTheGoalItself) {
  // Robot (3,2) in A, window [1,5]x[0,4], goal (4.5,2) in B; dAB's opening is in the window.
  const ProjectedGoal p = Project(Vec2(3, 2), Vec2(4.5, 2), Box{Vec2(1, 0), Vec2(5, 4)});
  EXPECT_EQ(path_.doors, (std::vector<std::string>{"dAB"}));
  EXPECT_EQ(p.projection_case, ProjectionCase::kGoalInWindow);
  EXPECT_FALSE(p.on_border);
  EXPECT_TRUE(p.goal.isApprox(Vec2(4.5, 2)));
}

TEST_F(GoalProjection, GoalInWindowButAPathEdgeOutsideIsStillCase3) {
  // Robot (3.6,3.6) in A, window [2.6,4.6]^2, goal (3.6,4.4) in H, inside the window. The path
  // A-dAH-H (2 + sqrt(17) = 6.12 < 7 via B) uses dAH, whose opening (x in [1.5,2.5], y = 4) is
  // outside the window: case 3 with e_k = dAH, n_k = A, not the goal itself. The line x = 2
  // through A's centre and dAH's centre misses the window, so the line from the robot to dAH's
  // centre (2,4) is used: (3.6,3.6) + t (-1.6,0.4) meets x = 2.6 at t = 0.625, y = 3.85. The
  // left side x = 2.6 holds y in [2.6,4] in A.
  const ProjectedGoal p =
      Project(Vec2(3.6, 3.6), Vec2(3.6, 4.4), Box{Vec2(2.6, 2.6), Vec2(4.6, 4.6)});
  EXPECT_EQ(path_.doors, (std::vector<std::string>{"dAH"}));
  EXPECT_EQ(p.projection_case, ProjectionCase::kGeneral);
  EXPECT_EQ(p.edge_id, "dAH");
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(2.6, 3.85)));
  EXPECT_EQ(p.side, WindowSide::kLeft);
  EXPECT_TRUE(SameSegment(p.border, Vec2(2.6, 2.6), Vec2(2.6, 4)));
  EXPECT_EQ(p.rule, "the line from the node's centre misses the window: the line from the robot");
}

TEST_F(GoalProjection, EdgePartlyOutsideTheWindowIsNotWithinIt) {
  // dAB's opening is x = 4, y in [1.5,2.5]. A window [1,5]x[2,6] holds only half of it.
  const auto& graph = planner_.graph();
  const spott_map::Door& dab = graph.door(*graph.FindDoor("dAB"));
  EXPECT_FALSE(EdgeWithinWindow(dab, Box{Vec2(1, 2), Vec2(5, 6)}));
  EXPECT_TRUE(EdgeWithinWindow(dab, Box{Vec2(1, 1.5), Vec2(4, 2.5)}));  // border included
}

TEST_F(GoalProjection, EdgeCutByTheWindowAlongItsLineFallsBackToNodeKsNearestBorderPortion) {
  // Robot (3,3) in A, window [1,5]x[2,6]: dAB's centre (4,2) is on the bottom side and the lower
  // half of its opening outside, so e_k = dAB (goal (6,1) in B), n_k = A. The line y = 2 through
  // (2,2) and (4,2) runs along the bottom side; it is extended past the edge's centre to (5,2).
  // No side through (5,2) has a portion of A (x <= 4) holding it, so the rule takes A's nearest
  // portion of the border: the bottom side from (1,2) to (4,2).
  const ProjectedGoal p = Project(Vec2(3, 3), Vec2(6, 1), Box{Vec2(1, 2), Vec2(5, 6)});
  EXPECT_EQ(p.edge_id, "dAB");
  EXPECT_EQ(p.node_id, "A");
  ASSERT_TRUE(p.on_border);
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(5, 2)));
  EXPECT_TRUE(SameSegment(p.border, Vec2(1, 2), Vec2(4, 2)));
  EXPECT_EQ(p.rule,
            "the line is extended past the edge's centre to the border; no portion of the node "
            "holds the crossing: the node's nearest portion of the border");
}

TEST_F(GoalProjection, GoalOutsideWindowInAnotherNodeWithEveryEdgeInsideStandsInForTheEdge) {
  // Robot (3,2) in A, window [1,5]x[0,4], goal (7,2) in B: dAB is inside, the goal is not. The
  // goal stands in for e_k: the line from B's centre (6,2) to the goal (7,2) is y = 2; B's centre
  // is right of the window, so the crossing nearer the goal is (5,2); the right side x = 5,
  // y in [0,4] lies wholly in B.
  const ProjectedGoal p = Project(Vec2(3, 2), Vec2(7, 2), Box{Vec2(1, 0), Vec2(5, 4)});
  EXPECT_EQ(p.projection_case, ProjectionCase::kGeneral);
  EXPECT_EQ(p.edge_id, "");
  EXPECT_EQ(p.node_id, "B");
  EXPECT_TRUE(p.projected_point.isApprox(Vec2(5, 2)));
  EXPECT_TRUE(SameSegment(p.border, Vec2(5, 0), Vec2(5, 4)));
}

TEST_F(GoalProjection, MalformedPathIsAProgrammingError) {
  GlobalPath bad;
  EXPECT_THROW(ProjectGoalOntoWindow(planner_.graph(), bad, Vec2(1, 1), Vec2(2, 2),
                                     Box{Vec2(0, 0), Vec2(3, 3)}),
               std::invalid_argument);
}

}  // namespace
}  // namespace spott_global_planner
