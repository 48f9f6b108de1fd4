// The node's pipeline (Localizer): the motion gate, readings of two sensors, the published
// estimate through a fixed map -> odom, map replacement.
#include <gtest/gtest.h>

#include "markov_localization/localizer.h"
#include "markov_localization/odometry_buffer.h"
#include "test_helpers.h"

namespace markov_localization {
namespace {

// A 30-beam laser 0.15 m ahead of the centre over +-90 degrees, max 25 m.
SensorModelParameters Laser() {
  SensorModelParameters sp;
  for (int i = 0; i < 31; ++i) {
    sp.beam_angles_rad.push_back(-M_PI / 2 + M_PI * i / 30);
    sp.beam_origins_m.push_back(Vec2(0.15, 0.0));
  }
  sp.max_range_m = 25.0;
  return sp;
}

std::vector<double> LaserScan(const MapModel& map, const SensorModelParameters& sp,
                              const Pose2& pose, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<double> z;
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  for (std::size_t b = 0; b < sp.beam_angles_rad.size(); ++b) {
    const Vec2& o = sp.beam_origins_m[b];
    const Vec2 from = pose.Position() + Vec2(c * o.x() - s * o.y(), s * o.x() + c * o.y());
    const double r = map.RayCast(from, pose.yaw + sp.beam_angles_rad[b], sp.max_range_m);
    z.push_back(r < sp.max_range_m ? r + noise(rng) : INFINITY);
  }
  return z;
}

struct Corridor {
  double max_error = 0.0, mean_error = 0.0, max_stuck_m = 0.0;
  int updates = 0;
};

// Drives 36 m east along crossing_corridors' 42 m hallway at 0.5 m/s with a scan at 10 Hz (5 cm
// apart), odometry 2% long and turning 0.5 degrees per metre; the published estimate's error
// and the longest distance driven while the estimate stayed within one cell.
struct Hallway {
  Hallway() {
    auto loaded =
        spott_map::LoadWorldFile(std::string(EVAL_WORLDS_DIR) + "/crossing_corridors.yaml");
    if (!loaded.ok()) throw std::runtime_error("crossing_corridors");
    MapModelParameters mp;
    mp.resolution_m = 0.15;
    mp.ray_cast_subdivision = 5;
    mp.state_clearance_m = 0.26;
    map = std::make_shared<const MapModel>(MapModel::FromWorld(*loaded.world, mp));
    sp = Laser();
    sp.max_range_m = 12.0;
    models = LocalizationModels::Build(map, {sp}, 90);
  }
  std::shared_ptr<const MapModel> map;
  SensorModelParameters sp;
  std::shared_ptr<const LocalizationModels> models;
};

Corridor DriveTheHallway(const Hallway& h, double update_min_d_m) {
  const auto& map = h.map;
  const auto& sp = h.sp;
  const auto& models = h.models;
  LocalizerParameters lp;
  lp.grid.angular_resolution_rad = 2 * M_PI / 90;
  lp.gate.update_min_d_m = update_min_d_m;
  lp.gate.update_min_a_rad = update_min_d_m > 0 ? M_PI / 6 : 0.0;
  Localizer loc(models, lp);
  Pose2 truth{3.0, 16.0, 0.0}, odom{0.0, 0.0, 0.0};
  loc.SetGaussian(truth, 0.1, 0.05);
  std::mt19937 rng(4);
  Corridor out;
  Vec2 stuck_at = truth.Position();
  double stuck_since_x = truth.x, sum = 0.0;
  int n = 0;
  for (int step = 0; truth.x < 39.0; ++step) {
    truth.x += 0.05;
    odom.x += 0.05 * 1.02 * std::cos(odom.yaw);
    odom.y += 0.05 * 1.02 * std::sin(odom.yaw);
    odom.yaw += 0.05 * 0.5 * M_PI / 180.0;
    loc.OnReading(0, LaserScan(*map, sp, truth, rng), odom, 0.1 * step);
    const Pose2 e = loc.Estimate(odom);
    const double err = (e.Position() - truth.Position()).norm();
    out.max_error = std::max(out.max_error, err);
    sum += err;
    ++n;
    if ((e.Position() - stuck_at).norm() > 0.15) {
      stuck_at = e.Position();
      stuck_since_x = truth.x;
    }
    out.max_stuck_m = std::max(out.max_stuck_m, truth.x - stuck_since_x);
  }
  out.mean_error = sum / n;
  out.updates = loc.updates();
  return out;
}

TEST(Localizer, TheMotionGateEndsTheCorridorLock) {
  const Hallway hallway;
  const Corridor gated = DriveTheHallway(hallway, 0.2);
  const Corridor every_scan = DriveTheHallway(hallway, 0.0);
  std::printf(
      "  gated: max %.2f m, mean %.3f m, stuck %.2f m, %d updates; every scan: max %.2f "
      "m, mean %.3f m, stuck %.2f m, %d updates\n",
      gated.max_error, gated.mean_error, gated.max_stuck_m, gated.updates, every_scan.max_error,
      every_scan.mean_error, every_scan.max_stuck_m, every_scan.updates);
  // Updates every 0.2 m of odometry (4 scans of 5 cm).
  EXPECT_NEAR(gated.updates, 36.0 * 1.02 / 0.2, 10);
  EXPECT_LT(gated.max_error, 0.4);
  EXPECT_LT(gated.mean_error, 0.08);
  // The estimate never sits on one place while the robot drives on (the lock held it for 3-5 m
  // in the runs; here, updated at every scan, it sits for over a metre).
  EXPECT_LT(gated.max_stuck_m, 0.6);
  EXPECT_GT(every_scan.max_stuck_m, 2 * gated.max_stuck_m);
}

// bonn_department at 25 cm, and the B21's 24 sonars.
std::shared_ptr<const MapModel> Bonn25() {
  MapModelParameters mp;
  mp.resolution_m = 0.25;
  return std::make_shared<const MapModel>(
      MapModel::FromWorld(testing::LoadWorld("bonn_department"), mp));
}
SensorModelParameters Sonar24() {
  SensorModelParameters sonar;
  sonar.beam_angles_rad = SonarRingAngles(24);
  return sonar;
}

TEST(Localizer, TwoSensorsJoinOneUpdateAndTheEstimateFollowsTheOdometryBetween) {
  const auto map = Bonn25();
  const SensorModelParameters sonar = Sonar24();
  const SensorModelParameters laser = Laser();
  auto models = LocalizationModels::Build(map, {sonar, laser}, 72);
  LocalizerParameters lp;
  lp.grid.angular_resolution_rad = 2 * M_PI / 72;
  lp.gate.standing_interval_s = 2.0;
  Localizer loc(models, lp);
  const Pose2 truth{17.0, 6.0, -M_PI / 2};
  loc.SetGaussian(truth, 0.2, 0.1);
  std::mt19937 rng(1);
  const Pose2 odom{1.0, 2.0, 0.3};
  const auto ring = testing::SimulateScan(*map, sonar, truth, 0.03, rng);
  // A new belief updates at the next readings whatever the gate says, once both sensors have
  // one: the ring waits for the scan of the same moment.
  EXPECT_FALSE(loc.OnReading(0, ring, odom, 0.0).updated);
  LocalizerStep s = loc.OnReading(1, LaserScan(*map, laser, truth, rng), odom, 0.0);
  EXPECT_TRUE(s.updated);
  EXPECT_EQ(s.sensors_used, 2);
  EXPECT_EQ(s.stats.beams + s.stats.beams_filtered, 24 + 31);
  EXPECT_GT(loc.summary().certainty.certainty, 0.8);
  // Standing: no update until standing_interval_s (2 s) passed; then the ring waits for the
  // scan, and when the ring comes again first the update runs without the scan.
  EXPECT_FALSE(loc.OnReading(0, ring, odom, 1.0).updated);
  EXPECT_FALSE(loc.OnReading(0, ring, odom, 2.1).updated);
  s = loc.OnReading(0, ring, odom, 2.2);
  EXPECT_TRUE(s.updated);
  EXPECT_EQ(s.sensors_used, 1);
  // Between updates map -> odom stays and the estimate moves with the odometry.
  const Pose2 before = loc.Estimate(odom);
  const Pose2 moved{odom.x + 0.1 * std::cos(odom.yaw), odom.y + 0.1 * std::sin(odom.yaw), odom.yaw};
  EXPECT_FALSE(loc.OnReading(0, ring, moved, 2.3).updated);
  const Pose2 after = loc.Estimate(moved);
  EXPECT_NEAR((after.Position() - before.Position()).norm(), 0.1, 1e-9);
  EXPECT_LT((before.Position() - truth.Position()).norm(), 0.15);
  EXPECT_THROW(loc.OnReading(2, ring, odom, 3.0), std::invalid_argument);
  EXPECT_THROW(loc.OnReading(0, {1.0, 2.0}, odom, 3.0), std::invalid_argument);
}

// A pan-tilt range profiler (QUADRIS) as the node feeds it: a beam at every heading bin from the
// robot's centre, the profile's points binned by direction, every other bin NaN (no reading).
std::vector<double> Profile(const MapModel& map, int bins, const Pose2& pose, double from_rad,
                            double to_rad) {
  std::vector<double> z(bins, std::nan(""));
  for (int b = 0; b < bins; ++b) {
    double a = 2 * M_PI * b / bins;
    if (a > M_PI) a -= 2 * M_PI;
    if (a < from_rad || a > to_rad) continue;
    const double r = map.RayCast(pose.Position(), pose.yaw + a, 4.0);
    z[b] = r < 4.0 ? r : INFINITY;
  }
  return z;
}

TEST(Localizer, ASlowlyDrivingRobotUpdatesByTheGateAndOnlyAStandingOneByTheInterval) {
  const auto map = Bonn25();
  const SensorModelParameters sonar = Sonar24();
  LocalizerParameters lp;
  lp.grid.angular_resolution_rad = 2 * M_PI / 72;
  lp.gate.standing_interval_s = 0.5;
  Localizer loc(LocalizationModels::Build(map, {sonar}, 72), lp);
  Pose2 truth{17.0, 4.0, M_PI / 2};
  loc.SetGaussian(truth, 0.2, 0.1);
  std::mt19937 rng(1);
  Pose2 odom{0.0, 0.0, 0.0};
  EXPECT_TRUE(
      loc.OnReading(0, testing::SimulateScan(*map, sonar, truth, 0.03, rng), odom, 0.0).updated);
  // 0.12 m/s, a ring every 0.5 s (6 cm): an update every 0.2 m, not at every interval (which
  // brought the corridor lock back: sub-cell steps re-peaked at cell centres).
  int updates = 0;
  double t = 0.0;
  for (int k = 1; k <= 8; ++k) {
    truth.y += 0.06;
    odom.x += 0.06;
    updates +=
        loc.OnReading(0, testing::SimulateScan(*map, sonar, truth, 0.03, rng), odom, t += 0.5)
            .updated;
  }
  EXPECT_EQ(updates, 2);
  // Standing, it updates every 0.5 s (the first reading still sees the last step's motion).
  updates = 0;
  loc.OnReading(0, testing::SimulateScan(*map, sonar, truth, 0.03, rng), odom, t += 0.5);
  for (int k = 0; k < 4; ++k)
    updates +=
        loc.OnReading(0, testing::SimulateScan(*map, sonar, truth, 0.03, rng), odom, t += 0.5)
            .updated;
  EXPECT_EQ(updates, 4);
}

// A respawned node sets its belief at the odometry of its start, then builds its models for
// seconds while the robot drives on: the first update moves the belief by that odometry.
TEST(Localizer, ABeliefSetAtAnOdometryMovesWithTheOdometrySinceThen) {
  const auto map = Bonn25();
  const SensorModelParameters sonar = Sonar24();
  LocalizerParameters lp;
  lp.grid.angular_resolution_rad = 2 * M_PI / 72;
  Localizer loc(LocalizationModels::Build(map, {sonar}, 72), lp);
  std::mt19937 rng(1);
  loc.SetGaussian(Pose2{17.0, 4.0, M_PI / 2}, 0.2, 0.1, Pose2{1.0, 0.0, 0.0});
  Pose2 truth{17.0, 5.5, M_PI / 2}, odom{2.5, 0.0, 0.0};  // 1.5 m on at the first reading
  ASSERT_TRUE(
      loc.OnReading(0, testing::SimulateScan(*map, sonar, truth, 0.03, rng), odom, 1.0).updated);
  EXPECT_LT((loc.Estimate(odom).Position() - truth.Position()).norm(), 0.3);
  // Without an odometry the belief holds at the next reading's: the metre driven since the
  // last update belongs to the old belief.
  truth.y += 1.0;
  odom.x += 1.0;
  loc.SetGaussian(truth, 0.2, 0.1);
  ASSERT_TRUE(
      loc.OnReading(0, testing::SimulateScan(*map, sonar, truth, 0.03, rng), odom, 2.0).updated);
  EXPECT_LT((loc.Estimate(odom).Position() - truth.Position()).norm(), 0.3);
}

TEST(Localizer, AnOpenGateWaitsJoinSForASlowSensorAndJoinsOnlyReadingsTakenSinceItOpened) {
  const auto map = Bonn25();
  const SensorModelParameters sonar = Sonar24();
  SensorModelParameters profiler;
  for (int b = 0; b < 72; ++b) profiler.beam_angles_rad.push_back(2 * M_PI * b / 72);
  profiler.max_range_m = 4.0;
  auto models = LocalizationModels::Build(map, {sonar, profiler}, 72);
  LocalizerParameters lp;
  lp.grid.angular_resolution_rad = 2 * M_PI / 72;
  lp.gate.standing_interval_s = 0.0;
  lp.gate.join_s = 0.6;
  lp.unjudged_sensors = {1};
  Localizer loc(models, lp);
  Pose2 truth{17.0, 4.0, M_PI / 2};  // room B, facing its door
  loc.SetGaussian(truth, 0.2, 0.1);
  std::mt19937 rng(1);
  Pose2 odom{1.0, 2.0, 0.3};
  const auto ahead = [&](double d) {
    truth.y += d;
    odom.x += d * std::cos(odom.yaw);
    odom.y += d * std::sin(odom.yaw);
  };
  const auto ring = [&] { return testing::SimulateScan(*map, sonar, truth, 0.03, rng); };
  // The new belief opens the gate: the rings wait for a profile up to join_s (0.6 s) ...
  EXPECT_FALSE(loc.OnReading(0, ring(), odom, 0.0).updated);
  EXPECT_FALSE(loc.OnReading(0, ring(), odom, 0.1).updated);
  // ... which joins the newest ring when it comes.
  LocalizerStep s = loc.OnReading(1, Profile(*map, 72, truth, -0.35, 0.35), odom, 0.3);
  EXPECT_TRUE(s.updated);
  EXPECT_EQ(s.sensors_used, 2);
  EXPECT_EQ(s.stats.beams + s.stats.beams_filtered, 24 + 9);
  // A profile taken 0.1 m on, before the gate opens again, is not joined: 0.25 m further the
  // gate opens, and without a new profile the ring updates alone once join_s has passed.
  ahead(0.1);
  EXPECT_FALSE(loc.OnReading(1, Profile(*map, 72, truth, -0.35, 0.35), odom, 0.6).updated);
  ahead(0.15);
  EXPECT_FALSE(loc.OnReading(0, ring(), odom, 1.0).updated);
  EXPECT_FALSE(loc.OnReading(0, ring(), odom, 1.3).updated);
  s = loc.OnReading(0, ring(), odom, 1.6);
  EXPECT_TRUE(s.updated);
  EXPECT_EQ(s.sensors_used, 1);
  EXPECT_LT((loc.Estimate(odom).Position() - truth.Position()).norm(), 0.2);
  EXPECT_GT(loc.summary().certainty.certainty, 0.8);
  // Profiles across something the map lacks (every sample 0.5 m ahead) are no kidnap: the lost
  // detector does not judge the profiler; the distance filter leaves the samples out and the
  // pose is not refined towards them.
  std::vector<double> desk(72, std::nan(""));
  for (int b = -4; b <= 4; ++b) desk[(b + 72) % 72] = 0.5;
  double t = 1.6;
  for (int k = 0; k < 2; ++k) {
    ahead(0.05);
    EXPECT_FALSE(loc.OnReading(0, ring(), odom, t += 0.1).updated);  // under the gate's 0.2 m
    ahead(0.2);
    EXPECT_FALSE(loc.OnReading(0, ring(), odom, t += 0.1).updated);  // waits for a profile
    s = loc.OnReading(1, desk, odom, t += 0.2);
    EXPECT_TRUE(s.updated);
    EXPECT_EQ(s.sensors_used, 2);
    EXPECT_FALSE(s.lost) << s.lost_reason;
    EXPECT_GE(s.stats.beams_filtered, 9);
  }
  EXPECT_THROW(loc.OnReading(2, desk, odom, t), std::invalid_argument);
}

// A door's state changes in the map database: the models are built from the current ones,
// casting only the rays that can reach the door, and equal a full build bin for bin (sonar
// physics: cone and specular second legs; the doorway's cells leave or join the states).
TEST(LocalizationModels, AnIncrementalBuildEqualsAFullOneAndCastsFewRays) {
  const spott_map::World world = testing::LoadWorld("cim_office");
  MapModelParameters mp;
  mp.resolution_m = 0.25;
  mp.ray_cast_subdivision = 5;
  auto open = std::make_shared<const MapModel>(MapModel::FromWorld(world, mp));
  spott_map::MapDatabase db = spott_map::MapDatabase::FromWorld(world);
  ASSERT_TRUE(db.SetDoorState("d_lab_w", spott_map::DoorState::kClosed));
  auto closed = std::make_shared<const MapModel>(MapModel::FromDatabase(world, db, mp));
  ASSERT_TRUE(closed->SameRaster(*open));
  ASSERT_TRUE(closed->OccupancyChangedFrom(*open));
  SensorModelParameters sonar;
  sonar.beam_angles_rad = SonarRingAngles(16);
  sonar.sensor_offset_m = 0.2;
  sonar.max_range_m = 6.5;
  sonar.beam_width_rad = 0.4;
  sonar.critical_angle_rad = 0.4;
  const int nt = 72;
  const auto full_open = LocalizationModels::Build(open, {sonar}, nt);
  const auto full_closed = LocalizationModels::Build(closed, {sonar}, nt);
  const auto closing = LocalizationModels::Build(closed, {sonar}, nt, full_open);
  const auto opening = LocalizationModels::Build(open, {sonar}, nt, closing);
  const auto same = [&](const LocalizationModels& a, const LocalizationModels& b) {
    const SensorModel& x = *a.sensors[0];
    const SensorModel& y = *b.sensors[0];
    int differ = 0;
    for (int d = 0; d < nt; ++d)
      for (std::size_t c = 0; c < a.map->NumCells(); ++c)
        differ += x.ExpectedBin(d, c) != y.ExpectedBin(d, c);
    EXPECT_EQ(differ, 0);
    for (int z = 0; z < x.num_bins(); ++z) {
      EXPECT_NEAR(x.AverageLikelihood(z), y.AverageLikelihood(z), 1e-12);
      for (int e = 0; e < x.num_bins(); ++e) EXPECT_EQ(x.Ratio(e, z), y.Ratio(e, z));
    }
  };
  same(*closing, *full_closed);
  same(*opening, *full_open);
  // Tables that must differ do (the beam through the doorway), and few rays were cast.
  bool through = false;
  for (int d = 0; d < nt; ++d)
    for (std::size_t c = 0; c < open->NumCells(); ++c)
      through = through || full_open->sensors[0]->ExpectedBin(d, c) !=
                               full_closed->sensors[0]->ExpectedBin(d, c);
  EXPECT_TRUE(through);
  EXPECT_LT(closing->sensors[0]->rays_cast(), full_closed->sensors[0]->rays_cast() / 10)
      << closing->sensors[0]->rays_cast() << " of " << full_closed->sensors[0]->rays_cast();
  EXPECT_LT(opening->sensors[0]->rays_cast(), full_open->sensors[0]->rays_cast() / 10);
  // Another raster: a full build.
  MapModelParameters coarse = mp;
  coarse.resolution_m = 0.3;
  auto other = std::make_shared<const MapModel>(MapModel::FromWorld(world, coarse));
  const auto rebuilt = LocalizationModels::Build(other, {sonar}, nt, full_open);
  EXPECT_EQ(rebuilt->sensors[0]->rays_cast(), other->NumStateCells() * nt);
}

TEST(Localizer, ANewMapKeepsTheBeliefWhereTheStatesRemain) {
  // bonn_department; then door_b closes (a map update): the belief in room B stays there.
  spott_map::World world = testing::LoadWorld("bonn_department");
  MapModelParameters mp;
  mp.resolution_m = 0.25;
  auto map = std::make_shared<const MapModel>(MapModel::FromWorld(world, mp));
  SensorModelParameters sonar;
  sonar.beam_angles_rad = SonarRingAngles(24);
  LocalizerParameters lp;
  lp.grid.angular_resolution_rad = 2 * M_PI / 72;
  Localizer loc(LocalizationModels::Build(map, {sonar}, 72), lp);
  const Pose2 truth{17.0, 6.0, -M_PI / 2};
  loc.SetGaussian(truth, 0.2, 0.1);
  spott_map::MapDatabase db = spott_map::MapDatabase::FromWorld(world);
  ASSERT_TRUE(db.SetDoorState("door_b", spott_map::DoorState::kClosed));
  auto closed = std::make_shared<const MapModel>(MapModel::FromDatabase(world, db, mp));
  EXPECT_LT(closed->NumStateCells(), map->NumStateCells());  // the doorway's cells went
  loc.ReplaceModels(LocalizationModels::Build(closed, {sonar}, 72));
  EXPECT_EQ(&loc.models().map->state_mask(), &closed->state_mask());
  const PositionCertainty c = PosCertainty(BeliefSnapshot::Of(loc.grid()), CertaintyParameters{});
  EXPECT_GT(c.certainty, 0.8);
  EXPECT_LT((c.estimate.Position() - truth.Position()).norm(), 0.2);
  EXPECT_FALSE(loc.lost());
  // The door is closed in the new map: north from room B the beam stops at its leaf (y = 9)
  // instead of the corridor's far wall (y = 11).
  EXPECT_NEAR(closed->RayCast(Vec2(17.5, 8.0), M_PI / 2, 5.0), 0.975, 0.06);
  EXPECT_NEAR(map->RayCast(Vec2(17.5, 8.0), M_PI / 2, 5.0), 2.925, 0.06);
}

}  // namespace
}  // namespace markov_localization

