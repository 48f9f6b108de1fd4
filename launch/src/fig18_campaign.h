// SPOTT Fig. 18, the guaranteed cell: GO with the CAD map. A seeded campaign of tasks in
// cim_office, each from its own start pose to its own goal in another room: a run is a fresh
// stack (robot_sim at the run's start, markov_localization starting there too) and
// one task command `go to point(x, y)` for the TR+ controller, judged on the simulator's ground
// truth (scripts/fig18_campaign.sh runs the campaign; test/fig18.test runs one case in CI).
#pragma once

#include <random>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "spott_map/world.h"

namespace spott_launch {

struct Fig18Case {
  int seed = 0;
  spott_map::Pose2 start;
  spott_map::Vec2 goal{0.0, 0.0};
  std::string start_room, goal_room;
  std::string command;  ///< "go to point(x, y)"
};

/// The case of `seed`: start and goal uniformly in two different rooms of `world` that the
/// robot can reach from each other through doors known to be open (openings included), at
/// least `clearance_m` from every wall and object of the world file and `min_distance_m`
/// apart; the start heading uniform. Deterministic in the seed.
Fig18Case Fig18CaseFor(const spott_map::World& world, int seed, double clearance_m = 0.7,
                       double min_distance_m = 6.0);

struct Fig18Run {
  Fig18Case c;
  bool arrived = false;      ///< Controller reached, truth within the tolerance, no contact.
  std::string outcome;       ///< The controller's outcome (and message).
  double sim_time_s = 0.0;   ///< From the command to the result (simulated s).
  double path_length_m = 0;  ///< Driven (ground truth, m).
  double straight_m = 0;     ///< Start to goal in a straight line (m).
  double final_error_m = 0;  ///< Ground truth to the goal at the end (m).
  int contacts = 0;
  double mean_speed_mps() const { return sim_time_s > 0 ? path_length_m / sim_time_s : 0.0; }
};

/// Runs one case against the running stack (robot_sim started at c.start): gives markov the
/// start, waits for the estimate, sends the command on /task and judges on /sim/ground_truth.
Fig18Run RunFig18Case(ros::NodeHandle& nh, const Fig18Case& c, double timeout_s,
                      double tolerance_m);

/// One line per run, for the campaign's table: "seed start_room goal_room arrived time length
/// straight speed error contacts outcome".
std::string Fig18Line(const Fig18Run& r);

}  // namespace spott_launch
