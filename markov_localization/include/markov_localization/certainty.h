// How sure the localization is (Beetz et al. section 2, "cognizant" position estimation):
// POS-CERTAINTY (the mass of the mode of the global maximum), the entropy H_P, eq. (5), and the
// modes of the belief, each approximated by a Gaussian with its mass (section 2.2).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "markov_localization/markov_grid.h"

namespace markov_localization {

/// A dense snapshot of a belief: value (k * ny + iy) * nx + ix is P(ix, iy, heading bin k).
struct BeliefSnapshot {
  int nx = 0, ny = 0, nt = 0;
  Vec2 origin{0.0, 0.0};    ///< Lower-left corner of cell (0, 0) (m, map frame).
  double resolution = 1.0;  ///< (m)
  std::vector<float> p;
  std::size_t num_states = 0;  ///< |L|: the states the belief ranges over.

  static BeliefSnapshot Of(const MarkovGrid& grid);
  double angular_resolution() const { return 2.0 * M_PI / nt; }
  std::size_t Index(int ix, int iy, int k) const {
    return (static_cast<std::size_t>(k) * ny + iy) * nx + ix;
  }
  Pose2 PoseOf(int ix, int iy, int k) const;
};

/// H_P = -sum_l P(l) log P(l), eq. (5), in nats.
double Entropy(const BeliefSnapshot& belief);

struct CertaintyParameters {
  double mode_radius_m = 0.5;      ///< Half-side of the neighbourhood of the maximum (m), > 0.
  double mode_radius_rad = 0.175;  ///< Half-width in heading (rad, 10 degrees), > 0.
  double threshold = 0.8;          ///< Certain (tracking) above this, lost below; in (0, 1).
};

std::vector<std::string> ValidateParameters(const CertaintyParameters& params);

struct PositionCertainty {
  double certainty = 0.0;  ///< POS-CERTAINTY: mass within the neighbourhood of the maximum.
  Pose2 maximum;           ///< Centre of the most likely state.
  Pose2 estimate;          ///< Weighted mean over the neighbourhood (below the cell size).
};

/// POS-CERTAINTY: one 15 cm x 2 degree cell never holds 0.8 of the mass, so the certainty is
/// the mass in the box of +-mode_radius_m x +-mode_radius_rad around the global maximum.
PositionCertainty PosCertainty(const BeliefSnapshot& belief, const CertaintyParameters& params);

struct Mode {
  Pose2 mean;  ///< Weighted mean (m, m, rad; heading by circular mean).
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< over (x, y, theta).
  double mass = 0.0;                                     ///< Probability mass of the mode's cells.
  std::size_t cells = 0;
};

struct ModeParameters {
  /// A state belongs to a mode when P(l) > max(uniform_factor / |L|, max_fraction * max P).
  double uniform_factor = 10.0;  ///< > 0
  double max_fraction = 0.01;    ///< in [0, 1)
  int max_modes = 16;            ///< The heaviest are kept, > 0.
};

/// The modes: states above the threshold grouped by adjacency in (x, y, theta) (heading
/// wraps), each summarized as a Gaussian. Heaviest first.
std::vector<Mode> ExtractModes(const BeliefSnapshot& belief, const ModeParameters& params);

}  // namespace markov_localization
