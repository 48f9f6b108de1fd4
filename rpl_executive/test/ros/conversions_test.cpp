// The node's conversions between the executives' core types and messages, on hand-made cases.
#include <gtest/gtest.h>

#include <cmath>

#include "conversions.h"
#include "spott_ros/pose_conversions.h"

namespace rpl_executive {
namespace {

namespace conv = ros_conversions;
namespace nc = noreils_chatila;

TEST(RplExecutiveConversions, FluentsKeepTheirTypes) {
  rpl::FluentState f;
  f.name = "NAVIGATION-ACTIVE?*";
  f.stamp_s = 2.5;
  EXPECT_EQ(conv::ToMsg(f).type, spott_msgs::Fluent::BOOL);
  EXPECT_FALSE(conv::ToMsg(f).bool_value);
  EXPECT_DOUBLE_EQ(conv::ToMsg(f).stamp.toSec(), 2.5);
  f.value = rpl::Value::True();
  EXPECT_TRUE(conv::ToMsg(f).bool_value);
  f.value = rpl::Value::Number(0.8);
  EXPECT_EQ(conv::ToMsg(f).type, spott_msgs::Fluent::NUMBER);
  EXPECT_DOUBLE_EQ(conv::ToMsg(f).number_value, 0.8);
  f.value = rpl::Value::Point(19.6, 6.0);
  EXPECT_EQ(conv::ToMsg(f).type, spott_msgs::Fluent::STRING);
  EXPECT_EQ(conv::ToMsg(f).string_value, "(19.6 6)");
}

TEST(RplExecutiveConversions, TheTaskTreeSaysWhatEachThreadWaitsOnAndHowThreadsEnded) {
  rpl::TaskInfo policy;
  policy.id = 3;
  policy.parent = 1;
  policy.depth = 1;
  policy.label = "WHENEVER";
  policy.state = rpl::TaskInfo::State::kWaitBlocked;
  policy.waiting_for = "(<= POS-CERTAINTY* 0.8)";
  policy.policy = true;
  policy.where = {"", 94, 5};  // no file: the node names it
  const auto tasks = conv::ToMsgs({policy}, "office_delivery.rpl");
  ASSERT_EQ(tasks.size(), 1u);
  EXPECT_EQ(tasks[0].state, spott_msgs::PlanTask::WAIT_BLOCKED);
  EXPECT_EQ(tasks[0].waiting_for, "(<= POS-CERTAINTY* 0.8)");
  EXPECT_EQ(tasks[0].where, "office_delivery.rpl:94:5");
  EXPECT_TRUE(tasks[0].policy);

  rpl::Event failed;
  failed.kind = rpl::Event::Kind::kThreadEnded;
  failed.subject = "GO-TO > NAVIGATION-PROC";
  failed.detail = "failed: NAVIGATION failed: unreachable";
  failed.time_s = 4.0;
  const auto ended = conv::EndedThread(failed);
  ASSERT_TRUE(ended);
  EXPECT_EQ(ended->state, spott_msgs::PlanTask::FAILED);
  EXPECT_EQ(ended->detail, "NAVIGATION failed: unreachable");
  EXPECT_EQ(ended->id, -1);
  failed.detail = "evaporated";
  EXPECT_EQ(conv::EndedThread(failed)->state, spott_msgs::PlanTask::EVAPORATED);
  failed.detail = "done";
  EXPECT_EQ(conv::EndedThread(failed)->state, spott_msgs::PlanTask::DONE);
  rpl::Event pulse = failed;
  pulse.kind = rpl::Event::Kind::kPulse;
  EXPECT_FALSE(conv::EndedThread(pulse));

  spott_msgs::Fluent certainty;
  certainty.name = "POS-CERTAINTY*";
  certainty.type = spott_msgs::Fluent::NUMBER;
  certainty.number_value = 0.512;
  std::vector<spott_msgs::PlanTask> all = tasks;
  all.push_back(*conv::EndedThread(failed));
  EXPECT_EQ(conv::TaskTreeText(all, {certainty}),
            "  WHENEVER [policy]: wait-blocked on (<= POS-CERTAINTY* 0.8)\n"
            "ended:\n"
            "  GO-TO > NAVIGATION-PROC: done\n"
            "fluents: POS-CERTAINTY*=0.512");
}

TEST(RplExecutiveConversions, BindingsAreReadAsRplData) {
  std::string error;
  const auto dest = conv::ParseBinding("dest (19.6 6.0)", &error);
  ASSERT_TRUE(dest) << error;
  EXPECT_EQ(dest->first, "DEST");  // the reader folds symbols to upper case
  EXPECT_EQ(dest->second, rpl::Value::Point(19.6, 6.0));
  const auto quoted = conv::ParseBinding("DEST '(1 2)", &error);
  ASSERT_TRUE(quoted) << error;
  EXPECT_EQ(quoted->second, rpl::Value::Point(1, 2));
  EXPECT_FALSE(conv::ParseBinding("DEST", &error));
  EXPECT_EQ(error, "binding 'DEST' must be a name and a value, e.g. DEST (19.6 6.0)");
  EXPECT_FALSE(conv::ParseBinding("DEST (19.6", &error));
  EXPECT_NE(error.find("binding 'DEST (19.6':1:6"), std::string::npos) << error;
}

TEST(RplExecutiveConversions, TheRoomDoorGraphBecomesTheBuilding) {
  spott_msgs::RoomDoorGraph g;
  spott_msgs::Room hall;
  hall.id = "corridor_c";
  hall.kind = spott_msgs::Room::HALLWAY;
  for (auto [x, y] : {std::pair{9.0, 9.0}, {18.0, 9.0}, {18.0, 11.0}, {9.0, 11.0}}) {
    geometry_msgs::Point32 p;
    p.x = x;
    p.y = y;
    hall.polygon.points.push_back(p);
  }
  g.rooms.push_back(hall);
  spott_msgs::Room b = hall;
  b.id = "room_b";
  b.kind = spott_msgs::Room::ROOM;
  g.rooms.push_back(b);
  spott_msgs::Door d;
  d.id = "door_b";
  d.room_a = "corridor_c";
  d.room_b = "room_b";
  d.kind = spott_msgs::Door::KIND_DOOR;
  d.state = spott_msgs::Door::CLOSED;
  d.centre.x = 17.5;
  d.centre.y = 9.0;
  geometry_msgs::Point e1, e2;
  e1.x = 17.05;
  e1.y = 9.0;
  e2.x = 17.95;
  e2.y = 9.0;
  d.opening = {e1, e2};
  g.doors.push_back(d);
  d.id = "unknown";
  d.state = spott_msgs::Door::UNKNOWN;
  g.doors.push_back(d);
  d.id = "opening";
  d.kind = spott_msgs::Door::KIND_OPENING;
  d.state = spott_msgs::Door::CLOSED;  // an opening has no leaf: always open
  g.doors.push_back(d);
  const rpl::office::BuildingMap map = conv::FromMsg(g);
  ASSERT_EQ(map.rooms.size(), 2u);
  EXPECT_TRUE(map.rooms[0].hallway);
  EXPECT_FALSE(map.rooms[1].hallway);
  ASSERT_EQ(map.rooms[0].polygon.size(), 4u);
  EXPECT_DOUBLE_EQ(map.rooms[0].polygon[1].x_m, 18.0);
  ASSERT_EQ(map.doors.size(), 3u);
  EXPECT_FALSE(map.doors[0].open);
  EXPECT_TRUE(map.doors[1].open);  // unknown doors count as open, as the planners take them
  EXPECT_TRUE(map.doors[2].open);
  EXPECT_DOUBLE_EQ(map.doors[0].end_b.x_m, 17.95);
}

spott_msgs::RangeRing TwoSonars() {
  spott_msgs::RangeRing r;
  r.field_of_view = 0.5f;
  r.min_range = 0.1f;
  r.max_range = 4.0f;
  geometry_msgs::Pose2D m1, m2;
  m1.x = 0.4;
  m2.y = 0.4;
  m2.theta = M_PI / 2;
  r.mounts = {m1, m2};
  r.ranges = {0.5f, NAN};
  return r;
}

TEST(RplExecutiveConversions, TheSonarBeltAndItsRanges) {
  const nc::SonarRing ring = conv::RingFromMsg(TwoSonars());
  ASSERT_EQ(ring.mounts.size(), 2u);
  EXPECT_DOUBLE_EQ(ring.mounts[1].yaw_rad, M_PI / 2);
  EXPECT_FLOAT_EQ(ring.half_field_of_view_rad, 0.25);
  EXPECT_DOUBLE_EQ(ring.max_range_m, 4.0);
  const nc::SonarScan scan = conv::ScanFromMsg(TwoSonars());
  EXPECT_DOUBLE_EQ(scan.ranges_m[0], 0.5);
  EXPECT_FALSE(ring.IsEcho(scan.ranges_m[1]));  // a dropped-out sensor hears nothing
}

TEST(RplExecutiveConversions, LaserAndBattery) {
  sensor_msgs::LaserScan l;
  l.angle_min = -1.0f;
  l.angle_increment = 0.5f;
  l.range_min = 0.1f;
  l.range_max = 10.0f;
  l.ranges = {0.05f, 2.0f};
  const nc::LaserScan s = conv::FromMsg(l, 0.25);
  EXPECT_DOUBLE_EQ(s.angle_min_rad, -0.75);
  EXPECT_TRUE(std::isinf(s.ranges_m[0]));  // below range_min: no return
  EXPECT_DOUBLE_EQ(s.ranges_m[1], 2.0);
  sensor_msgs::BatteryState b;
  b.percentage = 0.146f;
  EXPECT_NEAR(conv::FromMsg(b)->level_percent, 14.6, 1e-4);  // a fraction in, percent out
  b.percentage = NAN;
  EXPECT_FALSE(conv::FromMsg(b));
}

// Issue 21: what the node refuses at its edge, each with the field named first.
TEST(RplExecutiveConversions, ImpossibleRingReadingsAreDroppedOut) {
  // A negative or beyond-max reading would be an echo at an impossible distance: dropped out.
  auto ring = TwoSonars();
  ring.ranges = {-1.0f, 9.0f};
  int discarded = -1;
  const nc::SonarScan scan = conv::ScanFromMsg(ring, &discarded);
  EXPECT_EQ(discarded, 0);
  EXPECT_TRUE(std::isnan(scan.ranges_m[0]));
  EXPECT_TRUE(std::isnan(scan.ranges_m[1]));
  conv::ScanFromMsg(TwoSonars(), &discarded);
  EXPECT_EQ(discarded, -1);
}

TEST(RplExecutiveConversions, StatusesAndCommandsAreChecked) {
  spott_msgs::LocalizationStatus st;
  st.estimate.x = 1.2;
  st.estimate.y = 8.25;
  st.certainty = 0.9;
  EXPECT_EQ(conv::StatusProblem(st), "");
  st.estimate.theta = NAN;
  EXPECT_EQ(conv::StatusProblem(st), "estimate: not finite or beyond 10 km");
  st.estimate.theta = 0.0;
  st.certainty = 1.5;
  EXPECT_EQ(conv::StatusProblem(st).rfind("certainty: ", 0), 0u);

  geometry_msgs::Twist t;
  t.linear.x = 0.3;
  EXPECT_EQ(conv::TwistProblem(t), "");
  t.angular.z = NAN;
  EXPECT_EQ(conv::TwistProblem(t), "linear/angular: not finite");
}

TEST(RplExecutiveConversions, AGraphWithANonFiniteDoorIsRefusedAsWorldServerWould) {
  spott_msgs::RoomDoorGraph g;
  spott_msgs::Room hall;
  hall.id = "hall";
  for (auto [x, y] : {std::pair{0.0, 0.0}, {4.0, 0.0}, {4.0, 2.0}}) {
    geometry_msgs::Point32 p;
    p.x = x;
    p.y = y;
    hall.polygon.points.push_back(p);
  }
  g.rooms.push_back(hall);
  EXPECT_EQ(conv::GraphProblem(g), "");
  spott_msgs::Door d;
  d.id = "d1";
  d.room_a = d.room_b = "hall";
  d.state = spott_msgs::Door::OPEN;
  d.centre.x = NAN;
  d.opening.resize(2);
  g.doors.push_back(d);
  EXPECT_EQ(conv::GraphProblem(g).rfind("rooms/doors: door d1: ", 0), 0u) << conv::GraphProblem(g);
  g.rooms[0].polygon.points.pop_back();
  EXPECT_EQ(conv::GraphProblem(g).rfind("rooms/doors: room hall: fewer than 3 points", 0), 0u);
}

TEST(RplExecutiveConversions, PathsAreMissionValuesInCentimetresAndTenthsOfADegree) {
  spott_msgs::NamedPath path;
  for (auto [x, y] : {std::pair{1.8, 5.2}, {3.5, 5.2}, {3.6, 3.2}}) {
    geometry_msgs::Point p;
    p.x = x;
    p.y = y;
    path.points.push_back(p);
  }
  path.has_final_heading = true;
  path.final_heading = -1.5708;  // hilare_room's PATH: 270.0 degrees
  EXPECT_EQ(conv::PathToValue(path).ToText(), "((180 520) (350 520) (360 320 2700))");
  path.has_final_heading = false;
  EXPECT_EQ(conv::PathToValue(path).ToText(), "((180 520) (350 520) (360 320))");
}

// executive_messages_fuzz's finding: a finite but huge final heading overflowed to infinity in
// degrees and gave PATH a NaN heading.
TEST(RplExecutiveConversions, AHugeFiniteFinalHeadingStillGivesATenthOfADegree) {
  spott_msgs::NamedPath path;
  path.points.resize(1);
  path.has_final_heading = true;
  path.final_heading = 1e308;  // * 180 overflows a double
  const std::string text = conv::PathToValue(path).ToText();
  EXPECT_EQ(text.find("nan"), std::string::npos) << text;
  EXPECT_EQ(text.find("inf"), std::string::npos) << text;
  path.final_heading = 2 * M_PI + M_PI / 2;  // a turn and a quarter: 90 degrees
  EXPECT_EQ(conv::PathToValue(path).ToText(), "((0 0 900))");
}

TEST(RplExecutiveConversions, MonitorEventsByKind) {
  nc::MonitorEvent e;
  e.id = 2;
  e.label = "MNTR STATIC (S_us-threshold sensors-list) at m.nc:28:5";
  e.condition = "(S_us-threshold sensors-list)";
  e.reflex = "(stop)";
  e.terminal = true;
  e.is_static = true;
  e.control = "(IF (LOA) ((avoid-obstacle) (resume-order)) ((FAIL)))";
  e.command = "smooth-move 3 points at m.nc:15:3";
  auto m = conv::ToMsg(e, "mission2", "map", ros::Time(3.0));
  EXPECT_EQ(m.kind, spott_msgs::MonitorEvent::STATIC);
  EXPECT_EQ(m.monitor_id, "2: " + e.label);
  EXPECT_EQ(m.mission, "mission2");
  ASSERT_EQ(m.reflex_actions.size(), 1u);
  EXPECT_EQ(m.reflex_actions[0], "(stop)");
  EXPECT_EQ(m.control_action, e.control);
  EXPECT_EQ(m.command, e.command);
  e.is_static = false;
  EXPECT_EQ(conv::ToMsg(e, "m", "map", ros::Time()).kind, spott_msgs::MonitorEvent::TERMINAL);
  e.terminal = false;
  e.o_surveillance = true;
  m = conv::ToMsg(e, "m", "map", ros::Time());
  EXPECT_EQ(m.kind, spott_msgs::MonitorEvent::NON_TERMINAL);
  EXPECT_EQ(m.mission, "O-surveillance");
}

TEST(RplExecutiveConversions, DrawPlacesThePoseAndTheEchoesInTheMap) {
  nc::DrawCommand d;
  d.formats = {"G_pos", "G_echoes"};
  // r-position (100 cm, 200 cm, 90.0 degrees), r-us-data: sensor 1 at 50 cm.
  d.data = {
      nc::Value::List({nc::Value::Number(100), nc::Value::Number(200), nc::Value::Number(900)}),
      nc::Value::List({nc::Value::List({nc::Value::Number(1), nc::Value::Number(50)})})};
  const nc::SonarRing ring = conv::RingFromMsg(TwoSonars());
  int id = 7;
  const auto markers = conv::DrawToMarkers(d, ring, "map", ros::Time(1.0), &id);
  ASSERT_EQ(markers.markers.size(), 2u);
  EXPECT_EQ(id, 9);
  EXPECT_EQ(markers.markers[0].type, visualization_msgs::Marker::ARROW);
  EXPECT_DOUBLE_EQ(markers.markers[0].pose.position.x, 1.0);
  EXPECT_NEAR(*spott_ros::YawOf(markers.markers[0].pose.orientation), M_PI / 2, 1e-9);
  ASSERT_EQ(markers.markers[1].points.size(), 1u);
  // Sensor 1 sits 0.4 m ahead and looks ahead: the echo is 0.9 m ahead of the robot, i.e. north.
  EXPECT_NEAR(markers.markers[1].points[0].x, 1.0, 1e-9);
  EXPECT_NEAR(markers.markers[1].points[0].y, 2.9, 1e-9);
}

}  // namespace
}  // namespace rpl_executive
