#include "rpl_executive/noreils_chatila/path_smoothing.h"

#include <algorithm>
#include <cmath>

namespace rpl_executive::noreils_chatila {

std::vector<std::string> ValidateParameters(const PathSmoothingParameters& p) {
  std::vector<std::string> v;
  if (!(p.corner_distance_max_m > 0.0)) v.push_back("corner_distance_max_m: must be above 0");
  // A line is sampled in ceil(length / sample_step_m) steps, counted in an int.
  if (!(p.sample_step_m >= 0.001 && p.sample_step_m <= 1.0)) {
    v.push_back("sample_step_m: must be in [0.001, 1]");
  }
  if (!(p.max_deflection_rad > 0.0 && p.max_deflection_rad < kPi)) {
    v.push_back("max_deflection_rad: must be in (0, pi)");
  }
  return v;
}

void NormalizedFresnel(double a, double* c, double* s) {
  const int n = 256;
  double sc = 0.0, ss = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double u = static_cast<double>(i) / n;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sc += w * std::cos(a * u * u);
    ss += w * std::sin(a * u * u);
  }
  *c = sc / (3.0 * n);
  *s = ss / (3.0 * n);
}

ClothoidCorner CornerForDistance(double deflection, double distance) {
  ClothoidCorner k;
  k.distance_m = distance;
  const double half = std::fabs(deflection) / 2.0;
  if (half < 1e-9) {
    k.clothoid_length_m = distance;
    return k;
  }
  double c = 0.0, s = 0.0;
  NormalizedFresnel(half, &c, &s);
  k.clothoid_length_m = distance / (c + s * std::tan(half));
  k.peak_curvature = (deflection > 0 ? 1.0 : -1.0) * 2.0 * half / k.clothoid_length_m;
  return k;
}

namespace {

class Sampler {
 public:
  explicit Sampler(double step) : step_(step) {}

  void Add(double x, double y, double yaw, double curvature, bool turn = false) {
    PathSample p;
    p.x = x;
    p.y = y;
    p.yaw = WrapAngle(yaw);
    p.curvature = curvature;
    p.turn_in_place = turn;
    if (!path_.samples.empty()) {
      const PathSample& q = path_.samples.back();
      p.s = q.s + std::hypot(x - q.x, y - q.y);
    }
    path_.max_curvature = std::max(path_.max_curvature, std::fabs(curvature));
    path_.samples.push_back(p);
  }

  // A straight piece from the last sample to (x, y), the last sample excluded.
  void Line(double x, double y) {
    const PathSample q = path_.samples.back();
    const double length = std::hypot(x - q.x, y - q.y);
    if (length < 1e-9) return;
    const double yaw = std::atan2(y - q.y, x - q.x);
    const int n = std::max(1, static_cast<int>(std::ceil(length / step_)));
    for (int i = 1; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      Add(q.x + t * (x - q.x), q.y + t * (y - q.y), yaw, 0.0);
    }
  }

  // A clothoid of length L from the last sample, turning by `turn` (signed) with the curvature
  // growing (rising) or falling linearly; integrated with the midpoint rule on fine substeps.
  void Clothoid(double length, double turn, bool rising, double start_yaw) {
    const PathSample q = path_.samples.back();
    double x = q.x, y = q.y;
    const int n = std::max(2, static_cast<int>(std::ceil(length / step_)));
    const int sub = 16;
    const double ds = length / (n * sub);
    auto heading = [&](double s) {
      const double u = s / length;
      return rising ? start_yaw + turn * u * u : start_yaw + turn * (1.0 - (1.0 - u) * (1.0 - u));
    };
    auto curvature = [&](double s) {
      const double u = s / length;
      return rising ? 2.0 * turn * u / length : 2.0 * turn * (1.0 - u) / length;
    };
    for (int i = 1; i <= n; ++i) {
      for (int k = 0; k < sub; ++k) {
        const double s_mid = ((i - 1) * sub + k + 0.5) * ds;
        x += ds * std::cos(heading(s_mid));
        y += ds * std::sin(heading(s_mid));
      }
      const double s = i * sub * ds;
      Add(x, y, heading(s), curvature(s));
    }
  }

  SmoothedPath Take() {
    if (!path_.samples.empty()) path_.length_m = path_.samples.back().s;
    return std::move(path_);
  }
  PathSample& back() { return path_.samples.back(); }

 private:
  double step_;
  SmoothedPath path_;
};

}  // namespace

SmoothedPath SmoothBrokenLine(const std::vector<Point2>& input, const PathSmoothingParameters& p) {
  std::vector<Point2> v;
  for (const Point2& q : input) {
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
    if (v.empty() || Distance(v.back(), q) > 1e-6) v.push_back(q);
  }
  Sampler sampler(p.sample_step_m);
  if (v.empty()) return sampler.Take();
  if (v.size() == 1) {
    sampler.Add(v[0].x, v[0].y, 0.0, 0.0);
    return sampler.Take();
  }
  const size_t n = v.size();
  std::vector<double> length(n - 1), yaw(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    length[i] = Distance(v[i], v[i + 1]);
    yaw[i] = std::atan2(v[i + 1].y - v[i].y, v[i + 1].x - v[i].x);
  }
  sampler.Add(v[0].x, v[0].y, yaw[0], 0.0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const double deflection = WrapAngle(yaw[i] - yaw[i - 1]);
    const Point2& vertex = v[i];
    if (std::fabs(deflection) < 1e-9) continue;
    if (std::fabs(deflection) > p.max_deflection_rad) {
      sampler.Line(vertex.x, vertex.y);
      sampler.back().turn_in_place = true;
      sampler.Add(vertex.x, vertex.y, yaw[i], 0.0, true);
      continue;
    }
    const double d = std::min({p.corner_distance_max_m, 0.5 * length[i - 1], 0.5 * length[i]});
    const ClothoidCorner corner = CornerForDistance(deflection, d);
    const double start_x = vertex.x - d * std::cos(yaw[i - 1]);
    const double start_y = vertex.y - d * std::sin(yaw[i - 1]);
    sampler.Line(start_x, start_y);
    sampler.Clothoid(corner.clothoid_length_m, deflection / 2.0, true, yaw[i - 1]);
    sampler.Clothoid(corner.clothoid_length_m, deflection / 2.0, false,
                     yaw[i - 1] + deflection / 2.0);
  }
  sampler.Line(v[n - 1].x, v[n - 1].y);
  return sampler.Take();
}

}  // namespace rpl_executive::noreils_chatila
