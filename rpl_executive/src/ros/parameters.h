// The node's parameters (config/rpl_executive.yaml has every one with its default), read through
// spott_ros::ParameterReader: unknown keys and bad values stop the node by name.
#pragma once

#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/executive.h"
#include "rpl_executive/noreils_chatila/on_board_modules.h"
#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/office_modules.h"

namespace spott_ros {
class ParameterReader;
}

namespace rpl_executive::ros_parameters {

struct TravelModeLimits {
  /// Speed limits of the travel modes through the arbiter's set_speed_limits (m/s, rad/s);
  /// 0 = the robot's own. [0, 10] each.
  double office_max_linear_mps = 0.3;
  double hallway_max_linear_mps = 0.0;
  double doorway_max_linear_mps = 0.2;
  double office_max_angular_rps = 0.0;
  double hallway_max_angular_rps = 0.0;
  double doorway_max_angular_rps = 0.0;
  /// "switch off the sonars when driving through doorways (to avoid crosstalk)" (section 3.1):
  /// the localization's enable_sonar service, false in a doorway, true again outside.
  bool doorway_sonars_off = true;
};

struct NodeParameters {
  // ---- both ----
  std::string map_frame = "map";
  std::string base_frame = "base_link";
  /// The arbiter's namespace (take_wheels, release_wheels, set_speed_limits, status).
  std::string arbiter = "cmd_vel_arbiter";
  /// The executive's source at the arbiter (its input is /cmd_vel/<source>).
  std::string wheels_source = "executive";
  /// ~state is published on every change and also at this rate (Hz): 0 (on change only) or
  /// [0.01, 100].
  double state_rate_hz = 1.0;
  /// Ended threads of control kept in the task tree feedback, [0, 1000].
  int ended_threads_kept = 30;
  /// Service calls (arbiter, localization) wait this long for the server (s), (0, 60].
  double service_timeout_s = 2.0;

  // ---- RPL ----
  rpl::ExecutiveParameters rpl;
  rpl::office::NavigationModuleParameters navigation;
  rpl::office::ActiveLocalizationParameters active_localization;
  TravelModeLimits travel;
  /// POSITION-TRACKING fails without a localization status for this long (s), (0, 600].
  double tracking_status_timeout_s = 3.0;
  std::string navigate_action = "harmonic_planner/navigate";
  std::string active_localize_action = "active_localize";
  std::string global_localization_service = "global_localization";
  /// markov_localization's sensor selection (std_srvs/SetBool): the doorway travel mode.
  std::string enable_sonar_service = "enable_sonar";
  /// velocity sources that ACTIVE-LOCALIZATION and NAVIGATION drive through (relayed to
  /// /cmd_vel/<wheels_source> while the plan holds WHEELS): the harmonic planner's descent and
  /// the localization's random motion.
  std::string planner_cmd_topic = "cmd_vel/planner";
  std::string wander_cmd_topic = "cmd_vel/wander";

  // ---- Noreils-Chatila ----
  noreils_chatila::ExecutiveParameters nc;
  noreils_chatila::SurveillanceParameters surveillance;
  noreils_chatila::OnBoardParameters on_board;
  /// The control cycle of HILARE's modules (Pilot, processes) and the executive (Hz), [1, 1000].
  double control_rate_hz = 20.0;
  /// Where the pose comes from: "odometry" (tf odom_frame -> base_frame, placed in the map by
  /// the localization's map -> odom when the mission starts: HILARE's Odometer module, section
  /// 6.1, so that a jump of the estimate cannot fake a zone entry or a line crossing) or
  /// "localization" (tf map_frame -> base_frame, live).
  std::string pose_source = "odometry";
  std::string odom_frame = "odom";
  /// A shipped O-surveillance file (missions/<name>.nc), "" = none.
  std::string o_surveillances = "o_surveillances";
  std::string sonar_topic = "sonar";
  std::string laser_topic = "scan";
  std::string battery_topic = "battery";
};

std::vector<std::string> ValidateParameters(const NodeParameters& p);

/// Fills `p` from the reader (keys as in config/rpl_executive.yaml).
void Read(spott_ros::ParameterReader& r, NodeParameters& p);

}  // namespace rpl_executive::ros_parameters
