// The executive and the surveillance manager (sections 4 and 5) on small missions with
// scripted modules and sensor data: each monitor kind, NEXT, FAIL, static monitors, priority,
// nested monitors, preconditions, execution environments and Fig. 5's message order.
#include "rpl_executive/noreils_chatila/executive.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "rpl_executive/noreils_chatila/sonar_interpretation.h"
#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::At;
using testing::HilareRing;
using testing::Parse;
using testing::ParseFile;
using testing::Scan;
using testing::ScriptedModules;

// A 20 x 20 cm zone around x = 60 cm, y = 0 and a scene to script data in.
const char* kZone = "(define Tclist[4] Z ((50 -10)(50 10)(70 10)(70 -10)))\n";

struct Rig {
  ScriptedModules modules;
  Executive exec{ExecutiveParameters(), SurveillanceParameters(), HilareRing(), &modules};
  double t = 0.0;

  Rig() { exec.SetRobotState("motors", Value::Symbol("ON")); }
  StartResult Start(const std::string& text) {
    const StartResult r = exec.StartMission(Parse(kZone + text), t);
    EXPECT_TRUE(r.accepted) << r.refusal;
    return r;
  }
  void Pose(double x, double y = 0.0) {
    t += 0.1;
    exec.OnPose(At(x, y), t);
  }
  void Sonar(std::vector<std::pair<int, double>> echoes) {
    t += 0.1;
    exec.OnSonar(Scan(std::move(echoes)), t);
  }
  void Tick(double dt = 0.1) {
    t += dt;
    modules.Deliver(&exec, t);
    exec.Step(t);
  }
  void Finish(OperatorStatus status = OperatorStatus::kCompleted) {
    t += 0.1;
    modules.Finish(&exec, t, status);
  }
};

TEST(Executive, TerminalMonitorStopsTheActionAndNextRunsTheNextCommandAfterThePilotsReport) {
  Rig rig;
  rig.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((stop)) ((NEXT)))"
      " (read-pos)))");
  rig.Pose(0.0);
  rig.Pose(0.6);  // enters Z
  // The reflex is sent at once; the control action waits for the pilot's report (Fig. 5, 7).
  EXPECT_EQ(rig.modules.Names(), (std::vector<std::string>{"smooth-move", "stop"}));
  EXPECT_EQ(rig.exec.state(), MissionState::kRunning);
  rig.Tick();
  EXPECT_EQ(rig.modules.Names(), (std::vector<std::string>{"smooth-move", "stop", "read-pos"}));
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);
  EXPECT_EQ(rig.exec.active_monitors(), 0u);
}

TEST(Executive, NonTerminalMonitorRunsBesideTheActionAndIsKilledWithIt) {
  Rig rig;
  rig.Start(
      "(define Tsym forever T)\n"
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((set-speed 20))"
      " {(WHILE (forever) (read-pos))}) (read-all-us-data)))");
  rig.Pose(0.6);
  EXPECT_EQ(rig.modules.Count("set-speed"), 1);
  EXPECT_EQ(rig.modules.Count("stop"), 0);
  EXPECT_NE(rig.modules.running, 0u);           // smooth-move goes on
  EXPECT_EQ(rig.modules.Count("read-pos"), 1);  // the loop's first iteration, at once
  rig.Tick();
  rig.Tick();
  EXPECT_EQ(rig.modules.Count("read-pos"), 3);  // one iteration per step
  rig.Finish();                                 // smooth-move done: the loop dies with it
  rig.Tick();
  rig.Tick();
  EXPECT_EQ(rig.modules.Count("read-pos"), 3);
  EXPECT_EQ(rig.modules.Count("read-all-us-data"), 1);
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);
}

TEST(Executive, NextOnTheLastCommandEndsTheMissionWithSuccess) {
  Rig rig;
  rig.Start("(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((stop)) ((NEXT)))))");
  rig.Pose(0.6);
  rig.Tick();
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);
  EXPECT_EQ(rig.modules.sent.size(), 2u);
}

