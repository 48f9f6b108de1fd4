#include "markov_localization/active_localization.h"
#include "markov_localization/validation.h"

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
  ThrowIfInvalid(errors);
}

struct ActiveLocalizer::Targets {
  int n = 0;               // targets on each side of the robot
  int N = 1;               // 2n + 1 per row
  double sp = 0.0;         // spacing (m)
  std::size_t origin = 0;  // the robot's own cell
  double Rel(int i) const { return (i - n) * sp; }
  std::size_t cells() const { return static_cast<std::size_t>(N) * N; }
};

struct ActiveLocalizer::Scratch {
  struct Footprint {
    long cell[4];
    double weight[4];
    int count = 0;
    long nearest = -1;
  };
  static constexpr int kSpread = 2;  // heading bins on each side
  explicit Scratch(std::size_t m)
      : foot(m), dir_of(m), dir_weight(m), dir_centre(m), logl(m), cell_ll(4 * (2 * kSpread + 1)) {}
  std::vector<Footprint> foot;
  std::vector<int> dir_of;
  std::vector<std::array<double, 2 * kSpread + 1>> dir_weight;
  std::vector<int> dir_centre;
  std::vector<double> logl;
  std::vector<double> cell_ll;
};

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

  Targets t;
  t.n = static_cast<int>(std::floor(params_.window_m / params_.target_spacing_m));
  t.N = 2 * t.n + 1;
  t.sp = params_.target_spacing_m;
  t.origin = static_cast<std::size_t>(t.n) * t.N + t.n;
  out.size = t.N;

  const std::vector<std::uint8_t> free_under = OccupancyOfTargets(t, modes, w, out.occupancy);
  out.cost_to_go = CostToGo(t, out.occupancy);

  out.expected_entropy_grid.assign(t.cells(), std::numeric_limits<double>::quiet_NaN());
  Scratch scratch(modes.size());
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_a = t.origin;
  for (std::size_t a = 0; a < t.cells(); ++a) {
    if (out.occupancy[a] > params_.max_target_occupancy || !std::isfinite(out.cost_to_go[a]))
      continue;
    const double expected_h = ExpectedEntropyAt(t, a, modes, w, free_under, scratch);
    if (std::isnan(expected_h)) continue;
    out.expected_entropy_grid[a] = expected_h;
    const double score = expected_h + params_.alpha * out.cost_to_go[a];  // eq. (9)
    if (score < best) {
      best = score;
      best_a = a;
    }
  }
  if (!std::isfinite(best)) return out;
  out.found = true;
  out.ax = t.Rel(static_cast<int>(best_a % t.N));
  out.ay = t.Rel(static_cast<int>(best_a / t.N));
  out.expected_entropy = out.expected_entropy_grid[best_a];
  out.cost = out.cost_to_go[best_a];
  out.path = PathBack(t, out.cost_to_go, best_a);
  return out;
}

// Eq. (7): P_occ(a) = sum_l P(l) P_occ(f_a(l)), over the modes; "occupied" = not a state.
std::vector<std::uint8_t> ActiveLocalizer::OccupancyOfTargets(
    const Targets& t, const std::vector<Mode>& modes, const std::vector<double>& w,
    std::vector<double>& occupancy) const {
  occupancy.assign(t.cells(), 0.0);
  std::vector<std::uint8_t> free_under(t.cells() * modes.size(), 0);
  for (int j = 0; j < t.N; ++j) {
    for (int i = 0; i < t.N; ++i) {
      const std::size_t a = static_cast<std::size_t>(j) * t.N + i;
      double occ = 0.0;
      for (std::size_t m = 0; m < modes.size(); ++m) {
        const bool free = map_.IsStateAt(TargetInWorld(modes[m].mean, t.Rel(i), t.Rel(j)));
        free_under[a * modes.size() + m] = free;
        if (!free) occ += w[m];
      }
      occupancy[a] = occ;
    }
  }
  return free_under;
}

