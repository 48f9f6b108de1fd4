#include <gtest/gtest.h>

#include <cmath>

#include "robot_sim/range_sensors.h"
#include "robot_sim/robot_spec.h"
#include "test_world.h"

namespace robot_sim {
namespace {

using Eigen::Vector3d;

class SensorTest : public ::testing::Test {
 protected:
  SensorTest() : world_(SimWorldParameters{}) { world_.Build(testing::TestWorld()); }

  // A noise-free Polaroid-like transducer: 30 degree cone, 20 degree critical angle.
  static RangeRingSpec Sonar(int rays) {
    RangeRingSpec ring;
    ring.name = "sonar";
    ring.field_of_view = 30 * M_PI / 180;
    ring.min_range = 0.15;
    ring.max_range = 6.5;
    ring.rays = rays;
    ring.critical_angle = 20 * M_PI / 180;
    ring.noise_stddev = 0.0;
    ring.noise_per_metre = 0.0;
    return ring;
  }
  static TransducerPose At(double x, double y, double yaw) { return {Vector3d(x, y, 0.7), yaw}; }

  // A 1 x 0.2 m board turned 45 degrees whose face, normal (1, -1)/sqrt(2), is 1 m up-left of
  // (9.95, 4.95) on the east wall: the pulse of a transducer at (8, 3) aimed at 45 degrees
  // glances off the wall (45 deg > 20 deg), reaches the board face square on and comes back.
  void AddBoard() {
    const double k = 1.1 / std::sqrt(2.0);
    ASSERT_TRUE(world_.AddObstacle(
        testing::Box("board", 9.95 - k, 4.95 + k, M_PI / 4, 1.0, 0.2, 2.0), nullptr));
  }

