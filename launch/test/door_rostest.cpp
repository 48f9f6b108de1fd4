// A door found closed (door.test): the robot is sent from the west hallway of cim_office into
// the lab; the global planner's first path runs through the lab's west door d_lab_w. Once the
// robot is on its way the door is closed in the simulator only (/sim/set_door_state): nobody
// tells the map database. The TR+ controller must sense the leaf with the sonar and send the
// door's state on map_updates; the global planner must replan through hall_join and d_lab_e; the
// robot must arrive in the lab; and markov_localization's map must have the door closed (its
// belief grid marks no state in the doorway any more).
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <spott_msgs/Door.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/SetDoorState.h>

#include <algorithm>

#include "task_test_helpers.h"

namespace {

using namespace spott_launch::testing;

bool Has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// The belief grid's value at (x, y): -1 where the cell is not a state of the belief.
int BeliefAt(const nav_msgs::OccupancyGrid& g, double x, double y) {
  const int ix = static_cast<int>(std::floor((x - g.info.origin.position.x) / g.info.resolution));
  const int iy = static_cast<int>(std::floor((y - g.info.origin.position.y) / g.info.resolution));
  if (ix < 0 || iy < 0 || ix >= static_cast<int>(g.info.width) ||
      iy >= static_cast<int>(g.info.height)) {
    return -2;
  }
  return g.data[iy * g.info.width + ix];
}

TEST(Door, ADoorFoundClosedIsSensedSentReplannedAroundAndLocalizationFollows) {
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Watch watch(nh);
  std::mutex mutex;
  spott_msgs::GlobalPath path;
  bool closed = false, replanned = false;  // a path round d_lab_w after it closed
  ros::Subscriber path_sub = nh.subscribe<spott_msgs::GlobalPath>(
      "global_path", 5, [&](const spott_msgs::GlobalPath::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        path = *m;
        if (closed && !m->doors.empty() && !Has(m->doors, "d_lab_w") &&
            (Has(m->doors, "d_lab_e") || Has(m->doors, "d_meeting_lab"))) {
          replanned = true;
        }
      });
  nav_msgs::OccupancyGrid belief;
  ros::Subscriber belief_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "belief", 2, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        belief = *m;
      });
  const auto path_has = [&](const std::string& door) {
    std::lock_guard<std::mutex> lock(mutex);
    return Has(path.doors, door);
  };
  TaskClient client("task", true);
  ASSERT_TRUE(ros::Time::waitForValid(ros::WallDuration(60.0)));
  ASSERT_TRUE(client.waitForServer(ros::Duration(60.0)));
  ASSERT_TRUE(watch.WaitForLocalization(120.0)) << "no localization_status";
  {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::WallTime::now() < end) {
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (!belief.data.empty()) break;
      }
      ros::WallDuration(0.1).sleep();
    }
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_FALSE(belief.data.empty()) << "no belief grid from markov_localization";
    EXPECT_GE(BeliefAt(belief, 12.5, 9.5), 0) << "the open doorway is no state of the belief";
  }
  spott_msgs::TaskGoal goal;
  goal.command = "go in room(lab)";
  client.sendGoal(goal);
  const ros::Time plan_deadline = ros::Time::now() + ros::Duration(30.0);
  while (!path_has("d_lab_w") && ros::Time::now() < plan_deadline) ros::WallDuration(0.05).sleep();
  ASSERT_TRUE(path_has("d_lab_w"));
  const ros::Time go_deadline = ros::Time::now() + ros::Duration(60.0);
  while (watch.position().x() < 4.0 && ros::Time::now() < go_deadline) {
    ros::WallDuration(0.05).sleep();
  }
  ASSERT_GE(watch.position().x(), 4.0) << "the robot did not set off";
  ASSERT_LT(watch.position().x(), 10.0) << "the robot is at the door already";
  spott_msgs::SetDoorState srv;
  srv.request.door_id = "d_lab_w";
  srv.request.state = spott_msgs::Door::CLOSED;
  ASSERT_TRUE(ros::service::call("/sim/set_door_state", srv));
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  {
    std::lock_guard<std::mutex> lock(mutex);
    closed = true;
  }

  ASSERT_TRUE(client.waitForResult(ros::Duration(220.0)));
  const auto r = client.getResult();
  ASSERT_TRUE(r);
  // Sensed and sent: a map update from the controller with d_lab_w CLOSED.
  bool sent = false;
  for (const auto& u : watch.updates()) {
    for (const auto& d : u.doors)
      sent = sent || (d.door_id == "d_lab_w" && d.state == spott_msgs::Door::CLOSED);
  }
  EXPECT_TRUE(sent) << "no map update closed d_lab_w";
  // Replanned through the other way into the lab.
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_TRUE(replanned) << "no global path round the closed door";
  }
  EXPECT_EQ(r->outcome, "reached") << Describe(r);
  const auto p = watch.position();
  EXPECT_TRUE(p.x() > 10.0 && p.x() < 30.0 && p.y() > 9.5 && p.y() < 20.0)
      << "the robot ended at (" << p.x() << ", " << p.y() << "), not in the lab";
  // The localization's map: the leaf across the doorway, no state of the belief there now.
  bool closed_in_belief = false;
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(20.0);
  while (!closed_in_belief && ros::WallTime::now() < end) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      closed_in_belief = !belief.data.empty() && BeliefAt(belief, 12.5, 9.5) == -1;
    }
    ros::WallDuration(0.2).sleep();
  }
  EXPECT_TRUE(closed_in_belief) << "markov_localization's map still has d_lab_w open";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "door_rostest");
  return RUN_ALL_TESTS();
}
