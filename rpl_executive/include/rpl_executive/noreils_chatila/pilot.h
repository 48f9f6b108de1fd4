// The Pilot module (section 3.1, [17]): the only effector module of HILARE. It follows a
// smoothed path (path_smoothing.h) with the tracking law of Kanayama, Kimura, Miyazaki and
// Noguchi ("A stable tracking control method for an autonomous mobile robot", 1990):
//     v = v_r cos(e_theta) + k_x e_x
//     w = w_r + v_r (k_y e_y + k_theta sin(e_theta))
// where (e_x, e_y, e_theta) is the reference posture in the robot's frame. The reference is the
// path sample lookahead_m beyond the nearest one (progress along the path never goes back), and
// e_x counts from that offset,
// v_r the set speed (slowed down near the end) and w_r = curvature * v_r. The pilot turns in
// place when the reference's heading is more than turn_in_place_rad away, and at the end to the
// path's final heading when it has one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/geometry.h"
#include "rpl_executive/noreils_chatila/path_smoothing.h"

namespace rpl_executive::noreils_chatila {

struct VelocityCommand {
  double linear_mps = 0.0;
  double angular_rps = 0.0;
};

struct PilotParameters {
  double default_speed_mps = 0.3;       ///< until set-speed, (0, max_speed_mps]
  double max_speed_mps = 0.4;           ///< set-speed is clamped to it, (0, inf)
  double max_angular_rps = 1.0;         ///< (0, inf)
  double lookahead_m = 0.25;            ///< [0, inf)
  double k_x = 1.0;                     ///< 1/s, (0, inf)
  double k_y = 6.0;                     ///< 1/m^2, (0, inf)
  double k_theta = 3.0;                 ///< 1/m, (0, inf)
  double goal_tolerance_m = 0.05;       ///< (0, inf)
  double heading_tolerance_rad = 0.05;  ///< (0, pi)
  double turn_in_place_rad = 0.8;       ///< (0, pi]
  double k_turn = 1.5;                  ///< in-place turns: rad/s per rad of error, (0, inf)
  double slow_down_distance_m = 0.4;    ///< speed falls linearly to 20 % over it, [0, inf)
  PathSmoothingParameters smoothing;
};
std::vector<std::string> ValidateParameters(const PilotParameters& p);

class Pilot {
 public:
  enum class State { kIdle, kTracking, kFinalTurn, kDone };

  explicit Pilot(const PilotParameters& parameters);

  /// Starts along `vertices` from `pose` (the robot's position becomes the first vertex).
  void Start(const Pose2& pose, const std::vector<Point2>& vertices,
             std::optional<double> final_yaw_rad);
  /// Goes on along what is left of the last path from `pose` (resume-order). False when there
  /// is no path to resume.
  bool Resume(const Pose2& pose);
  /// The vertices Resume would drive along (empty without a path).
  std::vector<Point2> RemainingVertices() const;
  void SetSpeed(double speed_mps);
  /// Back to default_speed_mps (a new mission).
  void ResetSpeed() { speed_mps_ = parameters_.default_speed_mps; }
  /// Stops where it is; the path is kept for Resume.
  void Stop();

  /// One control cycle at `pose`: the wheels' command (zero when idle or done).
  VelocityCommand Update(const Pose2& pose);

  State state() const { return state_; }
  double speed_mps() const { return speed_mps_; }
  const SmoothedPath& path() const { return path_; }

 private:
  VelocityCommand Track(const Pose2& pose);
  size_t NextVertexIndex() const;

  PilotParameters parameters_;
  State state_ = State::kIdle;
  double speed_mps_;
  std::vector<Point2> vertices_;  // the order's vertices (without the start)
  std::optional<double> final_yaw_;
  std::vector<double> vertex_s_;  // arc length where the path passes each vertex (approx.)
  SmoothedPath path_;
  size_t progress_ = 0;
  size_t first_vertex_ = 0;  // vertices_[first_vertex_..] are what path_ drives to
};

}  // namespace rpl_executive::noreils_chatila
