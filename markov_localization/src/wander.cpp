#include "markov_localization/wander.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace markov_localization {
namespace {

double Wrap(double a) { return std::remainder(a, 2.0 * M_PI); }

// A dropped-out beam (NaN) is not free space: the wanderer does not drive where it cannot see.
double Reading(double r, double max_range) {
  if (std::isnan(r)) return 0.0;
  return std::isfinite(r) && r < max_range ? std::max(0.0, r) : max_range;
}

}  // namespace

std::vector<std::string> ValidateParameters(const WanderParameters& p) {
  std::vector<std::string> errors;
  if (!(p.max_speed_mps > 0.0)) errors.push_back("max_speed_mps must be > 0 m/s");
  if (!(p.max_turn_rps > 0.0)) errors.push_back("max_turn_rps must be > 0 rad/s");
  if (!(p.heading_gain > 0.0)) errors.push_back("heading_gain must be > 0 1/s");
  if (!(p.stop_distance_m > 0.0)) errors.push_back("stop_distance_m must be > 0 m");
  if (!(p.slow_distance_m > p.stop_distance_m))
    errors.push_back("slow_distance_m must be > stop_distance_m");
  if (!(p.side_distance_m >= 0.0)) errors.push_back("side_distance_m must be >= 0 m");
  if (!(p.free_range_m > 0.0)) errors.push_back("free_range_m must be > 0 m");
  if (!(p.front_half_angle_rad > 0.0 && p.front_half_angle_rad < M_PI / 2))
    errors.push_back("front_half_angle_rad must be in (0, pi/2)");
  if (p.stall_steps < 1) errors.push_back("stall_steps must be >= 1");
  return errors;
}

Wanderer::Wanderer(const WanderParameters& params, std::uint64_t seed)
    : params_(params), rng_(seed) {
  const auto errors = ValidateParameters(params);
  if (!errors.empty()) {
    std::ostringstream out;
    for (std::size_t i = 0; i < errors.size(); ++i) out << (i ? "; " : "") << errors[i];
    throw std::invalid_argument(out.str());
  }
}

void Wanderer::DrawHeading(const std::vector<double>& angles, const std::vector<double>& ranges,
                           double odom_yaw, bool behind) {
  // Free directions, weighted by how far they are open; none free: the most open one.
  // Only the most open directions count (in a corridor: along it, not diagonally into a wall).
  std::vector<double> weights(angles.size(), 0.0);
  bool any = false;
  std::size_t best = 0;
  // `behind`: only directions more than 90 degrees from the robot's heading count.
  auto allowed = [&](std::size_t b) { return !behind || std::abs(Wrap(angles[b])) > M_PI / 2; };
  for (std::size_t b = 0; b < angles.size(); ++b)
    if (allowed(b) && (!allowed(best) || ranges[b] > ranges[best])) best = b;
  const double open = std::max(params_.free_range_m, 0.8 * ranges[best]);
  for (std::size_t b = 0; b < angles.size(); ++b) {
    if (allowed(b) && ranges[b] >= open) {
      weights[b] = ranges[b];
      any = true;
    }
  }
  std::size_t pick = best;
  if (any) {
    std::discrete_distribution<std::size_t> draw(weights.begin(), weights.end());
    pick = draw(rng_);
  }
  heading_ = Wrap(odom_yaw + angles[pick]);
}

WanderCommand Wanderer::Step(const std::vector<double>& angles_rad,
                             const std::vector<double>& ranges_m, double max_range_m, double odom_x,
                             double odom_y, double odom_yaw) {
  if (stalled_ < 0 || std::hypot(odom_x - anchor_x_, odom_y - anchor_y_) > 0.3) {
    anchor_x_ = odom_x;
    anchor_y_ = odom_y;
    stalled_ = 0;
  } else if (++stalled_ >= params_.stall_steps && !angles_rad.empty() &&
             angles_rad.size() == ranges_m.size()) {
    std::vector<double> r(ranges_m.size());
    for (std::size_t b = 0; b < r.size(); ++b) r[b] = Reading(ranges_m[b], max_range_m);
    DrawHeading(angles_rad, r, odom_yaw, /*behind=*/true);
    stalled_ = 0;
  }
  return Step(angles_rad, ranges_m, max_range_m, odom_yaw);
}

