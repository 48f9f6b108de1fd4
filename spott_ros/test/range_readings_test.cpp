// The one rule for impossible range readings (spott_ros/range_readings.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "spott_ros/range_readings.h"

namespace spott_ros {
namespace {

TEST(RangeReadings, NegativeAndBeyondMaxRangeBecomeDroppedOutTheRestStays) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> r{1.0, -0.5, nan, 6.5, 6.504, 7.0, inf, -inf, 0.0};
  EXPECT_EQ(DiscardImpossibleRanges(6.5, &r), 1);
  EXPECT_EQ(r[0], 1.0);
  EXPECT_TRUE(std::isnan(r[1]));
  EXPECT_TRUE(std::isnan(r[2]));
  EXPECT_EQ(r[3], 6.5);    // max range: no echo, a reading
  EXPECT_EQ(r[4], 6.504);  // within float rounding of max range
  EXPECT_TRUE(std::isnan(r[5]));
  EXPECT_TRUE(std::isnan(r[6]));
  EXPECT_TRUE(std::isnan(r[7]));
  EXPECT_EQ(r[8], 0.0);
  std::vector<double> fine{0.3, 2.0, nan};
  EXPECT_EQ(DiscardImpossibleRanges(6.5, &fine), -1);
  EXPECT_EQ(fine[1], 2.0);
}

}  // namespace
}  // namespace spott_ros