namespace markov_localization {
namespace {

TEST(OdometryBuffer, ThePoseAtAReadingsTimeIsInterpolatedTheShortWayRound) {
  OdometryBuffer odo(2.0);
  EXPECT_FALSE(odo.At(0.0));
  odo.Add(1.0, Pose2{0.0, 0.0, 3.0});
  odo.Add(1.1, Pose2{0.1, 0.0, -3.0});  // turned 0.28 rad through +-pi
  odo.Add(1.2, Pose2{0.2, 0.2, -2.9});
  const Pose2 mid = *odo.At(1.05);
  EXPECT_NEAR(mid.x, 0.05, 1e-12);
  EXPECT_NEAR(std::abs(mid.yaw), M_PI, 1e-9);  // half way: pi, not 0
  EXPECT_NEAR(odo.At(1.15)->y, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(odo.At(0.5)->x, 0.0);  // before the oldest: the oldest
  EXPECT_DOUBLE_EQ(odo.At(9.0)->x, 0.2);  // after the newest: the newest
  odo.Add(5.0, Pose2{1.0, 1.0, 0.0});     // the old poses fall out of the 2 s window
  EXPECT_DOUBLE_EQ(odo.At(1.05)->x, 0.2);
  odo.Add(0.5, Pose2{7.0, 7.0, 0.0});  // time went back: only the new pose is kept
  EXPECT_DOUBLE_EQ(odo.At(5.0)->x, 7.0);
}

// A respawned node read a ring stamped 17 s after its newest odometry (queued while it built
// its models) and paired it with that odometry: its estimate stayed 1 m behind the robot.
TEST(OdometryBuffer, AReadingAheadOfTheOdometryHasNoPoseYet) {
  OdometryBuffer odo(2.0);
  EXPECT_FALSE(odo.At(1.0, 0.25));
  odo.Add(1.0, Pose2{0.0, 0.0, 0.0});
  odo.Add(1.1, Pose2{0.1, 0.0, 0.0});
  EXPECT_NEAR(odo.At(1.05, 0.25)->x, 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(odo.At(1.3, 0.25)->x, 0.1);  // within the lag: the newest
  EXPECT_FALSE(odo.At(1.4, 0.25));
  EXPECT_FALSE(odo.At(18.0, 0.25));
  odo.Add(18.0, Pose2{8.0, 0.0, 0.0});  // it arrived
  EXPECT_DOUBLE_EQ(odo.At(18.0, 0.25)->x, 8.0);
}

}  // namespace
}  // namespace markov_localization
