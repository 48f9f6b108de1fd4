// Global localization of the real node on the simulator (see relocalize.test).
#include <gtest/gtest.h>

#include <cmath>
#include <mutex>

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/LocalizationStatus.h>

namespace {

struct Listener {
  std::mutex mutex;
  spott_msgs::LocalizationStatus status;
  nav_msgs::Odometry truth;
  bool have_status = false, have_truth = false;
  void OnStatus(const spott_msgs::LocalizationStatus& s) {
    std::lock_guard<std::mutex> lock(mutex);
    status = s;
    have_status = true;
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

TEST(MarkovLocalizationNode, LocalizesGloballyFromAUniformBeliefOnTheSimulator) {
  ros::NodeHandle nh;
  Listener l;
  auto s1 = nh.subscribe("localization_status", 5, &Listener::OnStatus, &l);
  auto s2 = nh.subscribe("sim/ground_truth", 5, &Listener::OnTruth, &l);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  double error = 0.0;
  ASSERT_TRUE(WaitFor(l, 90.0, &error)) << "no certain, correct global localization; error "
                                        << error << " certainty " << l.status.certainty;
  // Relocalization after a kidnap is not asserted: with a stationary robot kidnapped from
  // room B into room A the node stayed certain (1.0) at the old place, 12 m off (README,
  // "Missing").
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "relocalize_rostest");
  return RUN_ALL_TESTS();
}
