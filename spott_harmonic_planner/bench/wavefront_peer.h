// The peer of the benchmarks: a navfn-style Dijkstra wavefront (navfn, global_planner's
// Dijkstra), written here from its published description: 4-connected propagation from the goal
// with navfn's quadratic update (the potential of a cell from its two smallest neighbours,
// approximated by -0.2301 d^2 + 0.5307 d + 0.7040), neutral cost 50 per cell, lethal cells never
// entered, and a path by steepest descent over the 8 neighbours. A binary heap stands in for
// navfn's threshold buffers. No inflation: the same padded grid as the harmonic planner.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace spott_harmonic_planner::bench {

class WavefrontPeer {
 public:
  static constexpr float kNeutral = 50.0f;

  /// `blocked`: row-major, nx x ny; the goal cell must be free.
  void Plan(const std::vector<std::uint8_t>& blocked, int nx, int ny, int goal) {
    nx_ = nx;
    ny_ = ny;
    const float inf = std::numeric_limits<float>::infinity();
    pot_.assign(blocked.size(), inf);
    done_.assign(blocked.size(), 0);
    using Item = std::pair<float, int>;
    std::vector<Item> storage;
    storage.reserve(blocked.size());
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open(std::greater<Item>(),
                                                                          std::move(storage));
    pot_[goal] = 0.0f;
    open.push({0.0f, goal});
    while (!open.empty()) {
      const auto [pc, c] = open.top();
      open.pop();
      if (done_[c]) continue;
      done_[c] = 1;
      const int x = c % nx, y = c / nx;
      const int n4[4] = {x > 0 ? c - 1 : -1, x < nx - 1 ? c + 1 : -1, y > 0 ? c - nx : -1,
                         y < ny - 1 ? c + nx : -1};
      for (int n : n4) {
        if (n < 0 || blocked[n] || done_[n]) continue;
        const float v = Update(n);
        if (v < pot_[n]) {
          pot_[n] = v;
          open.push({v, n});
        }
      }
    }
  }

  /// Steepest descent over the 8 neighbours (no corner cutting) from `start` to the goal.
  std::vector<int> Path(const std::vector<std::uint8_t>& blocked, int start) const {
    std::vector<int> path{start};
    if (!std::isfinite(pot_[start])) return {};
    int c = start;
    while (pot_[c] > 0.0f && path.size() < pot_.size()) {
      const int x = c % nx_, y = c / nx_;
      int best = -1;
      float best_p = pot_[c];
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int px = x + dx, py = y + dy;
          if ((dx == 0 && dy == 0) || px < 0 || py < 0 || px >= nx_ || py >= ny_) continue;
          const int n = py * nx_ + px;
          if (blocked[n]) continue;
          if (dx != 0 && dy != 0 && (blocked[y * nx_ + px] || blocked[py * nx_ + x])) continue;
          if (pot_[n] < best_p) {
            best_p = pot_[n];
            best = n;
          }
        }
      }
      if (best < 0) return {};
      c = best;
      path.push_back(c);
    }
    return path;
  }

  const std::vector<float>& potential() const { return pot_; }

 private:
  float Update(int n) const {
    const int x = n % nx_, y = n / nx_;
    const float inf = std::numeric_limits<float>::infinity();
    const float l = x > 0 ? pot_[n - 1] : inf, r = x < nx_ - 1 ? pot_[n + 1] : inf;
    const float d = y > 0 ? pot_[n - nx_] : inf, u = y < ny_ - 1 ? pot_[n + nx_] : inf;
    float ta = std::min(l, r), tc = std::min(d, u);
    if (ta > tc) std::swap(ta, tc);
    const float hf = kNeutral;
    const float dc = tc - ta;
    if (!(dc < hf)) return ta + hf;
    const float dd = dc / hf;
    return ta + hf * (-0.2301f * dd * dd + 0.5307f * dd + 0.7040f);
  }

  int nx_ = 0, ny_ = 0;
  std::vector<float> pot_;
  std::vector<std::uint8_t> done_;
};

}  // namespace spott_harmonic_planner::bench
