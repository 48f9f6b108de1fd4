// The heading from rectilinear walls: straight runs of a range profile (QUADRIS: 64 samples,
// 5 mm noise) and the correction their deviation from the lattice gives; the tracker turning
// map -> odom by it about the robot.
#include "markov_localization/wall_lattice_heading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "markov_localization/sensed_map_tracker.h"
#include "spott_map/pose_algebra.h"

namespace markov_localization {
namespace {

using spott_map::Pose2;
using spott_map::Vec2;

constexpr double kDeg = M_PI / 180.0;

// `n` samples from `a` to `b` with 5 mm noise across the line.
std::vector<Vec2> Wall(const Vec2& a, const Vec2& b, int n, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 0.005);
  const Vec2 u = (b - a).normalized(), normal(-u.y(), u.x());
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i) points.push_back(a + (b - a) * (i / (n - 1.0)) + noise(rng) * normal);
  return points;
}

Vec2 Heading(double yaw) { return Vec2(std::cos(yaw), std::sin(yaw)); }

// The defaults with a 10 s window of lines.
WallLatticeParameters TenSeconds() {
  WallLatticeParameters p;
  p.window_s = 10.0;
  return p;
}

TEST(FitProfileLines, AStraightWallIsOneLineAlongIt) {
  std::mt19937 rng(1);
  const Vec2 a(1.0, 2.0);
  const auto points = Wall(a, a + 1.5 * Heading(92.0 * kDeg), 64, rng);
  const auto lines = FitProfileLines(3.0, points, WallLatticeParameters{});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NEAR(lines[0].direction_rad, 92.0 * kDeg, 0.2 * kDeg);
  EXPECT_NEAR(lines[0].length_m, 1.5, 0.05);
  EXPECT_EQ(lines[0].points, 64);
  EXPECT_DOUBLE_EQ(lines[0].time_s, 3.0);
}

TEST(FitProfileLines, ACornerSplitsIntoItsTwoWalls) {
  std::mt19937 rng(2);
  auto points = Wall(Vec2(0.0, 1.0), Vec2(1.0, 1.0), 32, rng);
  const auto second = Wall(Vec2(1.0, 1.0), Vec2(1.0, 0.0), 32, rng);
  points.insert(points.end(), second.begin() + 1, second.end());
  const auto lines = FitProfileLines(0.0, points, WallLatticeParameters{});
  ASSERT_EQ(lines.size(), 2u);
  // A line has no sense: its direction is compared modulo pi.
  EXPECT_NEAR(std::remainder(lines[0].direction_rad, M_PI), 0.0, 0.5 * kDeg);
  EXPECT_NEAR(std::remainder(lines[1].direction_rad - M_PI / 2, M_PI), 0.0, 0.5 * kDeg);
}

TEST(FitProfileLines, ADrumGapsAndShortRunsAreNoLines) {
  // A drum of 0.3 m radius seen over 100 degrees of its face: no chord of it is straight.
  std::vector<Vec2> drum;
  for (int i = 0; i < 64; ++i) {
    const double a = (-50.0 + 100.0 * i / 63.0) * kDeg;
    drum.push_back(Vec2(2.0, 0.0) - 0.3 * Heading(a));
  }
  EXPECT_TRUE(FitProfileLines(0.0, drum, WallLatticeParameters{}).empty());
  // Two 0.3 m pieces of one wall 0.3 m apart: each too short; the gap is not bridged.
  std::mt19937 rng(3);
  auto pieces = Wall(Vec2(0.0, 1.0), Vec2(0.3, 1.0), 30, rng);
  const auto far = Wall(Vec2(0.6, 1.0), Vec2(0.9, 1.0), 30, rng);
  pieces.insert(pieces.end(), far.begin(), far.end());
  EXPECT_TRUE(FitProfileLines(0.0, pieces, WallLatticeParameters{}).empty());
  // A NaN sample breaks a run too.
  auto broken = Wall(Vec2(0.0, 1.0), Vec2(0.7, 1.0), 40, rng);
  broken[20] = Vec2(NAN, NAN);
  EXPECT_TRUE(FitProfileLines(0.0, broken, WallLatticeParameters{}).empty());
  broken[20] = Vec2(0.7 * 20 / 39.0, 1.0);
  EXPECT_EQ(FitProfileLines(0.0, broken, WallLatticeParameters{}).size(), 1u);
}

