// Example 2 (section 6.2.2) on HILARE's on-board modules with scripted poses and sonar data,
// each branch the paper describes, over ten seeded runs (pose and range noise, the obstacle's
// place): zone entered first (speed 20, LOA off, data drawn, speed 50 on leaving; an obstacle in
// the zone: FAIL), obstacle first (avoidance, the zone entered, LOA NIL stops the avoidance,
// the static monitor fires again: FAIL) and avoidance finishing before the zone, the obstacle
// gone (resume-order, success). avoid_obstacle_test.cpp goes round an obstacle that stays.
#include <random>

#include <gtest/gtest.h>

#include "rpl_executive/noreils_chatila/on_board_modules.h"
#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::HilareRing;
using testing::ParseFile;

class Example2 {
 public:
  explicit Example2(unsigned seed) : rng_(seed) {
    exec_.SetRobotState("motor", Value::Symbol("ON"));
    file_ = ParseFile("example2_zone_surveillance.nc");
    Cycle();  // the modules know where the robot is before the mission starts
    const StartResult r = exec_.StartMission(file_, t_);
    EXPECT_TRUE(r.accepted) << r.refusal;
  }

  // One 10 Hz cycle: data to the modules and the executive, the modules' reports back.
  void Cycle() {
    t_ += 0.1;
    std::normal_distribution<double> noise(0.0, 0.01);
    PoseDatum p{Pose2{pose_.x + noise(rng_), pose_.y + noise(rng_), pose_.yaw}};
    SonarScan scan = testing::Scan();
    for (const auto& [id, r] : echoes_) scan.ranges_m[id - 1] = r + noise(rng_);
    kit_.OnPose(p);
    kit_.OnSonar(scan);
    exec_.OnPose(p, t_);
    exec_.OnSonar(scan, t_);
    kit_.Update(t_);
    for (const auto& [h, reply] : kit_.TakeReports()) exec_.OnOperatorReport(h, reply, t_);
    exec_.Step(t_);
    for (const DrawCommand& d : kit_.TakeDrawings()) drawings_.push_back(d);
  }
  // Moves in 3 cm steps to (x, y), heading along, one cycle per step.
  void MoveTo(double x, double y, int max_cycles = 1000) {
    pose_.yaw = std::atan2(y - pose_.y, x - pose_.x);
    for (int i = 0; i < max_cycles && exec_.state() == MissionState::kRunning; ++i) {
      const double d = std::hypot(x - pose_.x, y - pose_.y);
      if (d < 1e-9) break;
      const double step = std::min(0.03, d);
      pose_.x += step * (x - pose_.x) / d;
      pose_.y += step * (y - pose_.y) / d;
      Cycle();
    }
  }
  void Wait(int cycles) {
    for (int i = 0; i < cycles && exec_.state() == MissionState::kRunning; ++i) Cycle();
  }
  // The rest of PATH from its first leg (x < 1.8 m).
  void FinishPath() {
    MoveTo(1.8, 5.2);
    MoveTo(3.5, 5.2);
    Arrive();
  }
  // The last leg to PATH's end and its final heading, 2700.
  void Arrive() {
    MoveTo(3.6, 3.2);
    pose_.yaw = -kPi / 2;
    Wait(5);
  }
  double Uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }

  std::vector<std::string> Fired() const {
    std::vector<std::string> out;
    for (const MonitorEvent& e : exec_.fired()) out.push_back(e.condition);
    return out;
  }
  bool Logged(const std::string& part) const {
    for (const Message& m : exec_.log().messages()) {
      if (m.text.find(part) != std::string::npos) return true;
    }
    return false;
  }
  int Operators(const std::string& part) const {
    int n = 0;
    for (const Message& m : exec_.log().messages()) {
      n += m.kind == Message::Kind::kOperator && m.text.find(part) != std::string::npos;
    }
    return n;
  }
  Value Var(const std::string& name) const { return exec_.Variable(name).value_or(Value()); }

  OnBoardModules kit_{OnBoardParameters(), HilareRing()};
  Executive exec_{ExecutiveParameters(), SurveillanceParameters(), HilareRing(), &kit_};
  MissionFile file_;
  std::mt19937 rng_;
  double t_ = 0.0;
  Pose2 pose_{0.8, 5.2, 0.0};  // hilare_room's robot_start, outside ZONE109
  std::vector<std::pair<int, double>> echoes_;
  std::vector<DrawCommand> drawings_;
};

