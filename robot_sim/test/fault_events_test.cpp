#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "robot_sim/fault_events.h"
#include "test_world.h"

namespace robot_sim {
namespace {

// One event of every kind, out of time order.
constexpr const char* kEveryKind = R"(
faults:
  - {time: 30, kind: kidnap, pose: [0, 0, -1.22], relative: true}
  - {time: 5, kind: door, door: d1, state: open}
  - {time: 10, kind: sensor, sensor: sonar/3, fault: dropout, duration: 2}
  - {time: 11, kind: sensor, sensor: laser, fault: noise, noise_stddev: 0.2}
  - {time: 12, kind: slip, linear_scale: 0.8, duration: 3}
  - {time: 13, kind: add_obstacle, id: box, shape: cylinder, pose: [3, 2, 0], size: [0.5, 0.5, 1]}
  - {time: 14, kind: remove_obstacle, id: box}
)";

TEST(FaultScheduleTest, ParsesEveryKindSortedByTime) {
  const auto r = ParseFaultSchedule(kEveryKind, "schedule.yaml");
  ASSERT_TRUE(r.ok()) << spott_map::FormatErrors(r.errors);
  ASSERT_EQ(r.events.size(), 7u);
  EXPECT_EQ(r.events[0].kind, FaultEvent::Kind::kDoor);
  EXPECT_FALSE(r.events[0].closed);
  EXPECT_EQ(r.events[0].where.line, 4);
  EXPECT_EQ(r.events[1].sensor_fault, FaultKind::kDropout);
  EXPECT_EQ(r.events[2].sensor_fault, FaultKind::kNoise);
  EXPECT_DOUBLE_EQ(r.events[3].linear_scale, 0.8);
  EXPECT_TRUE(r.events[4].obstacle.cylinder);
  EXPECT_EQ(r.events[6].kind, FaultEvent::Kind::kKidnap);
  EXPECT_TRUE(r.events[6].relative);
  EXPECT_DOUBLE_EQ(r.events[6].pose.yaw, -1.22);
}

TEST(FaultScheduleTest, EveryEventIsDescribedInTheUsersWords) {
  const auto r = ParseFaultSchedule(kEveryKind, "schedule.yaml");
  ASSERT_TRUE(r.ok()) << spott_map::FormatErrors(r.errors);
  const std::vector<std::string> expected = {
      // in time order
      "door d1 open",
      "sensor sonar/3 dropout for 2 s",
      "sensor laser noise (0.200 m) until cleared",
      "wheel slip x0.80 linear, x1.00 angular for 3.0 s",
      "cylinder box 0.50 x 0.50 x 1.00 m added at (3.00, 2.00)",
      "obstacle box removed",
      "kidnap by (0.00 m, 0.00 m, -1.22 rad) in the robot frame"};
  ASSERT_EQ(r.events.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(Describe(r.events[i]), expected[i]);
  EXPECT_STREQ(KindName(r.events[4].kind), "add_obstacle");
}

TEST(FaultScheduleTest, ErrorsNameLineColumnAndTheProblem) {
  const auto r = ParseFaultSchedule(
      "faults:\n"
      "  - {time: 1, kind: door, door: d1, state: ajar}\n"
      "  - {time: -2, kind: slip, duration: 1}\n"
      "  - {time: 3, kind: teleport}\n"
      "  - {time: 4, kind: sensor, sensor: sonar, fault: noise}\n",
      "bad.yaml");
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(r.events.empty());
  ASSERT_GE(r.errors.size(), 4u);
  EXPECT_EQ(r.errors[0].where.line, 2);
  EXPECT_NE(r.errors[0].message.find("ajar"), std::string::npos);
  EXPECT_EQ(r.errors[1].where.line, 3);
  EXPECT_EQ(r.errors[2].where.line, 4);
  EXPECT_NE(r.errors[2].message.find("teleport"), std::string::npos);
  EXPECT_EQ(r.errors[3].where.line, 5);
  EXPECT_NE(r.errors[3].message.find("noise_stddev"), std::string::npos);
}

TEST(FaultScheduleTest, EmptyScheduleAndSyntaxError) {
  EXPECT_TRUE(ParseFaultSchedule("", "empty").ok());
  EXPECT_TRUE(ParseFaultSchedule("faults: []", "empty").ok());
  const auto r = ParseFaultSchedule("faults: [{time: 1,", "broken.yaml");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors[0].where.file, "broken.yaml");
}

// The test world with a B-12 in it.
class FaultEventTest : public ::testing::Test {
 protected:
  FaultEventTest() : sim(MakeWorld()) {}
  static std::unique_ptr<SimWorld> MakeWorld() {
    SimWorldParameters p;
    p.octomap_resolution_m = 0.1;
    auto world = std::make_unique<SimWorld>(p);
    world->Build(testing::TestWorld());
    return world;
  }
  int AddB12(const spott_map::Pose2& at) {
    auto spec = LoadRobotSpec(testing::PackageFile("config/robots/b12.yaml"),
                              testing::PackageFile("urdf/b12.urdf"));
    EXPECT_TRUE(spec.ok());
    return *sim.AddRobot(*spec.spec, at, {}, nullptr);
  }
  Simulator sim;
};

TEST_F(FaultEventTest, AppliedEventsChangeTheSimulatorAndRefusalsChangeNothing) {
  const int id = AddB12({2, 3, 0});
  FaultEvent door;
  door.kind = FaultEvent::Kind::kDoor;
  door.name = "d1";
  door.closed = false;
  std::string error;
  ASSERT_TRUE(ApplyFaultEvent(sim, id, door, &error)) << error;
  EXPECT_EQ(sim.world().DoorClosed("d1"), std::optional<bool>(false));
  FaultEvent add;
  add.kind = FaultEvent::Kind::kAddObstacle;
  add.obstacle.id = "box";
  add.obstacle.pose = {4, 3, 0};
  add.obstacle.size_x = add.obstacle.size_y = add.obstacle.height = 0.2;
  EXPECT_TRUE(ApplyFaultEvent(sim, id, add, &error)) << error;
  FaultEvent remove;
  remove.kind = FaultEvent::Kind::kRemoveObstacle;
  remove.name = "wall_1";
  EXPECT_FALSE(ApplyFaultEvent(sim, id, remove, &error));
  FaultEvent sensor;
  sensor.kind = FaultEvent::Kind::kSensor;
  sensor.name = "sonar";
  sensor.duration = -1;
  EXPECT_FALSE(ApplyFaultEvent(sim, id, sensor, &error));
  sensor.duration = 0;  // until cleared
  EXPECT_TRUE(ApplyFaultEvent(sim, id, sensor, &error));
  Rng rng(1);
  EXPECT_TRUE(std::isnan(sim.SenseRing(id, *sim.spec(id).FindRing("sonar"), rng)[0]));
}

// A door is not shut, nor a box put, through a robot standing there (node_kill's kin: the
// fault campaign closed d_lab_e onto the Nomad in the doorway, which then pushed for 240 s).
TEST_F(FaultEventTest, NoDoorClosesAndNoObstacleAppearsThroughARobot) {
  std::string error;
  ASSERT_TRUE(sim.world().SetDoorClosed("d1", false, &error));
  const int id = AddB12({10, 3, 0});  // in the doorway
  FaultEvent close;
  close.kind = FaultEvent::Kind::kDoor;
  close.name = "d1";
  close.closed = true;
  bool blocked = false;
  EXPECT_FALSE(ApplyFaultEvent(sim, id, close, &error, &blocked));
  EXPECT_TRUE(blocked);
  EXPECT_NE(error.find("stands in the doorway"), std::string::npos) << error;
  EXPECT_EQ(sim.world().DoorClosed("d1"), std::optional<bool>(false));
  EXPECT_FALSE(sim.Overlapped(id));

  FaultEvent box;
  box.kind = FaultEvent::Kind::kAddObstacle;
  box.obstacle.id = "box";
  box.obstacle.pose = {10, 3, 0};
  box.obstacle.size_x = box.obstacle.size_y = box.obstacle.height = 0.2;
  EXPECT_FALSE(ApplyFaultEvent(sim, id, box, &error, &blocked));
  EXPECT_TRUE(blocked);
  box.obstacle.pose = {8, 3, 0};  // beside it: there
  EXPECT_TRUE(ApplyFaultEvent(sim, id, box, &error, &blocked)) << error;
  EXPECT_FALSE(blocked);

  ASSERT_TRUE(sim.Kidnap(id, {6, 3, 0}, false, &error)) << error;  // the robot moved on
  EXPECT_TRUE(ApplyFaultEvent(sim, id, close, &error, &blocked)) << error;
  EXPECT_FALSE(blocked);
  EXPECT_EQ(sim.world().DoorClosed("d1"), std::optional<bool>(true));
}

}  // namespace
}  // namespace robot_sim