  SimWorld world_;
  Rng rng_{42};
};

TEST_F(SensorTest, SonarFacingWallAtOneMetreReadsOneMetre) {
  // East wall face at x = 9.95 (the wall at y = 4.5 is away from the door).
  const double r = EchoRange(world_, Sonar(7), At(8.95, 4.5, 0.0), nullptr, nullptr);
  EXPECT_NEAR(r, 1.0, 1e-3);
}

TEST_F(SensorTest, SonarAtGrazingAngleReadsMaxRange) {
  // Aimed 20 degrees above east, 1 m below the north wall face (y = 5.95): the axis meets the
  // wall at 70 degrees of incidence and every ray of the cone at 55 to 85 degrees, beyond the
  // critical angle. The reflected pulses come down towards the east wall and would return from
  // it (incidence 5 to 20 degrees) only over paths longer than the 6.5 m range.
  const double r = EchoRange(world_, Sonar(7), At(2.0, 4.95, 20 * M_PI / 180), nullptr, nullptr);
  EXPECT_DOUBLE_EQ(r, 6.5);
}

TEST_F(SensorTest, SpecularPulseReturnsAsLongMultipathReading) {
  AddBoard();
  // Out: 1.95 * sqrt(2) = 2.7577 m to the east wall, then 1 m to the board: range 3.7577 m,
  // longer than the 2.76 m to the wall the transducer faces.
  const double r = EchoRange(world_, Sonar(1), At(8.0, 3.0, M_PI / 4), nullptr, nullptr);
  EXPECT_NEAR(r, 1.95 * std::sqrt(2.0) + 1.0, 1e-3);
}

TEST_F(SensorTest, AConeWithRowsHearsACrateBelowTheRing) {
  // A 0.6 m high crate 2 m ahead of a transducer at 0.7 m, its 2 x 0.6 m face square on: a flat
  // fan passes over it; a cone of three rows hears it with its lowest row (15 * 2/3 = 10
  // degrees down meets the face at 0.35 m height, 2 / cos(10 deg) = 2.03 m away).
  ASSERT_TRUE(world_.AddObstacle(testing::Box("low_crate", 5.3, 3.0, 0.0, 0.6, 2.0, 0.6), nullptr));
  RangeRingSpec flat = Sonar(7);
  EXPECT_GT(EchoRange(world_, flat, At(3.0, 3.0, 0.0), nullptr, nullptr), 4.0);  // the wall
  RangeRingSpec cone = Sonar(7);
  cone.vertical_rays = 3;
  EXPECT_NEAR(EchoRange(world_, cone, At(3.0, 3.0, 0.0), nullptr, nullptr),
              2.0 / std::cos(10 * M_PI / 180), 1e-3);
  // 5 cm above the crate's top over its near edge, the lowest row meets the top 0.28 m on at 80
  // degrees of incidence: glancing, no echo (the upper row's from the door 5 m on is the one).
  EXPECT_GT(
      EchoRange(world_, cone, TransducerPose{Vector3d(5.05, 3.0, 0.65), 0.0}, nullptr, nullptr),
      4.0);
}

// A door jamb's face is as wide as the wall is thick (0.15 m): 2 m away it spans 4.3 degrees of
// the 30-degree cone. A real cone is continuous and hears it wherever it lies in the cone; a fan
// of rays hears it only where a ray falls on it. Every shipped robot's sonar must hear it at every
// aim that keeps it inside the cone (rays 5 degrees apart did not: the localization, whose model
// samples the cone every 2 degrees, was pulled along cim_office's hallway by an open door).
TEST_F(SensorTest, EveryShippedSonarHearsAJambFaceAnywhereInItsCone) {
  ASSERT_TRUE(world_.AddObstacle(testing::Box("jamb", 5.0, 3.0, 0.0, 0.15, 0.15, 2.0), nullptr));
  const TransducerPose origin = At(4.925 - 2.0, 3.0, 0.0);  // 2 m from the face
  // Aims whose cone still holds the post; nothing else lies within the sonars' range there.
  auto deafest_aim = [&](const RangeRingSpec& ring) {
    int missed = 0;
    for (double deg = -10.0; deg <= 10.0; deg += 0.1) {
      TransducerPose t = origin;
      t.yaw = deg * M_PI / 180;
      missed += EchoRange(world_, ring, t, nullptr, nullptr) > 2.1;
    }
    return missed;
  };
  for (const std::string name : {"b12", "b21", "hilare", "nomad200"}) {
    auto spec = LoadRobotSpec(testing::PackageFile("config/robots/" + name + ".yaml"),
                              testing::PackageFile("urdf/" + name + ".urdf"));
    ASSERT_TRUE(spec.ok()) << name;
    const RangeRingSpec* sonar = spec.spec->FindRing("sonar");
    ASSERT_NE(sonar, nullptr) << name;
    EXPECT_EQ(deafest_aim(*sonar), 0) << name << ": aims at which the sonar misses the jamb";
  }
  // The same cone sampled by 7 rays misses it between rays.
  EXPECT_GT(deafest_aim(Sonar(7)), 0);
  EXPECT_EQ(deafest_aim(Sonar(15)), 0);
}

TEST_F(SensorTest, TransducersFiredTogetherHearEachOthersEchoes) {
  AddBoard();
  // Transducer 0 as above; transducer 1 at (8.5, 3) aimed at the point P = (9.2429, 5.6571)
  // where 0's pulse scatters off the board. Alone, 1's own pulse glances off the board
  // (60.6 deg) to the east wall (15.6 deg: an echo) over 2.759 + 0.734 = 3.493 m. Fired
  // together, it first hears 0's echo from P: (3.7577 + |P - (8.5, 3)|) / 2 = 3.2584 m.
  const Vector3d p(9.95 - 1 / std::sqrt(2.0), 4.95 + 1 / std::sqrt(2.0), 0.7);
  const Vector3d b(8.5, 3.0, 0.7);
  const double bearing = std::atan2(p.y() - b.y(), p.x() - b.x());
  const std::vector<TransducerPose> poses = {At(8.0, 3.0, M_PI / 4), At(8.5, 3.0, bearing)};
  RangeRingSpec ring = Sonar(1);
  ring.fire_groups = 2;  // one at a time
  const auto alone = SenseRangeRing(world_, ring, poses, nullptr, rng_);
  EXPECT_NEAR(alone[0], 3.7577, 1e-3);
  EXPECT_NEAR(alone[1], 2.759 + 0.734, 5e-3);
  ring.fire_groups = 1;  // both at once
  const auto together = SenseRangeRing(world_, ring, poses, nullptr, rng_);
  const double crosstalk = (1.95 * std::sqrt(2.0) + 1.0 + (p - b).norm()) / 2;
  EXPECT_NEAR(together[1], crosstalk, 1e-3);
  EXPECT_LT(together[0], alone[0]);  // 0 hears 1's echo off the east wall too
}

TEST_F(SensorTest, ReadingsAreClampedToMinimumRange) {
  // 0.2 m from the wall, under the 0.43 m blanking of a Nomad sonar.
  RangeRingSpec ring = Sonar(7);
  ring.min_range = 0.43;
  const auto r = SenseRangeRing(world_, ring, {At(9.75, 4.5, 0.0)}, nullptr, rng_);
  EXPECT_DOUBLE_EQ(r[0], 0.43);
}

TEST_F(SensorTest, NoiseHasTheConfiguredSpread) {
  RangeRingSpec ring = Sonar(7);
  ring.noise_stddev = 0.02;
  double sum = 0, sum2 = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double r = SenseRangeRing(world_, ring, {At(8.95, 4.5, 0.0)}, nullptr, rng_)[0];
    sum += r;
    sum2 += r * r;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 1.0, 0.003);
  EXPECT_NEAR(sd, 0.02, 0.002);
}

TEST_F(SensorTest, InfraredIsDiffuseAndShort) {
  RangeRingSpec ir = Sonar(1);
  ir.field_of_view = 0.1;
  ir.critical_angle = M_PI / 2;
  ir.max_range = 0.6;
  // 0.5 m from the east wall at 60 degrees: a sonar would lose it, the infrared sees it.
  const double d = 0.5;
  EXPECT_NEAR(
      EchoRange(world_, ir, At(9.95 - d * std::cos(M_PI / 3), 4.5, M_PI / 3), nullptr, nullptr), d,
      1e-3);
  EXPECT_DOUBLE_EQ(EchoRange(world_, ir, At(8.0, 4.5, 0.0), nullptr, nullptr), 0.6);
}

TEST_F(SensorTest, LaserBeamsMeasureHandComputedRanges) {
  LaserSpec laser;
  laser.angle_min = -M_PI / 2;
  laser.angle_max = M_PI / 2;
  laser.beams = 3;
  laser.max_range = 25;
  laser.noise_stddev = 0.0;
  const auto r = SenseLaser(world_, laser, At(5, 3, 0.0), nullptr, rng_);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 2.95, 1e-3);   // south wall face y = 0.05
  EXPECT_NEAR(r[1], 4.975, 1e-3);  // closed door leaf face x = 9.975
  EXPECT_NEAR(r[2], 2.95, 1e-3);   // north wall face y = 5.95
  laser.max_range = 1.0;
  EXPECT_TRUE(std::isinf(SenseLaser(world_, laser, At(5, 3, 0.0), nullptr, rng_)[1]));
}

