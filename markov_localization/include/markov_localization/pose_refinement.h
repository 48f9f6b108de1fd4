// The published pose below the grid's cell size (an addition to the paper, stated as such): the
// belief's maximum is a 15 cm x 2 degree cell, and a belief sharpened by many beams holds its
// mass on that one cell, so its estimate snaps to the cell's centre (5.7 cm mean error for a
// robot placed uniformly in a 15 cm cell, 0.5 degrees in a 2 degree bin). The last update's
// readings still say where in the cell the robot is: this maximizes their log-likelihood under
// the same sensor model (the tables' mixture, the beams' exact angles and origins, expected
// ranges cast on the fine raster with the same sonar physics) over continuous poses near the
// belief's estimate, by coordinate-wise parabolic steps, within a bounded box.
//
// ROS-free; no clock, no random generator.
#pragma once

#include <cstdint>
#include <vector>

#include "markov_localization/markov_grid.h"

namespace markov_localization {

struct PoseRefinementParameters {
  bool enabled = true;
  double max_offset_cells = 1.0;  ///< Box around the start: +-this many cells in x and y and
                                  ///< heading bins in theta, > 0.
  int sweeps = 2;                 ///< Passes over x, y, theta, >= 1.
  /// The hit term's spread is each sensor's sigma_hit_m times this, in (0, 1]: the tables'
  /// sigma covers the cells' quantization, which a continuous pose does not have.
  double sigma_scale = 0.33;
};

std::vector<std::string> ValidateParameters(const PoseRefinementParameters& params);

/// Sum over the readings' beams of log P(z | expected range at `pose`) (nats), the hit term's
/// spread each sensor's sigma_hit_m times `sigma_scale`.
/// `used` (optional): per beam of the readings in order, 0 = left out (the distance filter's).
double ScanLogLikelihood(const MapModel& map, const std::vector<SensorReading>& readings,
                         const Pose2& pose, double sigma_scale = 1.0,
                         const std::vector<std::uint8_t>* used = nullptr);

/// The pose near `start` that maximizes ScanLogLikelihood: probes at +-h (a third of a cell,
/// half a heading bin) on each axis, a parabola's peak (or the better probe when the three are
/// not concave), `sweeps` times; clamped to the box. Returns `start` when nothing fits better.
Pose2 RefinePose(const MapModel& map, const std::vector<SensorReading>& readings,
                 const Pose2& start, double angular_resolution_rad,
                 const PoseRefinementParameters& params,
                 const std::vector<std::uint8_t>* used = nullptr);

}  // namespace markov_localization
