#include "spott_tr_plus/controller/sonar_echo_fit.h"

#include <algorithm>
#include <cmath>

namespace spott_tr_plus::controller {

namespace {

using spott_map::ConeExcess;

// One direction of the normal: the offsets the echoes vote for, and the offset most of them
// agree on within their tolerances.
struct Vote {
  std::size_t count = 0;
  double sse = 0.0, offset = 0.0;
};

Vote VoteOffset(const std::vector<SonarEcho>& echoes, double phi, const EchoFitParameters& p,
                std::vector<std::pair<double, double>>& offsets,
                std::vector<std::pair<double, double>>& prefix) {
  const Vec2 n(std::cos(phi), std::sin(phi));
  const double toward = phi + M_PI;  // from the transducers to the line
  offsets.clear();
  for (const SonarEcho& e : echoes) {
    double side;
    const double excess = ConeExcess(e, toward, &side);
    if (excess > p.max_incidence_rad) continue;
    offsets.emplace_back(n.dot(e.from) - e.range * std::cos(excess), EchoTolerance(e, p));
  }
  Vote best;
  if (offsets.empty()) return best;
  std::sort(offsets.begin(), offsets.end());
  // Each offset as a candidate; the window counts offsets within the candidate's tolerance
  // (two pointers: tolerances differ little within one cluster's ranges), prefix sums give each
  // window's spread.
  prefix.assign(offsets.size() + 1, {0.0, 0.0});
  for (std::size_t k = 0; k < offsets.size(); ++k) {
    const double x = offsets[k].first - offsets[0].first;  // shifted: no cancellation
    prefix[k + 1] = {prefix[k].first + x, prefix[k].second + x * x};
  }
  std::size_t lo = 0, hi = 0;
  for (std::size_t j = 0; j < offsets.size(); ++j) {
    const double d = offsets[j].first, w = offsets[j].second;
    while (offsets[lo].first < d - w) ++lo;
    if (hi < j) hi = j;
    while (hi + 1 < offsets.size() && offsets[hi + 1].first <= d + w) ++hi;
    const std::size_t count = hi - lo + 1;
    if (count < best.count) continue;
    const double sum = prefix[hi + 1].first - prefix[lo].first;
    const double sq = prefix[hi + 1].second - prefix[lo].second;
    const double sse = std::max(0.0, sq - sum * sum / static_cast<double>(count));
    const double mean = offsets[0].first + sum / static_cast<double>(count);
    if (count > best.count || sse < best.sse) best = Vote{count, sse, mean};
  }
  return best;
}

}  // namespace

double EchoCost(double residual, double tolerance) {
  const double z = 2.0 * residual / tolerance;
  return std::min(z * z, 4.0);
}

namespace {

// Cost of the line with normal angle `phi` at the offset its echoes vote for.
double LineCost(const std::vector<SonarEcho>& echoes, double phi, const EchoFitParameters& p,
                std::vector<std::pair<double, double>>& offsets,
                std::vector<std::pair<double, double>>& prefix, double* offset) {
  const Vote v = VoteOffset(echoes, phi, p, offsets, prefix);
  if (v.count == 0) return 4.0 * static_cast<double>(echoes.size());
  *offset = v.offset;
  const Vec2 n(std::cos(phi), std::sin(phi));
  double cost = 0.0;
  for (const SonarEcho& e : echoes) {
    const auto predicted = PredictEcho(e, n, v.offset, p.max_incidence_rad);
    cost += predicted ? EchoCost(predicted->range - e.range, EchoTolerance(e, p)) : 4.0;
  }
  return cost;
}

}  // namespace

EchoLine FitEchoLine(const std::vector<SonarEcho>& echoes, double normal_guess, double search,
                     const EchoFitParameters& p) {
  EchoLine line;
  line.direction_error_rad = search;
  if (echoes.empty()) return line;
  std::vector<std::pair<double, double>> offsets, prefix;
  // Coarse over the search, then fine around the best: a direction 0.01 rad off spreads the
  // offsets of echoes 3 m apart along the wall by 3 cm, about a tolerance.
  std::vector<std::pair<double, double>> costs;  // (phi, cost)
  double best_phi = normal_guess, best_offset = 0.0, best_cost = 1e300;
  const auto consider = [&](double phi) {
    double offset = 0.0;
    const double c = LineCost(echoes, phi, p, offsets, prefix, &offset);
    costs.emplace_back(phi, c);
    if (c < best_cost) {
      best_cost = c;
      best_phi = phi;
      best_offset = offset;
    }
  };
  const int coarse = static_cast<int>(std::ceil(search / 0.01));
  for (int k = -coarse; k <= coarse; ++k) consider(normal_guess + 0.01 * k);
  const double centre = best_phi;
  for (int k = -10; k <= 10; ++k) consider(centre + 0.001 * k);
  if (best_cost >= 4.0 * static_cast<double>(echoes.size())) return line;
  // The directions whose cost lies within 4 (two sigma, one degree of freedom) of the best:
  // seen head on, or over a short stretch, a wall's direction is barely determined.
  line.direction_error_rad = 0.0;
  for (const auto& [phi, c] : costs)
    if (c <= best_cost + 4.0)
      line.direction_error_rad = std::max(line.direction_error_rad, std::abs(phi - best_phi));
  line.normal = Vec2(std::cos(best_phi), std::sin(best_phi));
  line.offset = best_offset;
  for (std::size_t i = 0; i < echoes.size(); ++i) {
    const auto predicted = PredictEcho(echoes[i], line.normal, line.offset, p.max_incidence_rad);
    if (!predicted || std::abs(predicted->range - echoes[i].range) > EchoTolerance(echoes[i], p))
      continue;
    line.inliers.push_back(i);
    line.reflections.push_back(predicted->reflection);
  }
  return line;
}

std::optional<double> CornerResidual(const SonarEcho& e, const Vec2& at) {
  const Vec2 d = at - e.from;
  const double r = d.norm();
  double side;
  if (r < 1e-6 || ConeExcess(e, std::atan2(d.y(), d.x()), &side) > 0.05) return std::nullopt;
  return e.range - r;
}

EchoPoint FitEchoPoint(const std::vector<SonarEcho>& echoes, const Vec2& guess,
                       const EchoFitParameters& p) {
  EchoPoint point{guess, {}};
  const auto fits = [&](const SonarEcho& e, const Vec2& at, double scale) {
    const std::optional<double> r = CornerResidual(e, at);
    return r && std::abs(*r) <= scale * EchoTolerance(e, p);
  };
  // The tolerance shrinks from 8 to 1 times the echoes' own: the guess (the axis points' mean)
  // lies within range * tan(half cone) of the corner.
  for (const double scale : {8.0, 4.0, 2.0, 1.0, 1.0, 1.0, 1.0, 1.0}) {
    double a = 1e-9, b = 0.0, c = 1e-9, gx = 0.0, gy = 0.0;
    int used = 0;
    for (const SonarEcho& e : echoes) {
      if (!fits(e, point.at, scale)) continue;
      const Vec2 d = point.at - e.from;
      const double r = d.norm();
      const Vec2 j = d / r;
      const double f = r - e.range;
      a += j.x() * j.x();
      b += j.x() * j.y();
      c += j.y() * j.y();
      gx += j.x() * f;
      gy += j.y() * f;
      ++used;
    }
    if (used < 2) break;
    const double det = a * c - b * b;
    if (!(std::abs(det) > 1e-12)) break;
    Vec2 step((-c * gx + b * gy) / det, (b * gx - a * gy) / det);
    if (step.norm() > 0.5) step *= 0.5 / step.norm();
    point.at += step;
  }
  for (std::size_t i = 0; i < echoes.size(); ++i)
    if (fits(echoes[i], point.at, 1.0)) point.inliers.push_back(i);
  return point;
}

}  // namespace spott_tr_plus::controller
