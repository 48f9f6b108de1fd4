// The sonar's physics in the expected ranges (cone, specular reflection, corners) and the lost
// detector, on hand-checkable maps and sequences.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "../src/worker_pool.h"
#include "markov_localization/lost_detector.h"
#include "test_helpers.h"

namespace markov_localization {
namespace {

// A 10 x 10 m room of 1 m cells (walls are the border ring of a 12 x 12 grid): x, y in [1, 11].
MapModel Room() {
  std::vector<std::int8_t> data(12 * 12, 100);
  for (int iy = 1; iy <= 10; ++iy)
    for (int ix = 1; ix <= 10; ++ix) data[iy * 12 + ix] = 0;
  return MapModel::FromOccupancy(Vec2(0, 0), 12, 12, 1.0, data, 50, 0.0);
}

SensorModelParameters Sonar(double beam_width, double critical_angle) {
  SensorModelParameters p;
  p.beam_angles_rad = {0.0};
  p.max_range_m = 10.0;
  p.range_bin_m = 0.5;
  p.beam_width_rad = beam_width;
  p.critical_angle_rad = critical_angle;
  return p;
}

// Robot at (3.5, 10.5), 0.5 m below the north wall; heading bins of 15 degrees (24).
constexpr int kHeadings = 24;

TEST(SonarPhysics, ObliqueWallsReflectAndCornersEchoTheWholePath) {
  const MapModel map = Room();
  const std::size_t cell = map.Index(3, 10);
  // Diffuse: the 15-degree ray meets the north wall after 0.5 / sin 15 = 1.93 m (bin 4).
  const SensorModel diffuse(map, kHeadings, Sonar(0.0, M_PI / 2));
  EXPECT_EQ(diffuse.ExpectedBin(1, cell), 4);
  // Specular (20 degrees): met at 75 degrees the north wall reflects the pulse east; the east
  // wall, met at 15 degrees, scatters it back: 1.932 + (11 - 5.366) / cos 15 = 7.765 m (bin 16).
  const SensorModel specular(map, kHeadings, Sonar(0.0, 0.35));
  EXPECT_EQ(specular.ExpectedBin(1, cell), 16);
  // Straight east the wall is met head on: 7.5 m (bin 15) in both models.
  EXPECT_EQ(diffuse.ExpectedBin(0, cell), 15);
  EXPECT_EQ(specular.ExpectedBin(0, cell), 15);
  // From (3.5, 5.5) at 45 degrees both walls are met at 45 degrees: no echo (max range, bin 20).
  const std::size_t middle = map.Index(3, 5);
  EXPECT_EQ(specular.ExpectedBin(3, middle), 20);
  EXPECT_EQ(diffuse.ExpectedBin(3, middle), 16);  // 5.5 sqrt 2 = 7.78 m
}

TEST(SonarPhysics, ACone30DegreesWideReadsTheNearestEchoInIt) {
  const MapModel map = Room();
  const std::size_t cell = map.Index(3, 10);
  const double cone = 2 * 15.0 * M_PI / 180 + 1e-6;  // rays at -15, 0 and +15 degrees
  // Diffuse: the +15 degree ray's 1.93 m is the nearest echo.
  EXPECT_EQ(SensorModel(map, kHeadings, Sonar(cone, M_PI / 2)).ExpectedBin(0, cell), 4);
  // Specular: that ray's echo is the corner's 7.765 m; the head-on 7.5 m is nearest.
  EXPECT_EQ(SensorModel(map, kHeadings, Sonar(cone, 0.35)).ExpectedBin(0, cell), 15);
}

// The expected ranges are filled on the worker thread too: the table must not depend on it.
TEST(SonarPhysics, TheExpectedRangesAreTheSameOnOneThreadAndTwo) {
  const auto world = testing::LoadWorld("bonn_department");
  const MapModel map = MapModel::FromWorld(world, MapModelParameters());
  SensorModelParameters sonar = Sonar(0.3, 0.35);
  sonar.beam_angles_rad = SonarRingAngles(24);
  sonar.sensor_offset_m = 0.3;
  const bool threads = WorkerThreadsEnabled();
  EnableWorkerThreads(false);
  const SensorModel one(map, 72, sonar);
  EnableWorkerThreads(true);
  const SensorModel two(map, 72, sonar);
  EnableWorkerThreads(threads);
  std::size_t states = 0, short_echoes = 0;
  for (int d = 0; d < 72; ++d)
    for (std::size_t c = 0; c < map.NumCells(); ++c) {
      if (!map.state_mask()[c]) continue;
      ++states;
      ASSERT_EQ(one.ExpectedBin(d, c), two.ExpectedBin(d, c)) << "heading " << d << " cell " << c;
      if (one.ExpectedBin(d, c) < 10) ++short_echoes;
    }
  EXPECT_GT(states, 10000u);
  EXPECT_GT(short_echoes, states / 10);  // walls are in the table, not only max range
}

TEST(SonarPhysics, InvalidParametersAreNamed) {
  auto p = Sonar(-0.1, 0.0);
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find("beam_width_rad"), std::string::npos);
  EXPECT_NE(errors[1].find("critical_angle_rad"), std::string::npos);
}

TEST(LostDetector, SteadyFitNeverFiresADropDoes) {
  LostDetector d(LostDetectorParameters{});
  // A fit that wobbles by +-20% around e^1 per beam for 200 scans: no alarm.
  for (int i = 0; i < 200; ++i) ASSERT_FALSE(d.Update(1.0 + 0.18 * std::sin(i))) << "scan " << i;
  EXPECT_NEAR(d.slow(), std::exp(1.0), 0.1);
  // A fit that falls to 0.6 of the usual (the worst seen while driving): no alarm.
  for (int i = 0; i < 20; ++i) ASSERT_FALSE(d.Update(1.0 + std::log(0.6))) << "scan " << i;
  d.Reset();
  for (int i = 0; i < 50; ++i) d.Update(1.0);
  // A fit that sinks to 0.2 of the usual per beam (above scan_lost_ratio 0.15: no collapse):
  // fast (rate 0.5) / slow (rate 0.05) is 0.6 / 0.96 = 0.63, 0.4 / 0.922 = 0.43,
  // 0.3 / 0.886 = 0.34, then 0.25 / 0.852 = 0.29 < lost_ratio 0.3: lost at the fourth scan.
  // (A sink to 0.3 never fires at lost_ratio 0.3: the slow average follows, the ratio's
  // minimum is 0.38.)
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(d.Update(1.0 + std::log(0.2))) << "scan " << i;
  EXPECT_TRUE(d.Update(1.0 + std::log(0.2)));
  for (int i = 0; i < 50; ++i) d.Update(1.0);
  // A kidnap: one scan's fit falls to e^-2 = 0.05 of the usual (< 0.15): lost at once.
  EXPECT_TRUE(d.Update(-2.0));
  // After a detection the hold keeps it quiet for hold_scans scans, then it fires again if the
  // fit has not come back.
  for (int i = 0; i < LostDetectorParameters{}.hold_scans - 1; ++i) EXPECT_FALSE(d.Update(-2.0));
  EXPECT_TRUE(d.Update(-2.0));
}

// A detection (the averages or the collapse) stands only if the scan without its unexpectedly
// short beams misfits too (below without_short_lost_ratio x the slow average); not given (NaN):
// the whole scan decides.
TEST(LostDetector, ADetectionNeedsTheScanWithoutItsShortBeamsToMisfitToo) {
  LostDetector d(LostDetectorParameters{});
  for (int i = 0; i < 50; ++i) d.Update(1.0);
  // The whole scan at e^-2 = 0.05 of the usual, the beams without the short ones at 0.7 x: no
  // collapse, though the averages see the whole scan.
  EXPECT_FALSE(d.Update(-2.0, 1.0 + std::log(0.7)));
  EXPECT_LT(d.fast(), 0.6 * d.slow()) << "the averages see the whole scan";
  for (int i = 0; i < 10; ++i) d.Update(1.0);
  // Without the short ones at 0.1 x (below 0.15): lost, the reason gives the whole scan's fit.
  EXPECT_TRUE(d.Update(-2.0, 1.0 + std::log(0.1)));
  EXPECT_NE(d.reason().find("one scan's fit collapsed (per-beam fit 0.135"), std::string::npos)
      << d.reason();
  for (int i = 0; i < 50; ++i) d.Update(1.0);
  EXPECT_TRUE(d.Update(-2.0, std::numeric_limits<double>::quiet_NaN()));
  // The averages: scans at 0.2 x (no collapse) bring the fast one below lost_ratio x slow at
  // the fourth (SteadyFitNeverFiresADropDoes); the beams without the short ones fit as usual:
  // not lost. Then they stop fitting: lost.
  LostDetector a(LostDetectorParameters{});
  for (int i = 0; i < 50; ++i) a.Update(1.0);
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(a.Update(1.0 + std::log(0.2), 1.0)) << "scan " << i;
  EXPECT_LT(a.fast(), 0.3 * a.slow());
  EXPECT_TRUE(a.Update(1.0 + std::log(0.2), 1.0 + std::log(0.05)));
}

TEST(LostDetector, ACertaintyDropWhileTheFitDropsIsLost) {
  LostDetector d(LostDetectorParameters{});
  for (int i = 0; i < 50; ++i) {
    d.Update(1.0);
    EXPECT_FALSE(d.OnCertainty(0.95, 0.8));
  }
  // The certainty falls with an unchanged fit (an ambiguous place): not lost.
  d.Update(1.0);
  EXPECT_FALSE(d.OnCertainty(0.6, 0.8));
  for (int i = 0; i < LostDetectorParameters{}.hold_scans; ++i) {  // certain for a while again
    d.Update(1.0);
    EXPECT_FALSE(d.OnCertainty(0.95, 0.8));
  }
  // The fit at 0.65 x with the certainty falling (cim_office's lab: the Nomad turning by the
  // partition dipped at 0.70 x, twice, each followed by a relocalization 4.5 m off): not lost.
  d.Update(1.0 + std::log(0.25));  // fast 0.625, slow 0.9625 of the usual: 0.65 x
  EXPECT_FALSE(d.OnCertainty(0.5, 0.8));
  for (int i = 0; i < 20; ++i) {  // back to the usual fit, certain for a while
    d.Update(1.0);
    EXPECT_FALSE(d.OnCertainty(0.95, 0.8));
  }
  // Two scans at 0.4 x the usual fit (fast 0.55 x slow: above lost_ratio 0.3, below
  // certainty_drop_ratio 0.6), the certainty falling at the second: lost.
  d.Update(1.0 + std::log(0.4));
  EXPECT_FALSE(d.OnCertainty(0.95, 0.8));
  d.Update(1.0 + std::log(0.4));
  EXPECT_TRUE(d.OnCertainty(0.5, 0.8));
}

TEST(LostDetector, NoAlarmDuringTheFirstScansAfterAReset) {
  LostDetectorParameters p;
  p.hold_scans = 5;
  LostDetector d(p);
  d.Update(3.0);
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(d.Update(-2.0));
  d.Reset();
  EXPECT_FALSE(d.Update(-2.0));
  EXPECT_DOUBLE_EQ(d.slow(), std::exp(-2.0));  // the history starts again
}

TEST(LostDetector, InvalidParametersAreNamed) {
  LostDetectorParameters p;
  p.slow_rate = 0.9;  // not below fast_rate
  p.lost_ratio = 1.5;
  p.relocalization_mass = 0.0;
  p.short_beams_min_others = 0;
  p.without_short_lost_ratio = 0.0;
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 5u);
  EXPECT_NE(errors[0].find("slow_rate"), std::string::npos);
  EXPECT_NE(errors[1].find("lost_ratio"), std::string::npos);
  EXPECT_NE(errors[2].find("without_short_lost_ratio"), std::string::npos);
  EXPECT_NE(errors[3].find("short_beams_min_others"), std::string::npos);
  EXPECT_NE(errors[4].find("relocalization_mass"), std::string::npos);
  MarkovGridParameters g;
  g.lost.relocalization_mass = 0.005;  // below threshold_fraction: eq. (4) would skip it
  const auto grid_errors = ValidateParameters(g);
  ASSERT_EQ(grid_errors.size(), 1u);
  EXPECT_NE(grid_errors[0].find("lost.relocalization_mass"), std::string::npos);
}

