#include "markov_localization/active_localization.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>
#include <stdexcept>

namespace markov_localization {

std::vector<std::string> ValidateParameters(const ActiveLocalizationParameters& p) {
  std::vector<std::string> errors;
  if (!(p.window_m > 0.0 && p.window_m <= 100.0))
    errors.push_back("window_m must be in (0, 100] m");
  if (!(p.target_spacing_m > 0.0))
    errors.push_back("target_spacing_m must be > 0 m");
  else if (p.window_m / p.target_spacing_m > 1000.0)
    errors.push_back("target_spacing_m too small for window_m (more than 2001^2 targets)");
  if (!(p.alpha >= 0.0)) errors.push_back("alpha must be >= 0");
  if (!(p.travel_cost_per_m >= 0.0)) errors.push_back("travel_cost_per_m must be >= 0");
  if (!(p.occupied_cost > 0.0)) errors.push_back("occupied_cost must be > 0");
  if (!(p.max_target_occupancy >= 0.0 && p.max_target_occupancy < 1.0))
    errors.push_back("max_target_occupancy must be in [0, 1)");
  if (p.max_modes < 1) errors.push_back("max_modes must be >= 1");
  return errors;
}

Vec2 TargetInWorld(const Pose2& pose, double ahead_m, double left_m) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return Vec2(pose.x + c * ahead_m - s * left_m, pose.y + s * ahead_m + c * left_m);
}

ActiveLocalizer::ActiveLocalizer(const MapModel& map, const SensorModel& sensor,
                                 const ActiveLocalizationParameters& params)
    : map_(map), sensor_(sensor), params_(params) {
  const auto errors = ValidateParameters(params);
  if (!errors.empty()) {
    std::ostringstream out;
    for (std::size_t i = 0; i < errors.size(); ++i) out << (i ? "; " : "") << errors[i];
    throw std::invalid_argument(out.str());
  }
}

