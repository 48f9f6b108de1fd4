// LegMetrics: the figures of a leg depend on the messages' stamps, not on the order they arrive
// in, so that a live run and its bag (bag_report) give the same report.
#include "spott_launch/leg_metrics.h"

#include <gtest/gtest.h>

#include "spott_map/world_loader.h"

namespace spott_launch {
namespace {

spott_map::World Corridor() {
  const auto loaded = spott_map::LoadWorldFromString(R"(
world: {name: corridor}
walls: {from_rooms: true, thickness: 0.1}
rooms:
  - {id: hall, kind: hallway, polygon: [[0, 0], [10, 0], [10, 2], [0, 2]]}
robot_start: {pose: [1, 1, 0]}
)",
                                                     "corridor.yaml");
  EXPECT_TRUE(loaded.ok()) << spott_map::FormatErrors(loaded.errors);
  return *loaded.world;
}

NavigationLeg Measured(LegMetrics& m) {
  NavigationLeg leg;
  m.Measure({5.0, 1.0}, leg);
  return leg;
}

TEST(LegMetrics, AStatusMeetsTheTruthAtItsStampWhicheverComesFirst) {
  const spott_map::World world = Corridor();
  // The robot drives along the corridor at 1 m/s, truth every 0.1 s; a status stamped 0.55 s
  // estimates (0.55, 1): the truth then, between the samples of 0.5 and 0.6 s.
  LegMetrics status_late(world), status_early(world);
  for (LegMetrics* m : {&status_late, &status_early}) m->Reset(0.0);
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.1 * i;
    if (i == 7) status_late.OnStatus(0.55, 0.55, 1.0, 0.0, false);
    if (i == 3) status_early.OnStatus(0.55, 0.55, 1.0, 0.0, false);
    for (LegMetrics* m : {&status_late, &status_early}) m->OnTruth(t, t, 1.0, 0.0);
  }
  const NavigationLeg late = Measured(status_late), early = Measured(status_early);
  EXPECT_EQ(late.estimates, 1);
  EXPECT_EQ(early.estimates, 1);
  EXPECT_NEAR(late.max_position_error_m, 0.0, 1e-9);
  EXPECT_NEAR(early.max_position_error_m, 0.0, 1e-9);
}

TEST(LegMetrics, DroppedTruthMessagesHardlyChangeTheError) {
  // CI's scenario_run: the live subscriber and the recorder can each drop ground truth (the
  // publisher's queue under load); the status must meet about the same truth in both.
  const spott_map::World world = Corridor();
  LegMetrics all(world), gappy(world);
  for (LegMetrics* m : {&all, &gappy}) m->Reset(0.0);
  for (int i = 0; i <= 50; ++i) {
    const double t = 0.02 * i;  // 50 Hz, 0.5 m/s along x, turning at 1 rad/s
    for (LegMetrics* m : {&all, &gappy}) {
      if (i == 30) m->OnStatus(0.43, 0.5 * 0.43 + 0.05, 1.0, 0.43, false);
      if (m == &gappy && i >= 12 && i <= 28) continue;  // 0.24-0.56 s dropped
      m->OnTruth(t, 0.5 * t, 1.0, t);
    }
  }
  const NavigationLeg a = Measured(all), g = Measured(gappy);
  EXPECT_NEAR(a.max_position_error_m, 0.05, 1e-9);
  EXPECT_NEAR(g.max_position_error_m, a.max_position_error_m, 1e-3);
  EXPECT_NEAR(g.max_heading_error_rad, a.max_heading_error_rad, 1e-3);
}