TEST(MarkovGrid, MixUniformKeepsTheMassAndLiftsEveryStateAboveTheThreshold) {
  const MapModel map = Room();
  SensorModelParameters sp = Sonar(0.0, M_PI / 2);
  const SensorModel sensor(map, kHeadings, sp);
  MarkovGridParameters gp;
  gp.angular_resolution_rad = 2 * M_PI / kHeadings;
  MarkovGrid grid(map, sensor, gp);
  grid.SetGaussian(Pose2{5.5, 5.5, 0.0}, 0.3, 0.1);
  std::mt19937 rng(1);
  for (int i = 0; i < 3; ++i)
    grid.SensorUpdate(testing::SimulateScan(map, sp, Pose2{5.5, 5.5, 0.0}, 0.0, rng));
  ASSERT_LT(grid.ActiveParts(), kHeadings);  // some parts were set aside
  grid.MixUniform(0.1);
  EXPECT_EQ(grid.ActiveParts(), kHeadings);
  const auto dense = grid.Dense();
  double total = 0.0, smallest = 1.0;
  for (int k = 0; k < kHeadings; ++k)
    for (int iy = 1; iy <= 10; ++iy)
      for (int ix = 1; ix <= 10; ++ix) {
        const double v = grid.Probability(ix, iy, k);
        total += v;
        smallest = std::min(smallest, v);
      }
  EXPECT_NEAR(total, 1.0, 1e-5);
  EXPECT_GE(smallest, 0.1 / grid.NumStates() * (1 - 1e-5));
  EXPECT_GT(smallest, grid.threshold());
  EXPECT_EQ(dense.size(), static_cast<std::size_t>(12 * 12 * kHeadings));
}

}  // namespace
}  // namespace markov_localization
