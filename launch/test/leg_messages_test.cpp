// The task result as the scenario runner and ./spott report take it (leg_messages.h): which
// outcomes end a leg as the controller meant (reached, found, stopped) and which do not.
#include "leg_messages.h"

#include <gtest/gtest.h>

#include <limits>

namespace {

spott_msgs::TaskResult Result(const std::string& outcome, const std::string& message = "") {
  spott_msgs::TaskResult r;
  r.outcome = outcome;
  r.message = message;
  r.goal.x = r.goal.y = std::numeric_limits<double>::quiet_NaN();
  return r;
}

TEST(ApplyTaskResult, AGoReachedAFindFoundAndATeleoperationStoppedEndAsMeant) {
  std::vector<std::string> features;
  spott_launch::NavigationLeg leg;
  EXPECT_TRUE(spott_launch::ApplyTaskResult(Result("reached"), features, leg));
  EXPECT_TRUE(spott_launch::ApplyTaskResult(Result("found"), features, leg));
  // SPOTT's tele-operation has no goal: it ends "stopped" (before a known structure).
  EXPECT_TRUE(spott_launch::ApplyTaskResult(Result("stopped", "a known structure 0.30 m ahead"),
                                            features, leg));
  EXPECT_FALSE(leg.has_target);
  EXPECT_EQ(leg.task_outcome, "stopped: a known structure 0.30 m ahead");  // why it stopped
  spott_launch::ApplyTaskResult(Result("stopped", "stopped: a known structure 0.30 m ahead"),
                                features, leg);
  EXPECT_EQ(leg.task_outcome, "stopped: a known structure 0.30 m ahead");  // said once
  EXPECT_FALSE(spott_launch::ApplyTaskResult(Result("failed", "blocked"), features, leg));
  EXPECT_EQ(leg.task_outcome, "failed: blocked");
  EXPECT_FALSE(spott_launch::ApplyTaskResult(Result("preempted"), features, leg));
}

}  // namespace
