#include "cmd_vel_arbiter/arbiter.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace cmd_vel_arbiter {
namespace {

ArbiterParameters Params() {
  ArbiterParameters p;
  p.sources = {{"planner", 10, 0.5}, {"wander", 50, 0.5}, {"reflex", 100, 0.5}};
  p.max_linear_mps = 0.5;
  p.max_angular_rps = 1.0;
  return p;
}

Velocity V(double v, double w) { return Velocity{v, w}; }

SourceState StateOf(const Arbiter& a, const std::string& name) {
  for (const SourceStatus& s : a.Sources())
    if (s.name == name) return s.state;
  ADD_FAILURE() << "no source " << name;
  return SourceState::kIdle;
}

TEST(Arbiter, TheOnlySenderDrivesAndItsCommandsPassThrough) {
  Arbiter a(Params());
  std::string why;
  const Output out = a.Command("planner", V(0.3, 0.1), 0.0, &why);
  EXPECT_TRUE(why.empty());
  ASSERT_TRUE(out.publish);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.3);
  EXPECT_DOUBLE_EQ(out.command.angular_rps, 0.1);
  EXPECT_EQ(a.driver(), "planner");
  // The same command again is still passed on (the base driver wants a steady stream).
  EXPECT_TRUE(a.Command("planner", V(0.3, 0.1), 0.05, &why).publish);
}

TEST(Arbiter, HigherPriorityWinsAndTheLowerIsPreemptedThenResumes) {
  Arbiter a(Params());
  std::string why;
  a.Command("planner", V(0.3, 0.0), 0.0, &why);
  const Output w = a.Command("wander", V(0.1, 0.5), 0.1, &why);
  EXPECT_EQ(a.driver(), "wander");
  EXPECT_DOUBLE_EQ(w.command.angular_rps, 0.5);
  // The planner's commands no longer reach the wheels.
  const Output p = a.Command("planner", V(0.3, 0.0), 0.2, &why);
  EXPECT_FALSE(p.publish);
  EXPECT_EQ(StateOf(a, "planner"), SourceState::kPreempted);
  // wander falls silent: after its timeout the planner drives again.
  a.Command("planner", V(0.3, 0.0), 0.5, &why);
  const Output back = a.Command("planner", V(0.3, 0.0), 0.65, &why);
  EXPECT_EQ(a.driver(), "planner");
  EXPECT_TRUE(back.publish);
  EXPECT_DOUBLE_EQ(back.command.linear_mps, 0.3);
  EXPECT_EQ(StateOf(a, "wander"), SourceState::kTimedOut);
}

TEST(Arbiter, ASilentDriverIsTimedOutAndTheRobotStopsOnce) {
  Arbiter a(Params());
  std::string why;
  a.Command("planner", V(0.3, 0.2), 0.0, &why);
  EXPECT_FALSE(a.Update(0.4).publish);  // within the timeout
  const Output stop = a.Update(0.51);
  ASSERT_TRUE(stop.publish);
  EXPECT_DOUBLE_EQ(stop.command.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(stop.command.angular_rps, 0.0);
  EXPECT_EQ(a.driver(), "");
  EXPECT_EQ(StateOf(a, "planner"), SourceState::kTimedOut);
  EXPECT_FALSE(a.Update(0.6).publish);  // once
}

TEST(Arbiter, NonFiniteAndOverLimitCommandsAreRefusedCountedAndStopTheRobot) {
  Arbiter a(Params());
  std::string why;
  a.Command("planner", V(0.3, 0.0), 0.0, &why);
  Output out = a.Command("planner", V(std::numeric_limits<double>::quiet_NaN(), 0.0), 0.1, &why);
  EXPECT_NE(why.find("not finite"), std::string::npos);
  ASSERT_TRUE(out.publish);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.0);
  out = a.Command("planner", V(0.9, 0.0), 0.2, &why);
  EXPECT_NE(why.find("beyond the robot's"), std::string::npos);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.0);
  out = a.Command("planner", V(0.1, std::numeric_limits<double>::infinity()), 0.3, &why);
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(a.refused(), 3u);
  EXPECT_EQ(a.Sources().back().refused, 3u);  // the planner has the lowest priority
  // Exactly the limit is fine.
  out = a.Command("planner", V(0.5, -1.0), 0.4, &why);
  EXPECT_TRUE(why.empty());
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.5);
}

TEST(Arbiter, UnknownSourcesAreRefused) {
  Arbiter a(Params());
  std::string why;
  EXPECT_FALSE(a.Command("teleop", V(0.1, 0), 0, &why).publish);
  EXPECT_NE(why.find("unknown source"), std::string::npos);
}

TEST(Arbiter, ExclusiveTakeBlocksLowerSourcesEvenWhileTheHolderIsSilent) {
  Arbiter a(Params());
  std::string why, msg, pre;
  Output out;
  a.Command("planner", V(0.3, 0.0), 0.0, &why);
  ASSERT_TRUE(a.Take("wander", 0.1, &msg, &pre, &out));
  EXPECT_TRUE(pre.empty());
  // The planner is pre-empted at once and the robot stops until wander sends.
  ASSERT_TRUE(out.publish);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.0);
  EXPECT_EQ(StateOf(a, "planner"), SourceState::kPreempted);
  EXPECT_FALSE(a.Command("planner", V(0.3, 0.0), 0.2, &why).publish);
  EXPECT_EQ(a.exclusive_holder(), "wander");
  // Long after wander's timeout the planner still does not drive.
  a.Command("planner", V(0.3, 0.0), 5.0, &why);
  EXPECT_EQ(a.driver(), "");
  // On release the planner drives again.
  ASSERT_TRUE(a.Release("wander", 5.1, &msg, &out));
  EXPECT_EQ(a.driver(), "planner");
  ASSERT_TRUE(out.publish);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.3);
}

