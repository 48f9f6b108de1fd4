#include "cmd_vel_arbiter/arbiter.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace cmd_vel_arbiter {
namespace {

// Commands within this relative margin of a limit are not refused (float round-off of senders
// that command exactly the limit).
constexpr double kLimitSlack = 1e-6;
// A contact pushes when the contact point moves inwards faster than this (m/s).
constexpr double kPushEpsilon = 1e-6;

bool ValidName(const std::string& n) {
  return !n.empty() && std::all_of(n.begin(), n.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

}  // namespace

bool operator==(const Velocity& a, const Velocity& b) {
  return a.linear_mps == b.linear_mps && a.angular_rps == b.angular_rps;
}

const char* ToString(SourceState s) {
  switch (s) {
    case SourceState::kIdle:
      return "idle";
    case SourceState::kDriving:
      return "driving";
    case SourceState::kPreempted:
      return "preempted";
    case SourceState::kTimedOut:
      return "timed out";
  }
  return "?";
}

std::vector<std::string> ValidateParameters(const ArbiterParameters& p) {
  std::vector<std::string> v;
  if (p.sources.empty()) v.push_back("sources must name at least one source");
  std::set<std::string> names;
  std::set<int> priorities;
  for (const SourceParameters& s : p.sources) {
    const std::string key = "sources/" + s.name;
    if (!ValidName(s.name)) v.push_back(key + ": a source name is [a-z0-9_]+");
    if (!names.insert(s.name).second) v.push_back(key + " is given twice");
    if (!priorities.insert(s.priority).second) {
      v.push_back(key + "/priority " + std::to_string(s.priority) +
                  " is shared with another source (priorities must differ)");
    }
    if (!(s.timeout_s > 0.0 && s.timeout_s <= 60.0))
      v.push_back(key + "/timeout_s must be in (0, 60]");
  }
  if (!(p.max_linear_mps > 0.0 && std::isfinite(p.max_linear_mps)))
    v.push_back("limits/max_linear_mps must be > 0");
  if (!(p.max_angular_rps > 0.0 && std::isfinite(p.max_angular_rps)))
    v.push_back("limits/max_angular_rps must be > 0");
  return v;
}

Arbiter::Arbiter(const ArbiterParameters& params)
    : params_(params),
      limit_linear_(params.max_linear_mps),
      limit_angular_(params.max_angular_rps) {
  const std::vector<std::string> problems = ValidateParameters(params);
  if (!problems.empty()) {
    std::string all;
    for (const std::string& p : problems) all += (all.empty() ? "" : "; ") + p;
    throw std::invalid_argument(all);
  }
  for (const SourceParameters& s : params.sources) sources_[s.name].params = s;
}

bool Arbiter::Sending(const Source& s, double now_s) const {
  return s.last_time && now_s - *s.last_time <= s.params.timeout_s;
}

int Arbiter::PriorityOf(const std::string& name) const { return sources_.at(name).params.priority; }

Velocity Arbiter::Filter(Velocity v, const std::string& driver) {
  // Run-time limits: one factor for both components keeps the commanded curvature.
  double scale = 1.0;
  if (std::abs(v.linear_mps) > limit_linear_) scale = limit_linear_ / std::abs(v.linear_mps);
  if (std::abs(v.angular_rps) * scale > limit_angular_)
    scale = limit_angular_ / std::abs(v.angular_rps);
  v.linear_mps *= scale;
  v.angular_rps *= scale;
  bumper_stop_ = false;
  for (double phi : contacts_) {
    if (v.linear_mps * std::cos(phi) > kPushEpsilon) bumper_stop_ = true;
  }
  if (bumper_stop_) v.linear_mps = 0.0;
  // The clearance caps the linear speed only: turning away stays possible.
  clearance_slowed_ = false;
  const auto& exempt = params_.clearance_exempt;
  if (std::find(exempt.begin(), exempt.end(), driver) == exempt.end()) {
    const double cap = v.linear_mps > 0.0 ? clear_forward_ : clear_backward_;
    if (std::abs(v.linear_mps) > cap) {
      v.linear_mps = std::copysign(cap, v.linear_mps);
      clearance_slowed_ = true;
    }
  }
  return v;
}

Output Arbiter::SetClearance(double forward_mps, double backward_mps, double now_s) {
  clear_forward_ = std::isnan(forward_mps) ? 0.0 : std::max(0.0, forward_mps);
  clear_backward_ = std::isnan(backward_mps) ? 0.0 : std::max(0.0, backward_mps);
  return Select(now_s, false);
}

Output Arbiter::Select(double now_s, bool force) {
  const std::string holder = exclusive_holder();
  const int holder_priority = holder.empty() ? 0 : PriorityOf(holder);
  std::string driver;
  int best = 0;
  for (const auto& [name, s] : sources_) {
    if (!Sending(s, now_s)) continue;
    if (!holder.empty() && name != holder && s.params.priority <= holder_priority) continue;
    if (driver.empty() || s.params.priority > best) {
      driver = name;
      best = s.params.priority;
    }
  }
  bool changed = driver != driver_;
  for (auto& [name, s] : sources_) {
    SourceState state;
    const bool holds = std::find(holders_.begin(), holders_.end(), name) != holders_.end();
    if (name == driver) {
      state = SourceState::kDriving;
      s.drove = true;
    } else if (Sending(s, now_s) || holds) {
      state = SourceState::kPreempted;
    } else if (s.drove) {
      state = SourceState::kTimedOut;
    } else {
      state = SourceState::kIdle;
    }
    changed |= state != s.state;
    s.state = state;
  }
  driver_ = driver;
  const bool was_bumper_stop = bumper_stop_;
  const Velocity command = driver.empty() ? Velocity{} : Filter(sources_.at(driver).last, driver);
  if (driver.empty()) bumper_stop_ = false;
  changed |= bumper_stop_ != was_bumper_stop;
  if (changed) ++revision_;
  Output out;
  out.command = command;
  out.publish = force || changed || !published_ || !(command == *published_);
  if (out.publish) {
    published_ = command;
    if (bumper_stop_) ++bumper_stops_;
    if (clearance_slowed_) ++clearance_slowdowns_;
  }
  return out;
}

Output Arbiter::Command(const std::string& source, const Velocity& v, double now_s,
                        std::string* refused) {
  refused->clear();
  auto it = sources_.find(source);
  if (it == sources_.end()) {
    ++refused_total_;
    *refused = "unknown source '" + source + "'";
    return Output{};
  }
  Source& s = it->second;
  if (!Sending(s, now_s)) s.drove = false;  // starts sending again
  std::ostringstream why;
  if (!std::isfinite(v.linear_mps) || !std::isfinite(v.angular_rps)) {
    why << "not finite (linear " << v.linear_mps << ", angular " << v.angular_rps << ")";
  } else if (std::abs(v.linear_mps) > params_.max_linear_mps * (1.0 + kLimitSlack)) {
    why << "linear " << v.linear_mps << " m/s beyond the robot's " << params_.max_linear_mps;
  } else if (std::abs(v.angular_rps) > params_.max_angular_rps * (1.0 + kLimitSlack)) {
    why << "angular " << v.angular_rps << " rad/s beyond the robot's " << params_.max_angular_rps;
  }
  *refused = why.str();
  ++s.commands;
  s.last_time = now_s;
  if (refused->empty()) {
    s.last = v;
  } else {
    s.last = Velocity{};  // a refused command stops its source
    ++s.refused;
    ++refused_total_;
    ++revision_;
  }
  // Select first, then force: the driver's every command is passed on.
  Output out = Select(now_s, false);
  if (driver_ == source && !out.publish) {
    out.publish = true;
    if (bumper_stop_) ++bumper_stops_;
    if (clearance_slowed_) ++clearance_slowdowns_;
  }
  return out;
}

Output Arbiter::Update(double now_s) { return Select(now_s, false); }

Output Arbiter::SetContacts(const std::vector<double>& pressed_angles_rad, double now_s) {
  contacts_.clear();
  for (double a : pressed_angles_rad)
    if (std::isfinite(a)) contacts_.push_back(a);
  return Select(now_s, false);
}

bool Arbiter::Take(const std::string& source, double now_s, std::string* message,
                   std::string* preempted, Output* out) {
  preempted->clear();
  *out = Output{};
  if (!sources_.count(source)) {
    *message = "unknown source '" + source + "'";
    return false;
  }
  const std::string holder = exclusive_holder();
  if (!holder.empty() && holder != source && PriorityOf(source) <= PriorityOf(holder)) {
    *message = "the wheels are held by '" + holder + "' (priority " +
               std::to_string(PriorityOf(holder)) + " >= " + std::to_string(PriorityOf(source)) +
               ")";
    return false;
  }
  if (holder == source) {
    *message = "'" + source + "' already holds the wheels";
    *out = Select(now_s, false);
    return true;
  }
  holders_.erase(std::remove(holders_.begin(), holders_.end(), source), holders_.end());
  holders_.push_back(source);
  *preempted = holder;
  *message = "'" + source + "' holds the wheels" +
             (holder.empty() ? std::string() : ", pre-empting '" + holder + "'");
  ++revision_;
  *out = Select(now_s, false);
  return true;
}

bool Arbiter::Release(const std::string& source, double now_s, std::string* message, Output* out) {
  *out = Output{};
  auto it = std::find(holders_.begin(), holders_.end(), source);
  if (it == holders_.end()) {
    *message = "'" + source + "' does not hold the wheels";
    return false;
  }
  holders_.erase(it);
  const std::string holder = exclusive_holder();
  *message = "'" + source + "' released the wheels" +
             (holder.empty() ? std::string() : "; '" + holder + "' holds them again");
  ++revision_;
  *out = Select(now_s, false);
  return true;
}

bool Arbiter::SetSpeedLimits(double max_linear_mps, double max_angular_rps,
                             const std::string& reason, std::string* message, double now_s,
                             Output* out) {
  *out = Output{};
  const auto bad = [](double x, double max) { return !std::isfinite(x) || x < 0.0 || x > max; };
  if (bad(max_linear_mps, params_.max_linear_mps) ||
      bad(max_angular_rps, params_.max_angular_rps)) {
    std::ostringstream m;
    m << "speed limits must be in [0, the robot's " << params_.max_linear_mps << " m/s] and [0, "
      << params_.max_angular_rps << " rad/s] (0 = the robot's); got " << max_linear_mps << ", "
      << max_angular_rps;
    *message = m.str();
    return false;
  }
  limit_linear_ = max_linear_mps > 0.0 ? max_linear_mps : params_.max_linear_mps;
  limit_angular_ = max_angular_rps > 0.0 ? max_angular_rps : params_.max_angular_rps;
  limits_reason_ = (max_linear_mps > 0.0 || max_angular_rps > 0.0) ? reason : "";
  std::ostringstream m;
  m << "limits " << limit_linear_ << " m/s, " << limit_angular_ << " rad/s";
  *message = m.str();
  ++revision_;
  *out = Select(now_s, false);
  return true;
}

std::vector<SourceStatus> Arbiter::Sources() const {
  std::vector<SourceStatus> list;
  for (const auto& [name, s] : sources_) {
    SourceStatus st;
    st.name = name;
    st.priority = s.params.priority;
    st.state = s.state;
    st.exclusive = std::find(holders_.begin(), holders_.end(), name) != holders_.end();
    st.commands = s.commands;
    st.refused = s.refused;
    list.push_back(st);
  }
  std::sort(list.begin(), list.end(),
            [](const SourceStatus& a, const SourceStatus& b) { return a.priority > b.priority; });
  return list;
}

}  // namespace cmd_vel_arbiter
