// MAP_OBJECTS_WITH_SONAR's fusion by the echoes' physics (sonar_echo_fit.h): walls are circles'
// common tangents, corners their common point.
#include "spott_tr_plus/controller/sonar_echo_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "echo_scene.h"
#include "spott_tr_plus/controller/sensor_mapper.h"

namespace {

using spott_tr_plus::controller::EchoFitParameters;
using spott_tr_plus::controller::FuseIntoSegments;
using spott_tr_plus::controller::SonarEcho;
using spott_tr_plus::controller::Vec2;
using test_scene::kHalfCone;
using test_scene::Scene;

// Each echo stands for its own cell, at its axis point, as the evidence grid places it.
struct Heard {
  std::vector<Vec2> cells;
  std::vector<std::vector<SonarEcho>> echoes;
  void Add(const Vec2& from, double axis, double range) {
    cells.push_back(from + range * Vec2(std::cos(axis), std::sin(axis)));
    echoes.push_back({SonarEcho{from, axis, range, kHalfCone}});
  }
};

double Degrees(const spott_map::MapFeature& f) {
  const Vec2 d = f.points.back() - f.points.front();
  return std::atan2(d.y(), d.x()) * 180 / M_PI;
}

bool AnySegmentLongerThan(const std::vector<spott_map::MapFeature>& fs, double length) {
  for (const auto& f : fs)
    if (f.type == spott_map::FeatureType::kLineSegment &&
        (f.points.back() - f.points.front()).norm() > length)
      return true;
  return false;
}

TEST(FuseIntoSegments, ACornersEchoesOnTheirAxesDrawAnArcButFuseIntoOnePoint) {
  // A jamb's corner at (3, 1), the robot driving east along y = 0 with transducers looking left
  // and 22.5 degrees ahead of that: seen over 50 degrees, its echoes placed on their axes draw an
  // arc, which the cells' fit takes for a wall; the echoes' ranges say a corner.
  Scene scene;
  scene.corners.push_back(Vec2(3.0, 1.0));
  std::mt19937 rng(7);
  Heard h;
  for (double x = 1.5; x <= 4.0; x += 0.05)
    for (const double axis : {M_PI / 2, M_PI / 2 - M_PI / 8})
      if (const auto r = scene.Read(Vec2(x, 0), axis, rng)) h.Add(Vec2(x, 0), axis, *r);
  ASSERT_GE(h.cells.size(), 20u);
  EXPECT_TRUE(AnySegmentLongerThan(FuseIntoSegments(h.cells, 0.07, 0.1), 0.3))
      << "the cells alone make the arc a segment (what this test guards against)";
  const auto fused = FuseIntoSegments(h.cells, 0.07, 0.1, &h.echoes);
  ASSERT_EQ(fused.size(), 1u);
  EXPECT_EQ(fused[0].type, spott_map::FeatureType::kPoint);
  EXPECT_LE((fused[0].points[0] - Vec2(3.0, 1.0)).norm(), 0.05);
}

TEST(FuseIntoSegments, AWallApproachedHeadOnIsNoSegmentOffItsLine) {
  // cim_office's hallway end: the wall x = 5 ahead, the robot driving east along y = 0 with the
  // Nomad's front transducers (0 and +-22.5 degrees). The oblique ones hear the wall by their
  // cones' inner edges (7.5 degrees of incidence); on their axes those echoes fall short of it
  // by 7 % of the distance, a line 10 degrees off the wall. Fused from the echoes: what is kept
  // lies on the wall, and no segment leaves its direction.
  Scene scene;
  scene.walls.push_back({Vec2(5.0, -1.2), Vec2(5.0, 1.2)});
  std::mt19937 rng(3);
  Heard h;
  for (double x = 2.0; x <= 4.5; x += 0.05)
    for (const double axis : {0.0, M_PI / 8, -M_PI / 8})
      if (const auto r = scene.Read(Vec2(x, 0), axis, rng)) h.Add(Vec2(x, 0), axis, *r);
  ASSERT_GE(h.cells.size(), 40u);
  bool off = false;
  for (const auto& f : FuseIntoSegments(h.cells, 0.07, 0.1))
    off = off || (f.type == spott_map::FeatureType::kLineSegment &&
                  std::abs(std::abs(Degrees(f)) - 90.0) > 5.0);
  EXPECT_TRUE(off) << "the cells alone make a segment off the wall's direction";
  const auto fused = FuseIntoSegments(h.cells, 0.07, 0.1, &h.echoes);
  ASSERT_FALSE(fused.empty());
  for (const auto& f : fused) {
    if (f.type == spott_map::FeatureType::kLineSegment) {
      EXPECT_NEAR(std::abs(Degrees(f)), 90.0, 5.0);
      for (const Vec2& p : f.points) EXPECT_NEAR(p.x(), 5.0, 0.05) << p.transpose();
    } else {  // where an echo reflected, within the cone's uncertainty
      EXPECT_NEAR(f.points[0].x(), 5.0, 0.2) << f.points[0].transpose();
    }
  }
}

TEST(FuseIntoSegments, AWallPassedAtAnAngleLiesOnItsLineAtItsDirection) {
  // A wall from (1, 1.2) to (4, 1.5) (5.7 degrees), the robot driving east along y = 0 with
  // a transducer looking left and one 22.5 degrees ahead of it: the fused segment lies on
  // the wall (within 3 cm) and along it (within 1 degree), also where the cells tilt.
  Scene scene;
  scene.walls.push_back({Vec2(1.0, 1.2), Vec2(4.0, 1.5)});
  std::mt19937 rng(11);
  Heard h;
  for (double x = 0.0; x <= 5.0; x += 0.05) {
    for (const double axis : {M_PI / 2, M_PI / 2 - M_PI / 8}) {
      const Vec2 from(x, 0.0);
      if (const auto r = scene.Read(from, axis, rng)) h.Add(from, axis, *r);
    }
  }
  ASSERT_GE(h.cells.size(), 40u);
  const auto fused = FuseIntoSegments(h.cells, 0.07, 0.1, &h.echoes);
  int segments = 0;
  for (const auto& f : fused) {
    if (f.type != spott_map::FeatureType::kLineSegment) continue;
    ++segments;
    EXPECT_NEAR(Degrees(f), std::atan2(0.3, 3.0) * 180 / M_PI, 1.0);
    for (const Vec2& p : f.points) {
      const double across = std::abs((p - Vec2(1.0, 1.2)).dot(Vec2(-0.3, 3.0).normalized()));
      EXPECT_LE(across, 0.03) << p.transpose();
      // Ends no farther past the wall's than an edge seen at the cone's rim: r tan(half cone).
      EXPECT_GE(p.x(), 1.0 - 1.5 * std::tan(kHalfCone));
      EXPECT_LE(p.x(), 4.0 + 1.6 * std::tan(kHalfCone));
    }
  }
  EXPECT_EQ(segments, 1);
}

TEST(FuseIntoSegments, AWallEndsAtADoorwaysJambsNotAcrossTheDoorway) {
  // A hallway wall y = 0 with a 0.9 m doorway from x = 2 to 2.9, passed 1.2 m off by a
  // transducer looking at it: past each jamb it hears the jamb's edge while the edge is in its
  // cone, a range at most 4 % longer than the wall's, within the noise each. On their feet those
  // echoes would run the wall 0.3 m into the doorway from both sides, closing all but 0.3 m of
  // it; the wall's ends are where the edges explain the echoes better.
  Scene scene;
  scene.walls = {{Vec2(-1.0, 0.0), Vec2(2.0, 0.0)}, {Vec2(2.9, 0.0), Vec2(6.0, 0.0)}};
  scene.corners = {Vec2(2.0, 0.0), Vec2(2.9, 0.0)};
  std::mt19937 rng(5);
  Heard h;
  for (double x = 0.0; x <= 5.0; x += 0.02)
    if (const auto r = scene.Read(Vec2(x, 1.2), -M_PI / 2, rng)) h.Add(Vec2(x, 1.2), -M_PI / 2, *r);
  const auto fused = FuseIntoSegments(h.cells, 0.07, 0.1, &h.echoes);
  int segments = 0;
  for (const auto& f : fused) {
    if (f.type != spott_map::FeatureType::kLineSegment) continue;
    ++segments;
    for (const Vec2& p : f.points) {
      EXPECT_NEAR(p.y(), 0.0, 0.03);
      EXPECT_FALSE(p.x() > 2.1 && p.x() < 2.8) << "an end " << p.x() << " in the doorway";
    }
  }
  EXPECT_EQ(segments, 2);
}

}  // namespace
