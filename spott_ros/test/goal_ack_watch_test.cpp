#include "spott_ros/goal_ack_watch.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace spott_ros {
namespace {

TEST(GoalAckWatch, ALostGoalIsSentAgainOncePerTimeout) {
  GoalAckWatch w(2.0);
  EXPECT_FALSE(w.ShouldResend(true, 0.0));  // nothing sent yet
  w.Sent(10.0);
  EXPECT_FALSE(w.ShouldResend(true, 11.9));
  EXPECT_TRUE(w.ShouldResend(true, 12.0));
  EXPECT_FALSE(w.ShouldResend(true, 13.0));  // restarted at 12
  EXPECT_TRUE(w.ShouldResend(true, 14.5));
  EXPECT_EQ(w.resends(), 2);
}

TEST(GoalAckWatch, AnAcknowledgedGoalIsNeverSentAgain) {
  GoalAckWatch w(2.0);
  w.Sent(0.0);
  EXPECT_FALSE(w.ShouldResend(false, 0.5));
  EXPECT_FALSE(w.watching());
  // PENDING again later (a server that lost its goal list) is not the transport's loss.
  EXPECT_FALSE(w.ShouldResend(true, 10.0));
  EXPECT_EQ(w.resends(), 0);
}

TEST(GoalAckWatch, StopEndsTheWatchAndANewGoalRestartsIt) {
  GoalAckWatch w(1.0);
  w.Sent(0.0);
  w.Stop();
  EXPECT_FALSE(w.ShouldResend(true, 5.0));
  w.Sent(5.0);
  EXPECT_FALSE(w.ShouldResend(true, 5.5));
  EXPECT_TRUE(w.ShouldResend(true, 6.0));
}

TEST(GoalAckWatch, TimeoutMustBePositiveAndFinite) {
  EXPECT_THROW(GoalAckWatch(0.0), std::invalid_argument);
  EXPECT_THROW(GoalAckWatch(-1.0), std::invalid_argument);
  EXPECT_THROW(GoalAckWatch(std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(GoalAckWatch(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace spott_ros
