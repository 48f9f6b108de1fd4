// Refused input at a node's edge (issue 21's validation rule): a message, goal or request that
// is not finite, absurd in size, empty where emptiness means nothing, or in a wrong frame changes
// no state. Each refusal is counted per cause (topic and field), logged once per cause with the
// reason (then every 100th, so a flood does not drown the log), and published on /diagnostics
// (diagnostic_msgs/DiagnosticArray, the ROS convention) once a second.
#pragma once

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/ros.h>

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

namespace spott_ros {

/// The counting, ROS-free: what was refused, how often, the last reason.
class RefusalCounts {
 public:
  struct Cause {
    std::uint64_t count = 0;
    std::string last_reason;
  };
  /// Records one refusal; returns its count for this cause (1 = the first).
  std::uint64_t Add(const std::string& topic, const std::string& field, const std::string& why);
  std::uint64_t count(const std::string& topic, const std::string& field) const;
  std::uint64_t total() const { return total_; }
  /// Keyed "topic field".
  const std::map<std::string, Cause>& causes() const { return causes_; }

 private:
  std::map<std::string, Cause> causes_;
  std::uint64_t total_ = 0;
};

/// A check's answer "field: why" (the form of every *Problem function) split at its first ": ";
/// a problem without one is all reason, field "message".
std::pair<std::string, std::string> SplitProblem(const std::string& problem);

/// The node's status "<node>: input": OK while nothing was refused since the last status, WARN
/// otherwise; one value per cause ("topic field" -> "count: last reason").
diagnostic_msgs::DiagnosticStatus ToDiagnosticStatus(const std::string& node,
                                                     const RefusalCounts& counts,
                                                     std::uint64_t refused_since_last);

/// A node's refusals, logged and published. Thread-safe (callbacks of several spinner threads).
class InputRefusals {
 public:
  /// Publishes on /diagnostics every `period_s` through `nh`'s callback queue.
  InputRefusals(ros::NodeHandle& nh, std::string node, double period_s = 1.0);
  void Refuse(const std::string& topic, const std::string& field, const std::string& why);
  /// Refuse with a check's "field: why" (SplitProblem).
  void RefuseProblem(const std::string& topic, const std::string& problem);
  std::uint64_t count(const std::string& topic, const std::string& field) const;

 private:
  void Publish(const ros::TimerEvent&);
  std::string node_;
  mutable std::mutex mutex_;
  RefusalCounts counts_;
  std::uint64_t published_total_ = 0;
  ros::Publisher pub_;
  ros::Timer timer_;
};

}  // namespace spott_ros
