#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "test_helpers.h"

namespace markov_localization {
namespace {

// A straight corridor 5 cells long (1 m cells) between walls: row 1 of a 7 x 3 grid.
MapModel Corridor() {
  std::vector<std::int8_t> data(7 * 3, 100);
  for (int ix = 1; ix <= 5; ++ix) data[1 * 7 + ix] = 0;
  return MapModel::FromOccupancy(Vec2(0, 0), 7, 3, 1.0, data, 50, 0.0);
}

SensorModelParameters OneBeam() {
  SensorModelParameters p;
  p.beam_angles_rad = {0.0};
  p.max_range_m = 10.0;
  p.range_bin_m = 0.5;
  p.sigma_hit_m = 0.3;
  return p;
}

TEST(MapModel, RayCastStopsAtTheFirstWallCell) {
  const MapModel map = Corridor();
  // From the centre of cell 2 (x = 2.5) east: the wall cell starts at x = 6.
  EXPECT_NEAR(map.RayCast(Vec2(2.5, 1.5), 0.0, 10.0), 3.5, 1e-9);
  EXPECT_NEAR(map.RayCast(Vec2(2.5, 1.5), M_PI, 10.0), 1.5, 1e-9);
  EXPECT_NEAR(map.RayCast(Vec2(2.5, 1.5), M_PI / 2, 10.0), 0.5, 1e-9);
  EXPECT_NEAR(map.RayCast(Vec2(2.5, 1.5), 0.0, 2.0), 2.0, 1e-9);  // capped at max range
  // Diagonal: from (2.5, 1.5) at 45 degrees the beam enters cell (2, 2) at y = 2.
  EXPECT_NEAR(map.RayCast(Vec2(2.5, 1.5), M_PI / 4, 10.0), 0.5 * std::sqrt(2.0), 1e-9);
}

TEST(MapModel, StatesAreTheFreeCellsAwayFromTheBorder) {
  const MapModel map = Corridor();
  EXPECT_EQ(map.NumStateCells(), 5u);
  EXPECT_TRUE(map.IsState(1, 1));
  EXPECT_FALSE(map.IsState(0, 1));
  EXPECT_FALSE(map.IsState(3, 0));
}

TEST(MapModel, BadOccupancyGridIsRefusedWithTheReason) {
  try {
    MapModel::FromOccupancy(Vec2(0, 0), 3, 3, 1.0, std::vector<std::int8_t>(8, 0), 50, 0.0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("data has 8 cells"), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      MapModel::FromOccupancy(Vec2(0, 0), 3, 3, 1.0, std::vector<std::int8_t>(9, 100), 50, 0.0),
      std::invalid_argument);  // no free cell
  MapModelParameters bad;
  bad.resolution_m = -1;
  bad.state_clearance_m = 5;
  const auto errors = ValidateParameters(bad);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find("resolution_m"), std::string::npos);
  EXPECT_NE(errors[1].find("state_clearance_m"), std::string::npos);
}

TEST(SensorModel, TablesAreDistributionsAndExpectedRangesComeFromRayCasting) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  EXPECT_EQ(sensor.num_bins(), 21);
  for (int e = 0; e < sensor.num_bins(); ++e) {
    double sum = 0.0;
    for (int z = 0; z < sensor.num_bins(); ++z) sum += sensor.Likelihood(e, z);
    EXPECT_NEAR(sum, 1.0, 1e-9) << "row " << e;
  }
  double avg = 0.0;
  for (int z = 0; z < sensor.num_bins(); ++z) avg += sensor.AverageLikelihood(z);
  EXPECT_NEAR(avg, 1.0, 1e-9);
  // Heading bin 0 (east) from cell (ix, 1): 5.5 - ix m, i.e. bin 11 - 2 ix.
  for (int ix = 1; ix <= 5; ++ix) EXPECT_EQ(sensor.ExpectedBin(0, map.Index(ix, 1)), 11 - 2 * ix);
  // Heading bin 1 (north): 0.5 m to the wall.
  EXPECT_EQ(sensor.ExpectedBin(1, map.Index(3, 1)), 1);
  // The likeliest reading for an expected bin is that bin.
  EXPECT_GT(sensor.Likelihood(5, 5), sensor.Likelihood(5, 7));
  // An unexpected obstacle (short reading) is likelier than an equally long reading.
  EXPECT_GT(sensor.Likelihood(10, 3), sensor.Likelihood(3, 10));
}

TEST(SensorModel, InvalidParametersAreNamed) {
  SensorModelParameters p;
  p.z_hit = 0.9;  // sum 1.2
  p.sigma_hit_m = 0;
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_NE(errors[0].find("beam_angles_rad"), std::string::npos);
  EXPECT_NE(errors[1].find("sigma_hit_m"), std::string::npos);
  EXPECT_NE(errors[2].find("must be 1"), std::string::npos);
}

MarkovGridParameters FourHeadings(bool selective) {
  MarkovGridParameters p;
  p.angular_resolution_rad = M_PI / 2;
  p.selective_update = selective;
  p.motion.sigma_xy_per_m = 0.0;
  p.motion.sigma_xy_per_rad = 0.0;
  p.motion.sigma_theta_per_m = 0.0;
  p.motion.sigma_theta_per_rad = 0.0;
  return p;
}

TEST(MarkovGrid, SensorUpdateFromUniformIsTheNormalizedLikelihood) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  MarkovGrid grid(map, sensor, FourHeadings(false));
  EXPECT_EQ(grid.NumStates(), 20u);
  EXPECT_NEAR(grid.Probability(3, 1, 2), 1.0 / 20, 1e-7);
  // Reading 2.5 m (bin 5): eq. (2) gives P(l) = P(s|l) / sum_l' P(s|l') from a uniform prior.
  grid.SensorUpdate({2.5});
  double norm = 0.0;
  for (int k = 0; k < 4; ++k)
    for (int ix = 1; ix <= 5; ++ix)
      norm += sensor.Likelihood(sensor.ExpectedBin(k, map.Index(ix, 1)), 5);
  for (int k = 0; k < 4; ++k) {
    for (int ix = 1; ix <= 5; ++ix) {
      const double expected = sensor.Likelihood(sensor.ExpectedBin(k, map.Index(ix, 1)), 5) / norm;
      EXPECT_NEAR(grid.Probability(ix, 1, k), expected, 1e-6) << ix << "," << k;
    }
  }
  // Facing east at cell 3 (3 m... 2.5 m to the wall) or west at cell 3 (x = 3.5, 2.5 m to the
  // wall at x = 1... the wall cell ends at x = 1): both explain 2.5 m; the corridor is symmetric.
  EXPECT_NEAR(grid.Probability(3, 1, 0), grid.Probability(3, 1, 2), 1e-7);
  EXPECT_GT(grid.Probability(3, 1, 0), 5 * grid.Probability(1, 1, 0));
}

