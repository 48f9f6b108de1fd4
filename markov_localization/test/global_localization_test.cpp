// Global localization in bonn_department (Beetz et al. Fig. 2): the corridor is symmetric under
// the half turn about (13.5, 10), so the corridor alone leaves two hypotheses; a room breaks the
// symmetry. A coarser grid than the default (25 cm, 5 degrees) keeps the test fast.
#include <gtest/gtest.h>

#include <cmath>

#include "test_helpers.h"

namespace markov_localization {
namespace {

using testing::AngleError;
using testing::Drive;

struct Bonn {
  Bonn() : world(testing::LoadWorld("bonn_department")) {
    MapModelParameters mp;
    mp.resolution_m = 0.25;
    map = MapModel::FromWorld(world, mp);
    sp.beam_angles_rad = SonarRingAngles(24);
    sp.max_range_m = 5.0;
    sensor = std::make_unique<SensorModel>(map, 72, sp);
  }
  MarkovGridParameters GridParams(bool selective) const {
    MarkovGridParameters p;
    p.angular_resolution_rad = 2 * M_PI / 72;
    p.selective_update = selective;
    return p;
  }
  spott_map::World world;
  MapModel map;
  SensorModelParameters sp;
  std::unique_ptr<SensorModel> sensor;
};

Pose2 HalfTurn(const Pose2& p) {
  return Pose2{27.0 - p.x, 20.0 - p.y, spott_map::NormalizeAngle(p.yaw + M_PI)};
}

double MassNear(const BeliefSnapshot& b, const Pose2& pose, double r_m, double r_rad) {
  double mass = 0.0;
  for (int k = 0; k < b.nt; ++k)
    for (int iy = 0; iy < b.ny; ++iy)
      for (int ix = 0; ix < b.nx; ++ix) {
        const Pose2 q = b.PoseOf(ix, iy, k);
        if (std::abs(q.x - pose.x) <= r_m && std::abs(q.y - pose.y) <= r_m &&
            AngleError(q.yaw, pose.yaw) <= r_rad)
          mass += b.p[b.Index(ix, iy, k)];
      }
  return mass;
}

TEST(GlobalLocalization, SymmetricCorridorStaysAmbiguousAndRoomBResolvesIt) {
  Bonn bonn;
  MarkovGrid grid(bonn.map, *bonn.sensor, bonn.GridParams(true));
  std::mt19937 rng(7);
  Pose2 pose{11.0, 10.0, 0.0};
  pose = Drive(grid, bonn.sp, pose, {Vec2(17.5, 10.0)}, 0.25, rng);
  BeliefSnapshot b = BeliefSnapshot::Of(grid);
  const double at_truth = MassNear(b, pose, 0.6, 0.3);
  const double at_twin = MassNear(b, HalfTurn(pose), 0.6, 0.3);
  // Both twins keep their mass; neither is certain.
  EXPECT_GT(at_truth, 0.2);
  EXPECT_GT(at_twin, 0.2);
  EXPECT_NEAR(at_truth / (at_truth + at_twin), 0.5, 0.2);
  EXPECT_LT(PosCertainty(b, CertaintyParameters{}).certainty, 0.8);
  EXPECT_GE(ExtractModes(b, ModeParameters{}).size(), 2u);

  // Into room B past the door (17.5, 9), down to the cupboard its twin C lacks.
  pose = Drive(grid, bonn.sp, pose, {Vec2(17.5, 8.0), Vec2(17.5, 5.0)}, 0.25, rng);
  b = BeliefSnapshot::Of(grid);
  const auto c = PosCertainty(b, CertaintyParameters{});
  EXPECT_GT(c.certainty, 0.8);
  EXPECT_LT((c.estimate.Position() - pose.Position()).norm(), 0.3);
  EXPECT_LT(AngleError(c.estimate.yaw, pose.yaw), 10 * M_PI / 180);
  EXPECT_LT(MassNear(b, HalfTurn(pose), 0.6, 0.3), 0.01);
}

TEST(SelectiveUpdate, SameAnswerAsFullUpdateWhileTouchingFewerStates) {
  Bonn bonn;
  MarkovGrid full(bonn.map, *bonn.sensor, bonn.GridParams(false));
  MarkovGrid selective(bonn.map, *bonn.sensor, bonn.GridParams(true));
  const Pose2 start{17.5, 6.0, M_PI / 2};
  full.SetGaussian(start, 0.3, 0.1);
  selective.SetGaussian(start, 0.3, 0.1);
  // The same drive and the same simulated readings for both.
  const std::vector<Vec2> route = {Vec2(17.5, 10.0), Vec2(12.5, 10.0), Vec2(12.5, 14.0)};
  std::mt19937 rng_a(3), rng_b(3);
  std::size_t evaluated_full = 0, evaluated_selective = 0;
  Pose2 pa = start, pb = start;
  for (const Vec2& w : route) {
    // Drive one leg at a time and count the evaluated states of the last update of each.
    pa = Drive(full, bonn.sp, pa, {w}, 0.25, rng_a);
    pb = Drive(selective, bonn.sp, pb, {w}, 0.25, rng_b);
    evaluated_full += full.SensorUpdate(testing::SimulateScan(bonn.map, bonn.sp, pa, 0.0, rng_a))
                          .states_evaluated;
    evaluated_selective +=
        selective.SensorUpdate(testing::SimulateScan(bonn.map, bonn.sp, pb, 0.0, rng_b))
            .states_evaluated;
  }
  const BeliefSnapshot bf = BeliefSnapshot::Of(full), bs = BeliefSnapshot::Of(selective);
  double l1 = 0.0;
  for (std::size_t i = 0; i < bf.p.size(); ++i) l1 += std::abs(bf.p[i] - bs.p[i]);
  // Tolerance: the total variation distance between the beliefs stays below 2%.
  EXPECT_LT(0.5 * l1, 0.02);
  const auto cf = PosCertainty(bf, CertaintyParameters{});
  const auto cs = PosCertainty(bs, CertaintyParameters{});
  EXPECT_NEAR(cf.certainty, cs.certainty, 0.02);
  EXPECT_LT((cf.estimate.Position() - cs.estimate.Position()).norm(), 0.02);
  EXPECT_LT((cs.estimate.Position() - pb.Position()).norm(), 0.3);
  EXPECT_LT(evaluated_selective * 20, evaluated_full);
  EXPECT_LT(selective.ActiveParts(), 20);
  EXPECT_EQ(full.ActiveParts(), 72);
}

TEST(SelectiveUpdate, KidnapWakesTheDeactivatedParts) {
  Bonn bonn;
  MarkovGridParameters params = bonn.GridParams(true);
  params.lost.enabled = false;  // the paper's rule alone: alpha_pi > 1
  MarkovGrid grid(bonn.map, *bonn.sensor, params);
  std::mt19937 rng(11);
  // Confidently (and wrongly) believing to be in room A, while really in room B facing its
  // cupboard.
  grid.SetGaussian(Pose2{14.0, 15.0, M_PI / 2}, 0.2, 0.05);
  grid.SensorUpdate(
      testing::SimulateScan(bonn.map, bonn.sp, Pose2{14.0, 15.0, M_PI / 2}, 0.0, rng));
  ASSERT_LT(grid.ActiveParts(), 10);
  const Pose2 truth{17.5, 5.0, -M_PI / 2};
  int woken = 0;
  for (int i = 0; i < 40; ++i)
    woken +=
        grid.SensorUpdate(testing::SimulateScan(bonn.map, bonn.sp, truth, 0.05, rng)).parts_woken;
  EXPECT_GT(woken, 0);
  const auto c = PosCertainty(BeliefSnapshot::Of(grid), CertaintyParameters{});
  EXPECT_LT((c.estimate.Position() - truth.Position()).norm(), 0.5)
      << c.estimate.x << " " << c.estimate.y;
}

TEST(Certainty, SparseBeliefGivesTheDenseCertaintyAndModes) {
  Bonn bonn;
  MarkovGrid grid(bonn.map, *bonn.sensor, bonn.GridParams(true));
  std::mt19937 rng(3);
  // Two modes in the corridor (the half-turn twins), then tracking in room B.
  for (const bool in_room : {false, true}) {
    if (!in_room) {
      testing::Drive(grid, bonn.sp, Pose2{19.0, 10.0, 0.0}, {Vec2(25.0, 10.0)}, 0.25, rng);
    } else {
      grid.SetGaussian(Pose2{17.5, 5.0, -M_PI / 2}, 0.2, 0.05);
      for (int i = 0; i < 5; ++i)
        grid.SensorUpdate(
            testing::SimulateScan(bonn.map, bonn.sp, Pose2{17.5, 5.0, -M_PI / 2}, 0.05, rng));
    }
    const auto dense = BeliefSnapshot::Of(grid);
    const auto sparse = SparseBelief::Of(grid, static_cast<float>(grid.threshold()));
    EXPECT_LT(sparse.p.size(), dense.p.size() / 20);
    const auto cd = PosCertainty(dense, CertaintyParameters{});
    const auto cs = PosCertainty(sparse, CertaintyParameters{});
    EXPECT_NEAR(cs.certainty, cd.certainty, 1e-4);
    EXPECT_NEAR(cs.estimate.x, cd.estimate.x, 1e-3);
    EXPECT_NEAR(cs.estimate.y, cd.estimate.y, 1e-3);
    EXPECT_NEAR(cs.estimate.yaw, cd.estimate.yaw, 1e-3);
    const auto md = ExtractModes(dense, ModeParameters{});
    const auto ms = ExtractModes(sparse, ModeParameters{});
    ASSERT_EQ(ms.size(), md.size()) << "in room: " << in_room;
    EXPECT_GE(md.size(), in_room ? 1u : 2u);
    for (std::size_t m = 0; m < md.size(); ++m) {
      EXPECT_NEAR(ms[m].mass, md[m].mass, 1e-6);
      EXPECT_EQ(ms[m].cells, md[m].cells);
      EXPECT_NEAR(ms[m].mean.x, md[m].mean.x, 1e-6);
    }
    // Summarize takes the sparse path here, and the dense one for a uniform belief.
    const auto summary = Summarize(grid, CertaintyParameters{}, ModeParameters{}, true);
    EXPECT_TRUE(summary.sparse);
    EXPECT_NEAR(summary.certainty.certainty, cd.certainty, 1e-4);
    EXPECT_EQ(summary.modes.size(), md.size());
    EXPECT_NEAR(summary.entropy, Entropy(dense), 1e-9);
  }
  grid.SetUniform();
  const auto uniform = Summarize(grid, CertaintyParameters{}, ModeParameters{}, false);
  EXPECT_FALSE(uniform.sparse);
  EXPECT_TRUE(std::isnan(uniform.entropy));
  EXPECT_LT(uniform.certainty.certainty, 0.01);
}

TEST(LostDetector, AKidnapIsDetectedAndTheRobotRelocalized) {
  Bonn bonn;
  MarkovGrid grid(bonn.map, *bonn.sensor, bonn.GridParams(true));
  std::mt19937 rng(5);
  const Pose2 before{17.5, 5.0, -M_PI / 2}, after{13.5, 14.0, M_PI / 2};
  grid.SetGaussian(before, 0.2, 0.05);
  for (int i = 0; i < 30; ++i) {
    const auto stats =
        grid.SensorUpdate(testing::SimulateScan(bonn.map, bonn.sp, before, 0.05, rng));
    ASSERT_FALSE(stats.lost_detected) << "false alarm at scan " << i;
  }
  int detected_at = -1, relocalized_at = -1;
  for (int i = 0; i < 20 && relocalized_at < 0; ++i) {
    const auto stats =
        grid.SensorUpdate(testing::SimulateScan(bonn.map, bonn.sp, after, 0.05, rng));
    if (stats.lost_detected && detected_at < 0) detected_at = i;
    const auto c = PosCertainty(BeliefSnapshot::Of(grid), CertaintyParameters{});
    if (c.certainty > 0.8 && (c.estimate.Position() - after.Position()).norm() < 0.5)
      relocalized_at = i;
  }
  EXPECT_EQ(detected_at, 0) << "the first scan after the kidnap must say lost";
  EXPECT_GE(relocalized_at, 0) << "not relocalized within 20 scans";
}

// A ring of 12 sonars (the B-12's) beside objects the map lacks (as cim_office's lab partition
// and crate: a wall 0.8 m to the robot's left, another 1 m ahead): 7 of 12 beams read short,
// more than the distance filter's cap (a quarter). The other 5 fit as usual, so the short ones
// are left out and the robot is not "lost"; without the confirmation every beam judged the
// pose and the detector fired with the pose right. (Kidnaps: the evaluation's kidnap rows,
// README.)
struct TwelveSonars : Bonn {
  TwelveSonars() {
    sp.beam_angles_rad = SonarRingAngles(12);
    sensor = std::make_unique<SensorModel>(map, 72, sp);
  }
  std::vector<double> ScanBesideAWall(const Pose2& pose, std::mt19937& rng) const {
    auto ranges = testing::SimulateScan(map, sp, pose, 0.05, rng);
    for (std::size_t b = 0; b < ranges.size(); ++b) {
      const double across = std::sin(sp.beam_angles_rad[b]);
      const double ahead = std::cos(sp.beam_angles_rad[b]);
      if (across > 0.3) ranges[b] = std::min(ranges[b], 0.8 / across);
      if (ahead > 0.8) ranges[b] = std::min(ranges[b], 1.0 / ahead);
    }
    return ranges;
  }
};

int FirstLostScan(double confirm_ratio, std::vector<SensorUpdateStats>* unexpected_stats,
                  bool judge_without_short_beams = true, int short_beams_min_others = 3) {
  TwelveSonars ring;
  MarkovGridParameters params = ring.GridParams(true);
  params.distance_filter_confirm_ratio = confirm_ratio;
  params.lost.judge_without_short_beams = judge_without_short_beams;
  params.lost.short_beams_min_others = short_beams_min_others;
  MarkovGrid grid(ring.map, *ring.sensor, params);
  std::mt19937 rng(5);
  const Pose2 pose{17.5, 5.0, -M_PI / 2};
  grid.SetGaussian(pose, 0.2, 0.05);
  for (int i = 0; i < 30; ++i) {
    const auto stats = grid.SensorUpdate(testing::SimulateScan(ring.map, ring.sp, pose, 0.05, rng));
    if (stats.lost_detected) return -100 - i;  // a false alarm before the wall
  }
  for (int i = 0; i < 30; ++i) {
    const auto stats = grid.SensorUpdate(ring.ScanBesideAWall(pose, rng));
    if (unexpected_stats) unexpected_stats->push_back(stats);
    if (stats.lost_detected) return i;
  }
  return -1;
}

TEST(LostDetector, AWallTheMapLacksIsLeftOutWhenTheOtherBeamsConfirmThePose) {
  std::vector<SensorUpdateStats> stats;
  EXPECT_EQ(FirstLostScan(0.8, &stats), -1) << "said lost beside an unmapped wall";
  ASSERT_EQ(stats.size(), 30u);
  EXPECT_TRUE(stats.front().distance_filter_confirmed);
  EXPECT_EQ(stats.front().beams_filtered, 7) << "every short beam left out, beyond the cap of 3";
  // Without the confirmation and judging the short beams too (the rules before 2026-12-05):
  // the whole misfit is judged and the detector fires although the pose is right.
  EXPECT_GE(FirstLostScan(0.0, nullptr, /*judge_without_short_beams=*/false), 0);
}

// Without the confirmation the update keeps the 7 short beams and the whole scan misfits, but
// the 5 other beams fit, so the lost detector's check without the short ones
// (lost.judge_without_short_beams) keeps it quiet at the wall. (The update itself takes the
// short beams then and the belief drifts towards the unmapped wall until the other beams stop
// fitting: the detector fires some 20 scans later, rightly.) With fewer other beams than
// short_beams_min_others, or without the check, it fires at the first scan.
TEST(LostDetector, ADetectionNeedsTheBeamsOtherThanTheShortOnesToMisfitToo) {
  std::vector<SensorUpdateStats> stats;
  const int first = FirstLostScan(0.0, &stats);
  EXPECT_TRUE(first == -1 || first >= 10) << "said lost at scan " << first << " by the wall";
  ASSERT_FALSE(stats.empty());
  EXPECT_EQ(stats.front().beams_filtered, 0) << "the update kept the short beams";
  EXPECT_TRUE(std::isfinite(stats.front().surprise_without_short_per_beam));
  EXPECT_GT(stats.front().surprise_without_short_per_beam, stats.front().surprise_per_beam);
  EXPECT_EQ(FirstLostScan(0.0, nullptr, true, /*short_beams_min_others=*/6), 0);
  EXPECT_EQ(FirstLostScan(0.0, nullptr, /*judge_without_short_beams=*/false), 0);
}

}  // namespace
}  // namespace markov_localization

