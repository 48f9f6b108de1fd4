// Helpers for the end-to-end tests of the TR+ controller on the running stack: a Task client,
// the simulator's ground truth and bumper (what the tests judge on; nothing in the stack reads
// them), the map database's features and the controller's map updates as they arrive.
#pragma once

#include <actionlib/client/simple_action_client.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/AddObstacle.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/TaskAction.h>

#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "spott_map/geometry.h"
#include "spott_ros/pose_conversions.h"

namespace spott_launch::testing {

using TaskClient = actionlib::SimpleActionClient<spott_msgs::TaskAction>;

/// The simulator's ground truth and bumper contacts, and the TR+ controller's map updates.
class Watch {
 public:
  explicit Watch(ros::NodeHandle& nh)
      : truth_(nh.subscribe("/sim/ground_truth", 50, &Watch::OnTruth, this)),
        bumper_(nh.subscribe("/bumper", 20, &Watch::OnBumper, this)),
        updates_(nh.subscribe("map_updates", 50, &Watch::OnUpdate, this)),
        features_(nh.subscribe("map_features", 5, &Watch::OnFeatures, this)),
        status_(nh.subscribe("localization_status", 5, &Watch::OnStatus, this)) {}

  spott_map::Vec2 position() {
    std::lock_guard<std::mutex> lock(mutex_);
    return spott_map::Vec2(x_, y_);
  }
  double yaw() {
    std::lock_guard<std::mutex> lock(mutex_);
    return yaw_;
  }
  double speed() {
    std::lock_guard<std::mutex> lock(mutex_);
    return speed_;
  }
  spott_map::Vec2 estimate() {
    std::lock_guard<std::mutex> lock(mutex_);
    return spott_map::Vec2(ex_, ey_);
  }
  /// A localization status has arrived (markov_localization is up and publishing map -> odom).
  bool localized() {
    std::lock_guard<std::mutex> lock(mutex_);
    return statuses_ > 0;
  }
  /// Waits up to `timeout_s` of wall time for the localization's first status (its start takes
  /// tens of seconds on a busy machine) and then `settle_s` of simulated time.
  bool WaitForLocalization(double timeout_s, double settle_s = 3.0) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (!localized() && ros::WallTime::now() < end) ros::WallDuration(0.1).sleep();
    if (!localized()) return false;
    ros::Duration(settle_s).sleep();
    return true;
  }
  /// Bumper messages with a pressed segment since the last Reset.
  int contacts() {
    std::lock_guard<std::mutex> lock(mutex_);
    return contacts_;
  }
  /// Lowest ground-truth speed since the last Reset (m/s).
  double min_speed() {
    std::lock_guard<std::mutex> lock(mutex_);
    return min_speed_;
  }
  void Reset() {
    std::lock_guard<std::mutex> lock(mutex_);
    contacts_ = 0;
    min_speed_ = 1e9;
  }
  std::vector<spott_msgs::MapUpdate> updates() {
    std::lock_guard<std::mutex> lock(mutex_);
    return update_log_;
  }
  std::vector<spott_msgs::MapFeature> features() {
    std::lock_guard<std::mutex> lock(mutex_);
    return features_now_;
  }
  /// A feature the controller sensed (source SENSED) within `radius` of (x, y) is in the map
  /// database's latest map_features.
  bool SensedFeatureNear(double x, double y, double radius) {
    for (const auto& f : features()) {
      if (f.source != spott_msgs::MapFeature::SOURCE_SENSED) continue;
      for (const auto& p : f.points) {
        if (std::hypot(p.x - x, p.y - y) <= radius) return true;
      }
      if (f.points.empty() && std::hypot(f.pose.position.x - x, f.pose.position.y - y) <= radius)
        return true;
    }
    return false;
  }

