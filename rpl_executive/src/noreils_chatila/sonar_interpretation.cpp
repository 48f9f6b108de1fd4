#include "rpl_executive/noreils_chatila/sonar_interpretation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rpl_executive::noreils_chatila {

std::vector<std::string> ValidateParameters(const SonarInterpretationParameters& p) {
  std::vector<std::string> v;
  if (p.min_sensors < 2 || p.min_sensors > 16) v.push_back("min_sensors: must be in [2, 16]");
  if (!(p.max_rms_m > 0.0 && p.max_rms_m <= 1.0)) v.push_back("max_rms_m: must be in (0, 1]");
  if (!(p.max_range_m > 0.0)) v.push_back("max_range_m: must be above 0");
  if (!(p.search_margin_rad >= 0.0 && p.search_margin_rad < kPi / 2)) {
    v.push_back("search_margin_rad: must be in [0, pi/2)");
  }
  if (!(p.rho_tolerance_m > 0.0)) v.push_back("rho_tolerance_m: must be above 0");
  if (!(p.theta_tolerance_rad > 0.0 && p.theta_tolerance_rad < kPi)) {
    v.push_back("theta_tolerance_rad: must be in (0, pi)");
  }
  return v;
}

double PredictedRange(const SonarMount& m, double h, double rho, double theta) {
  const double p = rho - (std::cos(theta) * m.x_m + std::sin(theta) * m.y_m);
  if (p <= 0.0) return -1.0;
  const double off = std::fabs(WrapAngle(theta - m.yaw_rad));
  if (off <= h) return p;
  const double delta = off - h;
  if (delta >= kPi / 2 - 1e-6) return -1.0;
  return p / std::cos(delta);
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Fit {
  double rho = 0.0;
  double theta = 0.0;
  double rms = kInfinity;
};

class WindowFitter {
 public:
  WindowFitter(const SonarScan& scan, const SonarRing& ring) : scan_(scan), ring_(ring) {}

  // Sum of squared residuals at theta for the sensors `idx`; *rho receives the best rho.
  double Cost(const std::vector<int>& idx, double theta, double* rho) const {
    const double c = std::cos(theta), s = std::sin(theta);
    const double h = ring_.half_field_of_view_rad;
    double num = 0.0, den = 0.0;
    double w[32], a[32], r[32];
    const size_t n = std::min<size_t>(idx.size(), 32);
    for (size_t k = 0; k < n; ++k) {
      const SonarMount& m = ring_.mounts[idx[k]];
      const double off = std::fabs(WrapAngle(theta - m.yaw_rad));
      double ci = 1.0;
      if (off > h) {
        const double delta = off - h;
        if (delta >= kPi / 2 - 1e-3) return kInfinity;
        ci = std::cos(delta);
      }
      w[k] = 1.0 / ci;
      a[k] = c * m.x_m + s * m.y_m;
      r[k] = scan_.ranges_m[idx[k]];
      num += w[k] * (r[k] + a[k] * w[k]);
      den += w[k] * w[k];
    }
    const double best_rho = num / den;
    double cost = 0.0;
    for (size_t k = 0; k < n; ++k) {
      if (best_rho - a[k] <= 0.0) return kInfinity;  // the sensor would be beyond the line
      const double e = r[k] - (best_rho - a[k]) * w[k];
      cost += e * e;
    }
    *rho = best_rho;
    return cost;
  }

  Fit FitWindow(const std::vector<int>& idx, double margin) const {
    const double h = ring_.half_field_of_view_rad;
    const double base = ring_.mounts[idx[0]].yaw_rad;
    double rel = 0.0, lo = 0.0, hi = 0.0;
    for (size_t k = 1; k < idx.size(); ++k) {
      rel += WrapAngle(ring_.mounts[idx[k]].yaw_rad - ring_.mounts[idx[k - 1]].yaw_rad);
      lo = std::min(lo, rel);
      hi = std::max(hi, rel);
    }
    lo = base + lo - h - margin;
    hi = base + hi + h + margin;
    const double step = kPi / 180.0;
    Fit best;
    double best_cost = kInfinity;
    for (double theta = lo; theta <= hi + 1e-12; theta += step) {
      double rho = 0.0;
      const double cost = Cost(idx, theta, &rho);
      if (cost < best_cost) {
        best_cost = cost;
        best.theta = theta;
        best.rho = rho;
      }
    }
    if (!std::isfinite(best_cost)) return best;
    // Golden-section refinement around the best grid point.
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = best.theta - step, b = best.theta + step;
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double r1 = 0.0, r2 = 0.0;
    double f1 = Cost(idx, x1, &r1), f2 = Cost(idx, x2, &r2);
    for (int it = 0; it < 30; ++it) {
      if (f1 < f2) {
        b = x2;
        x2 = x1;
        f2 = f1;
        x1 = b - g * (b - a);
        f1 = Cost(idx, x1, &r1);
      } else {
        a = x1;
        x1 = x2;
        f1 = f2;
        x2 = a + g * (b - a);
        f2 = Cost(idx, x2, &r2);
      }
    }
    const double xm = 0.5 * (a + b);
    double rm = 0.0;
    const double fm = Cost(idx, xm, &rm);
    if (fm < best_cost) {
      best_cost = fm;
      best.theta = xm;
      best.rho = rm;
    }
    best.theta = WrapAngle(best.theta);
    best.rms = std::sqrt(best_cost / static_cast<double>(idx.size()));
    return best;
  }

 private:
  const SonarScan& scan_;
  const SonarRing& ring_;
};

}  // namespace

