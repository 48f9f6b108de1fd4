// Shared pieces of the core tests: maps, a simulated sonar ring and a simulated drive.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "markov_localization/certainty.h"
#include "markov_localization/map_model.h"
#include "markov_localization/markov_grid.h"
#include "markov_localization/sensor_model.h"
#include "spott_map/world_loader.h"

namespace markov_localization {
namespace testing {

inline spott_map::World LoadWorld(const std::string& name) {
  auto result = spott_map::LoadWorldFile(std::string(WORLDS_DIR) + "/" + name + ".yaml");
  if (!result.ok()) throw std::runtime_error("cannot load world " + name);
  return *result.world;
}

/// Readings of a ring at `pose` by ray casting in `map` plus Gaussian noise.
inline std::vector<double> SimulateScan(const MapModel& map, const SensorModelParameters& sp,
                                        const Pose2& pose, double noise_m, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, noise_m);
  std::vector<double> ranges;
  for (double a : sp.beam_angles_rad) {
    const double angle = pose.yaw + a;
    const Vec2 from = pose.Position() + sp.sensor_offset_m * Vec2(std::cos(angle), std::sin(angle));
    double r = map.RayCast(from, angle, sp.max_range_m);
    if (r < sp.max_range_m && noise_m > 0) r = std::max(0.0, r + noise(rng));
    ranges.push_back(r);
  }
  return ranges;
}

/// Drives the true pose through `waypoints` in steps of at most `step_m` (turning on the spot
/// first), feeding exact odometry and a simulated scan after every step. Returns the final pose.
inline Pose2 Drive(MarkovGrid& grid, const SensorModelParameters& sp, Pose2 pose,
                   const std::vector<Vec2>& waypoints, double step_m, std::mt19937& rng) {
  for (const Vec2& w : waypoints) {
    const Vec2 d = w - pose.Position();
    const double dist = d.norm();
    if (dist < 1e-9) continue;
    const double yaw = std::atan2(d.y(), d.x());
    Pose2 turned = pose;
    turned.yaw = yaw;
    grid.MotionUpdate(MotionBetween(pose, turned));
    pose = turned;
    const int steps = static_cast<int>(std::ceil(dist / step_m));
    for (int i = 1; i <= steps; ++i) {
      const Pose2 next{pose.x + d.x() / steps, pose.y + d.y() / steps, yaw};
      grid.MotionUpdate(MotionBetween(pose, next));
      pose = next;
      grid.SensorUpdate(SimulateScan(grid.map(), sp, pose, 0.05, rng));
    }
  }
  return pose;
}

inline double AngleError(double a, double b) { return std::abs(spott_map::NormalizeAngle(a - b)); }

}  // namespace testing
}  // namespace markov_localization
