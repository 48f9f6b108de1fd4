// Sensor updates with many beams (a 180-beam laser scan, a laser and a sonar ring together):
// the product of 180 per-beam factors spans hundreds of orders of magnitude, far beyond a
// float's; the grid applies the beams in groups whose products cannot underflow, so the belief
// stays finite and normalized, and a belief that no state explains any more is reset loudly.
#include <gtest/gtest.h>

#include <numeric>

#include "test_helpers.h"

namespace markov_localization {
namespace {

std::vector<double> LaserAngles(int beams) {
  std::vector<double> a;
  for (int i = 0; i < beams; ++i) a.push_back(-M_PI / 2 + M_PI * i / (beams - 1));
  return a;
}

struct Bonn25 {
  Bonn25() : world(testing::LoadWorld("bonn_department")) {
    MapModelParameters mp;
    mp.resolution_m = 0.25;
    map = MapModel::FromWorld(world, mp);
    laser.beam_angles_rad = LaserAngles(180);
    laser.max_range_m = 8.0;
    laser.range_bin_m = 0.125;
    grid.angular_resolution_rad = 2 * M_PI / 72;
  }
  spott_map::World world;
  MapModel map;
  SensorModelParameters laser;
  MarkovGridParameters grid;
};

// Every probability finite and >= 0, the states' sum 1.
::testing::AssertionResult FiniteAndNormalized(const MarkovGrid& g) {
  const std::vector<float> p = g.Dense();
  double sum = 0.0;
  for (float v : p) {
    if (!std::isfinite(v) || v < 0.0f) return ::testing::AssertionFailure() << "P = " << v;
    sum += v;
  }
  if (std::abs(sum - 1.0) > 1e-3) return ::testing::AssertionFailure() << "sum " << sum;
  return ::testing::AssertionSuccess();
}

TEST(ManyBeams, ScansOf180BeamsNeverGiveANonFiniteBelief) {
  Bonn25 b;
  SensorModel sensor(b.map, 72, b.laser);
  for (bool selective : {true, false}) {
    MarkovGridParameters gp = b.grid;
    gp.selective_update = selective;
    MarkovGrid grid(b.map, sensor, gp);
    std::mt19937 rng(3);
    Pose2 pose{11.0, 10.0, 0.0};
    // Global localization from uniform along the corridor, exact-ish scans.
    for (int i = 0; i < 12; ++i) {
      const Pose2 next{pose.x + 0.5, pose.y, pose.yaw};
      grid.MotionUpdate(MotionBetween(pose, next));
      pose = next;
      const auto stats = grid.SensorUpdate(testing::SimulateScan(b.map, b.laser, pose, 0.03, rng));
      ASSERT_TRUE(FiniteAndNormalized(grid)) << "scan " << i << " selective " << selective;
      ASSERT_TRUE(std::isfinite(stats.log_likelihood_per_beam));
      EXPECT_EQ(stats.beams, 180);
      EXPECT_GT(stats.groups, 1) << "180 beams cannot be one float product";
      EXPECT_FALSE(grid.lost()) << grid.lost_reason();
    }
    const PositionCertainty c = PosCertainty(BeliefSnapshot::Of(grid), CertaintyParameters{});
    EXPECT_TRUE(std::isfinite(c.certainty));
    EXPECT_TRUE(std::isfinite(c.estimate.x) && std::isfinite(c.estimate.y));
    // Hostile scans: every beam a wall at 0.1 m, every beam at max range, alternating; the
    // belief is confident and each of them fits no state.
    for (const double r : {0.1, 8.0, 0.3, 7.9}) {
      std::vector<double> scan(180, r);
      for (int i = 0; i < 180; i += 2) scan[i] = r < 1.0 ? 7.9 : 0.1;
      grid.SensorUpdate(scan);
      ASSERT_TRUE(FiniteAndNormalized(grid)) << "hostile scan " << r;
    }
  }
}

TEST(ManyBeams, LaserAndSonarTogetherLocalizeAndStayFinite) {
  Bonn25 b;
  SensorModelParameters sonar;
  sonar.beam_angles_rad = SonarRingAngles(24);
  sonar.max_range_m = 5.0;
  SensorModel laser_model(b.map, 72, b.laser), sonar_model(b.map, 72, sonar);
  MarkovGrid grid(b.map, laser_model, b.grid);
  std::mt19937 rng(5);
  // Standing in room B facing its cupboard: laser and sonar in one update.
  const Pose2 truth{17.0, 6.0, -M_PI / 2};
  for (int i = 0; i < 4; ++i) {
    const auto l = testing::SimulateScan(b.map, b.laser, truth, 0.03, rng);
    const auto s = testing::SimulateScan(b.map, sonar, truth, 0.05, rng);
    const auto stats =
        grid.SensorUpdateWith({SensorReading{&laser_model, &l}, SensorReading{&sonar_model, &s}});
    EXPECT_EQ(stats.beams + stats.beams_filtered, 204);
    ASSERT_TRUE(FiniteAndNormalized(grid));
  }
  const PositionCertainty c = PosCertainty(BeliefSnapshot::Of(grid), CertaintyParameters{});
  EXPECT_GT(c.certainty, 0.8);
  EXPECT_LT(std::hypot(c.estimate.x - truth.x, c.estimate.y - truth.y), 0.3);
  // A reading of the wrong size is refused with the counts.
  const std::vector<double> short_scan(10, 1.0);
  EXPECT_THROW(grid.SensorUpdateWith({SensorReading{&sonar_model, &short_scan}}),
               std::invalid_argument);
}

TEST(ManyBeams, ABeliefThatVanishesIsResetLoudly) {
  // A 5-cell corridor: all of the belief sits in cell 2 facing east; a motion of 10 m east
  // pushes every state into the wall. The reset to uniform sets lost with the reason.
  MapModelParameters mp;
  mp.resolution_m = 1.0;
  mp.state_clearance_m = 0.0;
  mp.ray_cast_subdivision = 1;
  const int w = 7, h = 3;
  std::vector<std::int8_t> data(w * h, 0);
  for (int ix = 0; ix < w; ++ix) data[ix] = data[2 * w + ix] = 100;
  data[w] = data[w + w - 1] = 100;
  const MapModel map = MapModel::FromOccupancy(Vec2(0, 0), w, h, 1.0, data, 50, 0.0);
  SensorModelParameters sp;
  sp.beam_angles_rad = {0.0};
  SensorModel sensor(map, 4, sp);
  MarkovGridParameters gp;
  gp.angular_resolution_rad = M_PI / 2;
  gp.motion = MotionModelParameters{0, 0, 0, 0};
  MarkovGrid grid(map, sensor, gp);
  grid.SetGaussian(Pose2{2.5, 1.5, 0.0}, 0.01, 0.01);
  EXPECT_FALSE(grid.lost());
  grid.MotionUpdate(Motion{10.0, 0.0, 0.0});
  EXPECT_TRUE(grid.lost());
  EXPECT_EQ(grid.forced_resets(), 1);
  EXPECT_NE(grid.lost_reason().find("ruled out"), std::string::npos) << grid.lost_reason();
  EXPECT_NEAR(grid.Probability(3, 1, 0), 1.0 / 20, 1e-6);  // uniform over 5 cells x 4 headings
}

}  // namespace
}  // namespace markov_localization
