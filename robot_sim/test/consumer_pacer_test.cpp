#include "robot_sim/consumer_pacer.h"

#include <gtest/gtest.h>

namespace robot_sim {
namespace {

PacerParameters Params() {
  PacerParameters p;
  p.topics = {"localization_status", "harmonic_planner/status"};
  p.max_lag_s = 0.5;
  p.max_hold_s = 2.0;
  return p;
}

TEST(ConsumerPacer, ConsumersNotYetHeardFromAreNotWaitedFor) {
  ConsumerPacer pacer(Params());
  EXPECT_FALSE(pacer.Hold(100.0, 0.0));
}

TEST(ConsumerPacer, HoldsWhileAConsumerLagsAndGoesOnWhenItCatchesUp) {
  ConsumerPacer pacer(Params());
  pacer.Observe(0, 10.0);
  pacer.Observe(1, 10.0);
  EXPECT_FALSE(pacer.Hold(10.4, 0.0));
  EXPECT_TRUE(pacer.Hold(10.6, 0.1));  // localization 0.6 s behind
  EXPECT_NEAR(pacer.lag_s(), 0.6, 1e-12);
  EXPECT_TRUE(pacer.Hold(10.6, 0.3));
  pacer.Observe(0, 10.3);
  pacer.Observe(1, 10.55);
  EXPECT_FALSE(pacer.Hold(10.6, 0.4));
  EXPECT_NEAR(pacer.held_s(), 0.3, 1e-12);  // from 0.1 to 0.4
}

TEST(ConsumerPacer, ASilentConsumerIsGivenUpOnUntilItPublishesAgain) {
  ConsumerPacer pacer(Params());
  pacer.Observe(0, 5.0);
  EXPECT_TRUE(pacer.Hold(6.0, 10.0));
  EXPECT_TRUE(pacer.Hold(6.0, 11.9));
  EXPECT_FALSE(pacer.Hold(6.0, 12.1));  // held 2.1 s of wall time: dead, or starved
  EXPECT_EQ(pacer.TakeGivenUp(), std::vector<std::string>{"localization_status"});
  EXPECT_TRUE(pacer.TakeGivenUp().empty());
  EXPECT_FALSE(pacer.Hold(60.0, 13.0));
  pacer.Observe(0, 59.0);  // back: waited for again
  EXPECT_TRUE(pacer.Hold(60.0, 14.0));
}

TEST(ConsumerPacer, StampsNeverGoBack) {
  ConsumerPacer pacer(Params());
  pacer.Observe(0, 5.0);
  pacer.Observe(0, 3.0);  // an old message arriving late
  EXPECT_FALSE(pacer.Hold(5.4, 0.0));
}

TEST(ConsumerPacer, ValidationNamesTheParameters) {
  PacerParameters p = Params();
  p.max_lag_s = 0.0;
  p.topics.push_back("");
  EXPECT_EQ(ValidateParameters(p).size(), 2u);
}

}  // namespace
}  // namespace robot_sim