 private:
  void OnTruth(const nav_msgs::Odometry& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double x = m.pose.pose.position.x, y = m.pose.pose.position.y;
    const double t = m.header.stamp.toSec();
    if (t > t_) speed_ = std::hypot(x - x_, y - y_) / (t - t_);
    x_ = x;
    y_ = y;
    t_ = t;
    yaw_ = spott_ros::YawOf(m.pose.pose.orientation).value_or(yaw_);
    min_speed_ = std::min(min_speed_, speed_);
  }
  void OnBumper(const spott_msgs::BumperRing& r) {
    for (bool p : r.pressed) {
      if (!p) continue;
      std::lock_guard<std::mutex> lock(mutex_);
      ++contacts_;
      return;
    }
  }
  void OnUpdate(const spott_msgs::MapUpdate& u) {
    std::lock_guard<std::mutex> lock(mutex_);
    update_log_.push_back(u);
  }
  void OnFeatures(const spott_msgs::MapFeatureArray& a) {
    std::lock_guard<std::mutex> lock(mutex_);
    features_now_ = a.features;
  }
  void OnStatus(const spott_msgs::LocalizationStatus& s) {
    std::lock_guard<std::mutex> lock(mutex_);
    ex_ = s.estimate.x;
    ey_ = s.estimate.y;
    ++statuses_;
  }

  std::mutex mutex_;
  double x_ = 0, y_ = 0, yaw_ = 0, t_ = -1, speed_ = 0, min_speed_ = 1e9, ex_ = 0, ey_ = 0;
  int contacts_ = 0, statuses_ = 0;
  std::vector<spott_msgs::MapUpdate> update_log_;
  std::vector<spott_msgs::MapFeature> features_now_;
  ros::Subscriber truth_, bumper_, updates_, features_, status_;
};

/// Sends `command` and waits up to `timeout_s` of simulated time for the result.
inline spott_msgs::TaskResultConstPtr RunTask(TaskClient& client, const std::string& command,
                                              double timeout_s) {
  spott_msgs::TaskGoal goal;
  goal.command = command;
  client.sendGoal(goal);
  if (!client.waitForResult(ros::Duration(timeout_s))) {
    client.cancelGoal();
    client.waitForResult(ros::Duration(5.0));
  }
  return client.getResult();
}

/// "outcome: message" and the trace, for failure messages.
inline std::string Describe(const spott_msgs::TaskResultConstPtr& r) {
  if (!r) return "no result";
  std::string s = r->outcome + ": " + r->message + "\n  interpretation: " + r->interpretation;
  for (const std::string& rule : r->trace) s += "\n  fired: " + rule;
  return s;
}

/// Adds an obstacle to the simulated world (not to the map database).
inline bool AddObstacle(const std::string& id, const std::string& kind, double x, double y,
                        double yaw, double sx, double sy, double height, std::string* message) {
  spott_msgs::AddObstacle srv;
  srv.request.id = id;
  srv.request.kind = kind;
  srv.request.pose.x = x;
  srv.request.pose.y = y;
  srv.request.pose.theta = yaw;
  srv.request.size.x = sx;
  srv.request.size.y = sy;
  srv.request.size.z = height;
  if (!ros::service::call("/sim/add_obstacle", srv)) {
    *message = "/sim/add_obstacle call failed";
    return false;
  }
  *message = srv.response.message;
  return srv.response.success;
}

inline bool InPolygon(const spott_map::Vec2& p, const std::vector<spott_map::Vec2>& polygon) {
  return spott_map::PointInPolygon(p, polygon);
}

/// A suite on the stack with the TR+ controller: a spinner, the Watch and a /task client for the
/// suite's life. A suite's SetUpTestSuite calls StartSuite() first, then waits for its own.
class TaskStackTest : public ::testing::Test {
 protected:
  static void StartSuite() {
    nh_ = new ros::NodeHandle;
    spinner_ = new ros::AsyncSpinner(2);
    spinner_->start();
    watch_ = new Watch(*nh_);
    client_ = new TaskClient("task", true);
    ASSERT_TRUE(ros::Time::waitForValid(ros::WallDuration(60.0)));
    ASSERT_TRUE(client_->waitForServer(ros::Duration(60.0))) << "/task is not offered";
  }
  // Stopped before the process exits: a spinner thread still running while roscpp's statics
  // are destroyed aborted the process (boost::lock_error) after the results were written.
  static void TearDownTestSuite() {
    spinner_->stop();
    delete client_;
    delete watch_;
    delete spinner_;
    delete nh_;
  }
  static inline ros::NodeHandle* nh_ = nullptr;
  static inline ros::AsyncSpinner* spinner_ = nullptr;
  static inline Watch* watch_ = nullptr;
  static inline TaskClient* client_ = nullptr;
};

}  // namespace spott_launch::testing
