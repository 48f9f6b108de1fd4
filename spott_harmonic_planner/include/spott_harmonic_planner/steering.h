// Steering from the harmonic field (SPOTT III.D.1 step e): the steepest-descent direction at the
// robot's estimated position, bent toward a task's direction bias as far as descent allows
// (III.B: descend "in the specified direction or as close as possible to it"), turned into a
// (v, omega) command within the robot's limits, the task speed and the clearance.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_harmonic_planner/potential_field.h"
#include "spott_map/world.h"

namespace spott_harmonic_planner {

enum class SpeedMode { kSlowly = 0, kNormal = 1, kQuickly = 2 };  ///< spott_msgs constants

struct SteeringParameters {
  double max_linear_mps = 0.6;    ///< (m/s) > 0; Nomad 200 top speed.
  double max_angular_rps = 1.0;   ///< (rad/s) > 0.
  double slowly_fraction = 0.3;   ///< Share of max_linear_mps for SLOWLY, (0, 1].
  double normal_fraction = 0.6;   ///< For NORMAL, (0, 1].
  double quickly_fraction = 1.0;  ///< For QUICKLY, (0, 1].
  double heading_gain = 2.0;      ///< omega = gain * heading error (1/s), > 0.
  /// Largest angle (rad) between the command and steepest descent that a direction bias may
  /// ask for, in [0, pi/2): below pi/2 the robot still descends.
  double max_bias_deviation_rad = 1.2;
  /// A bias within this angle (rad) of straight behind descent bends the heading less, to none
  /// at straight behind, in [0, pi/2]: there the bias's side flips with the field's smallest
  /// change, and the full deviation flipped the command by 2 x 69 degrees every second or two
  /// (SPOTT's Experiment 1 without a map: the robot turned on the spot beside the lab's
  /// partition for 30 s, its goal behind the way round, and the odometry's heading drifted 5
  /// degrees). 0: the full deviation up to straight behind.
  double bias_reverse_fade_rad = 1.05;
  /// Below this clearance (m) the allowed deviation shrinks in proportion, to none at the
  /// padding's edge, > 0: beside a door's jamb a heading pulled off descent cuts the padded
  /// corner while the robot turns (Fig. 18 seed 20: a `to` bias through the wall, 24 contacts).
  double bias_clearance_m = 0.4;
  double slow_clearance_m = 0.4;  ///< Below this clearance the speed scales down (m), > 0.
  double goal_slowdown_m =
      0.5;  ///< Below this distance to the goal the speed scales down (m), > 0.
  /// A robot whose estimated position lies in the padding (localization error beside a door
  /// jamb) heads for the free cell closest to the goal within this distance (m), >= 0; 0: it
  /// stops. Keep it below the padding's width: no free cell beyond a wall is that near.
  double escape_radius_m = 0.4;
  /// Escaping, the speed as a share of SLOWLY's, (0, 1]. At 0.1 (1.5 cm/s for the Nomad 200)
  /// a robot whose estimate lay a few cm in a door's padding crawled through it for 50 s.
  double escape_speed_fraction = 0.5;
};

std::vector<std::string> ValidateSteeringParameters(const SteeringParameters& p);

struct SteeringCommand {
  bool valid = false;      ///< False where the field gives no direction (see `reason`).
  std::string reason;      ///< Why not valid; when valid, a note ("escaping the padding ...").
  bool escaping = false;   ///< Valid, but heading out of the padding (not descending).
  Vec2 descent{0.0, 0.0};  ///< Unit steepest-descent direction of u (map frame).
  double heading = 0.0;    ///< Commanded direction (rad, map frame), after the bias.
  double linear = 0.0;     ///< (m/s) >= 0.
  double angular = 0.0;    ///< (rad/s), counter-clockwise positive.
  double clearance = 0.0;  ///< Distance to the nearest padded obstacle cell (m).
};

/// The command that heads toward `heading` from `pose`: turn in place when facing away.
double WrapAngle(double a);

/// Heading closest to `bias` (rad) whose angle to `descent` is at most `max_deviation`; a bias
/// within `reverse_fade` of straight behind descent may turn it less, in proportion to its angle
/// from straight behind (none at straight behind: the heading is continuous as the bias's side
/// flips).
double BiasedHeading(const Vec2& descent, std::optional<double> bias, double max_deviation,
                     double reverse_fade = 0.0);

/// (e): steering at `pose` (map frame). `distance_to_goal_m` scales the speed down near the goal.
SteeringCommand ComputeSteering(const PotentialField& field, const spott_map::Pose2& pose,
                                SpeedMode mode, std::optional<double> direction_bias,
                                double distance_to_goal_m, const SteeringParameters& params);

/// At the goal position: turn in place toward `target_yaw` (rad, map) within the turn-rate
/// limit; `valid` and zero speeds once within `tolerance_rad`.
SteeringCommand TurnInPlace(double yaw, double target_yaw, double tolerance_rad,
                            const SteeringParameters& params, bool* done);

}  // namespace spott_harmonic_planner
