// What accuracy the path needs (README "Resolved where descent from the robot goes"): for each
// benchmark grid, the default field (multigrid_cg, start focus) solved to tolerances 1e-2 ..
// 1e-6, its iterations, and how far its steepest-descent path from the robot lies from the path
// of the exactly solved field (tolerance 1e-9, every cell judged): the largest distance, in
// cells, of either path's points from the other path, and the length difference. Prints a
// table; nothing is timed.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "scenarios.h"
#include "spott_harmonic_planner/potential_field.h"

namespace shp = spott_harmonic_planner;
using shp::bench::Scenario;

namespace {

// The largest distance of a point of `a` from the polyline `b`.
double Distance(const std::vector<shp::Vec2>& a, const std::vector<shp::Vec2>& b) {
  double worst = 0.0;
  for (const auto& p : a) {
    double best = (p - b.front()).norm();
    for (std::size_t k = 1; k < b.size(); ++k) {
      const shp::Vec2 d = b[k] - b[k - 1];
      const double l2 = d.squaredNorm();
      const double t = l2 > 0.0 ? std::clamp((p - b[k - 1]).dot(d) / l2, 0.0, 1.0) : 0.0;
      best = std::min(best, (p - (b[k - 1] + t * d)).norm());
    }
    worst = std::max(worst, best);
  }
  return worst;
}

void Row(const std::string& name, const Scenario& s) {
  shp::FieldOptions exact_options;
  exact_options.tolerance = 1e-9;
  shp::PotentialField exact(exact_options);
  exact.SetOccupancy(s.raster);
  exact.SetGoalPoint(s.Goal());
  exact.ColdStart();
  exact.Solve(100000);
  const auto reference = exact.DescendPath(s.Robot());
  std::printf("  %-10s %s", name.c_str(),
              exact.report().converged ? "" : "(reference not converged)");
  for (double tolerance : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    shp::FieldOptions o;
    o.tolerance = tolerance;
    shp::PotentialField f(o);
    f.SetOccupancy(s.raster);
    f.SetGoalPoint(s.Goal());
    f.SetStart(s.Robot());
    f.ColdStart();
    const auto report = f.Solve(100000);
    const auto path = f.DescendPath(s.Robot());
    const double off =
        std::max(Distance(path.points, reference.points), Distance(reference.points, path.points));
    std::printf(" | %2d %6.3f %+6.3f%%%s", report.sweeps, off / s.Res(),
                100.0 * (path.length_m / reference.length_m - 1.0),
                report.converged && path.reached_goal ? "" : " FAILED");
  }
  std::printf("\n");
}

}  // namespace

int main() {
  std::printf(
      "Default field at tolerance 1e-2 | 1e-3 | 1e-4 | 1e-5 | 1e-6: iterations, largest distance "
      "(cells) between its path and the exactly solved field's, length difference\n");
  for (int n : {35, 64, 128, 256, 512, 1024}) {
    Row("open " + std::to_string(n), shp::bench::Open(n));
    Row("rect " + std::to_string(n), shp::bench::Rect(n));
  }
  Row("office 70", shp::bench::Office(70, 3, 11, 0.1));
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    Row("office " + std::to_string(seed), shp::bench::Office(128, 3, seed));
  }
  return 0;
}
