// CONTROL_THE_PTU's patterns (ptu_control.h) on cim_office's hallway: d_lab_w (1.8 m, centre
// (12.5, 9.5)) in its north wall, d_103 (centre (14, 7)) in its south wall.
#include "spott_tr_plus/controller/ptu_control.h"

#include <gtest/gtest.h>

#include <cmath>

#include "spott_map/world_loader.h"

namespace {

using spott_map::Pose2;
using spott_tr_plus::controller::PanHeads;
using spott_tr_plus::controller::PtuParameters;

spott_map::MapDatabase CimOffice() {
  auto loaded = spott_map::LoadWorldFile(WORLDS_DIR "/cim_office.yaml");
  EXPECT_TRUE(loaded.ok());
  return spott_map::MapDatabase::FromWorld(*loaded.world);
}

TEST(PanHeads, InAHallwayTheHeadOnADoorsSideTurnsToItAsTheRobotComes) {
  const spott_map::MapDatabase map = CimOffice();
  const PtuParameters p;
  // 2.8 m before d_lab_w, driving east: the left head (index 0) to its middle, the right ahead.
  auto pan = PanHeads("hallway", 2, 0.0, Pose2{10.0, 8.25, 0.0}, map, p);
  ASSERT_EQ(pan.size(), 2u);
  EXPECT_NEAR(pan[0], std::atan2(1.25, 2.5), 1e-9);
  EXPECT_NEAR(pan[1], -0.3, 1e-9);
  // Past d_lab_w's middle by 0.5 m: d_103 ahead on the right.
  pan = PanHeads("hallway", 2, 0.0, Pose2{13.0, 8.25, 0.0}, map, p);
  EXPECT_NEAR(pan[0], 0.3, 1e-9);
  EXPECT_NEAR(pan[1], std::atan2(-1.25, 1.0), 1e-9);
  // Driving west there: d_lab_w ahead on the right.
  pan = PanHeads("hallway", 2, 0.0, Pose2{13.0, 8.25, M_PI}, map, p);
  EXPECT_NEAR(pan[1], std::atan2(1.25, -0.5) - M_PI, 1e-9);
  EXPECT_NEAR(pan[0], 0.3, 1e-9);
}

TEST(PanHeads, NoDoorWithinReachOrAheadLeavesBothHeadsAhead) {
  const spott_map::MapDatabase map = CimOffice();
  PtuParameters p;
  // d_201 and d_101 1 m behind, d_202 4.2 m ahead.
  auto pan = PanHeads("hallway", 2, 0.0, Pose2{5.0, 8.25, 0.0}, map, p);
  EXPECT_NEAR(pan[0], 0.3, 1e-9);
  EXPECT_NEAR(pan[1], -0.3, 1e-9);
  p.door_watch_m = 0.0;  // never
  pan = PanHeads("hallway", 2, 0.0, Pose2{10.0, 8.25, 0.0}, map, p);
  EXPECT_NEAR(pan[0], 0.3, 1e-9);
  // Without a pose the heads look ahead.
  pan = PanHeads("hallway", 2, 0.0, std::nullopt, map, PtuParameters{});
  EXPECT_NEAR(pan[0], 0.3, 1e-9);
}

TEST(PanHeads, InARoomTheHeadsSweepAcrossIt) {
  const spott_map::MapDatabase map = CimOffice();
  const PtuParameters p;  // 0.8 rad, 8 s
  const auto pan = PanHeads("room", 2, 2.0, Pose2{10.0, 8.25, 0.0}, map, p);
  EXPECT_NEAR(pan[0], 0.8, 1e-9);
  EXPECT_NEAR(pan[1], -0.8, 1e-9);
}

TEST(PanHeads, InARoomHeadZeroTurnsToAnObjectRecognitionNeedsWhileTheOtherSweeps) {
  const spott_map::MapDatabase map = CimOffice();
  const PtuParameters p;
  // Office 101 from its middle, facing south: the chair 2 m ahead, a little right.
  const Pose2 robot{2.64, 4.07, -M_PI / 2};
  auto pan = PanHeads("room", 2, 2.0, robot, map, p, spott_map::Vec2(2.5, 2.1));
  EXPECT_NEAR(pan[0], std::atan2(-1.97, -0.14) + M_PI / 2, 1e-9);
  EXPECT_NEAR(pan[1], -0.8, 1e-9);
  // Behind the robot: as far as the head turns.
  pan = PanHeads("room", 2, 2.0, robot, map, p, spott_map::Vec2(2.64, 6.0));
  EXPECT_NEAR(std::abs(pan[0]), p.max_pan_rad, 1e-9);
  // In a hallway the doors come first.
  pan = PanHeads("hallway", 2, 0.0, Pose2{10.0, 8.25, 0.0}, map, p, spott_map::Vec2(10, 6));
  EXPECT_NEAR(pan[0], std::atan2(1.25, 2.5), 1e-9);
}

TEST(TiltToward, AHeadTiltsDownOntoAFaceBelowItAndNeverUp) {
  const PtuParameters p;  // heads at 0.85 m
  const Pose2 robot{2.6, 4.1, 0.0};
  EXPECT_NEAR(spott_tr_plus::controller::TiltToward(robot, spott_map::Vec2(2.6, 1.4), 0.6, p),
              std::atan2(0.25, 2.7), 1e-9);
  EXPECT_EQ(spott_tr_plus::controller::TiltToward(robot, spott_map::Vec2(4.6, 4.1), 1.2, p), 0.0);
  EXPECT_NEAR(spott_tr_plus::controller::TiltToward(robot, spott_map::Vec2(2.7, 4.1), 0.0, p),
              p.max_tilt_rad, 1e-9);
  EXPECT_EQ(spott_tr_plus::controller::TiltToward(robot, robot.Position(), 2.0, p), 0.0);
}

}  // namespace
