// Sensor data the caller passes to the surveillance manager and the on-board modules. SI
// units; the caller stamps nothing: it passes `now` (s) with every call.
#pragma once

#include <vector>

#include "rpl_executive/noreils_chatila/geometry.h"

namespace rpl_executive::noreils_chatila {

/// One reading of the ultrasonic belt (HILARE: 16 sensors, section 6.1). ranges_m[i] is sensor
/// i + 1 (the paper numbers them from 1); a value that is not finite, or at or beyond the ring's
/// max_range_m, is "no echo".
struct SonarScan {
  std::vector<double> ranges_m;
};

/// Where one ultrasonic sensor sits on the robot (base_link: x forward, y left).
struct SonarMount {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;  ///< the sensor's axis
};

/// The geometry of the ultrasonic belt (from the robot's description).
struct SonarRing {
  std::vector<SonarMount> mounts;        ///< mounts[i] is sensor i + 1
  double half_field_of_view_rad = 0.26;  ///< half the beam's opening angle, (0, pi/2)
  double max_range_m = 4.0;              ///< (0, inf): a reading at or beyond it is no echo
  double min_range_m = 0.0;              ///< [0, max_range_m)

  /// A ring of `count` sensors on a circle of `radius_m`, sensor 1 facing forward and the
  /// others counter-clockwise at equal angles (HILARE's belt in robot_sim/urdf/hilare.urdf).
  static SonarRing Circular(int count, double radius_m, double half_field_of_view_rad,
                            double max_range_m);
  /// True when `range_m` is an echo of this ring.
  bool IsEcho(double range_m) const;
};

/// The robot's pose in the map frame (odometry or localization; section 3.1's Odometer module).
struct PoseDatum {
  Pose2 pose;
};

/// One planar sweep of the laser range finder (on its pan platform, section 6.1), in base_link.
struct LaserScan {
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double max_range_m = 10.0;
  std::vector<double> ranges_m;  ///< not finite or >= max_range_m: no return
};

/// The battery's charge (an O-surveillance's datum, section 4.1.1).
struct BatteryDatum {
  double level_percent = 100.0;  ///< [0, 100]
};

}  // namespace rpl_executive::noreils_chatila