TEST(MarkovGrid, ADroppedOutBeamIsLeftOutNotReadAsNoEcho) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  MarkovGrid grid(map, sensor, FourHeadings(false));
  const SensorUpdateStats dropped = grid.SensorUpdate({std::nan("")});
  EXPECT_EQ(dropped.beams, 0);
  EXPECT_EQ(dropped.beams_dropped, 1);
  ASSERT_EQ(dropped.beam_used.size(), 1u);
  EXPECT_EQ(dropped.beam_used[0], 0);
  for (int k = 0; k < 4; ++k)  // the uniform belief is left as it was
    for (int ix = 1; ix <= 5; ++ix) EXPECT_NEAR(grid.Probability(ix, 1, k), 1.0 / 20, 1e-7);
  // A reading that came (2.5 m) still updates: only the dropped beam was left out.
  const SensorUpdateStats read = grid.SensorUpdate({2.5});
  EXPECT_EQ(read.beams, 1);
  EXPECT_EQ(read.beams_dropped, 0);
  EXPECT_GT(grid.Probability(3, 1, 0), 5 * grid.Probability(1, 1, 0));
}

TEST(MarkovGrid, AReadingTurnedByTheTurretIsTheModelsFromTheTurnedHeading) {
  // SPOTT's dense scan turns the sonars on the turret: a ring of radial transducers turned by
  // a quarter turn reads what the unturned ring reads from the heading a quarter turn on.
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  for (const double reading : {1.5, 2.5, 0.5}) {
    MarkovGrid turned(map, sensor, FourHeadings(false));
    MarkovGrid plain(map, sensor, FourHeadings(false));
    const std::vector<double> ranges{reading};
    turned.SensorUpdateWith({SensorReading{&sensor, &ranges, true, M_PI / 2}});
    plain.SensorUpdateWith({SensorReading{&sensor, &ranges, true, 0.0}});
    double apart = 0.0;
    for (int k = 0; k < 4; ++k) {
      for (int ix = 1; ix <= 5; ++ix) {
        EXPECT_NEAR(turned.Probability(ix, 1, k), plain.Probability(ix, 1, (k + 1) % 4), 1e-7)
            << reading << " m at " << ix << "," << k;
        apart =
            std::max(apart, std::abs(turned.Probability(ix, 1, k) - plain.Probability(ix, 1, k)));
      }
    }
    EXPECT_GT(apart, 0.01) << "the turn changes the belief";
  }
  MarkovGrid grid(map, sensor, FourHeadings(false));
  const std::vector<double> ranges{1.5};
  EXPECT_THROW(grid.SensorUpdateWith({SensorReading{&sensor, &ranges, true, std::nan("")}}),
               std::invalid_argument);
}

