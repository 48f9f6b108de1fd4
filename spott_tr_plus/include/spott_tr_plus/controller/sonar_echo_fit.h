// Where a sonar echo came from, for MAP_OBJECTS_WITH_SONAR's fusion (Fig. 5; SPOTT section V on
// the sonar's "larger-than-life" doorways). A Polaroid transducer reports the nearest reflector
// in its cone that sends the pulse back: a wall returns the point of it nearest the transducer
// within the cone (the foot of the perpendicular when the wall's normal lies in the cone, else
// where the cone's edge meets it, if that edge meets it within the critical incidence); a
// concave corner or an edge returns itself. So one wall's echoes are circles tangent to one line
// and one corner's are circles through one point: Leonard and Durrant-Whyte's planes and corners
// (regions of constant depth). Placed on their axes instead, a corner's echoes draw an arc (a
// "wall" 10 degrees off cim_office's hallway end) and a wall's run on past its end by up to
// range * tan(half cone), into a doorway.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "spott_map/geometry.h"
#include "spott_map/sonar_echo.h"

namespace spott_tr_plus::controller {

using spott_map::Vec2;

// The echo model is spott_map's (sonar_echo.h), shared with the sensed-map localization.
using spott_map::PredictEcho;
using spott_map::PredictedEcho;
using spott_map::SonarEcho;

struct EchoFitParameters {
  /// An echo fits a hypothesis when its range lies within base_m + per_m * range of the
  /// predicted one (the sensor's noise: the Nomad's is 0.01 m + 0.01 m per metre, 1 sigma).
  double tolerance_base_m = 0.03;
  double tolerance_per_m = 0.02;
  /// Beyond this incidence on a wall the pulse reflects away: no echo (rad; robot_sim's
  /// critical_angle for the Polaroid ring).
  double max_incidence_rad = 0.35;
  /// A wall whose direction the echoes fix no better than this is kept as points where they
  /// reflected, not as a segment (rad; a wall seen head on, or over a few centimetres).
  double max_direction_error_rad = 0.05;
};

/// A wall that explains echoes: `inliers` index the echoes it explains, `reflections` (one per
/// inlier) are where they reflected on it.
struct EchoLine {
  Vec2 normal{0.0, 1.0};
  double offset = 0.0;
  std::vector<std::size_t> inliers;
  std::vector<Vec2> reflections;
  /// How far (rad) the direction may be off: the farthest direction whose cost is within two
  /// sigma of the best (the search's width when nothing fits).
  double direction_error_rad = 0.0;
};
/// The line that explains the echoes best (least truncated squared range residuals): a Hough
/// search over its normal's direction within `search` rad of `normal_guess`, the offset voted
/// by the echoes at each direction.
EchoLine FitEchoLine(const std::vector<SonarEcho>& echoes, double normal_guess, double search,
                     const EchoFitParameters& p);

/// The echo's range less the distance to a corner (or edge) at `at`, when `at` lies in its cone
/// (0.05 rad of slack for the cone's rim); nullopt when the transducer cannot hear it there.
std::optional<double> CornerResidual(const SonarEcho& e, const Vec2& at);

/// A corner (or edge) that explains echoes: each inlier's range is its distance to `at`, and
/// `at` lies in its cone.
struct EchoPoint {
  Vec2 at{0.0, 0.0};
  std::vector<std::size_t> inliers;
};
/// Gauss-Newton from `guess` on the echoes within a shrinking tolerance.
EchoPoint FitEchoPoint(const std::vector<SonarEcho>& echoes, const Vec2& guess,
                       const EchoFitParameters& p);

/// An echo's cost under a hypothesis: its squared range residual in units of its noise (the
/// tolerance is two sigma), truncated at 4 (MSAC: an echo the hypothesis does not explain costs
/// as one two sigma off).
double EchoCost(double residual, double tolerance);

/// The echo's tolerance (m).
inline double EchoTolerance(const SonarEcho& e, const EchoFitParameters& p) {
  return p.tolerance_base_m + p.tolerance_per_m * e.range;
}

}  // namespace spott_tr_plus::controller
