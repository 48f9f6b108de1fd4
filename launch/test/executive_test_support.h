// Helpers of the executives' end-to-end rostests (office_delivery, hilare_missions): the
// simulator's ground truth and bumper (for judging only), a Mission client that keeps every event
// of rpl_executive's ~state, and a one-line report for the seeded-run scripts.
#pragma once

#include <actionlib/client/simple_action_client.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/ExecutiveState.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MissionAction.h>
#include <spott_msgs/MonitorEvent.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "spott_ros/pose_conversions.h"

namespace spott_launch::testing {

/// The simulator's ground truth and bumper, for judging (the stack never reads them).
class Truth {
 public:
  explicit Truth(ros::NodeHandle& nh)
      : truth_(nh.subscribe("/sim/ground_truth", 10, &Truth::OnTruth, this)),
        bumper_(nh.subscribe("/bumper", 10, &Truth::OnBumper, this)) {}
  double DistanceTo(double x, double y) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::hypot(x_ - x, y_ - y);
  }
  void Pose(double* x, double* y, double* yaw) const {
    std::lock_guard<std::mutex> lock(mutex_);
    *x = x_;
    *y = y_;
    *yaw = yaw_;
  }
  bool seen() const { return seen_; }
  int contacts() const { return contacts_; }
  void ResetContacts() { contacts_ = 0; }
  double travelled_m() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return travelled_;
  }

 private:
  void OnTruth(const nav_msgs::Odometry& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double x = m.pose.pose.position.x, y = m.pose.pose.position.y;
    if (seen_) travelled_ += std::hypot(x - x_, y - y_);
    x_ = x;
    y_ = y;
    yaw_ = spott_ros::YawOf(m.pose.pose.orientation).value_or(yaw_);
    seen_ = true;
  }
  void OnBumper(const spott_msgs::BumperRing& r) {
    bool any = false;
    for (bool p : r.pressed) any = any || p;
    if (any) ++contacts_;
  }
  mutable std::mutex mutex_;
  double x_ = 0, y_ = 0, yaw_ = 0, travelled_ = 0;
  std::atomic<bool> seen_{false};
  std::atomic<int> contacts_{0};
  ros::Subscriber truth_, bumper_;
};

/// Every event line of rpl_executive's ~state ("12.300 PULSE EXECUTION-INTERRUPTED?"), and the
/// monitor events, as they come.
class ExecutiveEvents {
 public:
  explicit ExecutiveEvents(ros::NodeHandle& nh)
      : state_(nh.subscribe("/rpl_executive/state", 100, &ExecutiveEvents::OnState, this)),
        monitors_(nh.subscribe("/monitor_events", 100, &ExecutiveEvents::OnMonitor, this)) {}
  std::vector<std::string> lines() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return lines_;
  }
  std::vector<spott_msgs::MonitorEvent> monitors() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return monitor_events_;
  }
  std::string state() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_.state;
  }
  spott_msgs::ExecutiveState last() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_;
  }
  void Clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    lines_.clear();
    monitor_events_.clear();
  }
  /// The time (s) of the first event line at or after `from_s` that contains `what`; -1 if none.
  double TimeOf(const std::string& what, double from_s = 0.0) const {
    for (const std::string& l : lines()) {
      if (l.find(what) == std::string::npos) continue;
      const double t = std::atof(l.c_str());
      if (t >= from_s) return t;
    }
    return -1.0;
  }
  /// RPL: each change of the travel mode, (state stamp in s, mode), in order.
  std::vector<std::pair<double, std::string>> travel_modes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return travel_modes_;
  }
  int Count(const std::string& what, double from_s = 0.0) const {
    int n = 0;
    for (const std::string& l : lines()) {
      if (l.find(what) != std::string::npos && std::atof(l.c_str()) >= from_s) ++n;
    }
    return n;
  }

 private:
  void OnState(const spott_msgs::ExecutiveState& s) {
    std::lock_guard<std::mutex> lock(mutex_);
    lines_.insert(lines_.end(), s.events.begin(), s.events.end());
    if (travel_modes_.empty() || travel_modes_.back().second != s.travel_mode)
      travel_modes_.push_back({s.header.stamp.toSec(), s.travel_mode});
    last_ = s;
  }
  void OnMonitor(const spott_msgs::MonitorEvent& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    monitor_events_.push_back(m);
  }
  mutable std::mutex mutex_;
  std::vector<std::string> lines_;
  std::vector<spott_msgs::MonitorEvent> monitor_events_;
  spott_msgs::ExecutiveState last_;
  std::vector<std::pair<double, std::string>> travel_modes_;
  ros::Subscriber state_, monitors_;
};

/// A suite of tests on one running stack: a spinner, a node handle and the ground truth shared
/// by its tests. A suite with more (watchers) calls these from its own SetUp/TearDownTestSuite.
/// Everything goes before ROS's globals do, so that no callback meets a destroyed mutex.
class StackTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    spinner_ = new ros::AsyncSpinner(2);
    spinner_->start();
    nh_ = new ros::NodeHandle;
    truth_ = new Truth(*nh_);
  }
  static void TearDownTestSuite() {
    spinner_->stop();
    delete truth_;
    delete nh_;
    delete spinner_;
  }
  static inline ros::AsyncSpinner* spinner_ = nullptr;
  static inline ros::NodeHandle* nh_ = nullptr;
  static inline Truth* truth_ = nullptr;
};

using MissionClient = actionlib::SimpleActionClient<spott_msgs::MissionAction>;

/// Appends one line to the file (the seeded-run scripts collect them); nothing when "" .
inline void AppendReport(const std::string& file, const std::string& line) {
  if (file.empty()) return;
  std::ofstream out(file, std::ios::app);
  out << line << "\n";
}

/// Waits (wall time) until `ok` holds; false on the timeout.
template <class F>
bool WaitUntil(F ok, double wall_s) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(wall_s);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (ok()) return true;
    ros::WallDuration(0.02).sleep();
  }
  return ok();
}

}  // namespace spott_launch::testing
