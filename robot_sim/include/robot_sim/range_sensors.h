// Range sensor physics against the SimWorld.
//
// Sonar (Polaroid transducers): the cone is sampled by `rays` rays across the field of view;
// a ray that meets a surface within the critical incidence angle returns an echo (the surface
// scatters enough energy back); beyond it the pulse reflects specularly and either is lost
// (no echo: max range) or returns from a second surface as a long multipath reading (range =
// the out-and-back path / 2). The transducer reports the first echo it hears. Transducers fired
// together (same fire group) hear each other's echoes: crosstalk, the reason RHINO switches
// its sonars off in doorways. Readings are clamped to [min_range, max_range] with Gaussian noise
// of stddev noise_stddev + noise_per_metre * range. Infrared uses the same model with
// critical_angle = pi/2 (diffuse) and a narrow cone.
#pragma once

#include <limits>
#include <vector>

#include "robot_sim/drive.h"
#include "robot_sim/robot_spec.h"
#include "robot_sim/sim_world.h"

namespace robot_sim {

/// A transducer in the map frame.
struct TransducerPose {
  Eigen::Vector3d origin;  ///< (m)
  double yaw = 0.0;        ///< Axis heading (rad).
};

/// A mount carried by a base at `robot` (map frame) with the turret turned by `turret_yaw`.
TransducerPose PlaceMount(const Mount& mount, const spott_map::Pose2& robot, double turret_yaw);

/// Noise-free echo range of one transducer firing alone (m), or max_range for no echo; the
/// diffuse points its rays reached are appended to `scatter` (for crosstalk) if not null.
struct ScatterPoint {
  Eigen::Vector3d point;  ///< Where the pulse scattered back (map frame, m).
  double path_m = 0.0;    ///< Length of the path from the emitter to `point` (m).
};
double EchoRange(const SimWorld& world, const RangeRingSpec& ring, const TransducerPose& t,
                 const btCollisionObject* self, std::vector<ScatterPoint>* scatter);

/// A whole ring fired in ring.fire_groups cycles, with crosstalk inside each cycle and noise.
/// `poses` holds one pose per mount. Returns one range per transducer (m).
std::vector<double> SenseRangeRing(const SimWorld& world, const RangeRingSpec& ring,
                                   const std::vector<TransducerPose>& poses,
                                   const btCollisionObject* self, Rng& rng);

/// A planar laser scan: one ray per beam, Gaussian noise; +infinity for no return (REP-117).
std::vector<double> SenseLaser(const SimWorld& world, const LaserSpec& laser,
                               const TransducerPose& pose, const btCollisionObject* self, Rng& rng);

/// One profile of a pan-tilt head (QUADRIS). `horizontal`: samples across the head's horizontal
/// plane at angles a (about the head's z); otherwise across its vertical plane (a added to the
/// tilt, positive down). The floor (z = 0) is seen too. Returns one range per sample (m;
/// max_range for no return); `angles` receives the sample angles (rad).
std::vector<double> SenseProfile(const SimWorld& world, const ProfilerSpec& profiler,
                                 const TransducerPose& head, double tilt, bool horizontal,
                                 const btCollisionObject* self, Rng& rng,
                                 std::vector<double>* angles);

/// Which bumper segments are pressed, given contact directions in base_link (rad).
std::vector<bool> BumperSegments(const BumperSpec& bumper, const std::vector<double>& angles);

}  // namespace robot_sim
