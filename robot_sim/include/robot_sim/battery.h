// The robot's battery: a drain model for O-surveillances of the robot's operation (Noreils and
// Chatila section 4.1.1: "O-surveillances related to the operation of the robot, even if no task
// is being executed (e.g., battery power level)"). The papers give no figures for HILARE's
// batteries; the defaults (config/robot_sim.yaml) are assumed and say so.
//
// The charge falls with the power drawn: a constant load (electronics, sensors, computers) plus
// traction power proportional to the linear speed and to the turn rate,
//   P = idle_power_w + power_per_mps_w |v| + power_per_rps_w |w|     (W)
//   E(t + dt) = max(0, E(t) - P dt / 3600)                           (Wh)
// and the terminal voltage falls linearly from full_voltage_v to empty_voltage_v with the
// charge (a lead-acid pack's discharge curve, to first order). The caller passes dt and the
// robot's true velocity; nothing here reads a clock.
#pragma once

#include <string>
#include <vector>

namespace robot_sim {

struct BatteryParameters {
  double capacity_wh = 960.0;      ///< Energy when full (Wh), (0, 1e6]. Assumed: 24 V x 40 Ah.
  double initial_percent = 100.0;  ///< Charge at the start (%), [0, 100].
  double idle_power_w = 50.0;      ///< Drawn standing still (W), [0, 1e5].
  double power_per_mps_w = 150.0;  ///< Traction per m/s of linear speed (W s/m), [0, 1e5].
  double power_per_rps_w = 30.0;   ///< Per rad/s of turn rate (W s/rad), [0, 1e5].
  double full_voltage_v = 25.4;    ///< Terminal voltage when full (V), > empty_voltage_v.
  double empty_voltage_v = 21.0;   ///< Terminal voltage when empty (V), > 0.
};

/// Every violation, named as in config/robot_sim.yaml (battery/capacity_wh ...).
std::vector<std::string> ValidateParameters(const BatteryParameters& p);

class Battery {
 public:
  /// Parameters must be valid (std::invalid_argument listing the violations otherwise).
  explicit Battery(const BatteryParameters& params);

  /// Drains the battery for `dt_s` seconds at linear speed `v_mps` and turn rate `w_rps`.
  void Step(double dt_s, double v_mps, double w_rps);

  /// Remaining charge (%), [0, 100].
  double percent() const;
  double remaining_wh() const { return remaining_wh_; }
  /// Power drawn in the last step (W).
  double power_w() const { return power_w_; }
  /// Terminal voltage now (V).
  double voltage_v() const;
  /// Current drawn in the last step (A, >= 0).
  double current_a() const;
  /// Charge and capacity in Ah at the nominal voltage ((full + empty) / 2).
  double charge_ah() const;
  double capacity_ah() const;
  const BatteryParameters& parameters() const { return params_; }

 private:
  BatteryParameters params_;
  double remaining_wh_;
  double power_w_;
};

}  // namespace robot_sim
