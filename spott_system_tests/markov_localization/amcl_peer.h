// The particle-filter peer of the evaluation: AMCL's algorithm (ROS navigation's amcl, which is
// not in Debian), written here from its documented behaviour and defaults, to compare the grid
// with on the same simulated data:
// - KLD-sampling MCL (Fox 2003): after resampling, particles are drawn until their count
//   exceeds the KLD bound for the histogram bins they occupy (0.5 m x 0.5 m x 10 degrees,
//   pf_err 0.01, pf_z 0.99), between min_particles 500 and max_particles 5000; resampling every
//   resample_interval (2) updates; recovery (alpha_slow / alpha_fast) off, as AMCL's defaults;
// - the "diff" odometry motion model (Probabilistic Robotics table 5.6, with AMCL's
//   backward-motion fix of the rotation noise), odom_alpha1..4 = 0.2;
// - the likelihood-field laser model: distance to the nearest obstacle up to
//   laser_likelihood_max_dist 2 m, pz = z_hit exp(-d^2 / 2 sigma^2) + z_rand / range_max,
//   combined as AMCL does (p = 1 + sum pz^3), max-range readings skipped, laser_max_beams 30,
//   z_hit 0.95, z_rand 0.05, sigma_hit 0.2 m;
// - the same update trigger as AMCL (update_min_d 0.2 m, update_min_a pi/6);
// - the estimate: the weighted mean of the heaviest cluster of particles (clusters of adjacent
//   occupied histogram bins, as AMCL's kd-tree clustering).
// The obstacles are the grid's own map raster (the same map information).
#pragma once

#include <random>
#include <vector>

#include "eval_harness.h"

namespace markov_localization {
namespace eval {

struct AmclParameters {
  int min_particles = 500;
  int max_particles = 5000;
  double kld_err = 0.01;
  double kld_z = 0.99;
  double bin_xy_m = 0.5;
  double bin_theta_rad = 10.0 * M_PI / 180.0;
  int resample_interval = 2;
  double alpha1 = 0.2, alpha2 = 0.2, alpha3 = 0.2, alpha4 = 0.2;
  double update_min_d_m = 0.2;
  double update_min_a_rad = M_PI / 6.0;
  double z_hit = 0.95;
  double z_rand = 0.05;
  double sigma_hit_m = 0.2;
  double max_occ_dist_m = 2.0;
  double recovery_alpha_slow = 0.0;  ///< AMCL's default: no random particles
  double recovery_alpha_fast = 0.0;
};

class AmclPeer : public PeerFilter {
 public:
  /// `laser` / `sonar`: the beams (angles, origins, max range) of each sensor, as the grid's
  /// models have them (the sonar ring is read like a laser: AMCL has no sonar model).
  AmclPeer(const MapModel& map, const SensorModelParameters* laser,
           const SensorModelParameters* sonar, const AmclParameters& params, std::uint64_t seed);

  void OnReading(bool laser, const std::vector<double>& ranges, const Pose2& odom,
                 double now_s) override;
  Pose2 Estimate(const Pose2& odom) const override;
  void SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad) override;
  std::size_t particles() const { return particles_.size(); }

 private:
  struct Particle {
    double x, y, yaw, w;
  };
  double Distance(double x, double y) const;
  void Motion(const Pose2& from, const Pose2& to);
  void Sense(const SensorModelParameters& beams, const std::vector<double>& ranges);
  void Resample();
  void ComputeEstimate();

  const MapModel& map_;
  const SensorModelParameters* laser_;
  const SensorModelParameters* sonar_;
  AmclParameters params_;
  std::mt19937_64 rng_;
  // Likelihood field on the map's fine raster: distance (m) to the nearest obstacle, capped.
  int fw_ = 0, fh_ = 0;
  double fres_ = 0.05;
  std::vector<float> dist_;
  std::vector<Particle> particles_;
  bool has_update_odom_ = false;
  Pose2 update_odom_;
  int updates_ = 0;
  bool pending_laser_ = false, pending_sonar_ = false;
  double w_slow_ = 0.0, w_fast_ = 0.0;
  Pose2 estimate_;  // map frame, at estimate_odom_
  Pose2 estimate_odom_;
};

}  // namespace eval
}  // namespace markov_localization
