// The peer of the benchmarks: navfn's algorithm (ROS navigation's NavFn, the Dijkstra planner
// NavfnROS::makePlan runs), written here from its published source and description; no code
// copied. What makes navfn fast, kept as navfn has it:
//   - cost translation of the whole grid (free = COST_NEUTRAL 50, lethal = COST_OBS 254) and the
//     outer ring forced to COST_OBS, as setCostmap / setupNavFn do;
//   - float potentials initialised to POT_HIGH (1e10) and float gradient caches reset on every
//     plan (setupNavFn);
//   - the threshold-bucket priority ("curP / nextP / overP"): a cell whose new potential is
//     below the threshold curT goes to the next wave, else to the overflow block; curT grows by
//     priInc = 2 COST_NEUTRAL when the waves run dry; a pending flag per cell; buffers of
//     PRIORITYBUFSIZE = 10000 cells (navfn drops pushes beyond it);
//   - the planar-wave update from the lowest neighbour in x and in y with navfn's quadratic
//     approximation -0.2301 d^2 + 0.5307 d + 0.7040 (d = difference / cost);
//   - propagation from the robot cell until the goal cell has a potential (atStart, as makePlan
//     calls calcNavFnDijkstra(true)), at most max(nx ny / 20, nx + ny) cycles;
//   - the path by calcPath: half-cell steps along the bilinearly interpolated normalised gradient
//     of four cells, following the grid (lowest of 8 neighbours) next to unassigned cells, at
//     most 4 nx steps, from the goal down to the robot (makePlan then reverses it).
// Obstacle handling: lethal cells are never updated or pushed; cells next to them see POT_HIGH.
// No inflation here: the peer gets the same padded grid as the harmonic planner.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace spott_harmonic_planner::bench {

class NavfnPeer {
 public:
  static constexpr std::uint8_t kCostNeutral = 50;
  static constexpr std::uint8_t kCostObstacle = 254;
  static constexpr float kPotHigh = 1.0e10f;
  static constexpr int kPriorityBufferSize = 10000;

  struct Point {
    float x, y;
  };

  /// One makePlan: `blocked` row-major nx x ny (nonzero = lethal); robot and goal cell indices.
  /// Returns false when no path was found (the path is then empty).
  bool MakePlan(const std::vector<std::uint8_t>& blocked, int nx, int ny, int robot, int goal) {
    Resize(nx, ny);
    source_ = robot;
    SetCostmap(blocked);
    SetupNavFn(robot);
    const bool reached = Propagate(std::max(ns_ / 20, nx + ny), goal);
    path_.clear();
    if (!reached && !(pot_[goal] < kPotHigh)) return false;
    const int len = CalcPath(4 * nx, goal);
    if (len <= 0) {
      path_.clear();
      return false;
    }
    std::reverse(path_.begin(), path_.end());
    return true;
  }

  /// The path of the last plan (cell coordinates, robot to goal).
  const std::vector<Point>& path() const { return path_; }
  const std::vector<float>& potential() const { return pot_; }
  int cycles() const { return cycles_; }
  double PathLength() const {
    double len = 0.0;
    for (std::size_t k = 1; k < path_.size(); ++k) {
      len += std::hypot(path_[k].x - path_[k - 1].x, path_[k].y - path_[k - 1].y);
    }
    return len;
  }

 private:
  void Resize(int nx, int ny) {
    if (nx == nx_ && ny == ny_) return;  // navfn keeps its buffers while the size is unchanged
    nx_ = nx;
    ny_ = ny;
    ns_ = nx * ny;
    cost_.assign(ns_, 0);
    pot_.assign(ns_, kPotHigh);
    pending_.assign(ns_, 0);
    gradx_.assign(ns_, 0.0f);
    grady_.assign(ns_, 0.0f);
    for (auto& b : buffers_) b.assign(kPriorityBufferSize, 0);
  }

  void SetCostmap(const std::vector<std::uint8_t>& blocked) {
    const std::uint8_t* in = blocked.data();
    std::uint8_t* out = cost_.data();
    for (int i = 0; i < ns_; ++i) out[i] = in[i] ? kCostObstacle : kCostNeutral;
  }

