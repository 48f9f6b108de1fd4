// The sensed-map tracker (SPOTT's LOCALIZE_THE_ROBOT without an a priori map): echoes made by
// the specular-wall physics from the true pose, odometry that drifted, and what the fix recovers.
#include "markov_localization/sensed_map_tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "spott_map/pose_algebra.h"

namespace markov_localization {
namespace {

using spott_map::Pose2;
using spott_map::Segment;
using spott_map::Vec2;

constexpr double kFov = 25.0 * M_PI / 180.0;  // the Nomad 200's sonar cone

// The Nomad's ring: 16 transducers, 22.5 degrees apart, 0.2 m from the centre.
std::vector<Pose2> Ring() {
  std::vector<Pose2> mounts;
  for (int i = 0; i < 16; ++i) {
    const double a = i * M_PI / 8.0;
    mounts.push_back({0.2 * std::cos(a), 0.2 * std::sin(a), a});
  }
  return mounts;
}

// A wall echoes from the foot of the perpendicular when it lies in the cone and on the wall.
std::vector<double> Ranges(const Pose2& truth, const std::vector<Pose2>& mounts,
                           const std::vector<Segment>& walls, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<double> ranges;
  for (const Pose2& m : mounts) {
    const Pose2 t = spott_map::Compose(truth, m);
    const Vec2 beam(std::cos(t.yaw), std::sin(t.yaw));
    double best = 6.5;
    for (const Segment& w : walls) {
      const Vec2 u = w.Direction(), n(-u.y(), u.x());
      const double d = n.dot(t.Position() - w.a);
      const Vec2 foot = t.Position() - d * n;
      const double along = u.dot(foot - w.a);
      if (along < 0.0 || along > w.Length()) continue;
      const Vec2 toward = (d >= 0 ? -1.0 : 1.0) * n;
      if (std::acos(std::min(1.0, beam.dot(toward))) > kFov / 2) continue;
      best = std::min(best, std::abs(d) + noise(rng));
    }
    ranges.push_back(best);
  }
  return ranges;
}

// The odometry's frame off from the map by (dx, dy) and dyaw turned about `c`: the pose T with
// T(p) = R(dyaw) (p - c) + c + (dx, dy).
Pose2 AboutPoint(const Vec2& c, double dx, double dy, double dyaw) {
  const double cs = std::cos(dyaw), sn = std::sin(dyaw);
  return {c.x() + dx - (cs * c.x() - sn * c.y()), c.y() + dy - (sn * c.x() + cs * c.y()), dyaw};
}

// Drives along y = 1 in a 2 m corridor from x = 2 to 2 + distance at 0.25 m steps, feeding the
// tracker rings at 4 Hz taken at the true pose, placed by `odom_error` (the odometry's frame is
// off from the map by it: map -> odom is believed identity).
SensedMapTracker Drive(const std::vector<Segment>& walls, const Pose2& odom_error, double distance,
                       double* now, bool correct_heading = true) {
  SensedMapTrackerParameters p;
  p.correct_heading = correct_heading;
  SensedMapTracker tracker(p, Pose2{});
  tracker.SetSegments(walls);
  std::mt19937 rng(7);
  const std::vector<Pose2> mounts = Ring();
  for (double x = 2.0; x <= 2.0 + distance; x += 0.25) {
    const Pose2 truth{x, 1.0, 0.0};
    // odom = error^-1 * truth: odometry places the robot as if map -> odom were the identity.
    const Pose2 odom = spott_map::Compose(spott_map::MapToOdom(Pose2{}, odom_error), truth);
    tracker.AddRing(*now, odom, mounts, Ranges(truth, mounts, walls, rng), 0.15, 6.5, kFov);
    *now += 0.25;
  }
  return tracker;
}

const std::vector<Segment> kCorridor = {{{0.0, 0.0}, {20.0, 0.0}}, {{0.0, 2.0}, {20.0, 2.0}}};

TEST(SensedMapTracker, ACorridorsWallsFixTheSideAndTheHeadingNotTheWayAlong) {
  double now = 0.0;
  // The odometry is 0.15 m to the side, 0.3 m along and 2 degrees off (in the window's middle).
  const Pose2 error = AboutPoint({3.25, 1.0}, 0.3, 0.15, 2.0 * M_PI / 180.0);
  SensedMapTracker tracker = Drive(kCorridor, error, 2.5, &now);
  const Pose2 odom_now =
      spott_map::Compose(spott_map::MapToOdom(Pose2{}, error), Pose2{4.5, 1.0, 0.0});
  const SensedMapFix fix = tracker.Localize(now, odom_now);
  ASSERT_TRUE(fix.applied) << fix.why;
  EXPECT_EQ(fix.constrained, 2);
  const Pose2 estimate = spott_map::Compose(tracker.map_to_odom(), odom_now);
  EXPECT_NEAR(estimate.y, 1.0, 0.02);
  EXPECT_NEAR(estimate.yaw, 0.0, 0.005);
  // Along the corridor nothing tells: the estimate keeps odometry's x error (the corrected
  // heading swings it by a few millimetres about the robot only).
  const Pose2 before = spott_map::Compose(Pose2{}, odom_now);
  EXPECT_NEAR(estimate.x, before.x, 0.02);
  EXPECT_GT(std::abs(estimate.x - 4.5), 0.2);
  EXPECT_LT(fix.rms_after_m, 0.02);
  EXPECT_GT(fix.rms_before_m, 0.1);
}

TEST(SensedMapTracker, AnEndWallFixesTheWayAlongToo) {
  std::vector<Segment> walls = kCorridor;
  walls.push_back({{6.0, 0.0}, {6.0, 2.0}});  // the corridor ends 1.5 m ahead of the robot
  double now = 0.0;
  const Pose2 error = AboutPoint({3.25, 1.0}, 0.2, -0.15, -1.5 * M_PI / 180.0);
  SensedMapTracker tracker = Drive(walls, error, 2.5, &now);
  const Pose2 odom_now =
      spott_map::Compose(spott_map::MapToOdom(Pose2{}, error), Pose2{4.5, 1.0, 0.0});
  const SensedMapFix fix = tracker.Localize(now, odom_now);
  ASSERT_TRUE(fix.applied) << fix.why;
  EXPECT_EQ(fix.constrained, 3);
  const Pose2 estimate = spott_map::Compose(tracker.map_to_odom(), odom_now);
  EXPECT_NEAR(estimate.x, 4.5, 0.03);
  EXPECT_NEAR(estimate.y, 1.0, 0.02);
  EXPECT_NEAR(estimate.yaw, 0.0, 0.005);
}

TEST(SensedMapTracker, ByDefaultOnlyTheShiftIsFixedNotTheHeading) {
  double now = 0.0;
  const Pose2 error = AboutPoint({3.25, 1.0}, 0.3, 0.15, 2.0 * M_PI / 180.0);
  SensedMapTracker tracker = Drive(kCorridor, error, 2.5, &now, /*correct_heading=*/false);
  const Pose2 odom_now =
      spott_map::Compose(spott_map::MapToOdom(Pose2{}, error), Pose2{4.5, 1.0, 0.0});
  const SensedMapFix fix = tracker.Localize(now, odom_now);
  ASSERT_TRUE(fix.applied) << fix.why;
  EXPECT_EQ(fix.constrained, 1);  // across the corridor only
  EXPECT_EQ(fix.dyaw, 0.0);
  const Pose2 estimate = spott_map::Compose(tracker.map_to_odom(), odom_now);
  EXPECT_NEAR(estimate.yaw, -2.0 * M_PI / 180.0, 1e-9);  // odometry's heading, kept
  // The shift puts the echoes' centroid back between the walls: at the window's middle the
  // estimate is right across the corridor, at its end off by the heading's 2 degrees x 1.25 m.
  EXPECT_NEAR(estimate.y, 1.0 - 1.25 * std::sin(2.0 * M_PI / 180.0), 0.02);
}

TEST(SensedMapTracker, WithoutSegmentsOrEchoesNothingMoves) {
  double now = 0.0;
  SensedMapTracker tracker = Drive(kCorridor, Pose2{0.0, 0.2, 0.0}, 2.0, &now);
  tracker.SetSegments({});
  SensedMapFix fix = tracker.Localize(now, Pose2{4.0, 0.8, 0.0});
  EXPECT_FALSE(fix.applied);
  EXPECT_EQ(fix.why, "no sensed segment to match");
  // Segments beside which the robot never drove: its echoes match none of them.
  tracker.SetSegments({{{50.0, 0.0}, {60.0, 0.0}}});
  fix = tracker.Localize(now, Pose2{4.0, 0.8, 0.0});
  EXPECT_FALSE(fix.applied);
  EXPECT_EQ(fix.matched, 0);
  EXPECT_NEAR(tracker.map_to_odom().y, 0.0, 1e-12);
}

TEST(SensedMapTracker, AnErrorBeyondTheGateIsNotPulledToAWrongWall) {
  double now = 0.0;
  // 0.6 m to the side in a 2 m corridor: every echo is 0.6 m off its wall, beyond the gate.
  SensedMapTracker tracker = Drive(kCorridor, Pose2{0.0, 0.6, 0.0}, 2.5, &now);
  const SensedMapFix fix = tracker.Localize(now, Pose2{4.5, 0.4, 0.0});
  EXPECT_FALSE(fix.applied);
  EXPECT_NEAR(tracker.map_to_odom().y, 0.0, 1e-12);
}

TEST(SensedMapTracker, TheWindowKeepsOnlyRecentEchoesAndTheFixIsDueByPeriod) {
  SensedMapTrackerParameters p;
  p.window_s = 2.0;
  p.period_s = 10.0;
  SensedMapTracker tracker(p, Pose2{});
  const std::vector<Pose2> mounts = Ring();
  const std::vector<double> ranges(16, 1.0);
  tracker.AddRing(0.0, Pose2{}, mounts, ranges, 0.15, 6.5, kFov);
  tracker.AddRing(3.0, Pose2{}, mounts, ranges, 0.15, 6.5, kFov);
  EXPECT_EQ(tracker.echoes(), 16u);  // the ring of t = 0 fell out of the 2 s window
  EXPECT_FALSE(tracker.Due(9.0));
  EXPECT_TRUE(tracker.Due(10.0));
  tracker.Localize(10.0, Pose2{});
  EXPECT_FALSE(tracker.Due(15.0));
  // Dropped out (NaN), clamped (at the minimum) and no echo (at the maximum) are skipped.
  tracker.Reset(Pose2{}, 20.0);
  std::vector<double> bad(16, 6.5);
  bad[0] = std::nan("");
  bad[1] = 0.15;
  bad[2] = 1.2;
  tracker.AddRing(20.0, Pose2{}, mounts, bad, 0.15, 6.5, kFov);
  EXPECT_EQ(tracker.echoes(), 1u);
}

TEST(SensedMapTracker, BadParametersAreRefusedByName) {
  SensedMapTrackerParameters p;
  p.period_s = 0.0;
  p.min_echoes = 2;
  p.huber_m = std::nan("");
  EXPECT_EQ(ValidateParameters(p).size(), 3u);
  try {
    SensedMapTracker t(p, Pose2{});
    FAIL() << "constructed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("period_s must be > 0"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("min_echoes must be >= 3"), std::string::npos);
  }
  EXPECT_TRUE(ValidateParameters(SensedMapTrackerParameters{}).empty());
}

}  // namespace
}  // namespace markov_localization
