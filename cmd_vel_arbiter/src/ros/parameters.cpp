#include "cmd_vel_arbiter/ros/parameters.h"

namespace cmd_vel_arbiter {

std::vector<std::string> ClearanceTopicNames(const NodeParameters& p) {
  std::vector<std::string> all = p.clearance_topics;
  all.insert(all.end(), p.clearance_scan_topics.begin(), p.clearance_scan_topics.end());
  return all;
}

void Read(spott_ros::ParameterReader& r, NodeParameters& p) {
  for (const std::string& name : r.Keys("sources")) {
    SourceParameters s;
    s.name = name;
    r.Get("sources/" + name + "/priority", s.priority);
    r.Get("sources/" + name + "/timeout_s", s.timeout_s, "s");
    p.arbiter.sources.push_back(s);
  }
  r.Get("limits/max_linear_mps", p.arbiter.max_linear_mps, "m/s");
  r.Get("limits/max_angular_rps", p.arbiter.max_angular_rps, "rad/s");
  r.Get("update_rate_hz", p.update_rate_hz, "Hz");
  r.Get("status_rate_hz", p.status_rate_hz, "Hz");
  r.Get("clearance/enabled", p.clearance_enabled);
  r.Get("clearance/topics", p.clearance_topics);
  r.Get("clearance/scan_topics", p.clearance_scan_topics);
  r.Get("clearance/base_frame", p.base_frame);
  r.Get("clearance/max_age_s", p.clearance_max_age_s, "s");
  r.Get("clearance/exempt_sources", p.arbiter.clearance_exempt);
  ClearanceParameters& c = p.clearance;
  r.Get("clearance/deceleration_mps2", c.deceleration_mps2, "m/s^2");
  r.Get("clearance/latency_s", c.latency_s, "s");
  r.Get("clearance/stop_margin_m", c.stop_margin_m, "m");
  r.Get("clearance/corridor_margin_m", c.corridor_margin_m, "m");
  r.Get("clearance/footprint_radius_m", c.footprint_radius_m, "m");
  r.Get("clearance/min_range_at_face", c.min_range_at_face);
  for (const std::string& e : ValidateParameters(p.arbiter)) r.Fail(e);
  for (const std::string& e : ValidateParameters(p.clearance)) r.Fail(e);
  r.Require(p.clearance_max_age_s > 0 && p.clearance_max_age_s <= 60, "clearance/max_age_s",
            "in (0, 60]", p.clearance_max_age_s);
  if (p.clearance_enabled && p.clearance_topics.empty() && p.clearance_scan_topics.empty())
    r.Fail("clearance/topics and clearance/scan_topics must name at least one topic");
  const std::vector<std::string> all = ClearanceTopicNames(p);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const char* key = i < p.clearance_topics.size() ? "clearance/topics" : "clearance/scan_topics";
    if (all[i].empty()) r.Fail(std::string(key) + ": an empty topic name");
    for (std::size_t j = 0; j < i; ++j) {
      if (all[j] == all[i]) r.Fail(std::string(key) + ": '" + all[i] + "' twice");
    }
  }
  if (p.base_frame.empty()) r.Fail("clearance/base_frame must not be empty");
  // The timers' periods 1 / rate must make a ros::Duration (at most 2^31 s).
  r.Require(p.update_rate_hz >= 0.01 && p.update_rate_hz <= 1000, "update_rate_hz",
            "in [0.01, 1000]", p.update_rate_hz);
  r.Require(p.status_rate_hz == 0 || (p.status_rate_hz >= 0.01 && p.status_rate_hz <= 100),
            "status_rate_hz", "0 (on change only) or in [0.01, 100]", p.status_rate_hz);
}

}  // namespace cmd_vel_arbiter