TEST(Executive, CompletedOperatorKillsItsMonitorsAndTheNextCommandRuns) {
  Rig rig;
  rig.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((stop)) ((NEXT)))"
      " (read-pos)))");
  rig.Pose(0.0);
  rig.Finish();
  EXPECT_EQ(rig.exec.active_monitors(), 0u);
  rig.Pose(0.6);  // the killed monitor does not fire
  EXPECT_EQ(rig.modules.Count("stop"), 0);
  EXPECT_EQ(rig.modules.Names(), (std::vector<std::string>{"smooth-move", "read-pos"}));
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);
}

TEST(Executive, FailStopsEverythingCancelsNonStaticMonitorsAndDiagnoses) {
  Rig rig;
  rig.Start(
      "(MISSION m (LSURV: MNTR (S_battery-level BELOW 5) => ((stop)) ((FAIL)))\n"
      " (MAIN: (smooth-move ((100 0))\n"
      "   MNTR (S_zone IN Z) => ((set-speed 20)) {(MNTR (S_zone OUT Z) => ((set-speed 50)))}\n"
      "   MNTR STATIC (S_us-threshold ((1 40))) => ((stop)) ((FAIL)))))");
  rig.Pose(0.6);           // S1 fires; its control action creates the OUT monitor
  rig.Sonar({{1, 0.30}});  // an obstacle at 30 cm from sensor 1: S2 fires
  rig.Tick();              // the pilot reports the interruption; FAIL runs
  ASSERT_EQ(rig.exec.state(), MissionState::kFailed);
  const Diagnosis& d = rig.exec.diagnosis();
  EXPECT_EQ(d.cause,
            "FAIL in the control action of MNTR STATIC (S_us-threshold ((1 40))) at test.nc:5:4");
  EXPECT_EQ(d.where, "test.nc:5:55");
  ASSERT_EQ(d.fired.size(), 2u);
  EXPECT_EQ(d.fired[0].condition, "(S_zone IN Z)");
  EXPECT_EQ(d.fired[1].condition, "(S_us-threshold ((1 40)))");
  EXPECT_TRUE(d.fired[1].terminal);
  EXPECT_TRUE(d.fired[1].is_static);
  // Cancelled: the mission's battery monitor and the nested OUT monitor; kept: the static one.
  ASSERT_EQ(d.cancelled_monitors.size(), 2u);
  EXPECT_NE(d.cancelled_monitors[0].find("S_battery-level"), std::string::npos);
  EXPECT_NE(d.cancelled_monitors[1].find("(S_zone OUT Z)"), std::string::npos);
  ASSERT_EQ(d.static_monitors.size(), 1u);
  EXPECT_NE(d.static_monitors[0].find("S_us-threshold"), std::string::npos);
  EXPECT_EQ(rig.exec.active_monitors(), 0u);
  // Nothing more happens.
  const size_t sent = rig.modules.sent.size();
  rig.Pose(0.0);
  rig.Sonar({{1, 0.30}});
  rig.Tick();
  EXPECT_EQ(rig.modules.sent.size(), sent);
}

TEST(Executive, StaticMonitorBecomesActiveAgainAfterItsControlActionAndFiresAgain) {
  const char* mission =
      "(MISSION m (MAIN: (smooth-move ((100 0))"
      " MNTR %s (S_us-threshold ((1 40))) => ((stop)) {(resume-order)})))";
  for (const bool is_static : {true, false}) {
    Rig rig;
    char text[256];
    std::snprintf(text, sizeof text, mission, is_static ? "STATIC" : "");
    rig.Start(text);
    rig.Sonar({{1, 0.30}});
    rig.Tick();  // interrupted -> resume-order: smooth-move again
    EXPECT_EQ(rig.modules.Count("smooth-move"), 2);
    const auto& resumed = std::get<SmoothMoveCommand>(rig.modules.sent.back().command);
    EXPECT_TRUE(resumed.resume);
    rig.Sonar({{1, 0.30}});  // the obstacle again
    rig.Tick();
    EXPECT_EQ(rig.modules.Count("stop"), is_static ? 2 : 1) << (is_static ? "static" : "plain");
    EXPECT_EQ(rig.modules.Count("smooth-move"), is_static ? 3 : 2);
    EXPECT_EQ(rig.exec.state(), MissionState::kRunning);
  }
}

