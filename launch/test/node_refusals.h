// What one node says it refused (issue 21): its "<node>: input" status on /diagnostics, one value
// per cause ("topic field" -> "count: last reason"), as the rostests that send bad input read it.
#pragma once

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>
#include <spott_msgs/RangeRing.h>

#include <cmath>
#include <map>
#include <mutex>
#include <string>

namespace spott_launch::testing {

class NodeRefusals {
 public:
  NodeRefusals(ros::NodeHandle& nh, const std::string& node)
      : status_(node + ": input"),
        sub_(nh.subscribe("/diagnostics", 50, &NodeRefusals::On, this)) {}
  /// Whether the node has counted a refusal of this cause ("topic field").
  bool Has(const std::string& cause) {
    std::lock_guard<std::mutex> lock(mutex_);
    return causes_.count(cause) > 0;
  }
  /// "count: last reason", or "".
  std::string Value(const std::string& cause) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = causes_.find(cause);
    return it == causes_.end() ? "" : it->second;
  }

 private:
  void On(const diagnostic_msgs::DiagnosticArray& a) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& st : a.status)
      if (st.name == status_)
        for (const auto& kv : st.values) causes_[kv.key] = kv.value;
  }
  const std::string status_;
  std::mutex mutex_;
  std::map<std::string, std::string> causes_;
  ros::Subscriber sub_;
};

/// A ring of `n` transducers in base_link reading 1 m each, but with a max_range that is not a
/// number: every node must refuse it (mapped, each reading would be "no echo").
inline spott_msgs::RangeRing BlindRing(float field_of_view, float min_range, int n) {
  spott_msgs::RangeRing ring;
  ring.header.frame_id = "base_link";
  ring.field_of_view = field_of_view;
  ring.min_range = min_range;
  ring.max_range = std::nanf("");
  ring.mounts.resize(n);
  ring.ranges.assign(n, 1.0f);
  return ring;
}

}  // namespace spott_launch::testing
