// The belief a respawned localization resumes with (AMCL saves its pose's covariance for the
// same reason). Not a fixed initial spread: with /initialpose's 0.3 m a single sonar update in
// cim_office's west hallway pulled the resumed estimate 0.7-0.8 m along it (node_kill.test, twice
// in a day), a pull the tracking belief never feels because its spread stays near a cell.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "markov_localization/localizer.h"
#include "markov_localization/markov_grid.h"

namespace markov_localization {

struct Spread {
  double xy_m = 0.0;
  double theta_rad = 0.0;
};

/// The spread of a mode's covariance over (x, y, theta): position the larger axis (SetGaussian
/// is isotropic); none for a covariance that is not finite or has a negative variance.
std::optional<Spread> SpreadOf(const Eigen::Matrix3d& covariance);

/// The saved estimate's spread grown by the motion model over the odometry driven since it was
/// saved, as the node's own motion updates would have grown it: steps of the gate's
/// update_min_d_m / update_min_a_rad whose independent errors add in quadrature (one update of
/// the whole distance would count it linearly: 0.3 m for 3 m where the tracking gets 0.08 m).
/// Floored at half a cell and one heading bin: the grid holds no finer belief.
Spread ResumeSpread(const Spread& saved, const Pose2& odom_at_save, const Pose2& odom_now,
                    const MotionModelParameters& motion, const MotionGateParameters& gate,
                    double cell_m, double heading_bin_rad);

}  // namespace markov_localization