// Eq. (8): v(a) <- P_occ(a) + min_b v(b) over the 8 neighbours (single motor commands),
// v(0,0) = 0 and infinity elsewhere. With non-negative costs, value iteration converges to
// the shortest-path values, which Dijkstra computes in one sweep.
std::vector<double> ActiveLocalizer::CostToGo(const Targets& t,
                                              const std::vector<double>& occupancy) const {
  const int N = t.N;
  std::vector<double> v_of(t.cells(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  v_of[t.origin] = 0.0;
  queue.push({0.0, t.origin});
  while (!queue.empty()) {
    const auto [v, a] = queue.top();
    queue.pop();
    if (v > v_of[a]) continue;
    const int i = static_cast<int>(a % N), j = static_cast<int>(a / N);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (!di && !dj) continue;
        const int ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= N || jj >= N) continue;
        const std::size_t b = static_cast<std::size_t>(jj) * N + ii;
        if (occupancy[b] >= 1.0 - 1e-9) continue;  // a wall under every mode
        const double step = t.sp * std::hypot(di, dj);
        const double nv =
            v + params_.occupied_cost * occupancy[b] + params_.travel_cost_per_m * step;
        if (nv < v_of[b]) {
          v_of[b] = nv;
          queue.push({nv, b});
        }
      }
    }
  }
  return v_of;
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
double ActiveLocalizer::ExpectedEntropyAt(const Targets& t, std::size_t a,
                                          const std::vector<Mode>& modes,
                                          const std::vector<double>& w,
                                          const std::vector<std::uint8_t>& free_under,
                                          Scratch& s) const {
  constexpr int kSpread = Scratch::kSpread;
  const double inf = std::numeric_limits<double>::infinity();
  const int nt = sensor_.num_headings();
  const double heading_res = 2.0 * M_PI / nt;
  const double res = map_.resolution();
  const std::size_t M = modes.size();
  const int i = static_cast<int>(a % t.N), j = static_cast<int>(a / t.N);
  const double travel = (i == t.n && j == t.n) ? 0.0 : std::atan2(t.Rel(j), t.Rel(i));
  for (std::size_t m = 0; m < M; ++m) {
    Scratch::Footprint& f = s.foot[m];
    f.count = 0;
    f.nearest = -1;
    if (free_under[a * M + m]) {
      const Vec2 p = TargetInWorld(modes[m].mean, t.Rel(i), t.Rel(j));
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
    s.dir_of[m] = ((k0 % nt) + nt) % nt;
    s.dir_centre[m] = s.dir_of[m];
    const double sigma =
        std::max(0.5, std::sqrt(std::max(0.0, modes[m].covariance(2, 2))) / heading_res);
    double total = 0.0;
    for (int q = -kSpread; q <= kSpread; ++q) {
      const double off = (k0 + q) - d;
      s.dir_weight[m][q + kSpread] = std::exp(-0.5 * off * off / (sigma * sigma));
      total += s.dir_weight[m][q + kSpread];
    }
    for (double& v : s.dir_weight[m]) v /= total;
  }
  double expected_h = 0.0, weight = 0.0;
  for (std::size_t tm = 0; tm < M; ++tm) {  // the true mode
    if (s.foot[tm].nearest < 0) continue;
    double mx = -inf;
    for (std::size_t m = 0; m < M; ++m) {
      if (s.foot[m].count == 0) {
        s.logl[m] = -inf;
        continue;
      }
      // log sum_{c, q} w_c w_q prod_b P(z_b | expected at cell c, heading bin q)
      double cmx = -inf;
      int h = 0;
      for (int c = 0; c < s.foot[m].count; ++c) {
        for (int q = -kSpread; q <= kSpread; ++q, ++h) {
          const int dir = ((s.dir_centre[m] + q) % nt + nt) % nt;
          double ll = std::log(s.foot[m].weight[c] * s.dir_weight[m][q + kSpread]);
          for (int b = 0; b < sensor_.num_beams(); ++b) {
            const int z = sensor_.ExpectedBin((s.dir_of[tm] + sensor_.beam_offset(b)) % nt,
                                              s.foot[tm].nearest);
            const int e =
                sensor_.ExpectedBin((dir + sensor_.beam_offset(b)) % nt, s.foot[m].cell[c]);
            ll += std::log(sensor_.Likelihood(e, z));
          }
          s.cell_ll[h] = ll;
          cmx = std::max(cmx, ll);
        }
      }
      double sum = 0.0;
      for (int c = 0; c < h; ++c) sum += std::exp(s.cell_ll[c] - cmx);
      s.logl[m] = std::log(w[m]) + cmx + std::log(sum);
      mx = std::max(mx, s.logl[m]);
    }
    double z = 0.0;
    for (std::size_t m = 0; m < M; ++m)
      z += std::isfinite(s.logl[m]) ? std::exp(s.logl[m] - mx) : 0.0;
    double h = 0.0;
    for (std::size_t m = 0; m < M; ++m) {
      if (!std::isfinite(s.logl[m])) continue;
      const double p = std::exp(s.logl[m] - mx) / z;
      if (p > 0.0) h -= p * std::log(p);
    }
    expected_h += w[tm] * h;
    weight += w[tm];
  }
  if (!(weight > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return expected_h / weight;
}

// Hill-climbing in v from a* back to the robot gives the cost-optimal path.
std::vector<Vec2> ActiveLocalizer::PathBack(const Targets& t, const std::vector<double>& cost_to_go,
                                            std::size_t a) {
  const int N = t.N;
  std::vector<Vec2> back;
  back.push_back(Vec2(t.Rel(static_cast<int>(a % N)), t.Rel(static_cast<int>(a / N))));
  while (a != t.origin) {
    const int i = static_cast<int>(a % N), j = static_cast<int>(a / N);
    std::size_t next = a;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= N || jj >= N) continue;
        const std::size_t b = static_cast<std::size_t>(jj) * N + ii;
        if (cost_to_go[b] < cost_to_go[next]) next = b;
      }
    if (next == a) break;
    a = next;
    back.push_back(Vec2(t.Rel(static_cast<int>(a % N)), t.Rel(static_cast<int>(a / N))));
  }
  return std::vector<Vec2>(back.rbegin(), back.rend());
}

}  // namespace markov_localization