TEST(MarkovGrid, MotionShiftsEachHeadingAlongItself) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  MarkovGrid grid(map, sensor, FourHeadings(false));
  grid.SetGaussian(Pose2{2.5, 1.5, 0.0}, 0.01, 0.01);
  EXPECT_NEAR(grid.Probability(2, 1, 0), 1.0, 1e-6);
  grid.MotionUpdate(Motion{1.0, 0.0, 0.0});
  EXPECT_NEAR(grid.Probability(3, 1, 0), 1.0, 1e-6);
  // A quarter turn moves the mass to heading bin 1 (north), then forward 0.5 m splits it.
  grid.MotionUpdate(Motion{0.0, 0.0, M_PI / 2});
  EXPECT_NEAR(grid.Probability(3, 1, 1), 1.0, 1e-6);
  grid.MotionUpdate(Motion{0.0, 0.0, -M_PI / 2});
  grid.MotionUpdate(Motion{0.5, 0.0, 0.0});
  EXPECT_NEAR(grid.Probability(3, 1, 0), 0.5, 1e-6);
  EXPECT_NEAR(grid.Probability(4, 1, 0), 0.5, 1e-6);
  // Into the wall: the mass there is removed, the rest renormalized.
  grid.MotionUpdate(Motion{2.0, 0.0, 0.0});
  EXPECT_NEAR(grid.Probability(5, 1, 0), 1.0, 1e-6);
}

TEST(MarkovGrid, MotionNoiseSpreadsByTheModelsVariance) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  auto params = FourHeadings(false);
  params.motion.sigma_xy_per_m = 0.5;  // 1 m forward: sigma 0.5 m = 0.5 cells, variance 0.25
  MarkovGrid grid(map, sensor, params);
  grid.SetGaussian(Pose2{2.5, 1.5, 0.0}, 0.01, 0.01);
  grid.MotionUpdate(Motion{1.0, 0.0, 0.0});
  // One 3-tap pass with w = 0.125 along x; along y the mass leaving row 1 hits walls.
  const double wx = 0.125, wy = 0.125;
  const double centre = (1 - 2 * wx) * (1 - 2 * wy);
  const double side = wx * (1 - 2 * wy);
  const double total = centre + 2 * side;
  EXPECT_NEAR(grid.Probability(3, 1, 0), centre / total, 1e-5);
  EXPECT_NEAR(grid.Probability(2, 1, 0), side / total, 1e-5);
  EXPECT_NEAR(grid.Probability(4, 1, 0), side / total, 1e-5);
}