ActiveChoice ActiveLocalizer::Choose(const std::vector<Mode>& all_modes) const {
  ActiveChoice out;
  std::vector<Mode> modes(
      all_modes.begin(),
      all_modes.begin() + std::min<std::size_t>(all_modes.size(), params_.max_modes));
  double mass = 0.0;
  for (const auto& m : modes) mass += m.mass;
  if (modes.empty() || !(mass > 0.0)) return out;
  std::vector<double> w;
  for (const auto& m : modes) w.push_back(m.mass / mass);

  const int n = static_cast<int>(std::floor(params_.window_m / params_.target_spacing_m));
  const int N = 2 * n + 1;
  out.size = N;
  const double sp = params_.target_spacing_m;
  auto rel = [&](int i) { return (i - n) * sp; };
  const std::size_t cells = static_cast<std::size_t>(N) * N;

  // Eq. (7): P_occ(a) = sum_l P(l) P_occ(f_a(l)), over the modes; "occupied" = not a state.
  out.occupancy.assign(cells, 0.0);
  std::vector<std::uint8_t> free_under(cells * modes.size(), 0);
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      const std::size_t a = static_cast<std::size_t>(j) * N + i;
      double occ = 0.0;
      for (std::size_t m = 0; m < modes.size(); ++m) {
        const bool free = map_.IsStateAt(TargetInWorld(modes[m].mean, rel(i), rel(j)));
        free_under[a * modes.size() + m] = free;
        if (!free) occ += w[m];
      }
      out.occupancy[a] = occ;
    }
  }

  // Eq. (8): v(a) <- P_occ(a) + min_b v(b) over the 8 neighbours (single motor commands),
  // v(0,0) = 0 and infinity elsewhere. With non-negative costs, value iteration converges to
  // the shortest-path values, which Dijkstra computes in one sweep.
  const double inf = std::numeric_limits<double>::infinity();
  out.cost_to_go.assign(cells, inf);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  const std::size_t origin = static_cast<std::size_t>(n) * N + n;
  out.cost_to_go[origin] = 0.0;
  queue.push({0.0, origin});
  while (!queue.empty()) {
    const auto [v, a] = queue.top();
    queue.pop();
    if (v > out.cost_to_go[a]) continue;
    const int i = static_cast<int>(a % N), j = static_cast<int>(a / N);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (!di && !dj) continue;
        const int ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= N || jj >= N) continue;
        const std::size_t b = static_cast<std::size_t>(jj) * N + ii;
        if (out.occupancy[b] >= 1.0 - 1e-9) continue;  // a wall under every mode
        const double step = sp * std::hypot(di, dj);
        const double nv =
            v + params_.occupied_cost * out.occupancy[b] + params_.travel_cost_per_m * step;
        if (nv < out.cost_to_go[b]) {
          out.cost_to_go[b] = nv;
          queue.push({nv, b});
        }
      }
    }
  }

  // Eq. (6) over the modes: if mode m is true, the robot at a senses the ranges expected at
  // f_a(m) (heading: the direction of travel); the posterior over the modes follows eq. (2)
  // with P(s | l') for every other mode l'. E_a[H] is the mode-weighted entropy of that
  // posterior. The point f_a(l') is continuous: P(s | l') is the bilinear mixture over the four
  // state cells around it (rounding it to one cell is not equivariant under the building's
  // symmetries: half-turn twins whose points fall on a cell border were rounded to cells that
  // are no twins, which made them look distinguishable everywhere, E[H] ~ 0 in a symmetric
  // corridor). Likewise the heading: a mixture over the heading bins within two bins of
  // yaw + travel, weighted by the mode's heading spread (at least half a bin), so that twins
  // whose mean headings differ from an exact half turn by a fraction of their spread do not
  // look distinguishable. The true scan is the one expected at the nearest cell and bin.
  out.expected_entropy_grid.assign(cells, std::numeric_limits<double>::quiet_NaN());
  const int nt = sensor_.num_headings();
  const double heading_res = 2.0 * M_PI / nt;
  const std::size_t M = modes.size();
  struct Footprint {
    long cell[4];
    double weight[4];
    int count = 0;
    long nearest = -1;
  };
  std::vector<Footprint> foot(M);
  std::vector<int> dir_of(M);
  constexpr int kSpread = 2;  // heading bins on each side
  std::vector<std::array<double, 2 * kSpread + 1>> dir_weight(M);
  std::vector<int> dir_centre(M);
  std::vector<double> logl(M);
  std::vector<double> cell_ll(4 * (2 * 2 + 1));
  const double res = map_.resolution();
  double best = inf;
  std::size_t best_a = origin;
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      const std::size_t a = static_cast<std::size_t>(j) * N + i;
      if (out.occupancy[a] > params_.max_target_occupancy || !std::isfinite(out.cost_to_go[a]))
        continue;
      const double travel = (i == n && j == n) ? 0.0 : std::atan2(rel(j), rel(i));
      for (std::size_t m = 0; m < M; ++m) {
        Footprint& f = foot[m];
        f.count = 0;
        f.nearest = -1;
        if (free_under[a * M + m]) {
          const Vec2 p = TargetInWorld(modes[m].mean, rel(i), rel(j));
          const double fx = (p.x() - map_.origin().x()) / res - 0.5;
          const double fy = (p.y() - map_.origin().y()) / res - 0.5;
          const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
          const double tx = fx - x0, ty = fy - y0;
          double total = 0.0, heaviest = -1.0;
          for (int k = 0; k < 4; ++k) {
            const int cx = x0 + (k & 1), cy = y0 + (k >> 1);
            const double wgt = ((k & 1) ? tx : 1.0 - tx) * ((k >> 1) ? ty : 1.0 - ty);
            if (wgt <= 0.0 || !map_.Contains(cx, cy) || !map_.IsState(cx, cy)) continue;
            f.cell[f.count] = static_cast<long>(map_.Index(cx, cy));
            f.weight[f.count] = wgt;
            total += wgt;
            if (wgt > heaviest) {
              heaviest = wgt;
              f.nearest = f.cell[f.count];
            }
            ++f.count;
          }
          for (int k = 0; k < f.count; ++k) f.weight[k] /= total;
        }
        // floor(x + 0.5), not lround: rounding must not depend on the sign (twins differ by pi).
        const double d = (modes[m].mean.yaw + travel) / heading_res;
        const int k0 = static_cast<int>(std::floor(d + 0.5));
        dir_of[m] = ((k0 % nt) + nt) % nt;
        dir_centre[m] = dir_of[m];
        const double sigma =
            std::max(0.5, std::sqrt(std::max(0.0, modes[m].covariance(2, 2))) / heading_res);
        double total = 0.0;
        for (int q = -kSpread; q <= kSpread; ++q) {
          const double off = (k0 + q) - d;
          dir_weight[m][q + kSpread] = std::exp(-0.5 * off * off / (sigma * sigma));
          total += dir_weight[m][q + kSpread];
        }
        for (double& v : dir_weight[m]) v /= total;
      }
      double expected_h = 0.0, weight = 0.0;
      for (std::size_t t = 0; t < M; ++t) {  // the true mode
        if (foot[t].nearest < 0) continue;
        double mx = -inf;
        for (std::size_t m = 0; m < M; ++m) {
          if (foot[m].count == 0) {
            logl[m] = -inf;
            continue;
          }
          // log sum_{c, q} w_c w_q prod_b P(z_b | expected at cell c, heading bin q)
          double cmx = -inf;
          int h = 0;
          for (int c = 0; c < foot[m].count; ++c) {
            for (int q = -kSpread; q <= kSpread; ++q, ++h) {
              const int dir = ((dir_centre[m] + q) % nt + nt) % nt;
              double ll = std::log(foot[m].weight[c] * dir_weight[m][q + kSpread]);
              for (int b = 0; b < sensor_.num_beams(); ++b) {
                const int z =
                    sensor_.ExpectedBin((dir_of[t] + sensor_.beam_offset(b)) % nt, foot[t].nearest);
                const int e =
                    sensor_.ExpectedBin((dir + sensor_.beam_offset(b)) % nt, foot[m].cell[c]);
                ll += std::log(sensor_.Likelihood(e, z));
              }
              cell_ll[h] = ll;
              cmx = std::max(cmx, ll);
            }
          }
          double sum = 0.0;
          for (int c = 0; c < h; ++c) sum += std::exp(cell_ll[c] - cmx);
          logl[m] = std::log(w[m]) + cmx + std::log(sum);
          mx = std::max(mx, logl[m]);
        }
        double z = 0.0;
        for (std::size_t m = 0; m < M; ++m)
          z += std::isfinite(logl[m]) ? std::exp(logl[m] - mx) : 0.0;
        double h = 0.0;
        for (std::size_t m = 0; m < M; ++m) {
          if (!std::isfinite(logl[m])) continue;
          const double p = std::exp(logl[m] - mx) / z;
          if (p > 0.0) h -= p * std::log(p);
        }
        expected_h += w[t] * h;
        weight += w[t];
      }
      if (!(weight > 0.0)) continue;
      expected_h /= weight;
      out.expected_entropy_grid[a] = expected_h;
      const double score = expected_h + params_.alpha * out.cost_to_go[a];  // eq. (9)
      if (score < best) {
        best = score;
        best_a = a;
      }
    }
  }
  if (!std::isfinite(best)) return out;
  out.found = true;
  out.ax = rel(static_cast<int>(best_a % N));
  out.ay = rel(static_cast<int>(best_a / N));
  out.expected_entropy = out.expected_entropy_grid[best_a];
  out.cost = out.cost_to_go[best_a];
  // Hill-climbing in v from a* back to the robot gives the cost-optimal path.
  std::vector<Vec2> back;
  std::size_t a = best_a;
  back.push_back(Vec2(rel(static_cast<int>(a % N)), rel(static_cast<int>(a / N))));
  while (a != origin) {
    const int i = static_cast<int>(a % N), j = static_cast<int>(a / N);
    std::size_t next = a;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= N || jj >= N) continue;
        const std::size_t b = static_cast<std::size_t>(jj) * N + ii;
        if (out.cost_to_go[b] < out.cost_to_go[next]) next = b;
      }
    if (next == a) break;
    a = next;
    back.push_back(Vec2(rel(static_cast<int>(a % N)), rel(static_cast<int>(a / N))));
  }
  out.path.assign(back.rbegin(), back.rend());
  return out;
}

}  // namespace markov_localization
