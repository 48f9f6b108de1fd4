#include "cmd_vel_arbiter/clearance.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "cmd_vel_arbiter/arbiter.h"

namespace cmd_vel_arbiter {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The B21's ring: 24 sonars every 15 degrees on its 0.2625 m enclosure, 25-degree cones.
std::vector<Transducer> B21Ring() {
  std::vector<Transducer> t;
  for (int i = 0; i < 24; ++i) {
    const double a = i * M_PI / 12;
    t.push_back(Transducer{0.2625 * std::cos(a), 0.2625 * std::sin(a), a});
  }
  return t;
}

TEST(Clearance, TheStoppingSpeedBrakesBeforeTheMarginAfterTheLatency) {
  ClearanceParameters p;  // 0.5 m/s^2, 0.2 s, 0.05 m
  EXPECT_EQ(StoppingSpeed(kInf, p), kInf);
  EXPECT_EQ(StoppingSpeed(0.05, p), 0.0);
  EXPECT_EQ(StoppingSpeed(0.0, p), 0.0);
  const double v = StoppingSpeed(0.6, p);
  // Driving at v, it covers v T before braking and v^2 / (2 a) while braking: the 0.55 m left.
  EXPECT_NEAR(v * 0.2 + v * v / (2 * 0.5), 0.55, 1e-9);
  EXPECT_LT(StoppingSpeed(0.3, p), v);
}

TEST(Clearance, AWallAheadCapsForwardOnlyAndSideWallsCapNothing) {
  ClearanceParameters p;
  const auto ring = B21Ring();
  std::vector<double> z(24, 5.0);  // max range: no echo
  // A wall 0.6 m ahead of the body: the front sonar and its neighbours' cones meet it.
  z[0] = 0.6;
  z[1] = 0.6 / std::cos(M_PI / 12 - 0.218);
  z[23] = z[1];
  // Hallway walls 0.5 m to each side of the body (beyond the corridor the body sweeps).
  z[6] = 0.5;
  z[18] = 0.5;
  const SpeedBounds b = BoundsFromRing(ring, 0.436, 0.15, 5.0, z, p);
  EXPECT_NEAR(b.forward_gap_m, 0.6, 0.02);
  EXPECT_NEAR(b.forward_mps, StoppingSpeed(b.forward_gap_m, p), 1e-12);
  EXPECT_EQ(b.backward_mps, kInf);
  EXPECT_EQ(b.backward_gap_m, kInf);
  // The side walls alone bound nothing; a dropped-out (NaN) or too short reading neither.
  std::vector<double> sides(24, 5.0);
  sides[6] = sides[18] = 0.5;
  sides[3] = std::nan("");
  sides[2] = 0.1;  // below min_range
  EXPECT_EQ(BoundsFromRing(ring, 0.436, 0.15, 5.0, sides, p).forward_mps, kInf);
  // A reading of the minimum itself (a driver clamps what lies closer; robot_sim does) or -Inf
  // (REP 117: too close to measure) ahead: the object may touch the body, so no speed towards
  // it. (Read as 0.15 m, it let a B-12 push into a crate the sonar had missed at 0.23 m/s.)
  ClearanceParameters at_face_p = p;
  at_face_p.min_range_at_face = true;
  for (const double at_face : {0.15, static_cast<double>(0.15f), -kInf}) {
    std::vector<double> touching(24, 5.0);
    touching[0] = at_face;
    const SpeedBounds t = BoundsFromRing(ring, 0.436, 0.15, 5.0, touching, at_face_p);
    EXPECT_EQ(t.forward_mps, 0.0) << at_face;
    EXPECT_NEAR(t.forward_gap_m, 0.0, 1e-9) << at_face;
    EXPECT_EQ(t.backward_mps, kInf) << at_face;
  }
  // From a transducer looking aside (15 deg, outside the front cone's 12.5) the minimum stays
  // where it says: a Nomad's sonars, blind to 0.43 m, read a doorway's jambs so.
  std::vector<double> aside(24, 5.0);
  aside[1] = 0.15;
  const SpeedBounds a = BoundsFromRing(ring, 0.436, 0.15, 5.0, aside, at_face_p);
  EXPECT_GT(a.forward_gap_m, 0.1);
  EXPECT_GT(a.forward_mps, 0.0);
  // Off (the default: a Nomad's sonars are blind to 0.43 m, its infrared and bumper cover
  // that): the minimum ahead is a gap of min_range, -Inf bounds nothing.
  std::vector<double> clamped(24, 5.0);
  clamped[0] = 0.15;
  EXPECT_NEAR(BoundsFromRing(ring, 0.436, 0.15, 5.0, clamped, p).forward_gap_m, 0.15, 0.01);
  clamped[0] = -kInf;
  EXPECT_EQ(BoundsFromRing(ring, 0.436, 0.15, 5.0, clamped, p).forward_mps, kInf);
  // Something just behind: backing is capped, and stopped within the margin.
  std::vector<double> behind(24, 5.0);
  behind[12] = 0.16;
  const SpeedBounds back = BoundsFromRing(ring, 0.436, 0.15, 5.0, behind, p);
  EXPECT_EQ(back.forward_mps, kInf);
  EXPECT_NEAR(back.backward_gap_m, 0.16 * std::cos(0.218), 0.01);
  EXPECT_GT(back.backward_mps, 0.0);
}

// bonn_kidnap: the B21 turned towards a hallway wall; its sonars read their 0.15 m minimum while
// the laser (181 rays over 180 degrees, 0.1 m ahead of the centre) saw the wall 0.09 m ahead.
TEST(Clearance, ALaserScanBoundsByItsPointsInTheSweptCorridor) {
  ClearanceParameters p;
  ScanGeometry laser;
  laser.mount = Transducer{0.1, 0.0, 0.0};
  laser.angle_min_rad = -M_PI / 2;
  laser.angle_increment_rad = M_PI / 180;
  laser.range_min_m = 0.02;
  laser.range_max_m = 25.0;
  const double radius = 0.2625;
  // A wall across the way 0.5 m ahead of the centre: the ray at angle a reads 0.4 / cos(a).
  std::vector<double> wall(181);
  for (int i = 0; i < 181; ++i) {
    const double a = -M_PI / 2 + i * M_PI / 180;
    wall[i] = std::abs(std::cos(a)) > 1e-3 ? 0.4 / std::cos(a) : kInf;
  }
  SpeedBounds b = BoundsFromScan(laser, wall, radius, p);
  EXPECT_NEAR(b.forward_gap_m, 0.5 - radius, 1e-9);  // the body's front to the wall
  EXPECT_NEAR(b.forward_mps, StoppingSpeed(0.5 - radius, p), 1e-12);
  EXPECT_EQ(b.backward_gap_m, kInf);  // a laser looking ahead bounds nothing behind
  // 0.09 m from the face: within the stop margin's reach, no speed ahead.
  for (int i = 0; i < 181; ++i) {
    const double a = -M_PI / 2 + i * M_PI / 180;
    wall[i] = std::abs(std::cos(a)) > 1e-3 ? (radius + 0.09 - 0.1) / std::cos(a) : kInf;
  }
  b = BoundsFromScan(laser, wall, radius, p);
  EXPECT_NEAR(b.forward_gap_m, 0.09, 1e-9);
  EXPECT_LT(b.forward_mps, 0.15);
  // A hallway's side walls 0.6 m to either side bound nothing; NaN, Inf and readings out of
  // [range_min, range_max) neither.
  std::vector<double> side(181, kInf);
  side[0] = side[180] = 0.6;
  side[90] = std::numeric_limits<double>::quiet_NaN();
  side[89] = 0.01;  // below range_min
  side[91] = 25.0;  // at range_max: no echo
  b = BoundsFromScan(laser, side, radius, p);
  EXPECT_EQ(b.forward_gap_m, kInf);
  EXPECT_EQ(b.forward_mps, kInf);
  // A laser mounted backwards bounds the way back.
  laser.mount = Transducer{-0.1, 0.0, M_PI};
  std::vector<double> behind(181, kInf);
  behind[90] = 0.4;
  b = BoundsFromScan(laser, behind, radius, p);
  EXPECT_NEAR(b.backward_gap_m, 0.5 - radius, 1e-9);
  EXPECT_EQ(b.forward_gap_m, kInf);
  // footprint_radius_m, when set, is the body's radius.
  p.footprint_radius_m = 0.4;
  b = BoundsFromScan(laser, behind, radius, p);
  EXPECT_NEAR(b.backward_gap_m, 0.1, 1e-9);
}

TEST(Clearance, ValidationNamesEveryBadParameter) {
  ClearanceParameters p;
  EXPECT_TRUE(ValidateParameters(p).empty());
  p.deceleration_mps2 = 0.0;
  p.latency_s = std::nan("");
  p.stop_margin_m = -1;
  EXPECT_EQ(ValidateParameters(p).size(), 3u);
}

// The Nomad's two rings: the sonar at 0.65 m sees over the lab's 0.6 m crate; the infrared ring
// at 0.4 m sees it (Fig. 18 seed 15 touched it with only the sonar capping).
TEST(RingBoundsSet, TheTightestFreshRingBoundsAndASilentOneBoundsNothing) {
  RingBoundsSet rings(2, 0.5);
  EXPECT_EQ(rings.Tightest(0.0, nullptr).forward_mps, kInf) << "nothing heard: no bound";
  SpeedBounds sonar, infrared;
  sonar.forward_mps = 0.4;
  sonar.forward_gap_m = 1.2;
  infrared.forward_mps = 0.1;
  infrared.forward_gap_m = 0.3;
  infrared.backward_mps = 0.2;
  rings.Set(0, sonar, 1.0);
  rings.Set(1, infrared, 1.1);
  rings.Set(7, SpeedBounds{0.0, 0.0, 0.0, 0.0}, 1.1);  // no such ring: ignored
  std::vector<std::size_t> silent;
  SpeedBounds t = rings.Tightest(1.2, &silent);
  EXPECT_DOUBLE_EQ(t.forward_mps, 0.1);
  EXPECT_DOUBLE_EQ(t.forward_gap_m, 0.3);
  EXPECT_DOUBLE_EQ(t.backward_mps, 0.2);
  EXPECT_TRUE(silent.empty());
  // The infrared ring falls silent; the sonar goes on.
  rings.Set(0, sonar, 1.5);
  t = rings.Tightest(1.7, &silent);
  EXPECT_DOUBLE_EQ(t.forward_mps, 0.4);
  EXPECT_EQ(t.backward_mps, kInf);
  EXPECT_EQ(silent, std::vector<std::size_t>{1});
  silent.clear();
  rings.Tightest(1.8, &silent);
  EXPECT_TRUE(silent.empty()) << "said once";
  // Both silent: no bound at all.
  t = rings.Tightest(3.0, &silent);
  EXPECT_EQ(t.forward_mps, kInf);
  EXPECT_EQ(silent, std::vector<std::size_t>{0});
}

ArbiterParameters Params() {
  ArbiterParameters p;
  p.sources = {{"planner", 10, 0.5}, {"reflex", 100, 0.5}};
  p.max_linear_mps = 0.9;
  p.max_angular_rps = 1.5;
  return p;
}

// Section 4's kidnapped B21: turned towards a wall while the planner, on the old pose, drives on.
TEST(Arbiter, TheClearanceCapsTheDriversLinearSpeedButNotTurningNorAReflex) {
  Arbiter a(Params());
  std::string why;
  EXPECT_DOUBLE_EQ(a.Command("planner", Velocity{0.54, 0.3}, 0.0, &why).command.linear_mps, 0.54);
  Output out = a.SetClearance(0.2, kInf, 0.05);
  ASSERT_TRUE(out.publish);  // at once, not at the driver's next command
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.2);
  EXPECT_DOUBLE_EQ(out.command.angular_rps, 0.3);
  EXPECT_EQ(a.clearance_slowdowns(), 1u);
  // Backing away is capped by what is behind only.
  EXPECT_DOUBLE_EQ(a.Command("planner", Velocity{-0.3, 0.0}, 0.1, &why).command.linear_mps, -0.3);
  out = a.SetClearance(0.0, 0.1, 0.15);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, -0.1);
  // A stop in front leaves turning in place.
  out = a.Command("planner", Velocity{0.5, 1.0}, 0.2, &why);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(out.command.angular_rps, 1.0);
  // The reflex is exempt: it backs off a contact whatever the ring says.
  out = a.Command("reflex", Velocity{-0.3, 0.0}, 0.25, &why);
  EXPECT_DOUBLE_EQ(out.command.linear_mps, -0.3);
  // Cleared: the driver's speed again.
  a.Command("reflex", Velocity{}, 0.3, &why);
  out = a.SetClearance(kInf, kInf, 1.0);
  EXPECT_DOUBLE_EQ(a.Command("planner", Velocity{0.5, 0.0}, 1.0, &why).command.linear_mps, 0.5);
}

}  // namespace
}  // namespace cmd_vel_arbiter
