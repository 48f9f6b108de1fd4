// The sonar's echo model (sonar_echo.h): the foot of the perpendicular in the cone, the cone's
// edge ray beyond it up to the critical incidence, nothing behind the wall.
#include "spott_map/sonar_echo.h"

#include <gtest/gtest.h>

#include <cmath>

namespace spott_map {
namespace {

constexpr double kHalfCone = 0.26;  // the Nomad's Polaroid: 0.52 rad

TEST(PredictEcho, AWallInTheConeEchoesFromItsFootAndBeyondTheConeFromTheEdgeRay) {
  // The wall x = 2 (normal -x toward a transducer at the origin).
  const Vec2 n(-1.0, 0.0);
  const double offset = -2.0;
  SonarEcho e{Vec2(0, 0), 0.1, 0.0, kHalfCone};  // the normal 0.1 rad off the axis: in the cone
  auto p = PredictEcho(e, n, offset, 0.35);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->range, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(p->excess, 0.0);
  EXPECT_NEAR(p->reflection.x(), 2.0, 1e-12);
  EXPECT_NEAR(p->reflection.y(), 0.0, 1e-12);
  e.axis = 0.4;  // 0.14 rad beyond the cone: the edge ray at 0.14 rad meets the wall
  p = PredictEcho(e, n, offset, 0.35);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->range, 2.0 / std::cos(0.14), 1e-12);
  EXPECT_NEAR(p->excess, 0.14, 1e-12);
  EXPECT_NEAR(p->reflection.y(), 2.0 * std::tan(0.14), 1e-12);
  e.axis = -0.4;  // the other side
  EXPECT_NEAR(PredictEcho(e, n, offset, 0.35)->reflection.y(), -2.0 * std::tan(0.14), 1e-12);
  e.axis = 0.7;  // 0.44 beyond: past the critical incidence, the pulse glances off
  EXPECT_FALSE(PredictEcho(e, n, offset, 0.35));
  e.from = Vec2(3.0, 0.0);  // behind the wall
  e.axis = 0.0;
  EXPECT_FALSE(PredictEcho(e, n, offset, 0.35));
}

TEST(ConeExcess, IsZeroInsideTheConeAndTheAngleBeyondItOutside) {
  const SonarEcho e{Vec2(0, 0), 1.0, 2.0, kHalfCone};
  double side = 0.0;
  EXPECT_DOUBLE_EQ(ConeExcess(e, 1.2, &side), 0.0);
  EXPECT_NEAR(ConeExcess(e, 1.5, &side), 0.5 - kHalfCone, 1e-12);
  EXPECT_EQ(side, 1.0);
  EXPECT_NEAR(ConeExcess(e, 1.0 - 0.5 + 2.0 * M_PI, &side), 0.5 - kHalfCone, 1e-12);
  EXPECT_EQ(side, -1.0);
}

}  // namespace
}  // namespace spott_map
