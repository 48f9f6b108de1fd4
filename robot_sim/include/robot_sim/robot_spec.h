// A simulated robot: its body and sensor mounts from its URDF (urdfdom), its drive limits and
// sensor characteristics from a YAML robot file (config/robots/<name>.yaml). Metres, radians,
// seconds (REP-103); mounts are in base_link (REP-105).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_map/source_location.h"

namespace robot_sim {

/// A sensor's pose in base_link: position (m) and axis heading about +z (rad).
struct Mount {
  std::string frame_id;  ///< The sensor's link in the URDF ("sonar_3").
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  double yaw = 0.0;
};

enum class DriveKind {
  kSynchro,       ///< Nomad 200, B21, B-12: all wheels steer together; a unicycle base.
  kDifferential,  ///< HILARE: two independent driving wheels and a free wheel.
};

struct DriveSpec {
  DriveKind kind = DriveKind::kSynchro;
  double max_linear_mps = 0.5;     ///< (m/s) > 0
  double max_angular_rps = 1.0;    ///< (rad/s) > 0
  double max_linear_accel = 0.5;   ///< (m/s^2) > 0
  double max_angular_accel = 2.0;  ///< (rad/s^2) > 0
  double wheel_separation_m = 0;   ///< differential only: distance between the wheels (m) > 0
  double max_turret_rps = 0;       ///< turret slew rate (rad/s); 0 = no turret
};

enum class RangeKind { kUltrasound, kInfrared };

/// A ring of range transducers (sonar or infrared), one per URDF link `<link_prefix><n>`,
/// n = 1, 2, ... (numbered as the papers number them: HILARE's sensors 1 to 16).
struct RangeRingSpec {
  std::string name;  ///< Topic and fault name: "sonar", "infrared".
  RangeKind kind = RangeKind::kUltrasound;
  std::string link_prefix;
  double field_of_view = 0.52;  ///< Full cone angle (rad), (0, pi).
  double min_range = 0.15;      ///< (m) >= 0
  double max_range = 6.5;       ///< (m) > min_range
  /// Rays sampling the cone across, >= 1. A real cone is continuous: at 5 degrees apart (7 rays
  /// over 30) a door jamb's 15 cm face 2 m away fell between rays, and the localization, whose
  /// model samples the cone every 2 degrees, was pulled 0.5-0.7 m along cim_office's hallway at
  /// an open door; 15 rays (2.1 degrees) close the gaps the maps' features can hide in.
  int rays = 15;
  /// Rows of rays across the cone's height, >= 1: 1 is a flat fan at the mount's height (blind
  /// to a solid below or above it); more sample a circular cone (each row as wide as the cone
  /// at its elevation), so a Polaroid sonar hears a crate lower than its ring, as a real one.
  int vertical_rays = 1;
  /// Incidence angle (rad) beyond which a surface reflects the pulse away (specular): the ray
  /// returns no echo, or a long multipath one. pi/2 disables specular reflection (infrared).
  double critical_angle = 0.35;
  double noise_stddev = 0.01;      ///< Gaussian range noise (m) >= 0 ...
  double noise_per_metre = 0.005;  ///< ... plus this much per metre of range (m/m) >= 0.
  /// Transducers fired together: i and j fire in the same cycle when i % fire_groups ==
  /// j % fire_groups. fire_groups == ring size means one at a time (no crosstalk).
  int fire_groups = 4;
  std::vector<Mount> mounts;  ///< From the URDF, in ring order.
};

/// A planar scanning laser (SICK on the B21, HILARE's laser on its pan platform).
struct LaserSpec {
  std::string name = "laser";
  std::string link;
  double angle_min = -1.5708;  ///< (rad)
  double angle_max = 1.5708;   ///< (rad) > angle_min
  int beams = 181;             ///< >= 2
  double min_range = 0.05;     ///< (m)
  double max_range = 25.0;     ///< (m) > min_range
  double noise_stddev = 0.01;  ///< (m)
  Mount mount;                 ///< From the URDF.
};

/// A pan-tilt range sensor (the Nomad 200's BIRIS heads, QUADRIS: Zelek and Levine, section V):
/// a line of `samples` range samples across `field_of_view`, in the head's horizontal plane
/// (horizontal profile) or its vertical plane (vertical profile). Pan turns the head about +z,
/// tilt about its +y (positive tilt looks down, REP-103).
struct ProfilerSpec {
  std::string name;       ///< Topic frame and fault name: "quadris_1".
  std::string link;       ///< The sensor link (below its pan and tilt joints).
  std::string pan_joint;  ///< URDF joint names, published on joint_states.
  std::string tilt_joint;
  int samples = 64;             ///< >= 2
  double field_of_view = 0.7;   ///< (rad), (0, pi)
  double min_range = 0.1;       ///< (m)
  double max_range = 4.0;       ///< (m) > min_range
  double noise_stddev = 0.005;  ///< (m)
  Mount mount;                  ///< From the URDF, at zero pan and tilt.
};

/// Tactile bumper ring: `segments` equal arcs, segment 0 centred on +x, counter-clockwise.
struct BumperSpec {
  int segments = 20;
  double travel_m = 0.01;  ///< Contact closer than this to the shell presses a segment (m) > 0.
};

struct RobotSpec {
  std::string name;
  std::string base_frame = "base_link";
  double radius_m = 0.0;  ///< Body cylinder, from the URDF's base_link collision (m).
  double height_m = 0.0;  ///< (m)
  DriveSpec drive;
  std::vector<RangeRingSpec> rings;
  std::optional<LaserSpec> laser;
  std::optional<BumperSpec> bumper;
  std::vector<ProfilerSpec> profilers;
  /// Every non-fixed joint of the URDF (published on joint_states for robot_state_publisher).
  std::vector<std::string> movable_joints;
  /// The joint that turns the sensor turret ("turret_joint"), "" when the robot has none.
  std::string turret_joint;

  const RangeRingSpec* FindRing(const std::string& name) const;
};

struct RobotSpecResult {
  std::optional<RobotSpec> spec;
  std::vector<spott_map::SourceError> errors;
  bool ok() const { return spec.has_value(); }
};

/// Reads a robot file (YAML) and the URDF it goes with; body size and every mount come from the
/// URDF. Errors name the file, line and column (YAML) or the URDF link.
RobotSpecResult LoadRobotSpec(const std::string& robot_yaml_path, const std::string& urdf_path);

/// As LoadRobotSpec, from text (for tests and the fuzzer).
RobotSpecResult LoadRobotSpecFromStrings(const std::string& robot_yaml,
                                         const std::string& yaml_name, const std::string& urdf_xml,
                                         const std::string& urdf_name);

}  // namespace robot_sim
