// The random motion before the first active choice (Wanderer): in a closed 2 m corridor with
// a simulated 24-sonar ring it must keep driving (turning at the ends) without touching a wall.
#include <gtest/gtest.h>

#include <cmath>

#include "markov_localization/map_model.h"
#include "markov_localization/markov_grid.h"
#include "markov_localization/sensor_model.h"
#include "markov_localization/wander.h"

namespace markov_localization {
namespace {

// A corridor from x = 1 to 21 m, y = 1 to 3 m, walls all around, 5 cm cells.
MapModel Corridor() {
  const double res = 0.05;
  const int w = 440, h = 80;
  std::vector<std::int8_t> data(static_cast<std::size_t>(w) * h, 0);
  for (int iy = 0; iy < h; ++iy)
    for (int ix = 0; ix < w; ++ix) {
      const double x = (ix + 0.5) * res, y = (iy + 0.5) * res;
      if (x < 1.0 || x > 21.0 || y < 1.0 || y > 3.0) data[iy * w + ix] = 100;
    }
  return MapModel::FromOccupancy(Vec2(0, 0), w, h, res, data, 50, 0.0);
}

double WallDistance(const Pose2& p) {
  return std::min({p.x - 1.0, 21.0 - p.x, p.y - 1.0, 3.0 - p.y});
}

std::vector<double> Ring(const MapModel& map, const std::vector<double>& angles, const Pose2& p,
                         double offset, double max_range) {
  std::vector<double> r;
  for (double a : angles) {
    const double heading = p.yaw + a;
    const Vec2 from = p.Position() + offset * Vec2(std::cos(heading), std::sin(heading));
    r.push_back(map.RayCast(from, heading, max_range));
  }
  return r;
}

TEST(Wander, DrivesUpAndDownAClosedCorridorWithoutTouchingAWall) {
  const MapModel map = Corridor();
  const auto angles = SonarRingAngles(24);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    Wanderer wander(WanderParameters{}, seed);
    Pose2 p{3.0, 2.3, 0.7};  // off-centre, heading towards the north wall
    double driven = 0.0, min_clearance = 1e9, min_x = p.x, max_x = p.x;
    const double dt = 0.1;
    for (int step = 0; step < 1500; ++step) {  // 150 s
      const auto c = wander.Step(angles, Ring(map, angles, p, 0.25, 5.0), 5.0, p.yaw);
      ASSERT_GE(c.linear_mps, 0.0);
      ASSERT_LE(c.linear_mps, WanderParameters{}.max_speed_mps + 1e-9);
      p.x += c.linear_mps * dt * std::cos(p.yaw);
      p.y += c.linear_mps * dt * std::sin(p.yaw);
      p.yaw = std::remainder(p.yaw + c.angular_rps * dt, 2 * M_PI);
      driven += c.linear_mps * dt;
      min_clearance = std::min(min_clearance, WallDistance(p));
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
    }
    // The B21's radius is 0.26 m: its hull never met a wall.
    EXPECT_GT(min_clearance, 0.3) << "seed " << seed;
    // It kept moving (ten metres take well under a minute) and turned at the corridor's ends.
    EXPECT_GT(driven, 25.0) << "seed " << seed;
    EXPECT_LT(min_x, 4.0) << "seed " << seed;
    EXPECT_GT(max_x, 18.0) << "seed " << seed;
  }
}

TEST(Wander, AWallAheadStopsTheRobotAndTurnsItToAFreeDirection) {
  const auto angles = SonarRingAngles(24);  // beam 0 ahead, 15 degrees apart
  std::vector<double> ranges(24, 1.0);
  ranges[0] = ranges[1] = ranges[23] = 0.3;  // wall ahead
  ranges[12] = 5.0;                          // free behind (no echo)
  Wanderer wander(WanderParameters{}, 7);
  const auto c = wander.Step(angles, ranges, 5.0, 0.0);
  EXPECT_EQ(c.linear_mps, 0.0);
  ASSERT_TRUE(wander.heading());
  EXPECT_NEAR(std::abs(*wander.heading()), M_PI, 1e-9);  // the only free direction
  EXPECT_NEAR(std::abs(c.angular_rps), WanderParameters{}.max_turn_rps, 1e-9);
}

TEST(Wander, ADroppedOutSonarIsNotFreeSpace) {
  const auto angles = SonarRingAngles(24);
  std::vector<double> ranges(24, 0.3);  // walls all around ...
  ranges[12] = 5.0;                     // ... but behind
  ranges[0] = std::nan("");             // the sonar ahead dropped out
  Wanderer wander(WanderParameters{}, 7);
  const auto c = wander.Step(angles, ranges, 5.0, 0.0);
  EXPECT_EQ(c.linear_mps, 0.0) << "drove towards a sonar that reads nothing";
  ASSERT_TRUE(wander.heading());
  EXPECT_NEAR(std::abs(*wander.heading()), M_PI, 1e-9);
}

TEST(Wander, AfterStallStepsWithoutProgressItTurnsBack) {
  const auto angles = SonarRingAngles(24);
  std::vector<double> ranges(24, 0.6);
  ranges[0] = 5.0;   // ahead: the most open (a doorway it cannot pass)
  ranges[12] = 3.9;  // behind: open, less so
  ranges[13] = 3.5;
  WanderParameters p;
  p.stall_steps = 10;
  Wanderer wander(p, 3);
  // The first ring sets the place; nine more without progress: still ahead.
  for (int i = 0; i < 10; ++i) wander.Step(angles, ranges, 5.0, 1.0, 2.0, 0.0);
  ASSERT_TRUE(wander.heading());
  EXPECT_NEAR(*wander.heading(), 0.0, 0.3);
  wander.Step(angles, ranges, 5.0, 1.05, 2.0, 0.0);  // 5 cm: no progress, the tenth
  ASSERT_TRUE(wander.heading());
  EXPECT_GT(std::abs(*wander.heading()), M_PI / 2);  // a direction behind
  // Progress resets the count.
  Wanderer moving(p, 3);
  for (int i = 0; i < 30; ++i) moving.Step(angles, ranges, 5.0, 0.35 * i, 2.0, 0.0);
  EXPECT_NEAR(*moving.heading(), 0.0, 0.3);
}

TEST(Wander, BadParametersAreNamed) {
  WanderParameters p;
  p.slow_distance_m = 0.2;  // below stop_distance_m
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("slow_distance_m"), std::string::npos);
  EXPECT_THROW(Wanderer(p, 1), std::invalid_argument);
}

}  // namespace
}  // namespace markov_localization