TEST(MarkovGrid, Eq3AndEq4GiveOneBelief) {
  // Eq. (3): likely cells times P(s|l)/P(s), unlikely cells times P~(s)/P(s), P(s) the
  // normalizer. Eq. (4) (what the grid does): ratio P(s|l)/P~(s) or 1, then normalize.
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  auto params = FourHeadings(true);
  params.threshold_fraction = 0.9;  // theta = 0.9 / 20: cells below it take the average
  params.lost.enabled = false;      // eq. (4) alone
  MarkovGrid grid(map, sensor, params);
  grid.SetGaussian(Pose2{2.5, 1.5, 0.0}, 1.0, 1.0);
  std::vector<double> prior(20);
  for (int k = 0; k < 4; ++k)
    for (int ix = 1; ix <= 5; ++ix) prior[k * 5 + ix - 1] = grid.Probability(ix, 1, k);
  const int z = sensor.RangeBin(3.5);
  std::vector<double> eq3(20);
  double ps = 0.0;
  int below = 0;
  for (int k = 0; k < 4; ++k) {
    for (int ix = 1; ix <= 5; ++ix) {
      const double p = prior[k * 5 + ix - 1];
      const double l = p > grid.threshold()
                           ? sensor.Likelihood(sensor.ExpectedBin(k, map.Index(ix, 1)), z)
                           : sensor.AverageLikelihood(z);
      below += p <= grid.threshold();
      eq3[k * 5 + ix - 1] = l * p;
      ps += l * p;
    }
  }
  ASSERT_GT(below, 0);
  ASSERT_LT(below, 20);
  grid.SensorUpdate({3.5});
  for (int k = 0; k < 4; ++k)
    for (int ix = 1; ix <= 5; ++ix)
      EXPECT_NEAR(grid.Probability(ix, 1, k), eq3[k * 5 + ix - 1] / ps, 1e-6) << ix << "," << k;
}

TEST(MarkovGrid, WrongReadingCountIsRefused) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  MarkovGrid grid(map, sensor, FourHeadings(false));
  EXPECT_THROW(grid.SensorUpdate({1.0, 2.0}), std::invalid_argument);
  EXPECT_NEAR(grid.Probability(3, 1, 2), 1.0 / 20, 1e-7);  // the belief is kept
}

TEST(MarkovGrid, ParametersAreValidatedByName) {
  MarkovGridParameters p;
  p.angular_resolution_rad = 0.7;
  p.threshold_fraction = 2;
  p.motion.sigma_xy_per_m = -1;
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_NE(errors[0].find("angular_resolution_rad"), std::string::npos);
  EXPECT_NE(errors[1].find("threshold_fraction"), std::string::npos);
  EXPECT_NE(errors[2].find("motion.sigma_xy_per_m"), std::string::npos);
  const MapModel map = Corridor();
  const SensorModel sensor(map, 8, OneBeam());
  EXPECT_THROW(MarkovGrid(map, sensor, FourHeadings(false)), std::invalid_argument);
}

TEST(Certainty, EntropyOfUniformIsLogOfTheStateCount) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  MarkovGrid grid(map, sensor, FourHeadings(false));
  EXPECT_NEAR(Entropy(BeliefSnapshot::Of(grid)), std::log(20.0), 1e-5);
  grid.SetGaussian(Pose2{2.5, 1.5, 0.0}, 0.01, 0.01);
  EXPECT_NEAR(Entropy(BeliefSnapshot::Of(grid)), 0.0, 1e-5);
}

