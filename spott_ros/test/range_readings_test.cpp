// The rules for range rings, laser scans and their readings (spott_ros/range_readings.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
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

spott_msgs::RangeRing TwoSonars() {
  spott_msgs::RangeRing r;
  r.field_of_view = 0.5f;
  r.min_range = 0.1f;
  r.max_range = 4.0f;
  r.mounts.resize(2);
  r.mounts[1].y = 0.4;
  r.mounts[1].theta = M_PI / 2;
  r.ranges = {0.5f, NAN};
  return r;
}

TEST(RangeReadings, ARingIsRefusedByTheFieldThatMakesItUnusable) {
  EXPECT_EQ(RangeRingProblem(TwoSonars()), "");
  auto bad = TwoSonars();
  bad.max_range = NAN;  // every reading would be "no echo": a blind robot
  EXPECT_EQ(RangeRingProblem(bad).rfind("max_range: ", 0), 0u) << RangeRingProblem(bad);
  bad = TwoSonars();
  bad.min_range = 5.0f;
  EXPECT_EQ(RangeRingProblem(bad).rfind("min_range: ", 0), 0u);
  bad = TwoSonars();
  bad.field_of_view = INFINITY;
  EXPECT_EQ(RangeRingProblem(bad).rfind("field_of_view: ", 0), 0u);
  bad.field_of_view = 0.0f;
  EXPECT_EQ(RangeRingProblem(bad).rfind("field_of_view: ", 0), 0u);
  bad = TwoSonars();
  bad.mounts[1].theta = NAN;
  EXPECT_EQ(RangeRingProblem(bad), "mounts[1]: not finite or beyond 10 m of the base");
  bad = TwoSonars();
  bad.ranges.push_back(1.0f);
  EXPECT_EQ(RangeRingProblem(bad), "mounts: 2 mounts for 3 ranges");
}

TEST(RangeReadings, TheDiscardedReadingIsNamedWithItsIndexAndValue) {
  EXPECT_EQ(DiscardedReadingWhy(3, -0.5),
            "ranges[3] = -0.500000 is outside [0, max_range]: discarded as dropped out");
}

TEST(RangeReadings, AScanIsRefusedWithTheFieldThatMakesItUnusable) {
  sensor_msgs::LaserScan scan;
  scan.angle_min = -M_PI / 2;
  scan.angle_increment = M_PI / 180;
  scan.range_min = 0.05f;
  scan.range_max = 30.0f;
  scan.ranges.assign(181, 2.0f);
  EXPECT_EQ(LaserScanProblem(scan), "");
  auto refused = [&](auto change) {
    sensor_msgs::LaserScan s = scan;
    change(s);
    const std::string why = LaserScanProblem(s);
    return why.substr(0, why.find(':'));
  };
  EXPECT_EQ(refused([](auto& s) { s.angle_min = NAN; }), "angle_min");
  EXPECT_EQ(refused([](auto& s) { s.angle_min = 7.0f; }), "angle_min");
  EXPECT_EQ(refused([](auto& s) { s.angle_increment = 0.0f; }), "angle_increment");
  EXPECT_EQ(refused([](auto& s) { s.angle_increment = NAN; }), "angle_increment");
  EXPECT_EQ(refused([](auto& s) { s.angle_increment = 1e38f; }), "angle_increment");
  // Each step under half a turn, but 180 of them are not: the beams' directions would wrap.
  EXPECT_EQ(refused([](auto& s) { s.angle_increment = 0.5f; }), "angle_min/angle_increment");
  EXPECT_EQ(refused([](auto& s) { s.range_max = INFINITY; }), "range_max");
  EXPECT_EQ(refused([](auto& s) { s.range_max = -1.0f; }), "range_max");
  EXPECT_EQ(refused([](auto& s) { s.range_min = -1.0f; }), "range_min");
  EXPECT_EQ(refused([](auto& s) { s.range_min = NAN; }), "range_min");
  EXPECT_EQ(refused([](auto& s) { s.range_min = 40.0f; }), "range_min");
  EXPECT_EQ(refused([](auto& s) { s.ranges.clear(); }), "ranges");
  EXPECT_EQ(refused([](auto& s) {
              s.angle_increment = 1e-6f;
              s.ranges.assign(100001, 1.0f);
            }),
            "ranges");
  // A full turn from 0 (some lasers count 0 .. 2 pi) is fine; so are NaN and inf readings
  // (REP 117: each reading is judged by itself).
  EXPECT_EQ(refused([](auto& s) {
              s.angle_min = 0.0f;
              s.angle_increment = 2 * M_PI / 360;
              s.ranges.assign(360, 1.0f);
              s.ranges[0] = NAN;
              s.ranges[1] = INFINITY;
            }),
            "");
}

}  // namespace
}  // namespace spott_ros