const char* kIn = "(S_zone IN ZONE109)";
const char* kOut = "(S_zone OUT ZONE109)";
const char* kObstacle = "(S_us-threshold sensors-list)";

TEST(Example2, ZoneEnteredFirstSlowsDrawsAndSpeedsUpOnLeavingThenSucceeds) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    Example2 run(seed);
    run.MoveTo(2.5, 5.2);  // inside ZONE109 (x from 1.5 to 3.5 m)
    EXPECT_DOUBLE_EQ(run.kit_.pilot().speed_mps(), 0.2) << "set-speed 20, seed " << seed;
    EXPECT_TRUE(run.Var("LOA").IsNil());
    EXPECT_EQ(run.Var("robot-in-zone"), run.file_.definitions[0].value);
    const size_t drawn = run.drawings_.size();
    EXPECT_GT(drawn, 20u);  // one iteration per cycle since the robot entered
    ASSERT_FALSE(run.drawings_.empty());
    EXPECT_EQ(run.drawings_[0].formats, (std::vector<std::string>{"G_pos", "G_echoes"}));
    EXPECT_EQ(run.drawings_[0].data.at(0).list().size(), 3u);  // r-position (x y heading)
    run.MoveTo(3.5, 5.2);
    EXPECT_GT(run.drawings_.size(), drawn + 30u);  // the loop goes on while in the zone
    run.MoveTo(3.55, 4.2);                         // out of the zone (y < 5 m)
    // set-speed 50 asks 0.5 m/s; HILARE's pilot is limited to 0.4 m/s.
    EXPECT_DOUBLE_EQ(run.kit_.pilot().speed_mps(), 0.4);
    EXPECT_EQ(run.Var("LOA"), Value::True());
    EXPECT_TRUE(run.Var("robot-in-zone").IsNil());
    const size_t after_leaving = run.drawings_.size();
    run.Arrive();
    EXPECT_EQ(run.drawings_.size(), after_leaving);  // the loop ended with the zone
    EXPECT_EQ(run.Fired(), (std::vector<std::string>{kIn, kOut})) << seed;
    EXPECT_EQ(run.exec_.state(), MissionState::kSucceeded) << seed;
  }
}

TEST(Example2, TheCurrentCommandAndTheActiveMonitorsAreReportedForTheNodesFeedback) {
  Example2 run(1);
  const std::string file = testing::MissionPath("example2_zone_surveillance.nc");
  EXPECT_EQ(run.exec_.CurrentCommand(),
            "smooth-move 3 point(s) to (3.60, 3.20) m, heading -1.571 rad at " + file + ":15:3");
  const std::vector<std::string> monitors = run.exec_.ActiveMonitors();
  ASSERT_EQ(monitors.size(), 2u);  // S1 and S2
  EXPECT_NE(monitors[0].find("(S_zone IN ZONE109)"), std::string::npos) << monitors[0];
  EXPECT_NE(monitors[1].find("MNTR STATIC (S_us-threshold sensors-list)"), std::string::npos)
      << monitors[1];
  run.MoveTo(2.5, 5.2);  // S1 fired: its nested S1-2 is active instead
  const std::vector<std::string> inside = run.exec_.ActiveMonitors();
  ASSERT_EQ(inside.size(), 2u);
  EXPECT_NE(inside[1].find("(S_zone OUT ZONE109)"), std::string::npos) << inside[1];
  // The fired monitor names the command it acted on and its control action as written.
  ASSERT_EQ(run.exec_.fired().size(), 1u);
  const MonitorEvent& s1 = run.exec_.fired()[0];
  EXPECT_EQ(s1.command,
            "smooth-move 3 point(s) to (3.60, 3.20) m, heading -1.571 rad at " + file + ":15:3");
  EXPECT_NE(s1.control.find("robot-in-zone"), std::string::npos) << s1.control;
  EXPECT_NE(s1.control.find("WHILE"), std::string::npos) << s1.control;
}

