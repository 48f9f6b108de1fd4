#include "markov_localization/pose_refinement.h"

#include <algorithm>
#include <cmath>

namespace markov_localization {

std::vector<std::string> ValidateParameters(const PoseRefinementParameters& p) {
  std::vector<std::string> errors;
  if (!(p.max_offset_cells > 0.0 && p.max_offset_cells <= 10.0))
    errors.push_back("max_offset_cells must be in (0, 10]");
  if (p.sweeps < 1 || p.sweeps > 10) errors.push_back("sweeps must be in [1, 10]");
  if (!(p.sigma_scale > 0.0 && p.sigma_scale <= 1.0))
    errors.push_back("sigma_scale must be in (0, 1]");
  return errors;
}

double ScanLogLikelihood(const MapModel& map, const std::vector<SensorReading>& readings,
                         const Pose2& pose, double sigma_scale,
                         const std::vector<std::uint8_t>* used) {
  double total = 0.0;
  std::size_t i = 0;
  for (const SensorReading& r : readings) {
    const SensorModel& s = *r.sensor;
    const double sigma = sigma_scale * s.parameters().sigma_hit_m;
    const Pose2 turned{pose.x, pose.y, pose.yaw + r.turn_rad};  // SensorReading::turn_rad
    for (int b = 0; b < s.num_beams(); ++b, ++i) {
      if (used && i < used->size() && !(*used)[i]) continue;
      if (std::isnan((*r.ranges_m)[b])) continue;  // dropped out
      total += s.LogLikelihood(s.ExpectedRange(map, turned, b), (*r.ranges_m)[b], sigma);
    }
  }
  return total;
}

Pose2 RefinePose(const MapModel& map, const std::vector<SensorReading>& readings,
                 const Pose2& start, double angular_resolution_rad,
                 const PoseRefinementParameters& params, const std::vector<std::uint8_t>* used) {
  if (!params.enabled || readings.empty()) return start;
  const double res = map.resolution();
  const double h[3] = {res / 3.0, res / 3.0, angular_resolution_rad / 2.0};
  const double limit[3] = {params.max_offset_cells * res, params.max_offset_cells * res,
                           params.max_offset_cells * angular_resolution_rad};
  double x[3] = {start.x, start.y, start.yaw};
  const double x0[3] = {start.x, start.y, start.yaw};
  auto eval = [&](const double* v) {
    return ScanLogLikelihood(map, readings, Pose2{v[0], v[1], v[2]}, params.sigma_scale, used);
  };
  auto inside = [&](const double* v) {
    for (int a = 0; a < 3; ++a)
      if (std::abs(v[a] - x0[a]) > limit[a] + 1e-12) return false;
    return map.IsStateAt(Vec2(v[0], v[1])) || (v[0] == x0[0] && v[1] == x0[1]);
  };
  double f0 = eval(x);
  for (int sweep = 0; sweep < params.sweeps; ++sweep) {
    for (int a = 0; a < 3; ++a) {
      double lo[3] = {x[0], x[1], x[2]}, hi[3] = {x[0], x[1], x[2]};
      lo[a] -= h[a];
      hi[a] += h[a];
      const double fm = inside(lo) ? eval(lo) : -1e300;
      const double fp = inside(hi) ? eval(hi) : -1e300;
      double step = 0.0;
      const double curvature = fm - 2.0 * f0 + fp;
      if (fm > -1e299 && fp > -1e299 && curvature < 0.0) {
        step = std::clamp(0.5 * h[a] * (fm - fp) / curvature, -h[a], h[a]);
      } else if (std::max(fm, fp) > f0) {
        step = fp > fm ? h[a] : -h[a];
      }
      if (step == 0.0) continue;
      double next[3] = {x[0], x[1], x[2]};
      next[a] = std::clamp(x[a] + step, x0[a] - limit[a], x0[a] + limit[a]);
      if (!inside(next)) continue;
      const double fn = eval(next);
      if (fn > f0) {
        x[a] = next[a];
        f0 = fn;
      }
    }
  }
  return Pose2{x[0], x[1], spott_map::NormalizeAngle(x[2])};
}

}  // namespace markov_localization
