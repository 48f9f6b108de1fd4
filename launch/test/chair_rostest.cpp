// A chair on the way that the map does not show (chair.test): the robot starts in cim_office's
// west hallway at (1.2, 8.25) and is sent to (11, 8.25); a 0.5 m chair stands at (6, 8.1). The
// TR+ controller must sense it (sonar, QUADRIS, infrared or the bumper), record it in the map
// database (a sensed feature on /map_features within 0.45 m of the chair's centre: its outline
// is 0.25 m from it), the planners must steer round it, and the robot must arrive (ground truth
// within the goal disc) without touching it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "task_test_helpers.h"

namespace {

using namespace spott_launch::testing;

constexpr double kChairYaw = 0.3;  // rad: the chair stands turned, as chairs do

TEST(Chair, AChairNotInTheMapIsSensedRecordedAvoidedAndTheRobotArrives) {
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Watch watch(nh);
  TaskClient client("task", true);
  ASSERT_TRUE(ros::Time::waitForValid(ros::WallDuration(60.0)));
  ASSERT_TRUE(client.waitForServer(ros::Duration(60.0)));
  ASSERT_TRUE(watch.WaitForLocalization(120.0)) << "no localization_status";
  std::string message;
  ASSERT_TRUE(
      AddObstacle("chair_on_the_way", "chair", 6.0, 8.1, kChairYaw, 0.5, 0.5, 0.9, &message))
      << message;
  ros::Duration(2.0).sleep();
  EXPECT_FALSE(watch.SensedFeatureNear(6.0, 8.1, 0.45)) << "in the map before the robot saw it";
  watch.Reset();
  double closest = 1e9;
  std::string first_contact;  // where the body was, and whether the chair was mapped by then
  spott_msgs::TaskGoal goal;
  goal.command = "go to point(11, 8.25)";
  client.sendGoal(goal);
  const ros::Time deadline = ros::Time::now() + ros::Duration(150.0);
  while (!client.getState().isDone() && ros::Time::now() < deadline) {
    // The body must never come closer than its radius to the chair's outline: the Euclidean
    // distance from the centre to the square of 0.25 m half side, turned by the chair's yaw.
    const auto p = watch.position();
    const double ex = p.x() - 6.0, ey = p.y() - 8.1;
    const double lx = std::cos(kChairYaw) * ex + std::sin(kChairYaw) * ey;
    const double ly = -std::sin(kChairYaw) * ex + std::cos(kChairYaw) * ey;
    const double dx = std::max(std::abs(lx) - 0.25, 0.0);
    const double dy = std::max(std::abs(ly) - 0.25, 0.0);
    closest = std::min(closest, std::hypot(dx, dy));
    if (first_contact.empty() && watch.contacts() > 0) {
      first_contact =
          "first contact at t=" + std::to_string(ros::Time::now().toSec()) + " s, truth (" +
          std::to_string(p.x()) + ", " + std::to_string(p.y()) +
          "), chair mapped by then: " + (watch.SensedFeatureNear(6.0, 8.1, 0.45) ? "yes" : "no");
    }
    ros::WallDuration(0.02).sleep();
  }
  ASSERT_TRUE(client.getState().isDone()) << "no result in 150 s of simulated time";
  const auto r = client.getResult();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->outcome, "reached") << Describe(r);
  // Arrived on ground truth: within the point goal's 0.25 m radius (the controller judges it on
  // its estimate) plus 0.15 m of localization error (markov's maxima while tracking are 0.2-0.3 m,
  // its README; with 0.1 m, 2 of 8 runs ended 0.353 and 0.355 m off on 2026-12-02).
  EXPECT_LT((watch.position() - spott_map::Vec2(11.0, 8.25)).norm(), 0.25 + 0.15)
      << "truth (" << watch.position().x() << ", " << watch.position().y() << "), estimate ("
      << watch.estimate().x() << ", " << watch.estimate().y() << ")";
  EXPECT_TRUE(watch.SensedFeatureNear(6.0, 8.1, 0.45)) << "the chair is not in map_features";
  EXPECT_EQ(watch.contacts(), 0) << first_contact;
  // 2 cm below the Nomad's 0.2285 m radius: ground truth is sampled at 50 Hz and Bullet keeps a
  // collision margin; a real touch also shows as a bumper contact above.
  ::testing::Test::RecordProperty("closest_to_chair_m", std::to_string(closest));
  EXPECT_GT(closest, 0.2285 - 0.02)
      << "the body touched the chair (distance to its outline " << closest << " m)";
  EXPECT_FALSE(r->features_added.empty());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "chair_rostest");
  return RUN_ALL_TESTS();
}