TEST(Example2, ANewMissionStartsAtThePilotsDefaultSpeedNotAtTheLastSetSpeed) {
  Example2 run(1);
  run.MoveTo(2.5, 5.2);  // inside ZONE109: set-speed 20
  ASSERT_DOUBLE_EQ(run.kit_.pilot().speed_mps(), 0.2);
  run.echoes_ = {{1, 0.30}};  // an obstacle in the zone: S2, FAIL, still at 20 cm/s
  run.Wait(5);
  ASSERT_EQ(run.exec_.state(), MissionState::kFailed);
  ASSERT_DOUBLE_EQ(run.kit_.pilot().speed_mps(), 0.2);
  run.echoes_.clear();
  run.pose_ = Pose2{0.8, 5.2, 0.0};
  run.Cycle();
  const StartResult r = run.exec_.StartMission(run.file_, run.t_);
  ASSERT_TRUE(r.accepted) << r.refusal;
  EXPECT_DOUBLE_EQ(run.kit_.pilot().speed_mps(), OnBoardParameters().pilot.default_speed_mps);
}

TEST(Example2, ObstacleInTheZoneMakesTheMissionFail) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    Example2 run(seed);
    run.MoveTo(run.Uniform(1.7, 3.3), 5.2);
    run.echoes_ = {{1, 0.30}};  // 30 cm ahead: under sensor 1's 40 cm
    run.Wait(5);
    EXPECT_EQ(run.exec_.state(), MissionState::kFailed) << seed;
    EXPECT_EQ(run.Fired(), (std::vector<std::string>{kIn, kObstacle})) << seed;
    EXPECT_EQ(run.exec_.diagnosis().cause,
              "FAIL in the control action of MNTR STATIC (S_us-threshold sensors-list) at " +
                  testing::MissionPath("example2_zone_surveillance.nc") + ":28:5");
    EXPECT_EQ(run.kit_.wheels_holder(), "");  // stopped
    EXPECT_EQ(run.Operators("avoid-obstacle"), 0);
  }
}

TEST(Example2, ObstacleFirstAvoidanceIntoTheZoneIsStoppedAndTheStaticMonitorFails) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    Example2 run(seed);
    run.MoveTo(run.Uniform(1.0, 1.3), 5.2);  // before the zone
    run.echoes_ = {{1, 0.30}, {2, 0.35}};
    run.Wait(3);
    ASSERT_EQ(run.kit_.wheels_holder(), "avoid-obstacle") << "LOA is T: avoid, seed " << seed;
    // The avoidance takes the robot into the zone, the obstacle still beside it.
    run.echoes_ = {{2, 0.35}};
    run.MoveTo(1.7, 5.45);
    EXPECT_EQ(run.exec_.state(), MissionState::kFailed) << seed;
    EXPECT_TRUE(run.Logged("the execution environment of avoid-obstacle (LOA T) does not hold"));
    EXPECT_EQ(run.Fired(), (std::vector<std::string>{kObstacle, kIn, kObstacle})) << seed;
    EXPECT_NE(run.exec_.diagnosis().cause.find("FAIL in the control action of MNTR STATIC"),
              std::string::npos);
    EXPECT_EQ(run.kit_.wheels_holder(), "");
  }
}

TEST(Example2, AvoidanceFinishingBeforeTheZoneResumesTheOrderAndSucceeds) {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    Example2 run(seed);
    run.MoveTo(run.Uniform(0.9, 1.1), 5.2);
    run.echoes_ = {{1, 0.30}};
    run.Wait(3);
    ASSERT_EQ(run.kit_.wheels_holder(), "avoid-obstacle") << seed;
    // The obstacle goes away before the robot has moved round it: the front sensor reads past
    // it (something 3 m off) on five data, the way back along PATH is clear, resume-order.
    run.echoes_ = {{1, 3.0}};
    run.Wait(8);
    run.echoes_.clear();
    EXPECT_EQ(run.kit_.wheels_holder(), "smooth-move") << "resume-order, seed " << seed;
    EXPECT_EQ(run.Operators("smooth-move (resumed)"), 1);
    run.FinishPath();
    EXPECT_EQ(run.Fired(), (std::vector<std::string>{kObstacle, kIn, kOut})) << seed;
    EXPECT_EQ(run.exec_.state(), MissionState::kSucceeded) << seed;
  }
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