TEST(Executive, PartsOfOneSensorMustHoldOnTheSameDatum) {
  // (AND (sensor_i, S_i)(sensor_j, S_j)) of section 4.1.2: both parts belong to US-SSM.
  Rig rig;
  rig.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (AND (S_us-threshold ((1 40)))"
      " (S_us-threshold ((2 40)))) => ((stop)) ((NEXT)))))");
  rig.Sonar({{1, 0.30}});  // sensor 1 only
  rig.Sonar({{2, 0.30}});  // then sensor 2 only: never both on one datum
  EXPECT_EQ(rig.modules.Count("stop"), 0);
  rig.Sonar({{1, 0.30}, {2, 0.35}});
  EXPECT_EQ(rig.modules.Count("stop"), 1);
}

TEST(Executive, LaserAndBatteryConditionsHaveTheirOwnSsms) {
  Rig rig;
  rig.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_laser-threshold 50) => ((draw %l 1))"
      " MNTR (S_battery-level ABOVE 90) => ((draw %b 1)))))");
  LaserScan scan;
  scan.angle_min_rad = -kPi / 2;
  scan.angle_increment_rad = kPi / 2;
  scan.ranges_m = {2.0, 2.0, 2.0};  // right, ahead, left
  rig.exec.OnLaser(scan, 0.1);
  EXPECT_EQ(rig.modules.Count("draw"), 0);
  scan.ranges_m = {2.0, 0.45, 2.0};
  rig.exec.OnLaser(scan, 0.2);
  EXPECT_EQ(rig.modules.Count("draw"), 1);
  rig.exec.OnBattery(BatteryDatum{80.0}, 0.3);
  EXPECT_EQ(rig.modules.Count("draw"), 1);
  rig.exec.OnBattery(BatteryDatum{95.0}, 0.4);
  EXPECT_EQ(rig.modules.Count("draw"), 2);
  bool laser = false, battery = false;
  for (const Message& m : rig.exec.log().messages()) {
    laser |= m.kind == Message::Kind::kConditionTrue && m.from == "LASER-SSM";
    battery |= m.kind == Message::Kind::kConditionTrue && m.from == "BATTERY-SSM";
  }
  EXPECT_TRUE(laser);
  EXPECT_TRUE(battery);
}

TEST(Executive, ModuleFailureStandsWhenNoStaticMonitorFires) {
  Rig r;
  r.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0))"
      " MNTR STATIC (S_us-threshold ((1 40))) => ((stop)) ((NEXT))) (read-pos)))");
  r.Sonar({{1, 0.50}});  // not under the 40 cm threshold
  r.exec.OnOperatorReport(r.modules.running,
                          ScriptedModules::Reply(OperatorStatus::kFailed, "wheel blocked"), r.t);
  EXPECT_EQ(r.modules.Count("stop"), 0);
  EXPECT_EQ(r.exec.state(), MissionState::kFailed);
  EXPECT_EQ(r.exec.diagnosis().cause,
            "PILOT reported that smooth-move 1 point(s) to (1.00, 0.00) m failed: wheel blocked");
  EXPECT_EQ(r.modules.Count("read-pos"), 0);
}

TEST(Executive, MonitorSpanningTwoSensorsFiresOnlyOnFreshPartsOfBoth) {
  const char* mission =
      "(MISSION m (MAIN: (smooth-move ((100 0))"
      " MNTR (AND (S_us-threshold ((1 40))) (S_zone OUT Z)) => ((stop)) ((NEXT))) (read-pos)))";
  Rig fresh;
  fresh.Start(mission);
  fresh.exec.OnPose(At(0.0, 0.0), 0.1);        // POSE-SSM: out of Z
  fresh.exec.OnSonar(Scan({{1, 0.30}}), 0.3);  // US-SSM: obstacle; the pose part is 0.2 s old
  EXPECT_EQ(fresh.modules.Count("stop"), 1);
  fresh.modules.Deliver(&fresh.exec, 0.4);
  EXPECT_EQ(fresh.exec.state(), MissionState::kSucceeded);

  Rig stale;
  stale.Start(mission);
  stale.exec.OnPose(At(0.0, 0.0), 0.1);
  stale.exec.OnSonar(Scan({{1, 0.30}}), 0.7);  // the pose part is 0.6 s old: unknown
  EXPECT_EQ(stale.modules.Count("stop"), 0);
  stale.exec.OnPose(At(0.6, 0.0), 0.8);  // in Z now: the formula is false
  EXPECT_EQ(stale.modules.Count("stop"), 0);
  stale.exec.OnPose(At(0.0, 0.0), 0.9);  // out again, the obstacle 0.2 s old: fires
  EXPECT_EQ(stale.modules.Count("stop"), 1);
}

