// smooth-move's clothoid corners (section 6.2.1), checked against hand-computed geometry.
#include "rpl_executive/noreils_chatila/path_smoothing.h"

#include <cmath>

#include <gtest/gtest.h>

namespace rpl_executive::noreils_chatila {
namespace {

TEST(PathSmoothing, NormalizedFresnelMatchesTheTabulatedFresnelIntegrals) {
  double c = 0.0, s = 0.0;
  NormalizedFresnel(0.0, &c, &s);
  EXPECT_DOUBLE_EQ(c, 1.0);
  EXPECT_DOUBLE_EQ(s, 0.0);
  // int_0^1 cos(pi/2 u^2) du is the Fresnel C(1) = 0.7798934004, S(1) = 0.4382591474.
  NormalizedFresnel(kPi / 2, &c, &s);
  EXPECT_NEAR(c, 0.7798934004, 1e-9);
  EXPECT_NEAR(s, 0.4382591474, 1e-9);
}

TEST(PathSmoothing, RightAngleCornerIsTwoClothoidsFromHalfASegmentBeforeToAfterTheVertex) {
  PathSmoothingParameters p;
  p.corner_distance_max_m = 0.5;
  const SmoothedPath path = SmoothBrokenLine({{0, 0}, {2, 0}, {2, 2}}, p);
  // d = 0.5: the curve leaves y = 0 at (1.5, 0) and joins x = 2 at (2, 0.5).
  bool saw_start = false;
  size_t end_of_corner = 0;
  for (size_t i = 0; i < path.samples.size(); ++i) {
    const PathSample& q = path.samples[i];
    if (std::fabs(q.x - 1.5) < 1e-12 && std::fabs(q.y) < 1e-12) saw_start = true;
    if (q.curvature != 0.0) end_of_corner = i;
  }
  EXPECT_TRUE(saw_start);
  ASSERT_LT(end_of_corner + 1, path.samples.size());
  const PathSample& joined = path.samples[end_of_corner + 1];  // curvature back to 0
  EXPECT_NEAR(joined.x, 2.0, 1e-4);
  EXPECT_NEAR(joined.y, 0.5, 1e-4);
  EXPECT_NEAR(joined.yaw, kPi / 2, 1e-9);
  EXPECT_NEAR(joined.curvature, 0.0, 1e-9);
  // Each clothoid turns pi/4 over L = d / (C(pi/4) + S(pi/4) tan(pi/4)); peak curvature D/L.
  double c = 0.0, s = 0.0;
  NormalizedFresnel(kPi / 4, &c, &s);
  const double length = 0.5 / (c + s);
  EXPECT_NEAR(path.max_curvature, (kPi / 2) / length, 1e-6);
  const ClothoidCorner corner = CornerForDistance(kPi / 2, 0.5);
  EXPECT_NEAR(corner.clothoid_length_m, length, 1e-12);
  EXPECT_NEAR(corner.peak_curvature, (kPi / 2) / length, 1e-12);
  // The path ends at the last vertex, heading and curvature are continuous.
  EXPECT_NEAR(path.samples.back().x, 2.0, 1e-9);
  EXPECT_NEAR(path.samples.back().y, 2.0, 1e-9);
  for (size_t i = 1; i < path.samples.size(); ++i) {
    const double ds = path.samples[i].s - path.samples[i - 1].s;
    EXPECT_LE(std::fabs(WrapAngle(path.samples[i].yaw - path.samples[i - 1].yaw)),
              path.max_curvature * ds * 1.01 + 1e-12);
    // Curvature changes linearly: at most the sharpness (peak / L) times the step.
    EXPECT_LE(std::fabs(path.samples[i].curvature - path.samples[i - 1].curvature),
              corner.peak_curvature / corner.clothoid_length_m * ds * 1.01 + 1e-12);
    EXPECT_LE(path.samples[i].s - path.samples[i - 1].s, p.sample_step_m + 1e-9);
  }
  // Shorter than the broken line (4 m) by the corner's cut.
  EXPECT_LT(path.length_m, 4.0);
  EXPECT_GT(path.length_m, 4.0 - 2 * 0.5 + 0.5 * std::sqrt(2.0));
}

TEST(PathSmoothing, ShortSegmentsLimitTheCornerToHalfTheirLength) {
  PathSmoothingParameters p;
  p.corner_distance_max_m = 0.5;
  // Example 2's PATH in metres, from the robot's start: the second corner's outgoing segment is
  // 2.0 m, the incoming 1.7 m, so d = 0.5; the first corner is straight (no smoothing).
  const SmoothedPath path = SmoothBrokenLine({{0.8, 5.2}, {1.8, 5.2}, {3.5, 5.2}, {3.6, 3.2}}, p);
  EXPECT_NEAR(path.samples.back().x, 3.6, 1e-9);
  EXPECT_NEAR(path.samples.back().y, 3.2, 1e-9);
  const SmoothedPath tight = SmoothBrokenLine({{0, 0}, {0.4, 0}, {0.4, 0.4}}, p);
  bool saw_start = false;
  for (const PathSample& q : tight.samples) {
    saw_start |= std::fabs(q.x - 0.2) < 1e-12 && std::fabs(q.y) < 1e-12;
  }
  EXPECT_TRUE(saw_start);  // d = 0.2, half of each 0.4 m segment
}

TEST(PathSmoothing, UTurnIsMadeInPlace) {
  const SmoothedPath path =
      SmoothBrokenLine({{0, 0}, {1, 0}, {0, 0.01}}, PathSmoothingParameters());
  bool turn = false;
  for (const PathSample& q : path.samples) turn |= q.turn_in_place;
  EXPECT_TRUE(turn);
  EXPECT_DOUBLE_EQ(path.max_curvature, 0.0);
}

TEST(PathSmoothing, DegenerateInputs) {
  EXPECT_TRUE(SmoothBrokenLine({}, PathSmoothingParameters()).samples.empty());
  const SmoothedPath one = SmoothBrokenLine({{1, 1}, {1, 1}}, PathSmoothingParameters());
  EXPECT_EQ(one.samples.size(), 1u);
  const SmoothedPath line = SmoothBrokenLine({{0, 0}, {1, 0}, {3, 0}}, PathSmoothingParameters());
  EXPECT_NEAR(line.length_m, 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(line.max_curvature, 0.0);
}

TEST(PathSmoothing, ParametersAreValidatedByName) {
  PathSmoothingParameters p;
  p.corner_distance_max_m = 0.0;
  p.max_deflection_rad = 4.0;
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].rfind("corner_distance_max_m:", 0), 0u);
  EXPECT_EQ(v[1].rfind("max_deflection_rad:", 0), 0u);
}

// Found by rpl_executive_parameters_fuzz: nc/pilot/sample_step_m 1e-300 was accepted, and a
// line's sample count ceil(length / step) was cast into an int (undefined).
TEST(PathSmoothing, ASampleStepTooFineToCountIsRefused) {
  PathSmoothingParameters p;
  for (double step : {1e-300, 1e-9, 0.0009}) {
    p.sample_step_m = step;
    const auto v = ValidateParameters(p);
    ASSERT_EQ(v.size(), 1u) << step;
    EXPECT_EQ(v[0].rfind("sample_step_m:", 0), 0u);
  }
  p.sample_step_m = 0.001;
  EXPECT_TRUE(ValidateParameters(p).empty());
  const SmoothedPath path = SmoothBrokenLine({{0, 0}, {1, 0}, {1, 1}}, p);
  EXPECT_GT(path.samples.size(), 1000u);
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
