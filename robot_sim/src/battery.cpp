#include "robot_sim/battery.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace robot_sim {

std::vector<std::string> ValidateParameters(const BatteryParameters& p) {
  std::vector<std::string> e;
  if (!(p.capacity_wh > 0 && p.capacity_wh <= 1e6)) {
    e.push_back("battery/capacity_wh must be in (0, 1e6]");
  }
  if (!(p.initial_percent >= 0 && p.initial_percent <= 100)) {
    e.push_back("battery/initial_percent must be in [0, 100]");
  }
  auto power = [&](double w, const char* name) {
    if (!(w >= 0 && w <= 1e5)) e.push_back(std::string("battery/") + name + " must be in [0, 1e5]");
  };
  power(p.idle_power_w, "idle_power_w");
  power(p.power_per_mps_w, "power_per_mps_w");
  power(p.power_per_rps_w, "power_per_rps_w");
  if (!(p.empty_voltage_v > 0 && p.empty_voltage_v < 1e4)) {
    e.push_back("battery/empty_voltage_v must be in (0, 1e4)");
  }
  if (!(p.full_voltage_v > p.empty_voltage_v && p.full_voltage_v < 1e4)) {
    e.push_back("battery/full_voltage_v must be above battery/empty_voltage_v (and < 1e4)");
  }
  return e;
}

Battery::Battery(const BatteryParameters& params) : params_(params), power_w_(params.idle_power_w) {
  const std::vector<std::string> errors = ValidateParameters(params);
  if (!errors.empty()) {
    std::string all;
    for (const std::string& e : errors) all += (all.empty() ? "" : "; ") + e;
    throw std::invalid_argument(all);
  }
  remaining_wh_ = params.capacity_wh * params.initial_percent / 100.0;
}

void Battery::Step(double dt_s, double v_mps, double w_rps) {
  if (!(dt_s > 0) || !std::isfinite(dt_s)) return;
  const double v = std::isfinite(v_mps) ? std::fabs(v_mps) : 0.0;
  const double w = std::isfinite(w_rps) ? std::fabs(w_rps) : 0.0;
  power_w_ = params_.idle_power_w + params_.power_per_mps_w * v + params_.power_per_rps_w * w;
  remaining_wh_ = std::max(0.0, remaining_wh_ - power_w_ * dt_s / 3600.0);
}

double Battery::percent() const { return 100.0 * remaining_wh_ / params_.capacity_wh; }

double Battery::voltage_v() const {
  const double f = remaining_wh_ / params_.capacity_wh;
  return params_.empty_voltage_v + f * (params_.full_voltage_v - params_.empty_voltage_v);
}

double Battery::current_a() const { return power_w_ / voltage_v(); }

double Battery::charge_ah() const {
  return remaining_wh_ / (0.5 * (params_.full_voltage_v + params_.empty_voltage_v));
}

double Battery::capacity_ah() const {
  return params_.capacity_wh / (0.5 * (params_.full_voltage_v + params_.empty_voltage_v));
}

}  // namespace robot_sim
