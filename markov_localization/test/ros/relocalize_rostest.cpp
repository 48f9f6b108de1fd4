// Global localization of the real node on the simulator (see relocalize.test).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <mutex>

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/Kidnap.h>
#include <spott_msgs/LocalizationStatus.h>

namespace {

struct Listener {
  std::mutex mutex;
  spott_msgs::LocalizationStatus status;
  nav_msgs::Odometry truth;
  bool have_status = false, have_truth = false;
  bool saw_lost = false;  // A status said lost since the flag was cleared.
  void OnStatus(const spott_msgs::LocalizationStatus& s) {
    std::lock_guard<std::mutex> lock(mutex);
    status = s;
    have_status = true;
    saw_lost = saw_lost || s.lost;
  }
  void OnTruth(const nav_msgs::Odometry& t) {
    std::lock_guard<std::mutex> lock(mutex);
    truth = t;
    have_truth = true;
  }
  // True when the status is certain and within 0.5 m of the ground truth.
  bool CertainAndRight(double* error) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!have_status || !have_truth) return false;
    *error = std::hypot(status.estimate.x - truth.pose.pose.position.x,
                        status.estimate.y - truth.pose.pose.position.y);
    return status.certainty > 0.8 && *error < 0.5;
  }
};

bool WaitFor(Listener& l, double seconds, double* error) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (l.CertainAndRight(error)) return true;
    ros::WallDuration(0.1).sleep();
  }
  return false;
}

TEST(MarkovLocalizationNode, LocalizesGloballyThenRelocalizesAfterAKidnapOnTheSimulator) {
  ros::NodeHandle nh;
  Listener l;
  auto s1 = nh.subscribe("localization_status", 5, &Listener::OnStatus, &l);
  auto s2 = nh.subscribe("sim/ground_truth", 5, &Listener::OnTruth, &l);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  double error = 0.0;
  ASSERT_TRUE(WaitFor(l, 90.0, &error)) << "no certain, correct global localization; error "
                                        << error << " certainty " << l.status.certainty;

  // A robot that has been localized for a while (the lost detector has a history).
  ros::WallDuration(5.0).sleep();
  ASSERT_TRUE(l.CertainAndRight(&error)) << "lost its position while standing; error " << error;

  // Kidnap: from room B (south of the corridor) into room A (north), facing the end of the
  // wall stub that tells A from its twin D. The robot stands still: only the scans can tell.
  {
    std::lock_guard<std::mutex> lock(l.mutex);
    l.saw_lost = false;
  }
  spott_msgs::Kidnap kidnap;
  kidnap.request.pose.x = 13.5;
  kidnap.request.pose.y = 14.0;
  kidnap.request.pose.theta = 1.5708;
  ASSERT_TRUE(ros::service::waitForService("sim/kidnap", ros::Duration(10)));
  ASSERT_TRUE(ros::service::call("sim/kidnap", kidnap) && kidnap.response.success)
      << kidnap.response.message;
  const ros::WallTime kidnapped = ros::WallTime::now();
  ros::WallTime lost_at;
  while (ros::ok() && ros::WallTime::now() - kidnapped < ros::WallDuration(30)) {
    {
      std::lock_guard<std::mutex> lock(l.mutex);
      if (l.saw_lost) break;
    }
    ros::WallDuration(0.05).sleep();
  }
  lost_at = ros::WallTime::now();
  ASSERT_TRUE(l.saw_lost) << "the status never said lost after the kidnap";
  ASSERT_TRUE(WaitFor(l, 120.0, &error))
      << "not relocalized after the kidnap; error " << error << " certainty " << l.status.certainty
      << " estimate " << l.status.estimate.x << " " << l.status.estimate.y << " "
      << l.status.estimate.theta << " truth " << l.truth.pose.pose.position.x << " "
      << l.truth.pose.pose.position.y;
  std::printf("kidnap B -> A: lost after %.1f s, relocalized after %.1f s (wall)\n",
              (lost_at - kidnapped).toSec(), (ros::WallTime::now() - kidnapped).toSec());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "relocalize_rostest");
  return RUN_ALL_TESTS();
}
