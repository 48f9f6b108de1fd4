// smooth-move's geometry (section 6.2.1: "a sequence of points (a broken line) along which the
// robot has to move, smoothing orientation changes by clothoid curves"; the Pilot module of
// section 3.1 provides "lines, clothoids").
//
// Each inner vertex of the broken line is replaced by a symmetric pair of clothoids (no arc in
// between): curvature grows linearly with arc length from 0 on the incoming segment to its
// peak at the bisector, then falls back to 0 on the outgoing segment, so the heading and the
// curvature are continuous along the path. For a turn of deflection D, each clothoid turns by
// D/2 over a length L: heading(s) = (D/2) (s/L)^2. Its end point is L (C(D/2), S(D/2)) with
// C(a) = int_0^1 cos(a u^2) du, S(a) = int_0^1 sin(a u^2) du, so the curve leaves the incoming
// segment at the distance d = L (C + S tan(D/2)) before the vertex and joins the outgoing one at
// d after it. d is the largest of corner_distance_max_m and half of each adjacent segment (so
// that two corners never overlap); the peak curvature is 2 (D/2) / L = D / L. Vertices with a
// deflection over max_deflection_rad are not smoothed: the robot stops there and turns.
#pragma once

#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/geometry.h"

namespace rpl_executive::noreils_chatila {

struct PathSmoothingParameters {
  double corner_distance_max_m = 0.5;  ///< d at most, (0, inf)
  double sample_step_m = 0.02;         ///< spacing of the samples, [0.001, 1]
  double max_deflection_rad = 2.8;     ///< sharper turns are made in place, (0, pi)
};
std::vector<std::string> ValidateParameters(const PathSmoothingParameters& p);

struct PathSample {
  double x = 0.0, y = 0.0;     ///< m
  double yaw = 0.0;            ///< heading of the path, rad
  double curvature = 0.0;      ///< 1/m, positive turning left
  double s = 0.0;              ///< arc length from the start, m
  bool turn_in_place = false;  ///< a vertex not smoothed: stop and turn to the next heading
};

struct SmoothedPath {
  std::vector<PathSample> samples;
  double length_m = 0.0;
  double max_curvature = 0.0;  ///< 1/m
};

/// C(a) and S(a) of the header comment (Simpson's rule, 256 intervals: error below 1e-10
/// for |a| <= pi/2).
void NormalizedFresnel(double a, double* c, double* s);

/// The clothoid pair at one corner: the distance d from the vertex where it starts and ends and
/// the length L of each clothoid, for a deflection `deflection_rad` (|D| < pi) and a wanted d.
struct ClothoidCorner {
  double distance_m = 0.0;
  double clothoid_length_m = 0.0;
  double peak_curvature = 0.0;  ///< 1/m (signed like the deflection)
};
ClothoidCorner CornerForDistance(double deflection_rad, double distance_m);

/// Smooths the broken line `vertices` (the first is where the robot is). Repeated vertices are
/// dropped; fewer than two distinct vertices give a path of one sample (nothing to drive).
SmoothedPath SmoothBrokenLine(const std::vector<Point2>& vertices,
                              const PathSmoothingParameters& parameters);

}  // namespace rpl_executive::noreils_chatila
