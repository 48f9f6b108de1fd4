// What a sonar transducer hears from a wall (Leonard and Durrant-Whyte, "Directed Sonar Sensing
// for Mobile Robot Navigation", 1992; SPOTT's reference [30]): a Polaroid transducer reports the
// nearest reflector in its cone that sends the pulse back. A wall returns the point of it nearest
// the transducer within the cone: the foot of the perpendicular when the wall's normal lies in
// the cone, else where the cone's edge meets it, if it meets it within the critical incidence.
// The one echo model of the stack: the controller's sonar mapping fits walls with it
// (spott_tr_plus controller/sonar_echo_fit.h) and the sensed-map localization matches echoes to
// the mapped walls with it (markov_localization sensed_map_tracker.h).
#pragma once

#include <optional>

#include "spott_map/geometry.h"

namespace spott_map {

/// One sonar echo: the transducer (m), its axis (rad), the range (m) and the half width of its
/// cone (rad), in one frame.
struct SonarEcho {
  Vec2 from{0.0, 0.0};
  double axis = 0.0;
  double range = 0.0;
  double half_cone = 0.0;
};

/// How far (rad) the direction `toward` lies outside the echo's cone (0: inside); `*side` the
/// side (+1 left of the axis, -1 right) it lies on.
double ConeExcess(const SonarEcho& e, double toward, double* side);

/// The echo a transducer would hear from the line {x : normal . x = offset} (`normal` a unit
/// vector pointing from the line to the transducer): its range and where it reflects; `excess`
/// how far (rad) the normal lies outside the cone (the range is the distance / cos(excess)).
struct PredictedEcho {
  double range = 0.0;
  Vec2 reflection{0.0, 0.0};
  double excess = 0.0;
};
/// nullopt when the transducer is behind the line or the line's normal lies beyond its cone by
/// more than max_incidence_rad (the pulse reflects away).
std::optional<PredictedEcho> PredictEcho(const SonarEcho& e, const Vec2& normal, double offset,
                                         double max_incidence_rad);

}  // namespace spott_map
