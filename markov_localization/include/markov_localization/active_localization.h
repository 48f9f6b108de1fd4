// Active localization of Beetz et al. section 2.2, eqs. (6)-(9): target points a relative to
// the robot (x ahead, y left, m), the belief approximated by its modes, the expected occupancy
// P_occ(a), eq. (7), travel costs v(a) by value iteration, eq. (8), the expected entropy after
// moving to a and sensing, eq. (6), and the choice a* = argmin E_a[H_P] + alpha v(a), eq. (9),
// with the path to a* by hill-climbing in v.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "markov_localization/certainty.h"
#include "markov_localization/map_model.h"
#include "markov_localization/sensor_model.h"

namespace markov_localization {

struct ActiveLocalizationParameters {
  double window_m = 14.0;          ///< Targets within +-window_m ahead and to the left (m), > 0.
  double target_spacing_m = 0.25;  ///< Grid of targets and of value iteration (m), > 0.
  double alpha = 1.0;              ///< Weight of cost against entropy, eq. (9) (paper: 1), >= 0.
  /// Cost of a step (per metre) on top of eq. (8)'s P_occ: eq. (8) alone makes travel through
  /// free space free, while the paper reads v(a) as "its distance to the robot". (1/m), >= 0.
  double travel_cost_per_m = 0.05;
  double occupied_cost = 10.0;         ///< Cost of entering a cell with P_occ = 1 per step, > 0;
                                       ///< cells occupied under every mode are impassable.
  double max_target_occupancy = 0.01;  ///< Targets must be free under (almost) every mode.
  int max_modes = 8;                   ///< The heaviest modes used, > 0.
};

std::vector<std::string> ValidateParameters(const ActiveLocalizationParameters& params);

struct ActiveChoice {
  bool found = false;
  double ax = 0.0, ay = 0.0;      ///< a*: metres ahead and to the left of the robot.
  double expected_entropy = 0.0;  ///< E_a*[H_P] (nats, over the modes).
  double cost = 0.0;              ///< v(a*)
  std::vector<Vec2> path;         ///< From the robot to a*, relative coordinates (m).
  // The fields of Figs. 5-8 over the target grid, row-major, (2n+1)^2 with n = window/spacing;
  // entry (i, j) is a = (-window + i*spacing ahead, -window + j*spacing left) at index j*N+i.
  int size = 0;
  std::vector<double> occupancy;              ///< P_occ(a), eq. (7)
  std::vector<double> cost_to_go;             ///< v(a), eq. (8) (inf when unreachable)
  std::vector<double> expected_entropy_grid;  ///< E_a[H_P], eq. (6) (NaN: not a target)
};

/// The world point of target `a` (ahead, left) if the robot is at `pose`: f_a(l) of eq. (7).
Vec2 TargetInWorld(const Pose2& pose, double ahead_m, double left_m);

class ActiveLocalizer {
 public:
  /// Throws std::invalid_argument on invalid parameters.
  ActiveLocalizer(const MapModel& map, const SensorModel& sensor,
                  const ActiveLocalizationParameters& params);

  /// Chooses a* for the belief given by its modes (heaviest first; masses need not sum to 1).
  ActiveChoice Choose(const std::vector<Mode>& modes) const;

 private:
  struct Targets;  // the (2n+1) x (2n+1) lattice of targets around the robot
  struct Scratch;  // per-mode buffers of eq. (6), reused from target to target

  // The steps of Choose, as the paper gives them: eq. (7) fills `occupancy` and returns which
  // target is free under which mode; eq. (8) the cost to go; eq. (6) E_a[H] at one target (NaN
  // when no mode's point there is a state); the hill-climb from a* back to the robot.
  std::vector<std::uint8_t> OccupancyOfTargets(const Targets& t, const std::vector<Mode>& modes,
                                               const std::vector<double>& w,
                                               std::vector<double>& occupancy) const;
  std::vector<double> CostToGo(const Targets& t, const std::vector<double>& occupancy) const;
  double ExpectedEntropyAt(const Targets& t, std::size_t a, const std::vector<Mode>& modes,
                           const std::vector<double>& w,
                           const std::vector<std::uint8_t>& free_under, Scratch& s) const;
  static std::vector<Vec2> PathBack(const Targets& t, const std::vector<double>& cost_to_go,
                                    std::size_t a);

  const MapModel& map_;
  const SensorModel& sensor_;
  ActiveLocalizationParameters params_;
};

}  // namespace markov_localization