TEST(WallLatticeHeading, WallsOffTheLatticeByTheHeadingsErrorGiveItBack) {
  // The odometry's heading 2.5 deg off: walls along x and y come out 2.5 deg turned in odom.
  std::mt19937 rng(4);
  WallLatticeHeading lattice{TenSeconds()};
  const double error = 2.5 * kDeg;
  lattice.AddProfile(1.0, Wall(Vec2(0, 1), Vec2(0, 1) + 1.2 * Heading(error), 64, rng));
  lattice.AddProfile(2.0, Wall(Vec2(3, 0), Vec2(3, 0) + 0.8 * Heading(M_PI / 2 + error), 40, rng));
  // A crate turned 23 deg and a line 3.8 deg off (inside the gate, not agreeing): left out.
  lattice.AddProfile(3.0, Wall(Vec2(5, 5), Vec2(5, 5) + 1.0 * Heading(23.0 * kDeg), 40, rng));
  lattice.AddProfile(3.0, Wall(Vec2(7, 5), Vec2(7, 5) + 0.6 * Heading(-3.8 * kDeg), 40, rng));
  const WallLatticeCorrection c = lattice.Estimate(4.0, 0.0);
  ASSERT_TRUE(c.ok) << c.why;
  EXPECT_EQ(c.lines, 4);
  EXPECT_EQ(c.agreeing, 2);
  EXPECT_NEAR(c.dyaw, -error, 0.15 * kDeg);
  EXPECT_NEAR(c.length_m, 2.0, 0.1);
  // map -> odom already turned back: nothing left to correct.
  EXPECT_NEAR(lattice.Estimate(4.0, -error).dyaw, 0.0, 0.15 * kDeg);
  // The lattice turned by axis: the same lines are 2.5 deg off a 10 deg axis when map -> odom
  // turns them by 10 deg.
  WallLatticeParameters turned = TenSeconds();
  turned.axis_rad = 10.0 * kDeg;
  WallLatticeHeading other{turned};
  other.AddProfile(1.0, Wall(Vec2(0, 1), Vec2(0, 1) + 1.2 * Heading(error), 64, rng));
  EXPECT_NEAR(other.Estimate(1.0, 10.0 * kDeg).dyaw, -error, 0.15 * kDeg);
}

TEST(WallLatticeHeading, TooLittleAgreeingLineOrOldLinesOrOffCorrectNothing) {
  std::mt19937 rng(5);
  WallLatticeHeading lattice{TenSeconds()};
  lattice.AddProfile(1.0, Wall(Vec2(0, 1), Vec2(0.7, 1), 40, rng));  // 0.7 m < min_total_m
  EXPECT_FALSE(lattice.Estimate(1.5, 0.0).ok);
  lattice.AddProfile(2.0, Wall(Vec2(0, 2), Vec2(0.7, 2), 40, rng));
  EXPECT_TRUE(lattice.Estimate(2.5, 0.0).ok);
  const WallLatticeCorrection late = lattice.Estimate(11.5, 0.0);  // the first one left
  EXPECT_FALSE(late.ok);
  EXPECT_EQ(late.lines, 1);
  // Off: profiles are not kept.
  WallLatticeParameters off;
  off.enabled = false;
  WallLatticeHeading none{off};
  none.AddProfile(1.0, Wall(Vec2(0, 1), Vec2(1.5, 1), 64, rng));
  EXPECT_EQ(none.lines(), 0u);
  EXPECT_FALSE(none.Estimate(1.0, 0.0).ok);
}

TEST(WallLatticeHeading, ParametersAreValidated) {
  WallLatticeParameters p;
  EXPECT_TRUE(ValidateParameters(p).empty());
  p.gate_rad = M_PI / 4;  // halfway between two lattice directions: every line would vote
  p.min_points = 2;
  p.max_rms_m = 0.0;
  p.period_s = 0.0;
  EXPECT_EQ(ValidateParameters(p).size(), 4u);
  EXPECT_THROW(WallLatticeHeading{p}, std::invalid_argument);
  SensedMapTrackerParameters t;
  t.wall_lattice.break_m = -1.0;
  const auto errors = ValidateParameters(t);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0], "wall_lattice/break_m must be > 0");
}

TEST(SensedMapTracker, TheWallLatticeTurnsTheHeadingAboutTheRobot) {
  // The robot at (4, 2) in the map; odometry's heading 3 deg off (map -> odom turned -3 deg
  // too little). A wall along the map's x axis seen by the profile comes out 3 deg turned.
  std::mt19937 rng(6);
  const double error = 3.0 * kDeg;
  const Pose2 map_to_odom{0.0, 0.0, 0.0};
  const Pose2 odom_robot{4.0, 2.0, error};
  SensedMapTracker tracker(SensedMapTrackerParameters{}, map_to_odom);
  EXPECT_FALSE(tracker.LatticeDue(1.0));  // every 2 s
  EXPECT_TRUE(tracker.LatticeDue(2.0));
  tracker.AddProfile(5.0, Wall(Vec2(3.5, 3.0), Vec2(3.5, 3.0) + 1.5 * Heading(error), 64, rng));
  const WallLatticeCorrection turn = tracker.TurnToLattice(6.0, odom_robot);
  EXPECT_TRUE(turn.applied) << turn.why;
  EXPECT_FALSE(tracker.LatticeDue(7.0));
  const Pose2 robot = spott_map::Compose(tracker.map_to_odom(), odom_robot);
  EXPECT_NEAR(robot.x, 4.0, 1e-9);
  EXPECT_NEAR(robot.y, 2.0, 1e-9);
  EXPECT_NEAR(robot.yaw, 0.0, 0.15 * kDeg);
  // Off: the heading is the odometry's.
  SensedMapTrackerParameters off;
  off.wall_lattice.enabled = false;
  SensedMapTracker plain(off, map_to_odom);
  plain.AddProfile(5.0, Wall(Vec2(3.5, 3.0), Vec2(3.5, 3.0) + 1.5 * Heading(error), 64, rng));
  EXPECT_FALSE(plain.LatticeDue(10.0));
  EXPECT_FALSE(plain.TurnToLattice(6.0, odom_robot).applied);
  EXPECT_DOUBLE_EQ(plain.map_to_odom().yaw, 0.0);
}

}  // namespace
}  // namespace markov_localization