TEST_F(SensorTest, HorizontalRangeProfileOfAWall) {
  ProfilerSpec p;
  p.samples = 5;
  p.field_of_view = 0.4;
  p.max_range = 4.0;
  p.noise_stddev = 0.0;
  std::vector<double> angles;
  const auto r = SenseProfile(world_, p, At(8.95, 4.5, 0.0), 0.0, true, nullptr, rng_, &angles);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_NEAR(angles[0], -0.2, 1e-12);
  EXPECT_NEAR(r[2], 1.0, 1e-9);  // the east wall face, 1 m ahead
  EXPECT_NEAR(r[0], 1.0 / std::cos(0.2), 1e-9);
  EXPECT_NEAR(r[4], 1.0 / std::cos(0.2), 1e-9);
}

TEST_F(SensorTest, VerticalRangeProfileTiltedDownSeesTheFloor) {
  ProfilerSpec p;
  p.samples = 5;
  p.field_of_view = 0.4;
  p.max_range = 4.0;
  p.noise_stddev = 0.0;
  // Head 0.7 m up looking east, tilted 0.5 rad down: samples at 0.3 to 0.7 rad below the
  // horizon meet the floor at 0.7 / sin(pitch) m.
  std::vector<double> angles;
  const auto r = SenseProfile(world_, p, At(5.0, 3.0, 0.0), 0.5, false, nullptr, rng_, &angles);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(r[k], 0.7 / std::sin(0.5 + angles[k]), 1e-9) << "sample " << k;
  }
}

TEST(BumperTest, ContactAnglesPressTheSegmentsFacingThem) {
  BumperSpec bumper;  // 20 segments of 18 degrees, segment 0 centred on +x
  const double deg = M_PI / 180;
  auto pressed = BumperSegments(bumper, {0.0, 90 * deg, -8 * deg, -36 * deg});
  std::vector<int> on;
  for (int i = 0; i < 20; ++i) {
    if (pressed[i]) on.push_back(i);
  }
  EXPECT_EQ(on, (std::vector<int>{0, 5, 18}));
  EXPECT_TRUE(BumperSegments(bumper, {10 * deg})[1]);  // past the 9 degree edge of segment 0
}

TEST(PlaceMountTest, TurretAndBaseRotationCompose) {
  Mount m;
  m.x = 0.2;
  m.z = 0.6;
  m.yaw = 0.0;
  const TransducerPose t = PlaceMount(m, {1.0, 2.0, M_PI / 2}, M_PI / 2);
  EXPECT_NEAR(t.origin.x(), 0.8, 1e-9);
  EXPECT_NEAR(t.origin.y(), 2.0, 1e-9);
  EXPECT_NEAR(t.origin.z(), 0.6, 1e-9);
  EXPECT_NEAR(std::abs(t.yaw), M_PI, 1e-9);
}

}  // namespace
}  // namespace robot_sim