TEST(Executive, StaticMonitorReArmedAfterAModuleFailureFiresAtOnceWhenItsConditionHolds) {
  Rig r;
  r.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0))"
      " MNTR STATIC (S_zone IN Z) => ((draw %f 1)) ((NEXT))) (read-pos)))");
  r.Pose(0.6);  // fires (non-terminal): NEXT at once -> read-pos -> success
  EXPECT_EQ(r.exec.state(), MissionState::kSucceeded);

  Rig s;
  s.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0))"
      " MNTR STATIC (S_zone IN Z) => ((draw %f 1)) {(read-pos)}) (read-all-us-data)))");
  s.Pose(0.6);  // fires; its control action reads the position; it is active again
  EXPECT_EQ(s.modules.Count("read-pos"), 1);
  // The pilot fails while the robot is still in Z: the static monitor, active again at once,
  // fires on the latest pose; its control action does not resume, so the failure stands.
  s.exec.OnOperatorReport(s.modules.running,
                          ScriptedModules::Reply(OperatorStatus::kFailed, "wheel blocked"), s.t);
  EXPECT_EQ(s.modules.Count("draw"), 2);
  EXPECT_EQ(s.modules.Count("read-pos"), 2);
  EXPECT_EQ(s.exec.state(), MissionState::kFailed);
  EXPECT_NE(s.exec.diagnosis().cause.find("wheel blocked"), std::string::npos);
}

TEST(Executive, SimultaneousFiringsFollowThePriorityOrder) {
  Rig rig;
  const MissionFile o =
      Parse("(OSURV: MNTR (S_zone IN ((50 -10)(50 10)(70 10)(70 -10))) => ((draw %o 0)))", "o.nc");
  ASSERT_TRUE(rig.exec.SetOSurveillances(o, 0.0).empty());
  rig.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0))\n"
      " MNTR (S_zone IN Z) => ((draw %a 1)) {(read-pos)}\n"
      " MNTR STATIC (S_zone IN Z) => ((draw %b 2)) {(read-pos)}\n"
      " MNTR (S_zone IN Z) => ((stop) (draw %c 3)) ((NEXT))\n"
      " MNTR (S_zone IN Z) => ((draw %d 4)))))");
  rig.Pose(0.6);  // all five fire on this one datum
  std::vector<std::string> order;
  for (const auto& s : rig.modules.sent) {
    if (const auto* d = std::get_if<DrawCommand>(&s.command)) order.push_back(d->formats[0]);
  }
  // O-surveillance first, then terminal, then static, then as written.
  EXPECT_EQ(order, (std::vector<std::string>{"o", "c", "b", "a", "d"}));
  // The terminal monitor's NEXT ends the command: the control actions of a and b, which belong
  // to it, never run.
  rig.Tick();
  EXPECT_EQ(rig.modules.Count("read-pos"), 0);
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);
}

TEST(Executive, NestedMonitorLivesWithItsCommand) {
  Rig rig;
  rig.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((set-speed 20))"
      " {(MNTR (S_zone OUT Z) => ((set-speed 50)))}) (read-pos)))");
  rig.Pose(0.6);
  EXPECT_EQ(rig.exec.active_monitors(), 1u);  // S1 destroyed, S1-2 created
  rig.Pose(0.9);                              // leaves Z: S1-2 fires
  ASSERT_EQ(rig.modules.Count("set-speed"), 2);
  EXPECT_DOUBLE_EQ(std::get<SetSpeedCommand>(rig.modules.sent.back().command).speed_mps, 0.5);
  EXPECT_EQ(rig.exec.active_monitors(), 0u);

  Rig other;  // the command ends before the robot leaves: the nested monitor dies with it
  other.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((set-speed 20))"
      " {(MNTR (S_zone OUT Z) => ((set-speed 50)))}) (read-pos)))");
  other.Pose(0.6);
  other.Finish();
  other.Pose(0.9);
  EXPECT_EQ(other.modules.Count("set-speed"), 1);
}

