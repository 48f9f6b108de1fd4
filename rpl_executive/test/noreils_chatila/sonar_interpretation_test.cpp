// The ultrasonic belt's line interpretation behind S_us-perception.
#include "rpl_executive/noreils_chatila/sonar_interpretation.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::HilareRing;
using testing::Scan;

// The belt's reading of the line (rho, theta) by the model, on the given sensors (ids).
SonarScan Wall(const SonarRing& ring, double rho, double theta, std::vector<int> ids,
               SonarScan scan = Scan()) {
  for (int id : ids) {
    scan.ranges_m[id - 1] =
        PredictedRange(ring.mounts[id - 1], ring.half_field_of_view_rad, rho, theta);
  }
  return scan;
}

TEST(SonarInterpretation, PredictedRangeIsPerpendicularInsideTheBeamAndAlongItsEdgeOutside) {
  const SonarMount ahead{0.4, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(PredictedRange(ahead, 0.26, 1.0, 0.0), 0.6);
  EXPECT_DOUBLE_EQ(PredictedRange(ahead, 0.26, 1.0, 0.2), 1.0 - 0.4 * std::cos(0.2));
  // Normal 0.46 rad off the axis: the beam's edge, 0.2 rad from the normal, reads p / cos 0.2.
  EXPECT_NEAR(PredictedRange(ahead, 0.26, 1.0, 0.46), (1.0 - 0.4 * std::cos(0.46)) / std::cos(0.2),
              1e-12);
  EXPECT_LT(PredictedRange(ahead, 0.26, 0.3, 0.0), 0.0);  // the sensor is beyond the line
}

TEST(SonarInterpretation, WallAheadIsOneLineOfThreeSensors) {
  const SonarRing ring = HilareRing();
  const std::vector<SonarLine> lines =
      InterpretLines(Wall(ring, 0.8, 0.0, {16, 1, 2}), ring, SonarInterpretationParameters());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NEAR(lines[0].rho_m, 0.8, 1e-3);
  EXPECT_NEAR(lines[0].theta_rad, 0.0, 1e-3);
  EXPECT_EQ(lines[0].first_sensor, 16);
  EXPECT_EQ(lines[0].sensor_count, 3);
  EXPECT_TRUE(PerceivesLine(lines, 0.85, 0.1, SonarInterpretationParameters()));
  EXPECT_FALSE(PerceivesLine(lines, 1.0, 0.0, SonarInterpretationParameters()));  // rho off
  EXPECT_FALSE(PerceivesLine(lines, 0.8, 0.5, SonarInterpretationParameters()));  // theta off
}

TEST(SonarInterpretation, ObliqueWallAndCornerAreRecovered) {
  const SonarRing ring = HilareRing();
  const SonarInterpretationParameters p;
  const auto oblique = InterpretLines(Wall(ring, 1.0, 0.2, {16, 1, 2, 3}), ring, p);
  ASSERT_EQ(oblique.size(), 1u);
  EXPECT_NEAR(oblique[0].rho_m, 1.0, 1e-3);
  EXPECT_NEAR(oblique[0].theta_rad, 0.2, 1e-3);
  // A corner: a wall ahead (16, 1, 2) and one on the left (4, 5, 6).
  const SonarScan corner = Wall(ring, 1.2, kPi / 2, {4, 5, 6}, Wall(ring, 0.9, 0.0, {16, 1, 2}));
  const auto two = InterpretLines(corner, ring, p);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_TRUE(PerceivesLine(two, 0.9, 0.0, p));
  EXPECT_TRUE(PerceivesLine(two, 1.2, kPi / 2, p));
}

TEST(SonarInterpretation, TooFewOrInconsistentEchoesAreNoLine) {
  const SonarRing ring = HilareRing();
  const SonarInterpretationParameters p;
  EXPECT_TRUE(InterpretLines(Wall(ring, 0.8, 0.0, {1, 2}), ring, p).empty());  // two fit any line
  EXPECT_TRUE(InterpretLines(Scan({{1, 0.5}, {2, 2.0}, {3, 0.7}}), ring, p).empty());
  EXPECT_TRUE(InterpretLines(Scan(), ring, p).empty());
}

TEST(SonarInterpretation, FindsTheWallThatARayCastingBeltReadsInHilareRoom) {
  // The east wall's face is at x = 7.925 m: from (7.1, 2.5) heading east, rho = 0.825 m.
  const SonarRing ring = HilareRing();
  const SonarScan scan =
      testing::SimulateSonar(testing::HilareRoomWalls(), Pose2{7.1, 2.5, 0.0}, ring);
  const auto lines = InterpretLines(scan, ring, SonarInterpretationParameters());
  ASSERT_FALSE(lines.empty());
  EXPECT_TRUE(PerceivesLine(lines, 0.825, 0.0, SonarInterpretationParameters()));
  bool near = false;
  for (const SonarLine& l : lines)
    near |= std::fabs(l.rho_m - 0.825) < 0.02 && std::fabs(l.theta_rad) < 0.03;
  EXPECT_TRUE(near);
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
