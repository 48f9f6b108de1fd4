// MAP_OBJECTS_WITH_SONAR's dense scan (sonar_scan.h): the turret's steps, and what the scan
// gives the map that the driving ring does not.
#include "spott_tr_plus/controller/sonar_scan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "echo_scene.h"
#include "spott_tr_plus/controller/sensor_mapper.h"

namespace {

using spott_tr_plus::controller::DoorSensingParameters;
using spott_tr_plus::controller::MappingParameters;
using spott_tr_plus::controller::Pose2;
using spott_tr_plus::controller::RangeRing;
using spott_tr_plus::controller::SensorMapper;
using spott_tr_plus::controller::SonarScan;
using spott_tr_plus::controller::SonarScanParameters;
using spott_tr_plus::controller::ValidateParameters;
using spott_tr_plus::controller::Vec2;

constexpr double kStep = 2.5 * M_PI / 180;

// The Nomad's 16 axes with the turret at `turret`.
std::vector<double> Axes(double turret) {
  std::vector<double> a;
  for (int t = 0; t < 16; ++t) a.push_back(spott_map::NormalizeAngle(t * M_PI / 8 + turret));
  return a;
}

SonarScanParameters Every(double period_s) {
  SonarScanParameters p;
  p.period_s = period_s;
  return p;
}

TEST(SonarScan, StepsTheTurretNineTimesTwoAndAHalfDegreesApartThenHome) {
  SonarScan scan(Every(5.0));
  double t = 0, turret = 0;
  std::vector<double> asked;
  // A turret that reaches each target before the next ring (0.79 rad/s, 10 Hz: 4.5 degrees).
  for (int i = 0; i < 200; ++i, t += 0.1) {
    if (const auto a = scan.Ring(Axes(turret), true, t)) {
      asked.push_back(*a);
      turret = *a;
    }
  }
  // Homed at once, the first scan 5 s later: 8 steps from the ring read at home, then home.
  ASSERT_GE(asked.size(), 1u + 9u);
  EXPECT_EQ(asked[0], 0.0) << "the start angle is unknown: home first";
  for (int k = 1; k <= 8; ++k) EXPECT_NEAR(asked[k], k * kStep, 1e-9) << k;
  EXPECT_EQ(asked[9], 0.0);
  EXPECT_GE(scan.scans_done(), 3) << "every 5 s of 20";
  EXPECT_LE(scan.scans_done(), 4);
}

TEST(SonarScan, WaitsForEachAngleAndReadsNothingWhileTheConditionIsOff) {
  SonarScan scan(Every(2.0));
  double t = 0;
  scan.Ring(Axes(0), true, t);
  scan.Ring(Axes(0), true, t += 0.1);  // two rings agree: home
  EXPECT_FALSE(scan.Ring(Axes(0), false, t += 3)) << "the sonar's condition does not run";
  const auto first = scan.Ring(Axes(0), true, t += 0.1);
  ASSERT_TRUE(first);
  EXPECT_TRUE(scan.scanning());
  // Still turning (half way): no new step; there: the next.
  EXPECT_FALSE(scan.Ring(Axes(kStep / 2), true, t += 0.1));
  const auto second = scan.Ring(Axes(kStep), true, t += 0.1);
  ASSERT_TRUE(second);
  EXPECT_NEAR(*second, 2 * kStep, 1e-9);
}

TEST(SonarScan, ARobotWithoutATurretEndsItsScans) {
  SonarScan scan(Every(1.0));
  double t = 0;
  int asks = 0;
  for (int i = 0; i < 100; ++i, t += 0.1)
    if (scan.Ring(Axes(0), true, t)) ++asks;  // the axes never move
  EXPECT_FALSE(scan.available());
  EXPECT_FALSE(scan.scanning());
  EXPECT_EQ(scan.scans_done(), 0);
  EXPECT_EQ(asks, 3) << "home, the first step, home again; then never";
}

TEST(SonarScan, ParametersOutOfRangeAreNamed) {
  SonarScanParameters p;
  p.steps = 1;
  p.settle_rad = 0.1;
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_NE(v[0].find("steps"), std::string::npos);
  EXPECT_NE(v[1].find("settle_rad"), std::string::npos);
}

// The hallway's east end as cim_office has it (2.5 m wide, the end wall at x = 5), the Nomad
// driving east along its middle to 1.2 m from the end, mapped without an a priori map.
struct HallwayEnd {
  test_scene::Scene scene;
  HallwayEnd() {
    scene.walls = {{Vec2(5.0, -1.25), Vec2(5.0, 1.25)},
                   {Vec2(-1.0, 1.25), Vec2(5.0, 1.25)},
                   {Vec2(-1.0, -1.25), Vec2(5.0, -1.25)}};
    scene.corners = {Vec2(5.0, 1.25), Vec2(5.0, -1.25)};
  }
  RangeRing Ring(const Pose2& robot, double turret, std::mt19937& rng) const {
    RangeRing ring;
    ring.min_range_m = 0.43;
    ring.max_range_m = 6.5;
    ring.field_of_view_rad = 2 * test_scene::kHalfCone;
    for (const double a : Axes(turret)) {
      const double r = 0.2285;
      ring.mounts.push_back(Pose2{r * std::cos(a), r * std::sin(a), a});
      const Vec2 at = robot.Position() + r * Vec2(std::cos(robot.yaw + a), std::sin(robot.yaw + a));
      ring.ranges.push_back(scene.Read(at, robot.yaw + a, rng).value_or(6.5));
    }
    return ring;
  }
  // The end wall's segments among what the mapper fused: their largest angle from the wall's
  // direction (degrees), and their length.
  static void EndWall(const std::vector<spott_map::MapFeature>& features, double* worst_deg,
                      double* length) {
    *worst_deg = 0;
    *length = 0;
    for (const auto& f : features) {
      if (f.type != spott_map::FeatureType::kLineSegment) continue;
      const Vec2 d = f.points.back() - f.points.front();
      if (std::abs(f.points.front().x() - 5.0) > 0.3 || std::abs(d.x()) > std::abs(d.y())) continue;
      *worst_deg = std::max(*worst_deg, std::abs(std::atan2(d.x(), std::abs(d.y()))) * 180 / M_PI);
      *length += d.norm();
    }
  }
};

TEST(SonarScan, AWallHeardHeadOnIsASegmentAlongItMostlyFromTheDenseScan) {
  // Driven at 0.1 m/s with the ring at 10 Hz, the end wall is heard by the front transducers
  // only: their echoes barely fix its direction (a piece of it, the rest points). The dense
  // scan every 5 s (Experiment 1's sonar map period) reads it at 2.5-degree steps: most of it
  // a segment along it.
  const HallwayEnd hall;
  double length[2], worst[2];
  for (const bool dense : {false, true}) {
    const spott_map::MapDatabase empty;
    SensorMapper m("sonar", MappingParameters{}, DoorSensingParameters{}, true);
    m.SetMap(empty, Vec2(2.0, 0.0));
    SonarScan scan(Every(dense ? 5.0 : 0.0));
    std::mt19937 rng(11);
    double turret = 0;
    for (double t = 0; t < 60; t += 0.1) {
      const Pose2 robot{std::min(-0.5 + 0.1 * t, 3.8), 0.0, 0.0};
      const RangeRing ring = hall.Ring(robot, turret, rng);
      m.AddRing(ring, robot);
      std::vector<double> axes;
      for (const Pose2& mount : ring.mounts) axes.push_back(mount.yaw);
      if (const auto a = scan.Ring(axes, true, t)) turret = *a;  // reached by the next ring
    }
    HallwayEnd::EndWall(m.Take(empty).features, &worst[dense], &length[dense]);
    if (dense) {
      EXPECT_GE(scan.scans_done(), 10);
    }
  }
  EXPECT_GE(length[1], 1.25) << "half of the 2.5 m wall as a segment";
  EXPECT_GE(length[1], 2.0 * length[0]) << "the scan's echoes fix the most";
  EXPECT_LE(worst[1], 2.0) << "along the wall";
}

}  // namespace