WanderCommand Wanderer::Step(const std::vector<double>& angles_rad,
                             const std::vector<double>& ranges_m, double max_range_m,
                             double odom_yaw) {
  WanderCommand cmd;
  if (angles_rad.empty() || angles_rad.size() != ranges_m.size()) return cmd;
  std::vector<double> r(ranges_m.size());
  for (std::size_t b = 0; b < r.size(); ++b) r[b] = Reading(ranges_m[b], max_range_m);

  auto nearest_beam = [&](double relative) {
    std::size_t best = 0;
    for (std::size_t b = 1; b < angles_rad.size(); ++b)
      if (std::abs(Wrap(angles_rad[b] - relative)) < std::abs(Wrap(angles_rad[best] - relative)))
        best = b;
    return best;
  };
  double front = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < r.size(); ++b)
    if (std::abs(Wrap(angles_rad[b])) <= params_.front_half_angle_rad)
      front = std::min(front, r[b]);

  if (!heading_) DrawHeading(angles_rad, r, odom_yaw);
  double err = Wrap(*heading_ - odom_yaw);
  const bool facing = std::abs(err) <= params_.front_half_angle_rad;
  // The way along the heading closed (or, when facing it, the way ahead): draw a new heading.
  // (A margin of 5 cm: exactly at the stop distance the speed is zero.)
  const double blocked = params_.stop_distance_m + 0.05;
  if (r[nearest_beam(err)] < blocked || (facing && front < blocked)) {
    DrawHeading(angles_rad, r, odom_yaw);
    err = Wrap(*heading_ - odom_yaw);
  }

  if (std::abs(err) <= params_.front_half_angle_rad) {
    // While driving, the heading follows the open space around it: the mean direction of the
    // beams within 45 degrees of it, weighted by the square of their readings (in a corridor:
    // along its axis, whatever the 15 degree beam the heading was drawn from).
    double sx = 0.0, sy = 0.0;
    for (std::size_t b = 0; b < r.size(); ++b) {
      const double rel = Wrap(angles_rad[b] - err);
      if (std::abs(rel) > M_PI / 4) continue;
      sx += r[b] * r[b] * std::cos(angles_rad[b]);
      sy += r[b] * r[b] * std::sin(angles_rad[b]);
    }
    if (sx != 0.0 || sy != 0.0) {
      heading_ = Wrap(odom_yaw + std::atan2(sy, sx));
      err = Wrap(*heading_ - odom_yaw);
    }
  }
  if (std::abs(err) > params_.front_half_angle_rad) {
    // Turn in place towards the heading (never slower than a third of the turn limit, so that
    // nothing can hold the robot still).
    const double w = std::max(params_.heading_gain * std::abs(err), params_.max_turn_rps / 3.0);
    cmd.angular_rps = std::copysign(std::min(w, params_.max_turn_rps), err);
    return cmd;
  }
  // Driving: the nearest side obstacle pushes the heading away from it (at most half the
  // turn limit, so the heading keeps the upper hand).
  double nearest = params_.side_distance_m, side = 0.0;
  for (std::size_t b = 0; b < r.size(); ++b) {
    const double a = Wrap(angles_rad[b]);
    if (std::abs(a) < 0.3 || std::abs(a) > M_PI - 0.3 || r[b] >= nearest) continue;
    nearest = r[b];
    side = a > 0 ? 1.0 : -1.0;
  }
  const double push = -side * 0.5 * params_.max_turn_rps * (params_.side_distance_m - nearest) /
                      params_.side_distance_m;
  cmd.angular_rps =
      std::clamp(params_.heading_gain * err + push, -params_.max_turn_rps, params_.max_turn_rps);
  const double open = std::clamp(
      (front - params_.stop_distance_m) / (params_.slow_distance_m - params_.stop_distance_m), 0.0,
      1.0);
  cmd.linear_mps = params_.max_speed_mps * open * std::cos(err);
  return cmd;
}

}  // namespace markov_localization
