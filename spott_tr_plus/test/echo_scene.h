// A sonar transducer's reading in a 2-D scene of walls and corners, modelled independently of
// the fusion under test (sonar_echo_fit.h) as robot_sim models it: rays across the cone, a wall
// echoes a ray that meets it within the critical incidence, a concave corner (or an edge) in the
// cone echoes from itself; the nearest echo wins, with the Nomad's noise. For the tests and the
// sonar fusion benchmark.
#pragma once

#include <cmath>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "spott_map/geometry.h"

namespace test_scene {

using spott_map::Vec2;

constexpr double kHalfCone = 0.26;       // the Nomad's Polaroid: 0.52 rad
constexpr double kCriticalAngle = 0.35;  // robot_sim's nomad200.yaml

struct Scene {
  std::vector<std::pair<Vec2, Vec2>> walls;
  std::vector<Vec2> corners;
  double max_range = 3.0;

  std::optional<double> Read(const Vec2& from, double axis, std::mt19937& rng) const {
    double best = 1e9;
    for (int k = 0; k <= 12; ++k) {
      const double a = axis - kHalfCone + 2 * kHalfCone * k / 12;
      const Vec2 d(std::cos(a), std::sin(a));
      for (const auto& [p, q] : walls) {
        const Vec2 w = q - p;
        const double den = d.x() * w.y() - d.y() * w.x();
        if (std::abs(den) < 1e-12) continue;
        const Vec2 f = p - from;
        const double t = (f.x() * w.y() - f.y() * w.x()) / den;  // along the ray
        const double s = (f.x() * d.y() - f.y() * d.x()) / den;  // along the wall
        if (t <= 0 || s < 0 || s > 1) continue;
        const Vec2 normal = Vec2(-w.y(), w.x()).normalized();
        if (std::acos(std::abs(normal.dot(d))) > kCriticalAngle) continue;  // glances off
        best = std::min(best, t);
      }
    }
    for (const Vec2& c : corners) {
      const Vec2 d = c - from;
      if (std::abs(std::remainder(std::atan2(d.y(), d.x()) - axis, 2 * M_PI)) <= kHalfCone)
        best = std::min(best, d.norm());
    }
    if (best > max_range) return std::nullopt;
    std::normal_distribution<double> noise(0.0, 0.01 + 0.01 * best);
    return best + noise(rng);
  }
};

}  // namespace test_scene
