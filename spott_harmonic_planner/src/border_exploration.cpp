#include "spott_harmonic_planner/border_exploration.h"

#include <limits>
#include <vector>

namespace spott_harmonic_planner {

std::optional<Vec2> NearestReachableBorderCell(const PotentialField& field, const Vec2& start,
                                               const Vec2& target) {
  const auto s = field.CellOf(start);
  const int w = field.width(), h = field.height();
  if (!s || w < 3 || h < 3) return std::nullopt;
  const auto inner = [&](int x, int y) { return x >= 1 && y >= 1 && x <= w - 2 && y <= h - 2; };
  const auto open = [&](int x, int y) { return field.cell(x, y) != FieldCell::kObstacle; };
  if (!inner(s->first, s->second) || !open(s->first, s->second)) return std::nullopt;

  std::vector<bool> seen(static_cast<std::size_t>(w) * h, false);
  std::vector<std::pair<int, int>> stack{*s};
  seen[static_cast<std::size_t>(s->second) * w + s->first] = true;
  std::optional<Vec2> best;
  double best_d = std::numeric_limits<double>::infinity();
  const auto consider = [&](int bx, int by) {
    const Vec2 c = field.CellCentre(bx, by);
    const double d = (c - target).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  };
  static constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    for (int k = 0; k < 4; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (!inner(nx, ny)) {  // the border ring beside a reached inner cell
        consider(nx, ny);
        continue;
      }
      const std::size_t i = static_cast<std::size_t>(ny) * w + nx;
      if (seen[i] || !open(nx, ny)) continue;
      seen[i] = true;
      stack.emplace_back(nx, ny);
    }
  }
  return best;
}

}  // namespace spott_harmonic_planner