std::vector<SonarLine> InterpretLines(const SonarScan& scan, const SonarRing& ring,
                                      const SonarInterpretationParameters& p) {
  std::vector<SonarLine> lines;
  const int n = static_cast<int>(std::min(ring.mounts.size(), scan.ranges_m.size()));
  if (n < p.min_sensors || n > 32) return lines;
  std::vector<bool> echo(n);
  int echoes = 0;
  for (int i = 0; i < n; ++i) {
    const double r = scan.ranges_m[i];
    echo[i] = ring.IsEcho(r) && r <= p.max_range_m;
    echoes += echo[i];
  }
  if (echoes < p.min_sensors) return lines;
  WindowFitter fitter(scan, ring);
  struct Window {
    int start;
    int length;
    Fit fit;
  };
  std::vector<Window> windows;
  for (int s = 0; s < n; ++s) {
    if (!echo[s]) continue;
    std::vector<int> idx = {s};
    Window best{s, 0, Fit{}};
    for (int len = 2; len <= n; ++len) {
      const int e = (s + len - 1) % n;
      if (!echo[e]) break;
      idx.push_back(e);
      if (len < p.min_sensors) continue;
      const Fit f = fitter.FitWindow(idx, p.search_margin_rad);
      if (!(f.rms <= p.max_rms_m)) break;
      best.length = len;
      best.fit = f;
    }
    if (best.length >= p.min_sensors) windows.push_back(best);
  }
  for (size_t i = 0; i < windows.size(); ++i) {
    bool contained = false;
    for (size_t j = 0; j < windows.size() && !contained; ++j) {
      if (i == j) continue;
      const int offset = (windows[i].start - windows[j].start + n) % n;
      if (offset + windows[i].length <= windows[j].length &&
          (windows[i].length < windows[j].length || j < i)) {
        contained = true;
      }
    }
    if (contained) continue;
    SonarLine line;
    line.rho_m = windows[i].fit.rho;
    line.theta_rad = windows[i].fit.theta;
    line.rms_m = windows[i].fit.rms;
    line.first_sensor = windows[i].start + 1;
    line.sensor_count = windows[i].length;
    lines.push_back(line);
  }
  return lines;
}

bool PerceivesLine(const std::vector<SonarLine>& lines, double rho_m, double theta_rad,
                   const SonarInterpretationParameters& p) {
  for (const SonarLine& l : lines) {
    if (std::fabs(l.rho_m - rho_m) <= p.rho_tolerance_m &&
        std::fabs(WrapAngle(l.theta_rad - theta_rad)) <= p.theta_tolerance_rad) {
      return true;
    }
  }
  return false;
}

}  // namespace rpl_executive::noreils_chatila
