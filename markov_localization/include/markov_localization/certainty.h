// How sure the localization is (Beetz et al. section 2, "cognizant" position estimation):
// POS-CERTAINTY (the mass of the mode of the global maximum), the entropy H_P, eq. (5), and the
// modes of the belief, each approximated by a Gaussian with its mass (section 2.2).
#pragma once

#include <limits>
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

/// The states of a belief above a probability, sorted by dense index (k * ny + iy) * nx + ix.
/// When the position is known only a few orientation parts are active and a few thousand
/// states are above the selective update's theta: certainty and modes then cost microseconds
/// instead of a pass over millions of states. States left out are below `min_probability`.
struct SparseBelief {
  int nx = 0, ny = 0, nt = 0;
  Vec2 origin{0.0, 0.0};
  double resolution = 1.0;
  std::size_t num_states = 0;
  float min_probability = 0.0f;
  std::vector<std::uint32_t> index;  ///< Sorted.
  std::vector<float> p;              ///< P of index[i].

  /// The states of the grid's active parts above `min_probability` (>= theta: every state of
  /// an inactive part is below theta).
  static SparseBelief Of(const MarkovGrid& grid, float min_probability);
  double angular_resolution() const { return 2.0 * M_PI / nt; }
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
/// The same over the states a sparse belief holds (the mass below its min_probability is
/// left out: at most the box's state count times min_probability).
PositionCertainty PosCertainty(const SparseBelief& belief, const CertaintyParameters& params);

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
/// The same over a sparse belief; equal to the dense result when min_probability is below
/// the mode threshold max(uniform_factor / |L|, max_fraction max P).
std::vector<Mode> ExtractModes(const SparseBelief& belief, const ModeParameters& params);

/// What a node reports after each scan: POS-CERTAINTY, the modes and (when asked) the entropy.
struct BeliefSummary {
  PositionCertainty certainty;
  std::vector<Mode> modes;
  double entropy = std::numeric_limits<double>::quiet_NaN();  ///< (nats); NaN if not computed.
  bool sparse = false;  ///< Computed over the states above theta only.
};

/// Certainty and modes over the states above theta when they are few (the position is known:
/// microseconds), over the dense belief otherwise. The entropy needs every state: it is
/// computed only when `with_entropy` (a pass over the whole belief).
BeliefSummary Summarize(const MarkovGrid& grid, const CertaintyParameters& certainty,
                        const ModeParameters& modes, bool with_entropy);

}  // namespace markov_localization
