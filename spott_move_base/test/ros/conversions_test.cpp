#include "spott_move_base/conversions.h"

#include <cmath>

#include <gtest/gtest.h>

namespace spott_move_base {
namespace {

TEST(Conversions, AMoveBaseGoalKeepsPoseAndHeadingAtNormalSpeed) {
  move_base_msgs::MoveBaseGoal g;
  g.target_pose.header.frame_id = "map";
  g.target_pose.pose.position.x = 3.0;
  g.target_pose.pose.orientation.z = 1.0;
  const spott_msgs::NavigateGoal n = ToNavigateGoal(g);
  EXPECT_EQ(n.target.header.frame_id, "map");
  EXPECT_DOUBLE_EQ(n.target.pose.position.x, 3.0);
  EXPECT_DOUBLE_EQ(n.target.pose.orientation.z, 1.0);
  EXPECT_FALSE(n.ignore_heading);
  EXPECT_EQ(n.speed_mode, spott_msgs::NavigateGoal::NORMAL);
  EXPECT_TRUE(std::isnan(n.direction_bias));
  EXPECT_EQ(n.position_tolerance, 0.0);
}

TEST(Conversions, OutcomesBecomeMoveBaseStatesWithTheReason) {
  spott_msgs::NavigateResult r;
  r.outcome = r.SUCCEEDED;
  EXPECT_EQ(EndOf(r), MoveBaseEnd::kSucceeded);
  r.outcome = r.PREEMPTED;
  EXPECT_EQ(EndOf(r), MoveBaseEnd::kPreempted);
  r.outcome = r.UNREACHABLE;
  r.reason = "doors d_lab_w are closed";
  EXPECT_EQ(EndOf(r), MoveBaseEnd::kAborted);
  EXPECT_EQ(TextOf(r), "unreachable: doors d_lab_w are closed");
  r.outcome = r.FAILED;
  EXPECT_EQ(EndOf(r), MoveBaseEnd::kAborted);
}

}  // namespace
}  // namespace spott_move_base