TEST(Executive, PreconditionThatDoesNotHoldRefusesTheMissionNamingTheClause) {
  Rig rig;
  rig.exec.SetRobotState("motor", Value::Symbol("OFF"));
  const StartResult r =
      rig.exec.StartMission(Parse("(MISSION m\n (PRE: (eq motor ON))\n (MAIN: (read-pos)))"), 0.0);
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(r.refusal, "PRE: (eq motor ON) does not hold (motor is OFF)");
  EXPECT_EQ(r.refusal_where.line, 2);
  EXPECT_EQ(r.refusal_where.column, 8);
  EXPECT_EQ(rig.exec.state(), MissionState::kIdle);
  EXPECT_TRUE(rig.modules.sent.empty());

  // Example 2 refused when the robot is already in ZONE109.
  Rig in_zone;
  const MissionFile example2 = ParseFile("example2_zone_surveillance.nc");
  in_zone.exec.SetRobotState("robot-in-zone", example2.definitions[0].value);
  const StartResult refused = in_zone.exec.StartMission(example2, 0.0);
  EXPECT_FALSE(refused.accepted);
  EXPECT_EQ(refused.refusal.rfind("PRE: (not (eq robot-in-zone $ZONE109)) does not hold", 0), 0u)
      << refused.refusal;
}

TEST(Executive, MissionsWithErrorsAreRefusedWithTheCheckersDiagnostics) {
  Rig rig;
  const StartResult r = rig.exec.StartMission(Parse("(MISSION m (MAIN: (teleport)))"), 0.0);
  EXPECT_FALSE(r.accepted);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].ToString().rfind("test.nc:1:20: unknown operator 'teleport'", 0), 0u);
}

TEST(Executive, ATaskWhoseExecutionEnvironmentNoLongerHoldsIsStopped) {
  Rig rig;
  rig.Start(
      "(MISSION m (ENV: (set LOA T)) (MAIN: (avoid-obstacle MNTR (S_zone IN Z)"
      " => ((draw %z 1)) {(set LOA NIL)})))");
  const OperatorHandle avoid = rig.modules.running;
  rig.Pose(0.6);
  ASSERT_EQ(rig.modules.halted.size(), 1u);
  EXPECT_EQ(rig.modules.halted[0], avoid);
  EXPECT_EQ(rig.exec.state(), MissionState::kFailed);
  EXPECT_EQ(rig.exec.diagnosis().cause,
            "the execution environment of avoid-obstacle (LOA T) does not hold: LOA is NIL: the "
            "executive stops the task");
  // Without LOA the task does not even start.
  Rig none;
  none.Start("(MISSION m (MAIN: (avoid-obstacle)))");
  EXPECT_EQ(none.modules.Count("avoid-obstacle"), 0);
  EXPECT_EQ(none.exec.state(), MissionState::kFailed);
}

