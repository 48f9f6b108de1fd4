#include "spott_ros/input_refusals.h"

#include <diagnostic_msgs/DiagnosticArray.h>

namespace spott_ros {

std::uint64_t RefusalCounts::Add(const std::string& topic, const std::string& field,
                                 const std::string& why) {
  Cause& c = causes_[topic + " " + field];
  c.last_reason = why;
  ++total_;
  return ++c.count;
}

std::uint64_t RefusalCounts::count(const std::string& topic, const std::string& field) const {
  const auto it = causes_.find(topic + " " + field);
  return it == causes_.end() ? 0 : it->second.count;
}

diagnostic_msgs::DiagnosticStatus ToDiagnosticStatus(const std::string& node,
                                                     const RefusalCounts& counts,
                                                     std::uint64_t refused_since_last) {
  diagnostic_msgs::DiagnosticStatus s;
  s.name = node + ": input";
  s.hardware_id = node;
  s.level = refused_since_last > 0 ? diagnostic_msgs::DiagnosticStatus::WARN
                                   : diagnostic_msgs::DiagnosticStatus::OK;
  s.message = refused_since_last > 0
                  ? std::to_string(refused_since_last) + " input(s) refused in the last period"
              : counts.total() > 0 ? "no input refused in the last period"
                                   : "no input refused";
  for (const auto& [key, cause] : counts.causes()) {
    diagnostic_msgs::KeyValue kv;
    kv.key = key;
    kv.value = std::to_string(cause.count) + ": " + cause.last_reason;
    s.values.push_back(kv);
  }
  return s;
}

std::pair<std::string, std::string> SplitProblem(const std::string& problem) {
  const auto colon = problem.find(": ");
  if (colon == std::string::npos) return {"message", problem};
  return {problem.substr(0, colon), problem.substr(colon + 2)};
}

InputRefusals::InputRefusals(ros::NodeHandle& nh, std::string node, double period_s)
    : node_(std::move(node)) {
  pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  timer_ = nh.createTimer(ros::Duration(period_s), &InputRefusals::Publish, this);
}

void InputRefusals::Refuse(const std::string& topic, const std::string& field,
                           const std::string& why) {
  std::uint64_t n;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    n = counts_.Add(topic, field, why);
  }
  if (n == 1 || n % 100 == 0) {
    const std::string times = n == 1 ? "" : " [" + std::to_string(n) + " times]";
    ROS_WARN("%s: %s: refused (%s): %s%s", node_.c_str(), topic.c_str(), field.c_str(), why.c_str(),
             times.c_str());
  }
}

void InputRefusals::RefuseProblem(const std::string& topic, const std::string& problem) {
  const auto [field, why] = SplitProblem(problem);
  Refuse(topic, field, why);
}

std::uint64_t InputRefusals::count(const std::string& topic, const std::string& field) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counts_.count(topic, field);
}

void InputRefusals::Publish(const ros::TimerEvent&) {
  diagnostic_msgs::DiagnosticArray a;
  a.header.stamp = ros::Time::now();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    a.status.push_back(ToDiagnosticStatus(node_, counts_, counts_.total() - published_total_));
    published_total_ = counts_.total();
  }
  pub_.publish(a);
}

}  // namespace spott_ros
