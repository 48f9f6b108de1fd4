#include "markov_localization/certainty.h"

#include <algorithm>
#include <cmath>

namespace markov_localization {

BeliefSnapshot BeliefSnapshot::Of(const MarkovGrid& grid) {
  BeliefSnapshot s;
  s.nx = grid.nx();
  s.ny = grid.ny();
  s.nt = grid.nt();
  s.origin = grid.map().origin();
  s.resolution = grid.map().resolution();
  s.p = grid.Dense();
  s.num_states = grid.NumStates();
  return s;
}

Pose2 BeliefSnapshot::PoseOf(int ix, int iy, int k) const {
  return Pose2{origin.x() + (ix + 0.5) * resolution, origin.y() + (iy + 0.5) * resolution,
               spott_map::NormalizeAngle(k * angular_resolution())};
}

double Entropy(const BeliefSnapshot& belief) {
  double h = 0.0;
  for (float v : belief.p)
    if (v > 0.0f) h -= static_cast<double>(v) * std::log(static_cast<double>(v));
  return h;
}

std::vector<std::string> ValidateParameters(const CertaintyParameters& p) {
  std::vector<std::string> errors;
  if (!(p.mode_radius_m > 0.0)) errors.push_back("mode_radius_m must be > 0 m");
  if (!(p.mode_radius_rad > 0.0 && p.mode_radius_rad < M_PI))
    errors.push_back("mode_radius_rad must be in (0, pi)");
  if (!(p.threshold > 0.0 && p.threshold < 1.0)) errors.push_back("threshold must be in (0, 1)");
  return errors;
}

PositionCertainty PosCertainty(const BeliefSnapshot& b, const CertaintyParameters& params) {
  PositionCertainty out;
  if (b.p.empty()) return out;
  const std::size_t imax =
      static_cast<std::size_t>(std::max_element(b.p.begin(), b.p.end()) - b.p.begin());
  const int mx = static_cast<int>(imax % b.nx);
  const int my = static_cast<int>((imax / b.nx) % b.ny);
  const int mk = static_cast<int>(imax / (static_cast<std::size_t>(b.nx) * b.ny));
  out.maximum = b.PoseOf(mx, my, mk);
  const int rxy = static_cast<int>(std::floor(params.mode_radius_m / b.resolution + 1e-9));
  const int rt =
      static_cast<int>(std::floor(params.mode_radius_rad / b.angular_resolution() + 1e-9));
  double mass = 0.0, sx = 0.0, sy = 0.0, ss = 0.0, sc = 0.0;
  for (int dk = -rt; dk <= rt; ++dk) {
    const int k = ((mk + dk) % b.nt + b.nt) % b.nt;
    for (int iy = std::max(0, my - rxy); iy <= std::min(b.ny - 1, my + rxy); ++iy) {
      for (int ix = std::max(0, mx - rxy); ix <= std::min(b.nx - 1, mx + rxy); ++ix) {
        const double v = b.p[b.Index(ix, iy, k)];
        if (v <= 0.0) continue;
        const Pose2 pose = b.PoseOf(ix, iy, k);
        mass += v;
        sx += v * pose.x;
        sy += v * pose.y;
        ss += v * std::sin(pose.yaw);
        sc += v * std::cos(pose.yaw);
      }
    }
  }
  out.certainty = mass;
  if (mass > 0.0) out.estimate = Pose2{sx / mass, sy / mass, std::atan2(ss, sc)};
  return out;
}

std::vector<Mode> ExtractModes(const BeliefSnapshot& b, const ModeParameters& params) {
  std::vector<Mode> modes;
  if (b.p.empty() || b.num_states == 0) return modes;
  const float pmax = *std::max_element(b.p.begin(), b.p.end());
  const double threshold = std::max(params.uniform_factor / static_cast<double>(b.num_states),
                                    params.max_fraction * pmax);
  std::vector<std::uint8_t> seen(b.p.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < b.p.size(); ++start) {
    if (seen[start] || b.p[start] <= threshold) continue;
    // Flood fill over the 26-neighbourhood; heading wraps.
    std::vector<std::size_t> members;
    stack.assign(1, start);
    seen[start] = 1;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      members.push_back(i);
      const int ix = static_cast<int>(i % b.nx);
      const int iy = static_cast<int>((i / b.nx) % b.ny);
      const int k = static_cast<int>(i / (static_cast<std::size_t>(b.nx) * b.ny));
      for (int dk = -1; dk <= 1; ++dk) {
        const int kk = ((k + dk) % b.nt + b.nt) % b.nt;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = ix + dx, y = iy + dy;
            if (x < 0 || y < 0 || x >= b.nx || y >= b.ny) continue;
            const std::size_t n = b.Index(x, y, kk);
            if (seen[n] || b.p[n] <= threshold) continue;
            seen[n] = 1;
            stack.push_back(n);
          }
        }
      }
    }
    Mode mode;
    double sx = 0.0, sy = 0.0, ss = 0.0, sc = 0.0;
    for (std::size_t i : members) {
      const double v = b.p[i];
      const Pose2 pose = b.PoseOf(static_cast<int>(i % b.nx), static_cast<int>((i / b.nx) % b.ny),
                                  static_cast<int>(i / (static_cast<std::size_t>(b.nx) * b.ny)));
      mode.mass += v;
      sx += v * pose.x;
      sy += v * pose.y;
      ss += v * std::sin(pose.yaw);
      sc += v * std::cos(pose.yaw);
    }
    mode.cells = members.size();
    mode.mean = Pose2{sx / mode.mass, sy / mode.mass, std::atan2(ss, sc)};
    for (std::size_t i : members) {
      const double v = b.p[i] / mode.mass;
      const Pose2 pose = b.PoseOf(static_cast<int>(i % b.nx), static_cast<int>((i / b.nx) % b.ny),
                                  static_cast<int>(i / (static_cast<std::size_t>(b.nx) * b.ny)));
      const Eigen::Vector3d d(pose.x - mode.mean.x, pose.y - mode.mean.y,
                              spott_map::NormalizeAngle(pose.yaw - mode.mean.yaw));
      mode.covariance += v * d * d.transpose();
    }
    modes.push_back(mode);
  }
  std::sort(modes.begin(), modes.end(),
            [](const Mode& a, const Mode& c) { return a.mass > c.mass; });
  if (static_cast<int>(modes.size()) > params.max_modes) modes.resize(params.max_modes);
  return modes;
}

}  // namespace markov_localization
