#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "robot_sim/node_parameters.h"
#include "robot_sim/simulator.h"
#include "test_world.h"

namespace robot_sim {
namespace {

using testing::PackageFile;

RobotSpec Load(const std::string& name) {
  auto r = LoadRobotSpec(PackageFile("config/robots/" + name + ".yaml"),
                         PackageFile("urdf/" + name + ".urdf"));
  if (!r.ok()) throw std::runtime_error(spott_map::FormatErrors(r.errors));
  return *r.spec;
}

std::unique_ptr<SimWorld> MakeWorld(const spott_map::World& w) {
  SimWorldParameters p;
  p.octomap_resolution_m = 0.1;
  auto world = std::make_unique<SimWorld>(p);
  world->Build(w);
  return world;
}

class SimulatorTest : public ::testing::Test {
 protected:
  void Start(const std::string& robot, spott_map::Pose2 pose, OdometryErrorModel odo = {}) {
    sim_ = std::make_unique<Simulator>(MakeWorld(testing::TestWorld()));
    std::string error;
    auto index = sim_->AddRobot(Load(robot), pose, odo, &error);
    ASSERT_TRUE(index) << error;
    id_ = *index;
  }
  void Run(double seconds, double dt = 0.01) {
    const int steps = static_cast<int>(std::lround(seconds / dt));
    for (int i = 0; i < steps; ++i) sim_->Step(dt, rng_);
  }
  std::unique_ptr<Simulator> sim_;
  int id_ = 0;
  Rng rng_{1};
};

TEST_F(SimulatorTest, DrivingIntoAWallStopsTheRobotAndPressesTheBumperFacingIt) {
  Start("nomad200", {8.0, 4.5, 0.0});
  ASSERT_TRUE(sim_->SetCommand(id_, {0.5, 0.0}, nullptr));
  Run(10.0);
  // The shell touches the wall face x = 9.95: centre at 9.95 - 0.2285.
  EXPECT_NEAR(sim_->GroundTruth(id_).x, 9.95 - 0.2285, 0.002);
  EXPECT_NEAR(sim_->GroundTruth(id_).y, 4.5, 1e-9);
  EXPECT_TRUE(sim_->Stalled(id_));
  EXPECT_EQ(sim_->Velocity(id_).v, 0.0);
  const auto bumper = sim_->Bumper(id_);
  ASSERT_EQ(bumper.size(), 20u);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(bumper[i], i == 0) << "segment " << i;
  // Backing off frees it.
  sim_->SetCommand(id_, {-0.2, 0.0}, nullptr);
  Run(1.0);
  EXPECT_FALSE(sim_->Stalled(id_));
  for (bool b : sim_->Bumper(id_)) EXPECT_FALSE(b);
}

TEST_F(SimulatorTest, TheBodyContactIsKnownForARobotWithoutABumper) {
  // The B-12 has sonars only: the ground truth still says where its body touches.
  Start("b12", {8.0, 4.5, 0.0});
  EXPECT_TRUE(sim_->Bumper(id_).empty());
  EXPECT_TRUE(sim_->BodyContacts(id_).empty());
  ASSERT_TRUE(sim_->SetCommand(id_, {0.4, 0.0}, nullptr));
  Run(10.0);
  // The shell touches the wall face x = 9.95, straight ahead.
  EXPECT_NEAR(sim_->GroundTruth(id_).x, 9.95 - 0.1525, 0.002);
  const auto contacts = sim_->BodyContacts(id_);
  ASSERT_FALSE(contacts.empty());
  for (double a : contacts) EXPECT_NEAR(a, 0.0, 0.3);
  sim_->SetCommand(id_, {-0.2, 0.0}, nullptr);
  Run(1.0);
  EXPECT_TRUE(sim_->BodyContacts(id_).empty());
}

TEST_F(SimulatorTest, BumperSegmentFollowsTheContactAngleInTheRobotFrame) {
  // Heading 36 degrees left of the wall normal: the wall is at -36 degrees, segment 18.
  Start("nomad200", {8.5, 0.8, 36 * M_PI / 180});  // meets the east wall near y = 1.7
  sim_->SetCommand(id_, {0.3, 0.0}, nullptr);
  Run(10.0);
  const auto bumper = sim_->Bumper(id_);
  EXPECT_TRUE(bumper[18]);
  EXPECT_FALSE(bumper[0]);
  EXPECT_FALSE(bumper[5]);
}

TEST_F(SimulatorTest, NanCommandIsRefusedAndTheRobotStops) {
  Start("nomad200", {2.0, 3.0, 0.0});
  sim_->SetCommand(id_, {0.3, 0.0}, nullptr);
  Run(2.0);
  EXPECT_NEAR(sim_->Velocity(id_).v, 0.3, 1e-9);
  std::string error;
  EXPECT_FALSE(sim_->SetCommand(id_, {NAN, 0.0}, &error));
  EXPECT_NE(error.find("refused"), std::string::npos);
  Run(2.0);
  EXPECT_EQ(sim_->Velocity(id_).v, 0.0);
  EXPECT_FALSE(sim_->SetCommand(id_, {0.0, 1e9}, &error));
}

TEST_F(SimulatorTest, KidnapMovesTheRobotWithoutTheOdometrySeeingIt) {
  Start("b21", {3.0, 3.0, 0.0});
  const spott_map::Pose2 odo_before = sim_->odometry(id_).pose();
  std::string error;
  // RHINO's experiment: turned about 70 degrees to the right.
  ASSERT_TRUE(sim_->Kidnap(id_, {0.0, 0.0, -70 * M_PI / 180}, true, &error)) << error;
  EXPECT_NEAR(sim_->GroundTruth(id_).yaw, -70 * M_PI / 180, 1e-12);
  EXPECT_EQ(sim_->odometry(id_).pose().yaw, odo_before.yaw);
  ASSERT_TRUE(sim_->Kidnap(id_, {5.0, 2.0, 1.0}, false, &error));
  EXPECT_EQ(sim_->GroundTruth(id_).x, 5.0);
  EXPECT_EQ(sim_->odometry(id_).pose().x, odo_before.x);
}

TEST_F(SimulatorTest, KidnapIntoAWallOrOutsideTheMapIsRefusedAndNothingChanges) {
  Start("b21", {3.0, 3.0, 0.0});
  std::string error;
  EXPECT_FALSE(sim_->Kidnap(id_, {9.9, 1.0, 0.0}, false, &error));
  EXPECT_NE(error.find("inside"), std::string::npos);
  EXPECT_FALSE(sim_->Kidnap(id_, {7.0, 1.0, 0.0}, false, &error));  // the crate
  EXPECT_NE(error.find("crate"), std::string::npos);
  EXPECT_FALSE(sim_->Kidnap(id_, {-5.0, 3.0, 0.0}, false, &error));
  EXPECT_NE(error.find("outside"), std::string::npos);
  EXPECT_FALSE(sim_->Kidnap(id_, {NAN, 3.0, 0.0}, false, &error));
  EXPECT_EQ(sim_->GroundTruth(id_).x, 3.0);
  EXPECT_EQ(sim_->GroundTruth(id_).y, 3.0);
}

TEST_F(SimulatorTest, SensorDropoutLastsItsDurationAndUnknownSensorsAreErrors) {
  Start("nomad200", {5.0, 3.0, 0.0});
  const RangeRingSpec& sonar = *sim_->spec(id_).FindRing("sonar");
  std::string error;
  ASSERT_TRUE(sim_->InjectFault(id_, "sonar/3", {FaultKind::kDropout, 0.0, 1.0}, &error)) << error;
  auto r = sim_->SenseRing(id_, sonar, rng_);
  EXPECT_TRUE(std::isnan(r[2]));
  EXPECT_FALSE(std::isnan(r[1]));
  Run(1.5);
  r = sim_->SenseRing(id_, sonar, rng_);
  EXPECT_FALSE(std::isnan(r[2]));
  EXPECT_FALSE(sim_->InjectFault(id_, "sonar/17", {}, &error));
  EXPECT_FALSE(sim_->InjectFault(id_, "lidar", {}, &error));
  EXPECT_NE(error.find("lidar"), std::string::npos);
}

TEST_F(SimulatorTest, QuadrisHeadsPointAndProfile) {
  // Nomad at (8.95 - 0.05 - 1, 4.5) facing east: quadris_1 is 0.05 m ahead of the centre, so its
  // horizontal profile meets the east wall face (x = 9.95) 1 m ahead in its middle.
  Start("nomad200", {9.95 - 1.0 - 0.05, 4.5, 0.0});
  ASSERT_EQ(sim_->spec(id_).profilers.size(), 2u);
  std::vector<double> angles;
  auto r = sim_->SenseProfile(id_, 0, true, rng_, &angles);
  ASSERT_EQ(r.size(), 64u);
  EXPECT_NEAR(r[31], 1.0 / std::cos(angles[31]), 0.03);
  // Panned 90 degrees left it looks up the room: the north wall face y = 5.95 is 1.35 m away.
  ASSERT_TRUE(sim_->PointHead(id_, 0, M_PI / 2, 0.0));
  r = sim_->SenseProfile(id_, 0, true, rng_, &angles);
  EXPECT_NEAR(r[31], (5.95 - 4.6) / std::cos(angles[31]), 0.03);
  EXPECT_FALSE(sim_->PointHead(id_, 2, 0.0, 0.0));
  EXPECT_FALSE(sim_->PointHead(id_, 0, NAN, 0.0));
  ASSERT_TRUE(sim_->InjectFault(id_, "quadris_1", {FaultKind::kDropout, 0.0, 10.0}, nullptr));
  EXPECT_TRUE(std::isnan(sim_->SenseProfile(id_, 0, false, rng_, nullptr)[0]));
}

TEST_F(SimulatorTest, ReplacingTheWorldKeepsTheRobotOrRefusesAndKeepsEverything) {
  Start("b21", {3.0, 3.0, 0.0});
  const auto open_world = spott_map::LoadWorldFromString(
      "world: {name: hall}\nwalls: {from_rooms: true}\n"
      "rooms: [{id: r, polygon: [[0, 0], [20, 0], [20, 6], [0, 6]]}]\n"
      "robot_start: {pose: [2, 2, 0]}\n",
      "hall.yaml");
  ASSERT_TRUE(open_world.ok());
  std::string error;
  ASSERT_TRUE(sim_->ReplaceWorld(*open_world.world, &error)) << error;
  Rng rng(1);
  // No wall at x = 10 any more: the laser straight ahead reaches x = 19.95.
  auto scan = sim_->SenseLaser(id_, rng);
  EXPECT_NEAR(scan[90], 19.95 - 3.0 - 0.15, 0.05);
  const auto blocked = spott_map::LoadWorldFromString(
      "world: {name: blocked}\nwalls: {from_rooms: true}\n"
      "rooms: [{id: r, polygon: [[0, 0], [20, 0], [20, 6], [0, 6]]}]\n"
      "objects: [{id: pillar, kind: cylinder, pose: [3, 3, 0], size: [0.5, 0.5], height: 2}]\n"
      "robot_start: {pose: [2, 2, 0]}\n",
      "blocked.yaml");
  ASSERT_TRUE(blocked.ok());
  EXPECT_FALSE(sim_->ReplaceWorld(*blocked.world, &error));
  EXPECT_NE(error.find("pillar"), std::string::npos);
  scan = sim_->SenseLaser(id_, rng);
  EXPECT_NEAR(scan[90], 19.95 - 3.0 - 0.15, 0.05);  // still the hall
}

TEST(NodeParametersTest, EveryViolationIsNamed) {
  SimNodeParameters p;
  EXPECT_EQ(ValidateParameters(p).size(), 1u);  // world_file is required
  p.world_file = "w.yaml";
  EXPECT_TRUE(ValidateParameters(p).empty());
  p.robot = "../etc";
  p.sensor_rate_hz = 0;
  p.real_time_factor = -1;
  p.odometry.linear_scale = 2;
  const auto e = ValidateParameters(p);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_NE(e[0].find("robot"), std::string::npos);
  EXPECT_NE(e[1].find("sensor_rate_hz"), std::string::npos);
  EXPECT_NE(e[2].find("real_time_factor"), std::string::npos);
  EXPECT_NE(e[3].find("odometry/linear_scale"), std::string::npos);
}

TEST(NodeParametersTest, MapToOdomComesFromTheTruthOrTheStartNotBoth) {
  SimNodeParameters p;
  p.world_file = "w.yaml";
  p.publish_start_map_to_odom = true;
  EXPECT_TRUE(ValidateParameters(p).empty());
  p.publish_truth_map_to_odom = true;
  ASSERT_EQ(ValidateParameters(p).size(), 1u);
  EXPECT_NE(ValidateParameters(p)[0].find("at most one"), std::string::npos);
}

// Found by robot_sim_parameters_fuzz: a real_time_factor of 5e-324 was accepted, and the loop's
// ros::WallDuration(step * dt / real_time_factor) throws beyond 2^31 s; a rate of 1e-300 Hz made
// lround(physics_rate_hz / rate) overflow (published on every step instead of never).
TEST(NodeParametersTest, PacesAndRatesTheLoopCannotKeepAreRefused) {
  SimNodeParameters p;
  p.world_file = "w.yaml";
  p.real_time_factor = 5e-324;
  EXPECT_EQ(ValidateParameters(p).size(), 1u);
  p.real_time_factor = 0.009;
  EXPECT_EQ(ValidateParameters(p).size(), 1u);
  p.real_time_factor = 0.01;
  EXPECT_TRUE(ValidateParameters(p).empty());
  p.real_time_factor = 0.0;  // as fast as possible
  EXPECT_TRUE(ValidateParameters(p).empty());
  for (double* rate : {&p.sensor_rate_hz, &p.laser_rate_hz, &p.odom_rate_hz, &p.profile_rate_hz,
                       &p.battery_rate_hz}) {
    const double kept = *rate;
    *rate = 1e-300;
    EXPECT_EQ(ValidateParameters(p).size(), 1u);
    *rate = 0.01;
    EXPECT_TRUE(ValidateParameters(p).empty());
    *rate = kept;
  }
}

TEST_F(SimulatorTest, TurretSlewsAtItsRateAndCarriesTheSonarRing) {
  // SPOTT's dense scan turns the turret in 2.5 degree steps; the turret turns at 0.79 rad/s.
  Start("nomad200", {5.0, 3.0, 0.0});
  sim_->SetTurretYaw(id_, M_PI / 2);
  Run(1.0);
  EXPECT_NEAR(sim_->turret_yaw(id_), 0.79, 1e-9);
  Run(2.0);
  EXPECT_NEAR(sim_->turret_yaw(id_), M_PI / 2, 1e-9);
  EXPECT_EQ(sim_->GroundTruth(id_).yaw, 0.0);  // the base did not turn
  // sonar_1 now faces north: the north wall face (y = 5.95) is 2.95 - 0.2285 m away.
  const RangeRingSpec& sonar = *sim_->spec(id_).FindRing("sonar");
  EXPECT_NEAR(sim_->SenseRing(id_, sonar, rng_)[0], 2.95 - 0.2285, 0.1);
}

TEST_F(SimulatorTest, StuckSensorRepeatsItsLastReading) {
  Start("nomad200", {5.0, 3.0, 0.0});
  const RangeRingSpec& sonar = *sim_->spec(id_).FindRing("sonar");
  const double before = sim_->SenseRing(id_, sonar, rng_)[0];
  ASSERT_TRUE(sim_->InjectFault(id_, "sonar", {FaultKind::kStuck, 0.0, 100.0}, nullptr));
  sim_->SetCommand(id_, {0.5, 0.0}, nullptr);
  Run(3.0);
  EXPECT_EQ(sim_->SenseRing(id_, sonar, rng_)[0], before);
  ASSERT_TRUE(sim_->ClearFault(id_, "sonar", nullptr));
  EXPECT_LT(sim_->SenseRing(id_, sonar, rng_)[0], before - 0.5);
}

// A noisy sensor still reports within what it can measure: a reading below min_range or
// beyond max_range would be published as a valid range (REP 117).
void ExpectWithinRange(const std::vector<double>& r, double lo, double hi, const char* what) {
  for (double v : r) {
    if (std::isnan(v) || v == std::numeric_limits<double>::infinity()) continue;
    EXPECT_GE(v, lo) << what;
    EXPECT_LE(v, hi) << what;
  }
}

TEST_F(SimulatorTest, NoiseFaultsKeepReadingsWithinTheSensorsRange) {
  Start("nomad200", {5.0, 3.0, 0.0});
  const RangeRingSpec& sonar = *sim_->spec(id_).FindRing("sonar");
  const ProfilerSpec& quadris = sim_->spec(id_).profilers.at(0);
  ASSERT_TRUE(sim_->InjectFault(id_, "sonar", {FaultKind::kNoise, 5.0, 100.0}, nullptr));
  ASSERT_TRUE(sim_->InjectFault(id_, quadris.name, {FaultKind::kNoise, 5.0, 100.0}, nullptr));
  for (int k = 0; k < 20; ++k) {
    ExpectWithinRange(sim_->SenseRing(id_, sonar, rng_), sonar.min_range, sonar.max_range, "sonar");
    ExpectWithinRange(sim_->SenseProfile(id_, 0, true, rng_, nullptr), quadris.min_range,
                      quadris.max_range, "quadris");
  }
  Start("b21", {3.0, 3.0, 0.0});
  const LaserSpec& laser = *sim_->spec(id_).laser;
  ASSERT_TRUE(sim_->InjectFault(id_, laser.name, {FaultKind::kNoise, 30.0, 100.0}, nullptr));
  for (int k = 0; k < 20; ++k) {
    ExpectWithinRange(sim_->SenseLaser(id_, rng_), laser.min_range, laser.max_range, "laser");
  }
}

TEST_F(SimulatorTest, OdometrySlipShortensTheMeasuredDistance) {
  Start("nomad200", {2.0, 3.0, 0.0});
  ASSERT_TRUE(sim_->Slip(id_, 0.5, 1.0, 100.0, nullptr));
  sim_->SetCommand(id_, {0.5, 0.0}, nullptr);
  Run(4.0);
  const double truth = sim_->GroundTruth(id_).x - 2.0;
  EXPECT_NEAR(sim_->odometry(id_).pose().x, 0.5 * truth, 1e-9);
  std::string error;
  EXPECT_FALSE(sim_->Slip(id_, -1, 1, 1, &error));
}

TEST(SimulatorSquareTest, OdometryDivergesByTheConfiguredDriftOverA10mSquare) {
  // An empty 14 x 14 m room; a B21 drives a 10 m square open loop.
  const auto w = spott_map::LoadWorldFromString(
      "world: {name: square}\nwalls: {from_rooms: true}\n"
      "rooms: [{id: r, polygon: [[0, 0], [14, 0], [14, 14], [0, 14]]}]\n"
      "robot_start: {pose: [2, 2, 0]}\n",
      "square.yaml");
  ASSERT_TRUE(w.ok());
  Simulator sim(MakeWorld(*w.world));
  OdometryErrorModel odo;
  odo.linear_scale = 1.02;      // measures 2 % too far
  odo.angular_scale = 1.01;     // 1 % too much rotation
  odo.drift_rad_per_m = 0.002;  // and 2 mrad of heading per metre
  const int id = *sim.AddRobot(Load("b21"), {2.0, 2.0, 0.0}, odo, nullptr);
  Rng rng(3);
  double travelled = 0, turned = 0;
  auto step = [&] {
    const spott_map::Pose2 before = sim.GroundTruth(id);
    sim.Step(0.01, rng);
    const spott_map::Pose2 after = sim.GroundTruth(id);
    travelled += std::hypot(after.x - before.x, after.y - before.y);
    turned += std::remainder(after.yaw - before.yaw, 2 * M_PI);
  };
  for (int side = 0; side < 4; ++side) {
    sim.SetCommand(id, {0.5, 0.0}, nullptr);
    // Stop commanded 0.16 m early: braking from 0.5 m/s at 0.8 m/s^2 takes 0.156 m.
    while (travelled < 10.0 * (side + 1) - 0.16) step();
    sim.SetCommand(id, {0.0, 0.0}, nullptr);
    for (int i = 0; i < 200; ++i) step();
    sim.SetCommand(id, {0.0, 0.5}, nullptr);
    const double target = M_PI / 2 * (side + 1) - 0.05;
    while (turned < target) step();
    sim.SetCommand(id, {0.0, 0.0}, nullptr);
    for (int i = 0; i < 200; ++i) step();
  }
  EXPECT_GT(travelled, 39.0);
  // Hand-computed drift: heading error = 0.01 * rotation + 0.002 * distance.
  const double heading_error =
      std::remainder(sim.odometry(id).pose().yaw - (sim.GroundTruth(id).yaw), 2 * M_PI);
  EXPECT_NEAR(heading_error, 0.01 * turned + 0.002 * travelled, 1e-6);
  EXPECT_GT(heading_error, 0.1);
}

// A hash of every sensor reading and pose of a scripted run.
std::size_t RunAndHash(std::uint64_t seed) {
  SimWorldParameters p;
  p.octomap_resolution_m = 0.1;
  auto world = std::make_unique<SimWorld>(p);
  world->Build(testing::TestWorld());
  Simulator sim(std::move(world));
  OdometryErrorModel odo;
  odo.linear_noise = 0.01;
  odo.angular_noise = 0.01;
  const RobotSpec spec = Load("b21");
  const int id = *sim.AddRobot(spec, {2.0, 3.0, 0.0}, odo, nullptr);
  Rng rng(seed);
  std::size_t h = 0;
  auto mix = [&h](double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  };
  for (int i = 0; i < 300; ++i) {
    sim.SetCommand(id, {0.4, 0.3 * std::sin(i * 0.05)}, nullptr);
    sim.Step(0.01, rng);
    if (i % 10 == 0) {
      for (double r : sim.SenseRing(id, *spec.FindRing("sonar"), rng)) mix(r);
      for (double r : sim.SenseLaser(id, rng)) mix(r);
      mix(sim.odometry(id).pose().x);
      mix(sim.odometry(id).pose().yaw);
    }
  }
  return h;
}

TEST(DeterminismTest, SameSeedSameStreamOtherSeedOtherStream) {
  EXPECT_EQ(RunAndHash(5), RunAndHash(5));
  EXPECT_NE(RunAndHash(5), RunAndHash(6));
}

TEST(MultiRobotTest, RobotsSeeAndStopAtEachOther) {
  Simulator sim(MakeWorld(testing::TestWorld()));
  const RobotSpec b12 = Load("b12");
  const int a = *sim.AddRobot(b12, {2.0, 3.0, 0.0}, {}, nullptr);
  const int b = *sim.AddRobot(b12, {4.0, 3.0, M_PI}, {}, nullptr);
  std::string error;
  EXPECT_FALSE(sim.AddRobot(b12, {4.1, 3.0, 0.0}, {}, &error));  // on top of b
  Rng rng(1);
  sim.SetCommand(a, {0.3, 0.0}, nullptr);
  for (int i = 0; i < 1000; ++i) sim.Step(0.01, rng);
  EXPECT_NEAR(sim.GroundTruth(a).x, 4.0 - 2 * 0.1525, 0.002);
  EXPECT_TRUE(sim.Bumper(b).empty());  // a B-12 has no bumper ring in its robot file
  (void)b;
}

}  // namespace
}  // namespace robot_sim
