// The one owner of the robot's wheels (ROS-free core of the cmd_vel_arbiter node). Every
// velocity source (the local planner, reflexes, tele-operation, the localization's random
// motion, an executive) sends on its own input; the arbiter decides who drives:
//   - the source of highest priority that is sending (sent within its timeout) drives, as in
//     twist_mux; when it falls silent the next one takes over, and with none the robot stops;
//   - a source may take the wheels exclusively (the WHEELS valve of Beetz et al. 3.2, a reflex
//     of SPOTT Figs. 7-8): then only it and sources of higher priority drive. Takes stack: a
//     higher-priority take pre-empts the holder, which gets the wheels back on the release;
//   - sources that send (or hold) but do not drive are PREEMPTED: they read it in the status
//     and wait or give up;
//   - a command that is not finite or beyond the robot's limits is refused and counted, and
//     counts as a stop of its source (a NaN from the driver stops the robot);
//   - run-time speed limits (RPL travel modes) scale commands down, keeping their curvature;
//   - a pressed bumper segment stops the part of the motion that pushes towards it, whoever
//     drives (for a round robot the contact point moves inwards at v cos(phi); turning moves it
//     tangentially and stays allowed), so a source can always back off.
// The caller owns time: every call takes `now_s` (simulated or wall seconds, monotonic).
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cmd_vel_arbiter {

struct Velocity {
  double linear_mps = 0.0;   ///< Along the robot's x axis (m/s).
  double angular_rps = 0.0;  ///< About +z (rad/s).
};
bool operator==(const Velocity& a, const Velocity& b);

struct SourceParameters {
  std::string name;        ///< Input /cmd_vel/<name>; [a-z0-9_]+.
  int priority = 0;        ///< Higher wins; unique among the sources.
  double timeout_s = 0.5;  ///< Silent this long (s) = not sending; (0, 60].
};

struct ArbiterParameters {
  std::vector<SourceParameters> sources;  ///< At least one.
  double max_linear_mps = 0.5;            ///< The robot's limit: faster commands are refused, > 0.
  double max_angular_rps = 1.0;           ///< (rad/s), > 0.
  /// Sources the clearance bounds do not cap (a reflex backing off a contact); names that are
  /// not sources change nothing.
  std::vector<std::string> clearance_exempt{"reflex"};
};

/// Every violation, named as in config/cmd_vel_arbiter.yaml.
std::vector<std::string> ValidateParameters(const ArbiterParameters& p);

enum class SourceState { kIdle, kDriving, kPreempted, kTimedOut };
const char* ToString(SourceState s);

struct SourceStatus {
  std::string name;
  int priority = 0;
  SourceState state = SourceState::kIdle;
  bool exclusive = false;
  std::uint32_t commands = 0;
  std::uint32_t refused = 0;
};

/// What the caller publishes on /cmd_vel after a call: `publish` false = nothing to send.
struct Output {
  bool publish = false;
  Velocity command;
};

class Arbiter {
 public:
  /// Throws std::invalid_argument listing every violation.
  explicit Arbiter(const ArbiterParameters& params);

  /// A command from `source` at `now_s`. Refused (returns the stop of that source, `*refused`
  /// says why) when not finite, beyond the robot's limits or from an unknown source. The driver's
  /// commands pass straight through (after limits and the bumper).
  Output Command(const std::string& source, const Velocity& v, double now_s, std::string* refused);
  /// Timeouts: call at a steady rate. Publishes a stop when the driver falls silent.
  Output Update(double now_s);
  /// The bumper segments pressed now, as angles about +z from the robot's +x (rad).
  Output SetContacts(const std::vector<double>& pressed_angles_rad, double now_s);

  /// Linear speed bounds from the range sensors (m/s, magnitudes; infinite = none).
  Output SetClearance(double forward_mps, double backward_mps, double now_s);
  /// Exclusive take (see the header comment). False with `*message` when refused.
  bool Take(const std::string& source, double now_s, std::string* message, std::string* preempted,
            Output* out);
  bool Release(const std::string& source, double now_s, std::string* message, Output* out);
  /// Run-time limits; 0 = the robot's own. False (nothing changed) beyond the robot's limits.
  bool SetSpeedLimits(double max_linear_mps, double max_angular_rps, const std::string& reason,
                      std::string* message, double now_s, Output* out);

  const std::string& driver() const { return driver_; }
  std::string exclusive_holder() const { return holders_.empty() ? "" : holders_.back(); }
  std::vector<SourceStatus> Sources() const;
  double max_linear_mps() const { return limit_linear_; }
  double max_angular_rps() const { return limit_angular_; }
  const std::string& limits_reason() const { return limits_reason_; }
  bool bumper_stop() const { return bumper_stop_; }
  /// Commands the clearance bounds slowed (counted at each published command).
  std::uint32_t clearance_slowdowns() const { return clearance_slowdowns_; }
  std::uint32_t bumper_stops() const { return bumper_stops_; }
  std::uint32_t refused() const { return refused_total_; }
  /// Changes whenever the status (driver, states, holder, limits, bumper) changes.
  std::uint64_t revision() const { return revision_; }

 private:
  struct Source {
    SourceParameters params;
    std::optional<double> last_time;  ///< Of the last command (accepted or refused).
    Velocity last;
    bool drove = false;  ///< Drove since it last started sending.
    SourceState state = SourceState::kIdle;
    std::uint32_t commands = 0, refused = 0;
  };

  bool Sending(const Source& s, double now_s) const;
  int PriorityOf(const std::string& name) const;
  /// Chooses the driver and source states; returns what to publish. `force` publishes even
  /// when nothing changed (a driver's own command).
  Output Select(double now_s, bool force);
  Velocity Filter(Velocity v, const std::string& driver);

  ArbiterParameters params_;
  std::map<std::string, Source> sources_;
  std::vector<std::string> holders_;  ///< Exclusive takes, the current holder last.
  std::string driver_;
  std::optional<Velocity> published_;
  double limit_linear_, limit_angular_;
  std::string limits_reason_;
  std::vector<double> contacts_;
  bool bumper_stop_ = false;
  std::uint32_t bumper_stops_ = 0;
  double clear_forward_ = std::numeric_limits<double>::infinity();
  double clear_backward_ = std::numeric_limits<double>::infinity();
  bool clearance_slowed_ = false;  ///< The last filtered command was slowed by them.
  std::uint32_t clearance_slowdowns_ = 0;
  std::uint32_t refused_total_ = 0;
  std::uint64_t revision_ = 0;
};

}  // namespace cmd_vel_arbiter
