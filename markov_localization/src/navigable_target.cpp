#include "markov_localization/navigable_target.h"

#include <cmath>
#include <limits>

namespace markov_localization {

double Clearance(const MapModel& map, const Vec2& p, double max_m) {
  double best = max_m;
  for (int k = 0; k < 32; ++k) best = std::min(best, map.RayCast(p, k * M_PI / 16.0, max_m));
  return best;
}

std::optional<Vec2> NavigableTarget(const MapModel& map, const Vec2& target, double clearance_m,
                                    double search_radius_m, double step_m) {
  const int n = static_cast<int>(std::floor(search_radius_m / step_m));
  std::optional<Vec2> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (int j = -n; j <= n; ++j) {
    for (int i = -n; i <= n; ++i) {
      const double d = step_m * std::hypot(i, j);
      if (d > search_radius_m || d >= best_d) continue;
      const Vec2 p = target + Vec2(i * step_m, j * step_m);
      if (!map.IsStateAt(p) || Clearance(map, p, clearance_m + 0.01) < clearance_m) continue;
      best = p;
      best_d = d;
    }
  }
  return best;
}

}  // namespace markov_localization
