#include "spott_map/pose_text.h"

#include <gtest/gtest.h>

#include <string>

namespace spott_map {
namespace {

TEST(PoseText, ReadsThreeNumbers) {
  const auto pose = ParsePoseText("  1.5 -2 0.25\n");
  ASSERT_TRUE(pose.has_value());
  EXPECT_DOUBLE_EQ(pose->x, 1.5);
  EXPECT_DOUBLE_EQ(pose->y, -2.0);
  EXPECT_DOUBLE_EQ(pose->yaw, 0.25);
}

TEST(PoseText, RefusesWithWhy) {
  struct Case {
    std::string text, why;
  };
  for (const Case& c :
       {Case{"", "only 0 of 3"}, Case{"1 2", "only 2 of 3"}, Case{"1 x 3", "number 2 at column 3"},
        Case{"1 2 3 4", "column 7"}, Case{"1 2 nan", "number 3 is not finite"},
        Case{"1e999 2 3", "not finite"}, Case{"1,2,3", "number 1 at column 1"},
        Case{std::string("1 2 3\0 4", 9), "NUL"}}) {
    std::string error;
    EXPECT_FALSE(ParsePoseText(c.text, &error).has_value()) << c.text;
    EXPECT_NE(error.find(c.why), std::string::npos) << c.text << ": " << error;
    EXPECT_NE(error.find("expected 'x y yaw'"), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace spott_map