TEST(LegMetrics, AStatusThatComesSecondsLateStillMeetsTheTruthAtItsStamp) {
  // CI's scenario_run: a status computed on a loaded machine came over a second (simulated)
  // after its reading; with one second of truth kept it met a later truth than in the bag.
  const spott_map::World world = Corridor();
  LegMetrics m(world);
  m.Reset(0.0);
  for (int i = 0; i <= 50; ++i) {
    if (i == 40) m.OnStatus(0.55, 0.55, 1.0, 0.0, false);  // 3.45 s after its stamp
    m.OnTruth(0.1 * i, 0.1 * i, 1.0, 0.0);
  }
  const NavigationLeg leg = Measured(m);
  EXPECT_EQ(leg.estimates, 1);
  EXPECT_NEAR(leg.max_position_error_m, 0.0, 1e-9);
}

TEST(LegMetrics, OnlyMessagesStampedWithinTheLegCount) {
  const spott_map::World world = Corridor();
  LegMetrics m(world);
  m.OnTruth(0.0, 1.0, 1.0, 0.0);
  m.OnTruth(1.0, 2.0, 1.0, 0.0);  // before the leg: the robot's pose, not its path
  m.Reset(1.5);
  m.OnBumper(1.4, true);          // before
  m.OnTruth(2.0, 3.0, 1.0, 0.0);  // the path continues from (2, 1)
  m.OnBumper(2.0, true);
  m.EndAt(3.0);
  m.OnTruth(3.0, 4.0, 1.0, 0.0);
  m.OnBumper(3.5, true);          // after
  m.OnTruth(4.0, 9.0, 1.9, 0.0);  // after: neither path nor clearance
  m.OnStatus(3.5, 0.0, 0.0, 0.0, true);
  const NavigationLeg leg = Measured(m);
  EXPECT_NEAR(leg.path_length_m, 2.0, 1e-9);
  EXPECT_EQ(leg.bumper_hits, 1);
  EXPECT_EQ(leg.estimates, 0);
  EXPECT_NEAR(leg.final_position.x(), 4.0, 1e-9);
  EXPECT_NEAR(leg.final_error_m, 1.0, 1e-9);
  EXPECT_GT(leg.min_wall_distance_m, 0.5);  // the corridor's centre line, 1 m from each wall
}

TEST(LegMetrics, OnsetsOfLostAndOfContactAreTimed) {
  const spott_map::World world = Corridor();
  LegMetrics m(world);
  m.Reset(0.0);
  const bool lost[] = {false, true, true, false, true};
  const bool pressed[] = {false, true, true, false, true};
  for (int i = 0; i < 5; ++i) {
    m.OnTruth(i, 1.0 + 0.1 * i, 1.0, 0.0);
    m.OnStatus(i, 1.0 + 0.1 * i, 1.0, 0.0, lost[i]);
    m.OnBumper(i + 0.5, pressed[i]);
  }
  const NavigationLeg leg = Measured(m);
  EXPECT_EQ(leg.lost_reports, 3);
  EXPECT_EQ(leg.lost_onsets_s, (std::vector<double>{1.0, 4.0}));
  EXPECT_EQ(leg.bumper_hits, 3);
  EXPECT_EQ(leg.contact_onsets_s, (std::vector<double>{1.5, 4.5}));
  m.Reset(10.0);  // a new leg starts unpressed and not lost
  m.OnStatus(10.0, 1.0, 1.0, 0.0, true);
  m.OnTruth(10.0, 1.0, 1.0, 0.0);
  EXPECT_EQ(Measured(m).lost_onsets_s, (std::vector<double>{10.0}));
}

