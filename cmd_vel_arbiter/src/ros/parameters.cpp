#include "cmd_vel_arbiter/ros/parameters.h"

namespace cmd_vel_arbiter {

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
  for (const std::string& e : ValidateParameters(p.arbiter)) r.Fail(e);
  // The timers' periods 1 / rate must make a ros::Duration (at most 2^31 s).
  r.Require(p.update_rate_hz >= 0.01 && p.update_rate_hz <= 1000, "update_rate_hz",
            "in [0.01, 1000]", p.update_rate_hz);
  r.Require(p.status_rate_hz == 0 || (p.status_rate_hz >= 0.01 && p.status_rate_hz <= 100),
            "status_rate_hz", "0 (on change only) or in [0.01, 100]", p.status_rate_hz);
}

}  // namespace cmd_vel_arbiter
