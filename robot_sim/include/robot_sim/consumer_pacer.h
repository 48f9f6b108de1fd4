// Keeps the simulated clock from running ahead of the stack. Faster than real time on a busy
// machine, the simulator would otherwise step the world on while the localization and the
// planners fall behind its clock, so that they judge and steer a robot that has moved on (the
// demo then fails on machine load, not on its algorithms). The simulator watches the stamps of
// its consumers' outputs (the localization's status stamps the scan it processed; the local
// planner's status the cycle it ran) and holds its clock while the newest output of one lags
// more than max_lag_s of simulated time behind it. A consumer that stays silent for max_hold_s
// of wall time (dead, or not started) is not waited for until it publishes again.
#pragma once

#include <string>
#include <vector>

namespace robot_sim {

struct PacerParameters {
  std::vector<std::string> topics;  ///< Consumer outputs carrying a std_msgs/Header (none: off).
  double max_lag_s = 0.5;           ///< Simulated lag tolerated (s), > 0.
  double max_hold_s = 2.0;          ///< Longest wall hold for one consumer (s), > 0.
};

std::vector<std::string> ValidateParameters(const PacerParameters& p);

class ConsumerPacer {
 public:
  explicit ConsumerPacer(const PacerParameters& params);

  /// The consumer `index` (of params.topics) published an output stamped `stamp_s` (sim s).
  void Observe(std::size_t index, double stamp_s);
  /// Whether to hold the clock at `sim_now_s` (sim s) now, at wall time `wall_s` (s).
  bool Hold(double sim_now_s, double wall_s);

  /// Consumers given up on (silent beyond max_hold_s) since the last call; for a warning.
  std::vector<std::string> TakeGivenUp();
  /// Wall time spent holding so far (s).
  double held_s() const { return held_s_; }
  /// The largest lag among the consumers waited for at the last Hold (sim s).
  double lag_s() const { return lag_s_; }

 private:
  struct Consumer {
    bool seen = false;
    double stamp_s = 0.0;
    double hold_since_wall_s = -1.0;  ///< < 0: not holding for it.
    bool given_up = false;
  };
  PacerParameters params_;
  std::vector<Consumer> consumers_;
  std::vector<std::string> given_up_;
  double last_wall_s_ = -1.0;
  bool holding_ = false;
  double held_s_ = 0.0;
  double lag_s_ = 0.0;
};

}  // namespace robot_sim