// A belief of floats sums to 1 only within rounding: 0.6f + 0.3f + 0.1f is 1.0000000373. The
// status says a probability (rpl_executive refused "1.000000 is not in [0, 1]" a hundred times
// in a run and kept a stale POS-CERTAINTY*).
TEST(Certainty, PosCertaintyIsAProbabilityWhateverTheRounding) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  MarkovGrid grid(map, sensor, FourHeadings(false));
  BeliefSnapshot b = BeliefSnapshot::Of(grid);
  std::fill(b.p.begin(), b.p.end(), 0.0f);
  b.p[b.Index(1, 1, 0)] = 0.6f;
  b.p[b.Index(2, 1, 0)] = 0.3f;
  b.p[b.Index(1, 1, 1)] = 0.1f;
  ASSERT_GT(static_cast<double>(0.6f) + 0.3f + 0.1f, 1.0);
  CertaintyParameters cp;
  cp.mode_radius_m = 1.0;
  cp.mode_radius_rad = M_PI / 2;
  const auto c = PosCertainty(b, cp);
  EXPECT_LE(c.certainty, 1.0);
  EXPECT_NEAR(c.certainty, 1.0, 1e-6);
}

TEST(Certainty, PosCertaintyIsTheMassAroundTheMaximumAndModesAreSeparated) {
  const MapModel map = Corridor();
  const SensorModel sensor(map, 4, OneBeam());
  MarkovGrid grid(map, sensor, FourHeadings(false));
  grid.SensorUpdate({0.5});  // a wall 0.5 m ahead: east at cell 5, west at cell 1, or N/S
  BeliefSnapshot b = BeliefSnapshot::Of(grid);
  // Make a hand-built belief: 0.6 at (1, 1, east), 0.3 at (5, 1, west), 0.1 at (3, 1, north).
  std::fill(b.p.begin(), b.p.end(), 0.0f);
  b.p[b.Index(1, 1, 0)] = 0.6f;
  b.p[b.Index(5, 1, 2)] = 0.3f;
  b.p[b.Index(3, 1, 1)] = 0.1f;
  CertaintyParameters cp;
  cp.mode_radius_m = 1.0;         // +-1 cell
  cp.mode_radius_rad = M_PI / 2;  // +-1 heading bin
  const auto c = PosCertainty(b, cp);
  EXPECT_NEAR(c.certainty, 0.6, 1e-6);  // (3, 1) is two cells away
  EXPECT_NEAR(c.estimate.x, 1.5, 1e-9);
  EXPECT_NEAR(Entropy(b), -(0.6 * std::log(0.6) + 0.3 * std::log(0.3) + 0.1 * std::log(0.1)), 1e-6);
  ModeParameters mp;
  mp.uniform_factor = 0.5;  // threshold 0.5 / 20
  const auto modes = ExtractModes(b, mp);
  ASSERT_EQ(modes.size(), 3u);
  EXPECT_NEAR(modes[0].mass, 0.6, 1e-6);
  EXPECT_NEAR(modes[1].mean.x, 5.5, 1e-9);
  EXPECT_NEAR(std::abs(modes[1].mean.yaw), M_PI, 1e-9);
  EXPECT_NEAR(modes[2].mass, 0.1, 1e-6);
  // Two adjacent cells form one mode with their weighted mean.
  b.p[b.Index(2, 1, 0)] = 0.2f;
  b.p[b.Index(3, 1, 1)] = 0.0f;
  b.p[b.Index(1, 1, 0)] = 0.5f;
  const auto merged = ExtractModes(b, mp);
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_NEAR(merged[0].mass, 0.7, 1e-6);
  EXPECT_NEAR(merged[0].mean.x, (0.5 * 1.5 + 0.2 * 2.5) / 0.7, 1e-6);
  EXPECT_GT(merged[0].covariance(0, 0), 0.0);
}

}  // namespace
}  // namespace markov_localization
