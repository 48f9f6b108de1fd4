// The TR+ controller serving /task on the full stack (task.test): a malformed command is
// rejected with its column and changes nothing; a new task preempts the running one after the
// robot has stopped; `go in room(lab)` from the hall of cim_office brings the robot into the
// lab (ground truth) without a bumper contact. Bad sensor rings and places sent to the
// controller before it (issue 21) are refused and counted on /diagnostics, and change nothing.
#include <gtest/gtest.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/WorldPlaces.h>

#include <cmath>

#include "node_refusals.h"
#include "task_test_helpers.h"

namespace {

using spott_launch::testing::Describe;
using spott_launch::testing::RunTask;
using spott_launch::testing::TaskClient;
using spott_launch::testing::Watch;

class Task : public spott_launch::testing::TaskStackTest {
 protected:
  static void SetUpTestSuite() {
    StartSuite();
    if (HasFatalFailure()) return;
    ASSERT_TRUE(watch_->WaitForLocalization(120.0)) << "no localization_status";
  }
};

TEST_F(Task, MalformedTaskIsRejectedWithItsColumn) {
  const auto start = watch_->position();
  const auto r = RunTask(*client_, "go near tabel(1, 2)", 20.0);
  ASSERT_TRUE(r);
  EXPECT_EQ(client_->getState(), actionlib::SimpleClientGoalState::REJECTED);
  EXPECT_EQ(r->outcome, "rejected");
  EXPECT_FALSE(r->success);
  EXPECT_NE(r->message.find("task:1:9:"), std::string::npos) << r->message;
  EXPECT_NE(r->message.find("tabel"), std::string::npos) << r->message;
  EXPECT_LT((watch_->position() - start).norm(), 0.05) << "the robot moved";
}

TEST_F(Task, BadRingsAndPlacesAreRefusedAndCounted) {
  spott_launch::testing::NodeRefusals refusals(*nh_, "tr_plus_controller");
  ros::Publisher sonar = nh_->advertise<spott_msgs::RangeRing>("/sonar", 5);
  ros::Publisher infrared = nh_->advertise<spott_msgs::RangeRing>("/infrared", 5);
  ros::Publisher places = nh_->advertise<spott_msgs::WorldPlaces>("/world_places", 5);
  spott_msgs::RangeRing blind = spott_launch::testing::BlindRing(0.52f, 0.43f, 16);
  spott_msgs::RangeRing skewed = blind;
  skewed.max_range = 0.8f;
  skewed.min_range = 0.05f;
  skewed.mounts[0].theta = std::nan("");
  spott_msgs::WorldPlaces bad_places;
  bad_places.places.resize(1);
  bad_places.places[0].name = "meeting_room";
  bad_places.places[0].pose.x = std::nan("");
  const auto start = watch_->position();
  auto refused = [&] {
    return refusals.Has("sonar max_range") && refusals.Has("infrared mounts[0]") &&
           refusals.Has("world_places places[0].pose");
  };
  const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(30.0);
  while (!refused() && ros::WallTime::now() < until) {
    blind.header.stamp = skewed.header.stamp = ros::Time::now();
    sonar.publish(blind);
    infrared.publish(skewed);
    places.publish(bad_places);
    ros::WallDuration(0.2).sleep();
  }
  EXPECT_TRUE(refused()) << "tr_plus_controller did not count every bad message on /diagnostics";
  EXPECT_LT((watch_->position() - start).norm(), 0.05) << "the robot moved";
}

TEST_F(Task, SecondTaskPreemptsTheFirstAndGoInRoomLabArrivesWithoutContact) {
  TaskClient first("task", true);
  ASSERT_TRUE(first.waitForServer(ros::Duration(10.0)));
  spott_msgs::TaskGoal goal;
  goal.command = "go to door(d_106)";
  first.sendGoal(goal);
  const auto start = watch_->position();
  const ros::Time deadline = ros::Time::now() + ros::Duration(60.0);
  while ((watch_->position() - start).norm() < 1.0 && ros::Time::now() < deadline) {
    ros::WallDuration(0.05).sleep();
  }
  ASSERT_GE((watch_->position() - start).norm(), 1.0) << "the first task did not set off";
  ASSERT_GT(watch_->speed(), 0.05);
  watch_->Reset();
  const auto r = RunTask(*client_, "go in room(lab)", 200.0);
  // The first task was preempted...
  ASSERT_TRUE(first.waitForResult(ros::Duration(10.0)));
  EXPECT_EQ(first.getState(), actionlib::SimpleClientGoalState::PREEMPTED);
  ASSERT_TRUE(first.getResult());
  EXPECT_EQ(first.getResult()->outcome, "preempted");
  EXPECT_NE(first.getResult()->message.find("go in room(lab)"), std::string::npos);
  // ... the robot stood still before the second set off ...
  EXPECT_LT(watch_->min_speed(), 0.03);
  // ... and the second brought it into the lab (10..30 x 9.5..20) without a contact.
  ASSERT_TRUE(r);
  EXPECT_EQ(r->outcome, "reached") << Describe(r);
  const auto p = watch_->position();
  EXPECT_GT(p.x(), 10.0);
  EXPECT_LT(p.x(), 30.0);
  EXPECT_GT(p.y(), 9.5 + 0.2285) << "the body is not in the lab";
  EXPECT_LT(p.y(), 20.0);
  EXPECT_EQ(watch_->contacts(), 0);
  // The trace shows the program's way: Fig. 3 -> Fig. 9 -> Fig. 11 and the goal rule.
  const auto has = [&](const std::string& rule) {
    return std::find(r->trace.begin(), r->trace.end(), rule) != r->trace.end();
  };
  EXPECT_TRUE(has("INTERPRET_TASK[1]: apriori_map -> APRIORI_MAP_TASK(STATUS)")) << Describe(r);
  EXPECT_TRUE(has("APRIORI_MAP_TASK[2]: target_known(STATUS) -> set_goal(STATUS)"));
  EXPECT_NE(r->trace.back().find("SPOTT[3]"), std::string::npos) << Describe(r);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "task_rostest");
  return RUN_ALL_TESTS();
}