TEST(LegMetrics, AVerdictNeedsTheDriversWordTheGoalAndNoContact) {
  NavigationLeg leg;
  leg.final_error_m = 0.1;
  JudgeLeg("", OffPlace(leg, 0.25), leg);
  EXPECT_TRUE(leg.reached);
  leg.final_error_m = 0.3;
  JudgeLeg("", OffPlace(leg, 0.25), leg);
  EXPECT_FALSE(leg.reached);
  EXPECT_NE(leg.outcome.find("0.30 m from the target"), std::string::npos) << leg.outcome;
  leg.final_error_m = 0.1;
  leg.bumper_hits = 2;
  JudgeLeg("", OffPlace(leg, 0.25), leg);
  EXPECT_FALSE(leg.reached);
  leg.bumper_hits = 0;
  // A robot without a bumper (the B-12): the ground truth's body contact fails the leg too.
  const spott_map::World no_world;
  LegMetrics metrics(no_world);
  metrics.Reset(0.0);
  metrics.OnBodyContact(1.0, false);
  metrics.OnBodyContact(1.1, true);
  metrics.OnBodyContact(1.2, true);
  metrics.Measure(spott_map::Vec2(0.0, 0.0), leg);
  EXPECT_EQ(leg.body_contacts, 2);
  leg.final_error_m = 0.1;
  JudgeLeg("", OffPlace(leg, 0.25), leg);
  EXPECT_FALSE(leg.reached);
  EXPECT_NE(leg.outcome.find("the body touched"), std::string::npos) << leg.outcome;
  leg.body_contacts = 0;
  JudgeLeg("Navigate failed: blocked", "", leg);
  EXPECT_EQ(leg.outcome, "not reached: Navigate failed: blocked");
}

// `find chair` is judged by the object reported: a chair of the world within 0.5 m of it.
TEST(LegMetrics, AFindIsJudgedOnTheObjectReportedAgainstTheWorldsObjects) {
  const auto loaded = spott_map::LoadWorldFromString(R"(
world: {name: office}
walls: {from_rooms: true, thickness: 0.1}
rooms:
  - {id: office, polygon: [[0, 0], [6, 0], [6, 5], [0, 5]]}
objects:
  - {id: c1, kind: chair, pose: [2, 2, 0.3], size: [0.5, 0.5], height: 0.9}
  - {id: d1, kind: desk, pose: [4, 1, 0], size: [1.6, 0.8], height: 0.75}
robot_start: {pose: [1, 4, 0]}
)",
                                                     "office.yaml");
  ASSERT_TRUE(loaded.ok()) << spott_map::FormatErrors(loaded.errors);
  const spott_map::World& world = *loaded.world;
  NavigationLeg leg;
  const spott_map::Pose2 start{1, 4, 0};
  EXPECT_EQ(OffTaskGoal(world, "find chair", start, leg, 0.25), "nothing was found");
  leg.found_label = "chair";
  leg.found_at = spott_map::Vec2(2.2, 2.3);  // 0.36 m from c1: one face seen
  EXPECT_EQ(OffTaskGoal(world, "find chair", start, leg, 0.25), "");
  leg.found_at = spott_map::Vec2(4.0, 1.1);  // the desk's place
  const std::string off = OffTaskGoal(world, "find chair", start, leg, 0.25);
  EXPECT_NE(off.find("nearest chair is 1.84 m away"), std::string::npos) << off;  // its footprint
  // A desk is found where it was seen: 0.73 m from d1's centre but on its top.
  leg.found_label = "desk";
  leg.found_at = spott_map::Vec2(4.7, 1.2);
  EXPECT_EQ(OffTaskGoal(world, "find desk", start, leg, 0.25), "");
  leg.found_at = spott_map::Vec2(4.7, 2.0);  // 0.6 m beyond its long side
  EXPECT_NE(OffTaskGoal(world, "find desk", start, leg, 0.25).find("nearest desk is 0.60 m away"),
            std::string::npos);
  leg.found_label = "cylinder";
  EXPECT_NE(OffTaskGoal(world, "find chair", start, leg, 0.25).find("has no cylinder"),
            std::string::npos);
}

