// Surveillance conditions (the left-hand side of MNTR, sections 4.1 and 6.2) compiled to SI
// units, each attached to the sensor whose surveillance manager evaluates it.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rpl_executive/noreils_chatila/geometry.h"

namespace rpl_executive::noreils_chatila {

/// The sensor modules that own a Sensor Surveillance Manager (section 4.1.2).
enum class SensorKind { kSonar, kPose, kLaser, kBattery };
constexpr int kSensorKinds = 4;
/// US-SSM, POSE-SSM, LASER-SSM, BATTERY-SSM.
const char* SsmName(SensorKind sensor);

/// (S_zone IN|OUT <polygon>): the robot's position is inside (on the border counts) / outside.
struct ZoneCondition {
  bool inside = true;
  std::vector<Point2> polygon_m;
};

/// (S_us-threshold ((id cm)...)): some listed sonar has an echo nearer than its threshold.
struct UsThresholdCondition {
  std::vector<std::pair<int, double>> thresholds_m;  ///< (sensor id from 1, range)
};

/// (S_us-perception line (rho theta)): the sonar interpretation holds a line (a wall) at
/// distance rho from the robot's centre whose normal points at theta in the robot's frame,
/// within the interpretation's tolerances (sonar_interpretation.h).
struct UsPerceptionCondition {
  double rho_m = 0.0;
  double theta_rad = 0.0;
};

/// (S_straight-line (x y phi)): the robot's position crosses, in either direction, the
/// straight line through (x, y) with direction phi (map frame), between two pose data.
struct StraightLineCondition {
  Point2 origin_m;
  double direction_rad = 0.0;
};

/// (S_battery-level BELOW|ABOVE percent).
struct BatteryCondition {
  bool below = true;
  double level_percent = 0.0;
};

/// (S_laser-threshold cm): some laser return within the front half-plane is nearer.
struct LaserThresholdCondition {
  double distance_m = 0.0;
};

using AtomicCondition =
    std::variant<ZoneCondition, UsThresholdCondition, UsPerceptionCondition, StraightLineCondition,
                 BatteryCondition, LaserThresholdCondition>;

/// The sensor that evaluates an atomic condition.
SensorKind SensorOf(const AtomicCondition& atom);

/// A monitor's condition: a logical formula over atomic conditions.
struct CompiledCondition {
  enum class Op { kAtom, kAnd, kOr, kNot };
  Op op = Op::kAtom;
  AtomicCondition atom;
  std::vector<CompiledCondition> children;
  std::string text;  ///< as written in the mission
};

/// The sensors a formula needs (each once, in SensorKind order).
std::vector<SensorKind> SensorsOf(const CompiledCondition& condition);

}  // namespace rpl_executive::noreils_chatila