TEST(Arbiter, AHigherTakePreemptsTheHolderWhoGetsTheWheelsBackOnRelease) {
  Arbiter a(Params());
  std::string msg, pre, why;
  Output out;
  ASSERT_TRUE(a.Take("wander", 0.0, &msg, &pre, &out));
  EXPECT_FALSE(a.Take("planner", 0.0, &msg, &pre, &out));  // lower priority: refused
  EXPECT_NE(msg.find("held by 'wander'"), std::string::npos);
  ASSERT_TRUE(a.Take("reflex", 0.1, &msg, &pre, &out));
  EXPECT_EQ(pre, "wander");
  EXPECT_EQ(a.exclusive_holder(), "reflex");
  a.Command("wander", V(0.2, 0), 0.2, &why);
  EXPECT_EQ(a.driver(), "");
  EXPECT_EQ(StateOf(a, "wander"), SourceState::kPreempted);
  ASSERT_TRUE(a.Release("reflex", 0.3, &msg, &out));
  EXPECT_EQ(a.exclusive_holder(), "wander");
  EXPECT_EQ(a.driver(), "wander");
  EXPECT_FALSE(a.Release("reflex", 0.3, &msg, &out));
}

TEST(Arbiter, AHigherSourceMayDriveOverAnExclusiveHolder) {
  Arbiter a(Params());
  std::string msg, pre, why;
  Output out;
  ASSERT_TRUE(a.Take("wander", 0.0, &msg, &pre, &out));
  a.Command("wander", V(0.2, 0), 0.1, &why);
  const Output r = a.Command("reflex", V(-0.1, 0), 0.2, &why);
  EXPECT_EQ(a.driver(), "reflex");
  EXPECT_DOUBLE_EQ(r.command.linear_mps, -0.1);
}

TEST(Arbiter, SpeedLimitsScaleCommandsKeepingTheirCurvature) {
  Arbiter a(Params());
  std::string msg, why;
  Output out;
  ASSERT_TRUE(a.SetSpeedLimits(0.2, 0.0, "office", &msg, 0.0, &out));
  EXPECT_EQ(a.limits_reason(), "office");
  EXPECT_DOUBLE_EQ(a.max_angular_rps(), 1.0);
  out = a.Command("planner", V(0.4, 0.4), 0.1, &why);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.2);
  EXPECT_DOUBLE_EQ(out.command.angular_rps, 0.2);
  EXPECT_FALSE(a.SetSpeedLimits(0.9, 0.0, "too fast", &msg, 0.2, &out));
  EXPECT_FALSE(a.SetSpeedLimits(-1.0, 0.0, "negative", &msg, 0.2, &out));
  EXPECT_DOUBLE_EQ(a.max_linear_mps(), 0.2);
  ASSERT_TRUE(a.SetSpeedLimits(0.0, 0.0, "", &msg, 0.3, &out));
  EXPECT_DOUBLE_EQ(a.max_linear_mps(), 0.5);
  EXPECT_EQ(a.limits_reason(), "");
}

TEST(Arbiter, APressedFrontBumperStopsForwardMotionButAllowsBackingOffAndTurning) {
  Arbiter a(Params());
  std::string why;
  a.Command("planner", V(0.3, 0.2), 0.0, &why);
  Output out = a.SetContacts({0.2}, 0.05);  // front-left contact
  ASSERT_TRUE(out.publish);                 // the stop goes out at once
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(out.command.angular_rps, 0.2);
  EXPECT_TRUE(a.bumper_stop());
  out = a.Command("planner", V(-0.1, 0.0), 0.1, &why);  // backing off
  EXPECT_DOUBLE_EQ(out.command.linear_mps, -0.1);
  EXPECT_FALSE(a.bumper_stop());
  // A rear contact stops backing up but not going forward.
  a.SetContacts({M_PI}, 0.15);
  out = a.Command("planner", V(-0.1, 0.0), 0.2, &why);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.0);
  out = a.Command("planner", V(0.2, 0.0), 0.25, &why);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.2);
  EXPECT_GE(a.bumper_stops(), 2u);
}

TEST(Arbiter, ValidationNamesEveryBadParameter) {
  ArbiterParameters p = Params();
  p.sources.push_back({"Bad-Name", 10, 0.0});
  p.max_linear_mps = 0.0;
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_NE(v[0].find("[a-z0-9_]+"), std::string::npos);
  EXPECT_NE(v[1].find("priority 10 is shared"), std::string::npos);
  EXPECT_NE(v[2].find("timeout_s"), std::string::npos);
  EXPECT_NE(v[3].find("limits/max_linear_mps"), std::string::npos);
  EXPECT_THROW(Arbiter{p}, std::invalid_argument);
}

TEST(Arbiter, RevisionChangesWithTheDriver) {
  Arbiter a(Params());
  std::string why;
  const auto r0 = a.revision();
  a.Command("planner", V(0.1, 0), 0.0, &why);
  const auto r1 = a.revision();
  EXPECT_GT(r1, r0);
  a.Command("planner", V(0.2, 0), 0.1, &why);
  EXPECT_EQ(a.revision(), r1);  // same driver, same states
}

}  // namespace
}  // namespace cmd_vel_arbiter