TEST(Executive, Fig5MessageOrderOnExample1sFirstCommand) {
  Rig rig;
  const MissionFile example1 = ParseFile("example1_wall_following.nc");
  ASSERT_TRUE(rig.exec.StartMission(example1, 0.0).accepted);
  rig.exec.log().Clear();
  rig.exec.Step(0.0);
  // A wall 80 cm ahead: the belt reads what the sonar model predicts for sensors 16, 1 and 2.
  const SonarRing ring = HilareRing();
  SonarScan wall = Scan();
  for (int i : {15, 0, 1}) {
    wall.ranges_m[i] = PredictedRange(ring.mounts[i], ring.half_field_of_view_rad, 0.8, 0.0);
  }
  // The log holds (1)-(4) from the start; clear and replay: start again on a fresh rig.
  Rig fresh;
  ASSERT_TRUE(fresh.exec.StartMission(example1, 0.0).accepted);
  fresh.exec.OnSonar(wall, 0.1);
  fresh.modules.Deliver(&fresh.exec, 0.2);
  std::vector<std::string> flow;
  for (const Message& m : fresh.exec.log().messages()) {
    if (m.kind == Message::Kind::kNote || m.kind == Message::Kind::kMission) continue;
    flow.push_back(m.from + ">" + m.to + " " + KindName(m.kind) +
                   (m.monitor != 0 ? " n" + std::to_string(m.monitor) : ""));
  }
  const std::vector<std::string> expected = {
      "EM>PILOT operator (1)",           // smooth-move to the pilot
      "EM>SM monitor (2)",               // the surveillance monitor to the SM
      "SM>EM id (3) n1",                 // its identifier
      "EM> control stored n1",           // {(NEXT)} memorized under <n1>
      "SM>US-SSM condition (4) n1",      // the left member to the ultrasonic SSM
      "US-SSM>SM true (5) n1",           // the line is perceived
      "SM>PILOT reflex (6-1) n1",        // (stop)
      "SM>EM fired (6-2) n1",            // the executive is informed
      "PILOT>EM report (7)",             // the pilot: movement interrupted
      "EM>SM destroy n1",                // the monitor is destroyed
      "EM> control action n1",           // NEXT
      "EM>WALL-FOLLOWING operator (1)",  // the next command: RUN wall-following
      "EM>SM monitor (2)",
      "SM>EM id (3) n2",
      "EM> control stored n2",
      "SM>POSE-SSM condition (4) n2"};
  EXPECT_EQ(flow, expected);
}

TEST(Executive, OSurveillanceIsAlwaysOnAndFailsTheRunningMission) {
  Rig rig;
  ASSERT_TRUE(rig.exec.SetOSurveillances(ParseFile("o_surveillances.nc"), 0.0).empty());
  rig.t = 1.0;
  rig.exec.OnBattery(BatteryDatum{10.0}, rig.t);  // no mission: the reflex still stops
  EXPECT_EQ(rig.modules.Count("stop"), 1);
  rig.exec.OnBattery(BatteryDatum{9.0}, rig.t + 0.1);  // still low: fired once per event
  EXPECT_EQ(rig.modules.Count("stop"), 1);
  rig.exec.OnBattery(BatteryDatum{60.0}, rig.t + 0.2);
  rig.t += 0.3;
  rig.Start("(MISSION m (MAIN: (smooth-move ((100 0)))))");
  rig.exec.OnBattery(BatteryDatum{12.0}, rig.t);
  EXPECT_EQ(rig.modules.Count("stop"), 2);
  rig.Tick();  // the pilot reports the interruption; FAIL
  EXPECT_EQ(rig.exec.state(), MissionState::kFailed);
  EXPECT_EQ(rig.exec.diagnosis().cause,
            "FAIL in the control action of MNTR (S_battery-level BELOW 15) at " +
                testing::MissionPath("o_surveillances.nc") + ":4:3");
  EXPECT_TRUE(rig.exec.diagnosis().fired.at(0).o_surveillance);
  EXPECT_EQ(rig.exec.active_monitors(), 1u);  // the O-surveillance stays
}

TEST(Executive, ProcessFailureFailsTheMissionWithTheModulesReason) {
  Rig rig;
  rig.Start(
      "(MISSION m (MAIN: (RUN (wall-following (right-side 25)) MNTR (S_zone IN Z) => ((stop))"
      " ((NEXT)))))");
  rig.exec.OnOperatorReport(
      rig.modules.running,
      ScriptedModules::Reply(OperatorStatus::kFailed, "repeatedly insufficient data"), 1.0);
  EXPECT_EQ(rig.exec.state(), MissionState::kFailed);
  EXPECT_EQ(rig.exec.diagnosis().cause,
            "WALL-FOLLOWING reported that wall-following right side at 0.25 m failed: "
            "repeatedly insufficient data");
  EXPECT_EQ(rig.exec.diagnosis().where, "test.nc:2:19");
}