  void SetupNavFn(int start) {
    for (int i = 0; i < ns_; ++i) {
      pot_[i] = kPotHigh;
      gradx_[i] = grady_[i] = 0.0f;
    }
    for (int x = 0; x < nx_; ++x) cost_[x] = cost_[(ny_ - 1) * nx_ + x] = kCostObstacle;
    for (int y = 0; y < ny_; ++y) cost_[y * nx_] = cost_[y * nx_ + nx_ - 1] = kCostObstacle;
    threshold_ = kCostObstacle;
    cur_ = buffers_[0].data();
    next_ = buffers_[1].data();
    over_ = buffers_[2].data();
    cur_end_ = next_end_ = over_end_ = 0;
    std::memset(pending_.data(), 0, pending_.size());
    pot_[start] = 0.0f;
    Push(cur_, cur_end_, start + 1);
    Push(cur_, cur_end_, start - 1);
    Push(cur_, cur_end_, start - nx_);
    Push(cur_, cur_end_, start + nx_);
    int obstacles = 0;  // navfn counts them (for its statistics): one more pass over the grid
    for (int i = 0; i < ns_; ++i) obstacles += cost_[i] >= kCostObstacle ? 1 : 0;
    obstacles_ = obstacles;
  }

  void Push(int* buffer, int& end, int n) {
    if (n >= 0 && n < ns_ && !pending_[n] && cost_[n] < kCostObstacle &&
        end < kPriorityBufferSize) {
      buffer[end++] = n;
      pending_[n] = 1;
    }
  }

  void UpdateCell(int n) {
    const float l = pot_[n - 1], r = pot_[n + 1], u = pot_[n - nx_], d = pot_[n + nx_];
    float tc = l < r ? l : r;
    float ta = u < d ? u : d;
    if (cost_[n] >= kCostObstacle) return;
    const float hf = static_cast<float>(cost_[n]);
    float dc = tc - ta;
    if (dc < 0) {
      dc = -dc;
      ta = tc;
    }
    float pot;
    if (dc >= hf) {
      pot = ta + hf;
    } else {
      const float q = dc / hf;
      pot = ta + hf * (-0.2301f * q * q + 0.5307f * q + 0.7040f);
    }
    if (!(pot < pot_[n])) return;
    constexpr float kInvSqrt2 = 0.707106781f;
    const float le = kInvSqrt2 * cost_[n - 1], re = kInvSqrt2 * cost_[n + 1];
    const float ue = kInvSqrt2 * cost_[n - nx_], de = kInvSqrt2 * cost_[n + nx_];
    pot_[n] = pot;
    int* buffer = pot < threshold_ ? next_ : over_;
    int& end = pot < threshold_ ? next_end_ : over_end_;
    if (l > pot + le) Push(buffer, end, n - 1);
    if (r > pot + re) Push(buffer, end, n + 1);
    if (u > pot + ue) Push(buffer, end, n - nx_);
    if (d > pot + de) Push(buffer, end, n + nx_);
  }

  // propNavFnDijkstra(cycles, atStart = true): true when the goal cell got a potential.
  bool Propagate(int cycles, int goal) {
    int cycle = 0;
    for (; cycle < cycles; ++cycle) {
      if (cur_end_ == 0 && next_end_ == 0) break;
      for (int k = 0; k < cur_end_; ++k) pending_[cur_[k]] = 0;
      for (int k = 0; k < cur_end_; ++k) UpdateCell(cur_[k]);
      std::swap(cur_, next_);
      cur_end_ = next_end_;
      next_end_ = 0;
      if (cur_end_ == 0) {
        threshold_ += 2.0f * kCostNeutral;
        std::swap(cur_, over_);
        cur_end_ = over_end_;
        over_end_ = 0;
      }
      if (pot_[goal] < kPotHigh) break;
    }
    cycles_ = cycle;
    return pot_[goal] < kPotHigh;
  }

  // gradCell: normalised gradient (positive right and down), cached until the next plan.
  void GradCell(int n) {
    if (gradx_[n] + grady_[n] > 0.0f) return;
    if (n < nx_ || n > ns_ - nx_) return;
    const float cv = pot_[n];
    float dx = 0.0f, dy = 0.0f;
    if (cv >= kPotHigh) {
      if (pot_[n - 1] < kPotHigh) {
        dx = -static_cast<float>(kCostObstacle);
      } else if (pot_[n + 1] < kPotHigh) {
        dx = kCostObstacle;
      }
      if (pot_[n - nx_] < kPotHigh) {
        dy = -static_cast<float>(kCostObstacle);
      } else if (pot_[n + nx_] < kPotHigh) {
        dy = kCostObstacle;
      }
    } else {
      if (pot_[n - 1] < kPotHigh) dx += pot_[n - 1] - cv;
      if (pot_[n + 1] < kPotHigh) dx += cv - pot_[n + 1];
      if (pot_[n - nx_] < kPotHigh) dy += pot_[n - nx_] - cv;
      if (pot_[n + nx_] < kPotHigh) dy += cv - pot_[n + nx_];
    }
    const float norm = std::sqrt(dx * dx + dy * dy);
    if (norm > 0.0f) {
      gradx_[n] = dx / norm;
      grady_[n] = dy / norm;
    }
  }