// A tele-operation is judged on the way the robot went: at least kTeleopAdvanceM along the
// heading it was sent, from where it really started.
TEST(LegMetrics, ATeleoperationIsJudgedOnTheWayTheRobotWent) {
  const auto loaded = spott_map::LoadWorldFromString(R"(
world: {name: hall}
walls: {from_rooms: true, thickness: 0.1}
rooms:
  - {id: hall, kind: hallway, polygon: [[0, 0], [20, 0], [20, 2.5], [0, 2.5]]}
robot_start: {pose: [2, 1.25, 0]}
)",
                                                     "hall.yaml");
  ASSERT_TRUE(loaded.ok()) << spott_map::FormatErrors(loaded.errors);
  const spott_map::World& world = *loaded.world;
  NavigationLeg leg;
  const spott_map::Pose2 start{2, 1.25, M_PI};  // facing west
  leg.final_position = spott_map::Vec2(1.0, 1.3);
  EXPECT_EQ(OffTaskGoal(world, "go forward", start, leg, 0.25), "");  // 1 m west
  EXPECT_EQ(OffTaskGoal(world, "go west", start, leg, 0.25), "");
  const std::string east = OffTaskGoal(world, "go east", start, leg, 0.25);
  EXPECT_NE(east.find("went -1.00 m the way it was sent"), std::string::npos) << east;
  EXPECT_NE(OffTaskGoal(world, "go backward", start, leg, 0.25), "");
  leg.final_position = spott_map::Vec2(1.7, 1.25);  // 0.3 m: hardly moved
  EXPECT_NE(OffTaskGoal(world, "go forward", start, leg, 0.25), "");
}

// A mission counts as the scenario says: the executive's outcome, the monitors in their order,
// the message, then the goal on the ground truth.
TEST(LegMetrics, AMissionIsJudgedOnItsOutcomeMonitorsMessageAndGoal) {
  MissionSpec spec;
  spec.outcome = "failed";
  spec.monitors = std::vector<std::string>{"(S_zone IN ZONE109)", "(S_us-threshold sensors-list)"};
  spec.message_contains = "MNTR STATIC";
  const std::vector<std::string> fired = *spec.monitors;
  EXPECT_EQ(MissionMismatch(spec, "failed", "FAIL in the control action of MNTR STATIC", fired),
            "");
  EXPECT_NE(MissionMismatch(spec, "completed", "", fired).find("expected failed"),
            std::string::npos);
  const std::vector<std::string> reversed = {fired[1], fired[0]};
  const std::string order = MissionMismatch(spec, "failed", "MNTR STATIC", reversed);
  EXPECT_NE(order.find("the monitors fired [(S_us-threshold sensors-list), (S_zone IN ZONE109)]"),
            std::string::npos)
      << order;
  EXPECT_NE(MissionMismatch(spec, "failed", "FAIL elsewhere", fired).find("expected it to say"),
            std::string::npos);
  spec.monitors.reset();  // not judged: any
  EXPECT_EQ(MissionMismatch(spec, "failed", "MNTR STATIC", {}), "");
  // monitors_include: these in order, a static monitor's re-firings between them allowed.
  const std::string s = "(S_us-threshold sensors-list)", in = "(S_zone IN ZONE109)",
                    out = "(S_zone OUT ZONE109)";
  MissionSpec among;
  among.monitors_include = {s, in, out};
  EXPECT_EQ(MissionMismatch(among, "completed", "", {s, s, in, s, out, s}), "");
  EXPECT_NE(MissionMismatch(among, "completed", "", {s, out, in}).find("among them in this order"),
            std::string::npos);
  EXPECT_NE(MissionMismatch(among, "completed", "", {s, in}).find("among them in this order"),
            std::string::npos);
  NavigationLeg leg;
  leg.has_target = true;
  leg.final_error_m = 0.6;
  JudgeMissionLeg(MissionMismatch(spec, "failed", "MNTR STATIC", {}), 0.5, leg);
  EXPECT_FALSE(leg.reached);
  EXPECT_NE(leg.outcome.find("0.60 m from the mission's goal"), std::string::npos) << leg.outcome;
  leg.has_target = false;  // no goal: anywhere
  JudgeMissionLeg("", 0.5, leg);
  EXPECT_TRUE(leg.reached);
  EXPECT_EQ(leg.outcome, "as the scenario says");
  leg.body_contacts = 1;
  JudgeMissionLeg("", 0.5, leg);
  EXPECT_FALSE(leg.reached);
}

}  // namespace
}  // namespace spott_launch