TEST(Executive, ConcurrentActionWaitsWhileTheCurrentActionHoldsTheWheels) {
  Rig rig;
  rig.Start(
      "(MISSION m (ENV: (set LOA T)) (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z)"
      " => ((set-speed 20)) {(avoid-obstacle)}) (read-pos)))");
  rig.Pose(0.6);
  rig.Tick();
  rig.Tick();
  EXPECT_EQ(rig.modules.Count("avoid-obstacle"), 0);  // smooth-move holds the wheels
  rig.Finish();
  rig.Tick();
  EXPECT_EQ(rig.modules.Count("avoid-obstacle"), 0);  // killed with the action
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);
}

TEST(Executive, MissingInterruptionReportTimesOut) {
  Rig rig;
  rig.modules.report_interruptions = false;
  rig.Start(
      "(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((stop)) ((NEXT)))"
      " (read-pos)))");
  rig.Pose(0.6);
  rig.Tick(1.0);
  EXPECT_EQ(rig.modules.Count("read-pos"), 0);
  rig.Tick(1.5);  // past the 2 s timeout
  EXPECT_EQ(rig.modules.Count("read-pos"), 1);
  EXPECT_EQ(rig.modules.halted.size(), 1u);
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);
}

TEST(Executive, RuntimeErrorsFailTheMissionWithTheirLocation) {
  Rig rig;
  rig.Start(
      "(MISSION m (MAIN: (read-pos MNTR (S_zone IN Z) => ((stop)))\n (set v (1 2))\n"
      " (set-speed v)))");
  EXPECT_EQ(rig.exec.state(), MissionState::kFailed);
  EXPECT_EQ(rig.exec.diagnosis().where, "test.nc:4:2");
  EXPECT_NE(rig.exec.diagnosis().cause.find("set-speed: the speed must be a number"),
            std::string::npos);
}

TEST(Executive, AbortHaltsTheActionAndRemovesTheMonitors) {
  Rig rig;
  rig.Start("(MISSION m (MAIN: (smooth-move ((100 0)) MNTR (S_zone IN Z) => ((stop)))))");
  const OperatorHandle h = rig.modules.running;
  rig.exec.Abort("cancelled", 1.0);
  EXPECT_EQ(rig.exec.state(), MissionState::kAborted);
  EXPECT_EQ(rig.modules.halted, std::vector<OperatorHandle>{h});
  EXPECT_EQ(rig.exec.active_monitors(), 0u);
  EXPECT_TRUE(rig.exec.StartMission(Parse("(MISSION n (MAIN: (read-pos)))"), 2.0).accepted);
}

TEST(Executive, SubMissionChecksItsPreconditionSetsItsEnvironmentAndRunsItsMain) {
  Rig rig;
  rig.Start(
      "(MISSION outer (MAIN: (MISSION inner (PRE: (eq motors ON)) (ENV: (set LOA T))"
      " (LSURV: MNTR (S_zone IN Z) => ((stop)) ((NEXT)))"
      " (MAIN: (smooth-move ((100 0))))) (read-pos)))");
  EXPECT_EQ(rig.exec.Variable("LOA"), Value::True());
  EXPECT_EQ(rig.modules.Count("smooth-move"), 1);
  rig.Pose(0.6);  // the sub-mission's LSURV monitor: NEXT ends its current command
  rig.Tick();
  EXPECT_EQ(rig.modules.Names(), (std::vector<std::string>{"smooth-move", "stop", "read-pos"}));
  EXPECT_EQ(rig.exec.state(), MissionState::kSucceeded);

  Rig refused;
  refused.exec.SetRobotState("motors", Value::Symbol("OFF"));
  refused.exec.StartMission(
      Parse("(MISSION outer (MAIN: (MISSION inner (PRE: (eq motors ON)) (MAIN: (read-pos)))))"),
      0.0);
  EXPECT_EQ(refused.exec.state(), MissionState::kFailed);
  EXPECT_EQ(refused.exec.diagnosis().cause,
            "sub-mission inner: PRE: (eq motors ON) does not hold (motors is OFF)");
  EXPECT_EQ(refused.modules.Count("read-pos"), 0);
}

TEST(Executive, SecondMissionWhileOneRunsIsRefused) {
  Rig rig;
  rig.Start("(MISSION m (MAIN: (smooth-move ((100 0)))))");
  const StartResult r = rig.exec.StartMission(Parse("(MISSION n (MAIN: (read-pos)))"), 1.0);
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(r.refusal, "mission 'm' is running");
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
