// The elementary task avoid-obstacle (section 6.2.2: "the elementary-task avoid-obstacle, which
// includes the avoidance process"), followed in the mission by (resume-order). The process's law
// (processes.h: slow down with the nearest front echo, turn towards the freer side) moves the
// robot off the obstacle; the task ends when, facing it, the way resume-order will drive (the
// robot's position, then the interrupted order's vertices not passed yet) is clear over its first
// way_check_distance_m: no echo remembered during the task within robot_radius_m +
// way_clearance_m of it, and no front echo nearer than its end. Ending as soon as
// the front sensors see nothing (the process's "nothing to avoid") turned the robot away and
// handed it back to the pilot, which drove it at the same obstacle again (a cylinder after
// ZONE109: touched after five such rounds).
//
// Echoes are remembered in the map frame because the obstacle leaves the front sensors as the
// robot turns; a beam that reads past a remembered echo in its cone on five data in a row
// forgets it (the
// obstacle moved, or the echo was the beam's edge). While the front is clear the robot steers to
// the heading nearest the vertex whose next metre passes every remembered echo, so it follows
// the obstacle's contour even where the sonar's echo from it flickers (specular facets). The side
// chosen at the first obstacle is kept. Without an order to return to, the task ends as the process
// does: insufficient_data_limit data in a row without a front echo.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/geometry.h"
#include "rpl_executive/noreils_chatila/pilot.h"
#include "rpl_executive/noreils_chatila/processes.h"
#include "rpl_executive/noreils_chatila/sensor_data.h"

namespace rpl_executive::noreils_chatila {

class AvoidObstacleTask {
 public:
  enum class Status { kRunning, kCompleted, kFailed };
  struct Step {
    VelocityCommand command;
    Status status = Status::kRunning;
    std::string message;  ///< why it ended
  };

  AvoidObstacleTask(const ObstacleAvoidanceParameters& parameters, const SonarRing& ring);

  /// Starts afresh; `way` is what resume-order will drive along: the interrupted order's
  /// vertices not passed yet (empty: no order to return to).
  void Start(std::vector<Point2> way);
  /// One sonar datum taken at `pose` (map frame); `speed_cap_mps` is the pilot's set speed.
  Step Update(const Pose2& pose, const SonarScan& scan, double speed_cap_mps);

  static constexpr int kArcPoints = 5;
  struct Remembered {
    Point2 at;                           ///< on the beam's axis
    std::array<Point2, kArcPoints> arc;  ///< across the beam, where it may have come from
    int read_past = 0;                   ///< data in a row whose beams read past it
  };
  const std::vector<Remembered>& remembered() const { return echoes_; }

 private:
  // The way from the robot along `way_` over way_check_distance_m.
  struct Window {
    std::vector<Point2> points;
    double length_m = 0.0;
    bool ends_at_last_vertex = false;
  };
  void Remember(const Pose2& pose, const SonarScan& scan);
  Window WayWindow(const Point2& from) const;
  bool WayIsClear(const Window& window) const;

  ObstacleAvoidanceParameters parameters_;
  SonarRing ring_;
  std::vector<Point2> way_;
  std::vector<Remembered> echoes_;
  std::optional<Pose2> last_pose_;
  double travelled_m_ = 0.0;
  double turned_rad_ = 0.0;
  double side_ = 0.0;  // +1 left, -1 right once chosen
  int without_obstacle_ = 0;
};

}  // namespace rpl_executive::noreils_chatila
