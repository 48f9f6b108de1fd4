// Plane geometry of task interpretation (internal to spott_tr_plus): vectors, a target's axes
// and the support function of its footprint.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus {
namespace internal {

struct Vec {
  double x = 0, y = 0;
};
inline Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
inline Vec operator*(double s, Vec a) { return {s * a.x, s * a.y}; }
inline double Dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y; }
inline double Norm(Vec a) { return std::hypot(a.x, a.y); }
inline Vec Unit(Vec a, Vec fallback) {
  const double n = Norm(a);
  return n > 1e-12 ? (1.0 / n) * a : fallback;
}

/// The target's axes: along its long axis, and across it.
inline Vec Axis(const TargetGeometry& g) { return {std::cos(g.theta), std::sin(g.theta)}; }
inline Vec Across(const TargetGeometry& g) { return {-std::sin(g.theta), std::cos(g.theta)}; }

/// Half-extent of the footprint's box in direction v (the box's support function).
inline double Support(const TargetGeometry& g, Vec v) {
  return g.half_length * std::fabs(Dot(v, Axis(g))) + g.half_width * std::fabs(Dot(v, Across(g)));
}

bool InsidePolygon(const std::vector<std::pair<double, double>>& poly, double x, double y);

/// Signed distance from (x, y) to the footprint (its polygon when it has one): < 0 inside.
double FootprintDistance(const TargetGeometry& g, double x, double y);

/// A number with 3 significant digits, for messages.
std::string Number(double v);

}  // namespace internal
}  // namespace spott_tr_plus