namespace markov_localization {
namespace {

// The half-turn twins of bonn_department's corridor must be indistinguishable to the model:
// every expected range of a corridor cell equals its twin cell's in the opposite direction.
// (Rounding ranges that lie on a bin's half-way point once broke this for 1.8% of the entries
// at 15 cm, and 24 beams turned that into certainty about one twin.)
// At the resolutions used, with the sonar physics: an even ray_cast_subdivision put the cell
// centres on fine-raster borders, where the ray cast's start cell is not half-turn symmetric;
// at 20 and 25 cm 24 and 16 entries differed here with 4, and in the evaluation's perfectly
// symmetric world the belief picked one twin at 25 cm. The node uses 5.
TEST(SensorModel, HalfTurnTwinsOfTheCorridorHaveIdenticalExpectedRanges) {
  const auto world = testing::LoadWorld("bonn_department");
  struct Case {
    double resolution_m;
    int headings;
    bool sonar_physics;
  };
  // (A single diffuse ray differs in 104 and 70 entries at 20 and 25 cm with 5, in 24 and 16
  // with 4: not the node's model, see README "Missing".)
  for (const Case& k :
       {Case{0.15, 180, false}, Case{0.15, 180, true}, Case{0.2, 72, true}, Case{0.25, 72, true}}) {
    MapModelParameters mp;
    mp.resolution_m = k.resolution_m;
    if (k.sonar_physics) mp.ray_cast_subdivision = 5;  // as the node
    const MapModel map = MapModel::FromWorld(world, mp);
    SensorModelParameters sp;
    sp.beam_angles_rad = SonarRingAngles(24);
    if (k.sonar_physics) {
      sp.beam_width_rad = 0.53;
      sp.critical_angle_rad = 0.35;
    }
    const SensorModel sensor(map, k.headings, sp);
    std::size_t compared = 0, different = 0;
    for (int iy = 0; iy < map.height(); ++iy)
      for (int ix = 0; ix < map.width(); ++ix) {
        const Vec2 c = map.CellCentre(ix, iy);
        if (c.y() < 9.0 || c.y() > 11.0 || !map.IsState(ix, iy)) continue;
        const int jx = map.width() - 1 - ix, jy = map.height() - 1 - iy;
        ASSERT_TRUE(map.IsState(jx, jy)) << c.transpose();
        ASSERT_NEAR((map.CellCentre(jx, jy) - Vec2(27.0 - c.x(), 20.0 - c.y())).norm(), 0.0, 1e-9);
        for (int d = 0; d < k.headings; ++d, ++compared)
          different += sensor.ExpectedBin(d, map.Index(ix, iy)) !=
                       sensor.ExpectedBin((d + k.headings / 2) % k.headings, map.Index(jx, jy));
      }
    EXPECT_GT(compared, 10000u) << k.resolution_m;
    EXPECT_EQ(different, 0u) << "resolution " << k.resolution_m << " m, sonar physics "
                             << k.sonar_physics;
  }
}

}  // namespace
}  // namespace markov_localization
