#include "markov_localization/wall_lattice_heading.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "markov_localization/validation.h"

namespace markov_localization {

using spott_map::Vec2;

std::vector<std::string> ValidateParameters(const WallLatticeParameters& p) {
  std::vector<std::string> e;
  const auto positive = [&](double v, const char* name) {
    if (!(v > 0.0 && std::isfinite(v))) e.push_back(std::string(name) + " must be > 0");
  };
  positive(p.period_s, "period_s");
  positive(p.window_s, "window_s");
  if (!std::isfinite(p.axis_rad)) e.push_back("axis_rad must be finite");
  if (!(p.gate_rad > 0.0 && p.gate_rad < M_PI / 4.0))
    e.push_back(
        "gate_rad must be > 0 and below 45 degrees: lines between two lattice directions would "
        "vote");
  positive(p.agree_rad, "agree_rad");
  positive(p.min_length_m, "min_length_m");
  if (!(p.min_points >= 3)) e.push_back("min_points must be >= 3");
  positive(p.max_rms_m, "max_rms_m");
  positive(p.break_m, "break_m");
  if (!(p.min_total_m >= 0.0 && std::isfinite(p.min_total_m)))
    e.push_back("min_total_m must be >= 0");
  return e;
}

namespace {

struct Fit {
  Vec2 mean, axis, normal;
  double rms = 0.0, length = 0.0;
};

// Total least squares over points[first, last).
Fit FitRun(const std::vector<Vec2>& points, std::size_t first, std::size_t last) {
  Fit f;
  const double n = static_cast<double>(last - first);
  f.mean = Vec2::Zero();
  for (std::size_t i = first; i < last; ++i) f.mean += points[i];
  f.mean /= n;
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (std::size_t i = first; i < last; ++i)
    cov += (points[i] - f.mean) * (points[i] - f.mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  f.axis = eig.eigenvectors().col(1).normalized();  // the largest eigenvalue's
  f.normal = Vec2(-f.axis.y(), f.axis.x());
  double lo = 1e300, hi = -1e300, squares = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    const Vec2 v = points[i] - f.mean;
    const double t = v.dot(f.axis), d = v.dot(f.normal);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    squares += d * d;
  }
  f.rms = std::sqrt(squares / n);
  f.length = hi - lo;
  return f;
}

void SplitRun(double time_s, const std::vector<Vec2>& points, std::size_t first, std::size_t last,
              const WallLatticeParameters& p, int depth, std::vector<ProfileLine>& out) {
  if (last - first < static_cast<std::size_t>(p.min_points)) return;
  const Fit f = FitRun(points, first, last);
  if (f.rms > p.max_rms_m) {
    // A corner or a curve: split at the sample furthest from the chord of the run's ends (split
    // and merge's rule: that is the corner), the corner's sample on neither side.
    if (depth >= 8) return;
    const Vec2 a = points[first], chord = points[last - 1] - a;
    const double span = chord.norm();
    std::size_t corner = first + (last - first) / 2;
    if (span > 1e-9) {
      double worst = -1.0;
      for (std::size_t i = first + 1; i + 1 < last; ++i) {
        const double d =
            std::abs(chord.x() * (points[i] - a).y() - chord.y() * (points[i] - a).x());
        if (d > worst) {
          worst = d;
          corner = i;
        }
      }
    }
    SplitRun(time_s, points, first, corner, p, depth + 1, out);
    SplitRun(time_s, points, corner + 1, last, p, depth + 1, out);
    return;
  }
  if (f.length < p.min_length_m) return;
  double direction = std::atan2(f.axis.y(), f.axis.x());
  if (direction < 0.0) direction += M_PI;
  if (direction >= M_PI) direction -= M_PI;
  out.push_back({time_s, direction, f.length, f.rms, static_cast<int>(last - first)});
}

// `angle` folded into [-period / 2, period / 2).
double Fold(double angle, double period) {
  const double r = std::fmod(angle + period / 2.0, period);
  return (r < 0.0 ? r + period : r) - period / 2.0;
}

}  // namespace

std::vector<ProfileLine> FitProfileLines(double time_s, const std::vector<Vec2>& points,
                                         const WallLatticeParameters& p) {
  std::vector<ProfileLine> lines;
  std::size_t first = 0;
  for (std::size_t i = 0; i <= points.size(); ++i) {
    const bool ends = i == points.size() || !points[i].allFinite() ||
                      (i > first && (points[i] - points[i - 1]).norm() > p.break_m);
    if (!ends) continue;
    if (i > first) SplitRun(time_s, points, first, i, p, 0, lines);
    first = (i < points.size() && points[i].allFinite()) ? i : i + 1;
  }
  return lines;
}

WallLatticeHeading::WallLatticeHeading(const WallLatticeParameters& p) : p_(p) {
  ThrowIfInvalid(ValidateParameters(p));
}

void WallLatticeHeading::AddProfile(double time_s, const std::vector<Vec2>& odom_points) {
  if (!p_.enabled) return;
  for (const ProfileLine& l : FitProfileLines(time_s, odom_points, p_)) lines_.push_back(l);
}

WallLatticeCorrection WallLatticeHeading::Estimate(double now_s, double map_to_odom_yaw) {
  WallLatticeCorrection c;
  // Keep the window's lines only (a clock that went back starts over).
  while (!lines_.empty() && lines_.front().time_s < now_s - p_.window_s) lines_.pop_front();
  if (!lines_.empty() && lines_.back().time_s > now_s) lines_.clear();
  c.lines = static_cast<int>(lines_.size());
  if (!p_.enabled) {
    c.why = "off";
    return c;
  }
  // Each line's deviation from its nearest lattice direction, if it is a lattice wall at all.
  struct Vote {
    double deviation, weight;
  };
  std::vector<Vote> votes;
  for (const ProfileLine& l : lines_) {
    const double d = Fold(l.direction_rad + map_to_odom_yaw - p_.axis_rad, M_PI / 2.0);
    if (std::abs(d) <= p_.gate_rad) votes.push_back({d, l.length_m});
  }
  if (votes.empty()) {
    c.why = "no wall line along the lattice";
    return c;
  }
  // The length-weighted median, then the mean of the lines that agree with it.
  std::sort(votes.begin(), votes.end(),
            [](const Vote& a, const Vote& b) { return a.deviation < b.deviation; });
  double total = 0.0;
  for (const Vote& v : votes) total += v.weight;
  double below = 0.0, median = votes.back().deviation;
  for (const Vote& v : votes) {
    below += v.weight;
    if (below >= total / 2.0) {
      median = v.deviation;
      break;
    }
  }
  double sum = 0.0, weight = 0.0;
  for (const Vote& v : votes) {
    if (std::abs(v.deviation - median) > p_.agree_rad) continue;
    sum += v.weight * v.deviation;
    weight += v.weight;
    ++c.agreeing;
  }
  c.length_m = weight;
  if (weight < p_.min_total_m || weight <= 0.0) {
    c.why = "too little wall line agrees (" + std::to_string(weight) + " m)";
    return c;
  }
  c.dyaw = -sum / weight;
  c.ok = true;
  return c;
}

}  // namespace markov_localization
