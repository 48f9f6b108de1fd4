#include "spott_ros/input_refusals.h"

#include <gtest/gtest.h>

namespace spott_ros {
namespace {

TEST(RefusalCounts, CountsPerTopicAndFieldKeepingTheLastReason) {
  RefusalCounts c;
  EXPECT_EQ(c.Add("initialpose", "pose.pose.position", "not finite"), 1u);
  EXPECT_EQ(c.Add("initialpose", "pose.pose.position", "still not finite"), 2u);
  EXPECT_EQ(c.Add("odom", "pose.pose", "not finite"), 1u);
  EXPECT_EQ(c.count("initialpose", "pose.pose.position"), 2u);
  EXPECT_EQ(c.count("odom", "pose.pose"), 1u);
  EXPECT_EQ(c.count("odom", "twist"), 0u);
  EXPECT_EQ(c.total(), 3u);
  EXPECT_EQ(c.causes().at("initialpose pose.pose.position").last_reason, "still not finite");
}

TEST(RefusalCounts, AProblemIsSplitIntoItsFieldAndItsReason) {
  EXPECT_EQ(
      SplitProblem("range_max: -1.000000 is not in (0, 1000) m"),
      std::make_pair(std::string("range_max"), std::string("-1.000000 is not in (0, 1000) m")));
  EXPECT_EQ(SplitProblem("mounts[2]: not finite: or beyond 10 m"),
            std::make_pair(std::string("mounts[2]"), std::string("not finite: or beyond 10 m")));
  EXPECT_EQ(SplitProblem("no field here"),
            std::make_pair(std::string("message"), std::string("no field here")));
}

TEST(RefusalCounts, StatusWarnsOnlyForRefusalsOfTheLastPeriodAndListsEveryCause) {
  RefusalCounts c;
  auto s = ToDiagnosticStatus("markov_localization", c, 0);
  EXPECT_EQ(s.level, diagnostic_msgs::DiagnosticStatus::OK);
  EXPECT_EQ(s.name, "markov_localization: input");
  EXPECT_TRUE(s.values.empty());
  c.Add("sonar", "ranges[3]", "negative range -1");
  s = ToDiagnosticStatus("markov_localization", c, 1);
  EXPECT_EQ(s.level, diagnostic_msgs::DiagnosticStatus::WARN);
  ASSERT_EQ(s.values.size(), 1u);
  EXPECT_EQ(s.values[0].key, "sonar ranges[3]");
  EXPECT_EQ(s.values[0].value, "1: negative range -1");
  s = ToDiagnosticStatus("markov_localization", c, 0);  // a quiet period: OK, the count kept
  EXPECT_EQ(s.level, diagnostic_msgs::DiagnosticStatus::OK);
  EXPECT_EQ(s.values.size(), 1u);
}

}  // namespace
}  // namespace spott_ros