  // calcPath(n) from `from` (the goal cell) down the potential to the propagation's source.
  int CalcPath(int steps, int from) {
    int stc = from;
    float dx = 0.0f, dy = 0.0f;
    for (int i = 0; i < steps; ++i) {
      const int nearest = std::clamp(
          stc + static_cast<int>(std::round(dx)) + nx_ * static_cast<int>(std::round(dy)), 0,
          ns_ - 1);
      if (pot_[nearest] < kCostNeutral) {
        path_.push_back({static_cast<float>(source_x()), static_cast<float>(source_y())});
        return static_cast<int>(path_.size());
      }
      if (stc < nx_ || stc > ns_ - nx_) return 0;
      path_.push_back({static_cast<float>(stc % nx_) + dx, static_cast<float>(stc / nx_) + dy});
      const int up = stc + nx_, down = stc - nx_;
      const bool boundary =
          pot_[stc] >= kPotHigh || pot_[stc + 1] >= kPotHigh || pot_[stc - 1] >= kPotHigh ||
          pot_[up] >= kPotHigh || pot_[up + 1] >= kPotHigh || pot_[up - 1] >= kPotHigh ||
          pot_[down] >= kPotHigh || pot_[down + 1] >= kPotHigh || pot_[down - 1] >= kPotHigh;
      if (boundary) {
        // Follow the grid: the lowest of the eight neighbours (navfn compares int potentials).
        int best = stc;
        int best_p = static_cast<int>(pot_[stc]);
        const int around[8] = {down - 1, down, down + 1, stc - 1, stc + 1, up - 1, up, up + 1};
        for (int c : around) {
          if (pot_[c] < best_p) {
            best_p = static_cast<int>(pot_[c]);
            best = c;
          }
        }
        stc = best;
        dx = dy = 0.0f;
        if (pot_[stc] >= kPotHigh) return 0;
      } else {
        GradCell(stc);
        GradCell(stc + 1);
        GradCell(up);
        GradCell(up + 1);
        const float x1 = (1.0f - dx) * gradx_[stc] + dx * gradx_[stc + 1];
        const float x2 = (1.0f - dx) * gradx_[up] + dx * gradx_[up + 1];
        const float x = (1.0f - dy) * x1 + dy * x2;
        const float y1 = (1.0f - dx) * grady_[stc] + dx * grady_[stc + 1];
        const float y2 = (1.0f - dx) * grady_[up] + dx * grady_[up + 1];
        const float y = (1.0f - dy) * y1 + dy * y2;
        if (x == 0.0f && y == 0.0f) return 0;
        const float ss = 0.5f / std::sqrt(x * x + y * y);
        dx += x * ss;
        dy += y * ss;
        if (dx > 1.0f) {
          ++stc;
          dx -= 1.0f;
        }
        if (dx < -1.0f) {
          --stc;
          dx += 1.0f;
        }
        if (dy > 1.0f) {
          stc += nx_;
          dy -= 1.0f;
        }
        if (dy < -1.0f) {
          stc -= nx_;
          dy += 1.0f;
        }
      }
    }
    return 0;
  }

  int source_x() const { return source_ % nx_; }
  int source_y() const { return source_ / nx_; }

 private:
  int nx_ = 0, ny_ = 0, ns_ = 0;
  std::vector<std::uint8_t> cost_;
  std::vector<float> pot_, gradx_, grady_;
  std::vector<std::uint8_t> pending_;
  std::vector<int> buffers_[3];
  int *cur_ = nullptr, *next_ = nullptr, *over_ = nullptr;
  int cur_end_ = 0, next_end_ = 0, over_end_ = 0;
  float threshold_ = kCostObstacle;
  int obstacles_ = 0;
  int cycles_ = 0;
  int source_ = 0;  // the robot cell: propagation starts there, calcPath ends there
  std::vector<Point> path_;
};

}  // namespace spott_harmonic_planner::bench
