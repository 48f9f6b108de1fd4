#include "robot_sim/consumer_pacer.h"

#include <algorithm>
#include <cmath>

namespace robot_sim {

std::vector<std::string> ValidateParameters(const PacerParameters& p) {
  std::vector<std::string> v;
  if (!(p.max_lag_s > 0.0 && std::isfinite(p.max_lag_s)))
    v.push_back("consumers/max_lag_s must be > 0");
  if (!(p.max_hold_s > 0.0 && std::isfinite(p.max_hold_s)))
    v.push_back("consumers/max_hold_s must be > 0");
  for (const std::string& t : p.topics)
    if (t.empty()) v.push_back("consumers/topics must not hold an empty name");
  return v;
}

ConsumerPacer::ConsumerPacer(const PacerParameters& params)
    : params_(params), consumers_(params.topics.size()) {}

void ConsumerPacer::Observe(std::size_t index, double stamp_s) {
  if (index >= consumers_.size()) return;
  Consumer& c = consumers_[index];
  c.seen = true;
  c.stamp_s = std::max(c.stamp_s, stamp_s);
  c.given_up = false;
}

bool ConsumerPacer::Hold(double sim_now_s, double wall_s) {
  if (holding_ && last_wall_s_ >= 0.0) held_s_ += std::max(0.0, wall_s - last_wall_s_);
  last_wall_s_ = wall_s;
  bool hold = false;
  lag_s_ = 0.0;
  for (std::size_t i = 0; i < consumers_.size(); ++i) {
    Consumer& c = consumers_[i];
    if (!c.seen || c.given_up) continue;  // not started yet, or silent
    const double lag = sim_now_s - c.stamp_s;
    if (lag <= params_.max_lag_s) {
      c.hold_since_wall_s = -1.0;
      continue;
    }
    if (c.hold_since_wall_s < 0.0) c.hold_since_wall_s = wall_s;
    if (wall_s - c.hold_since_wall_s > params_.max_hold_s) {
      c.given_up = true;
      c.hold_since_wall_s = -1.0;
      given_up_.push_back(params_.topics[i]);
      continue;
    }
    hold = true;
    lag_s_ = std::max(lag_s_, lag);
  }
  holding_ = hold;
  return hold;
}

std::vector<std::string> ConsumerPacer::TakeGivenUp() {
  std::vector<std::string> out;
  out.swap(given_up_);
  return out;
}

}  // namespace robot_sim
