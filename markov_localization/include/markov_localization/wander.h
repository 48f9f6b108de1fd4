// The random motion before the first active choice (Beetz et al. section 2.3: the robot starts
// from a uniform belief and moves randomly for about ten metres). With a uniform belief there is
// no pose to navigate by, so the motion is reactive on the range ring alone: keep a heading
// (odometry frame) drawn at random among the free directions, keep off obstacles, and draw a new
// heading when the way ahead closes.
//
// ROS-free; the caller passes the readings, the odometry heading and the random generator's seed.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace markov_localization {

struct WanderParameters {
  double max_speed_mps = 0.4;          ///< (m/s), > 0
  double max_turn_rps = 0.8;           ///< (rad/s), > 0
  double heading_gain = 1.5;           ///< omega = gain x heading error (1/s), > 0
  double stop_distance_m = 0.5;        ///< Turn in place when a reading ahead is closer (m), > 0.
  double slow_distance_m = 1.5;        ///< Full speed beyond this free distance ahead (m), > stop.
  double side_distance_m = 0.6;        ///< Side readings closer than this push the robot away (m).
  double free_range_m = 2.0;           ///< A direction whose reading reaches this is free (m), > 0.
  double front_half_angle_rad = 0.35;  ///< Readings within this of the heading are "ahead".
  /// No 0.3 m of progress in this many steps (rings) means stuck (e.g. turning in a doorway):
  /// a new heading is drawn among the free directions behind the robot. >= 1.
  int stall_steps = 60;
};

std::vector<std::string> ValidateParameters(const WanderParameters& params);

struct WanderCommand {
  double linear_mps = 0.0;
  double angular_rps = 0.0;
};

class Wanderer {
 public:
  /// Throws std::invalid_argument on invalid parameters.
  Wanderer(const WanderParameters& params, std::uint64_t seed);

  /// One command for one ring: `angles_rad[b]` the axis of beam b relative to the robot's
  /// heading, `ranges_m[b]` its reading (NaN or >= max_range_m: no echo, i.e. free),
  /// `odom_yaw` the robot's heading in the odometry frame.
  WanderCommand Step(const std::vector<double>& angles_rad, const std::vector<double>& ranges_m,
                     double max_range_m, double odom_yaw);
  /// The same, with the odometry position (m) for the stall detection.
  WanderCommand Step(const std::vector<double>& angles_rad, const std::vector<double>& ranges_m,
                     double max_range_m, double odom_x, double odom_y, double odom_yaw);

  /// The heading being followed (odometry frame), once one was drawn.
  std::optional<double> heading() const { return heading_; }

 private:
  void DrawHeading(const std::vector<double>& angles, const std::vector<double>& ranges,
                   double odom_yaw, bool behind = false);

  WanderParameters params_;
  std::mt19937_64 rng_;
  std::optional<double> heading_;
  double anchor_x_ = 0.0, anchor_y_ = 0.0;
  int stalled_ = -1;  ///< Steps without progress; < 0: no position yet.
};

}  // namespace markov_localization
