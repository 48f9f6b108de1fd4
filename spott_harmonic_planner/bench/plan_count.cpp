// One plan of one benchmark grid, ours or the navfn peer, for instruction counts that do not
// depend on the machine's load (README "Figures"; bench/count_instructions.sh runs it under
// valgrind --tool=callgrind --collect-atstart=no). Only the timed part is collected: the same
// calls plan_bench.cpp times, after one untimed plan that allocates everything.
//   spott_harmonic_planner_plan_count GRID N WHO [MODE] [REPS]
//   GRID  open | rect (n x n, bench/scenarios.h) | office (the stack's 70 x 70 window, N
//         ignored) | corridor20 | corridor50 | corridor100 (5 wide, in an N x N window)
//   WHO   ours | peer
//   MODE  cold (a new map and goal: SetOccupancy, SetGoalPoint, SetStart, ColdStart, Solve,
//         DescendPath) | change (a 3 x 3 obstacle on the path, warm) | shift (the window two
//         cells on, warm); the peer always plans from scratch (navfn's makePlan)
//   REPS  collected plans (default 3); the count per plan is the total / REPS
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_TOGGLE_COLLECT
#endif

#include <cstdio>
#include <cstdlib>
#include <string>

#include "navfn_peer.h"
#include "scenarios.h"
#include "spott_harmonic_planner/potential_field.h"

namespace shp = spott_harmonic_planner;
using shp::bench::Scenario;

namespace {

// As in plan_bench.cpp: one more blocked cell in a far corner makes every map a new one.
spott_map::OccupancyRaster Variant(const spott_map::OccupancyRaster& r) {
  spott_map::OccupancyRaster v = r;
  v.Mark(1, 1, spott_map::Cell::kObstacle);
  return v;
}

bool MakeGrid(const std::string& grid, int n, Scenario* s) {
  if (grid == "open")
    *s = shp::bench::Open(n);
  else if (grid == "rect")
    *s = shp::bench::Rect(n);
  else if (grid == "office")
    *s = shp::bench::Office(70, 3, 11, 0.1);
  else if (grid == "corridor20")
    *s = shp::bench::Corridor(n, 100, 5);
  else if (grid == "corridor50")
    *s = shp::bench::Corridor(n, 250, 5);
  else if (grid == "corridor100")
    *s = shp::bench::Corridor(n, 500, 5);
  else
    return false;
  return true;
}

// plan_bench.cpp's warm changes: a 3 x 3 obstacle half way, or the window 2 cells on.
Scenario Changed(const Scenario& s, bool shift) {
  Scenario c = s;
  if (shift) {
    c.raster = spott_map::OccupancyRaster(s.raster.origin() + spott_map::Vec2(2, 0) * s.Res(),
                                          s.raster.width(), s.raster.height(), s.Res());
    for (int y = 0; y < s.raster.height(); ++y) {
      for (int x = 0; x + 2 < s.raster.width(); ++x) {
        if (s.raster.Blocked(x + 2, y)) c.raster.Mark(x, y, spott_map::Cell::kObstacle);
      }
    }
    c.goal_x -= 2;
    c.robot_x -= 2;
  } else {
    const auto free =
        shp::bench::FreeNear(s.raster, (s.robot_x + s.goal_x) / 2, (s.robot_y + s.goal_y) / 2);
    shp::testing_maps::Block(c.raster, free.first - 1, free.second - 1, free.first + 1,
                             free.second + 1);
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  Scenario s;
  if (argc < 4 || !MakeGrid(argv[1], std::atoi(argv[2]), &s)) {
    std::fprintf(stderr,
                 "usage: %s open|rect|office|corridor20|corridor50|corridor100 N "
                 "ours|peer [cold|change|shift] [REPS]\n",
                 argv[0]);
    return 2;
  }
  const std::string who = argv[3], mode = argc > 4 ? argv[4] : "cold";
  const int reps = argc > 5 ? std::max(1, std::atoi(argv[5])) : 3;
  const auto variant = Variant(s.raster);
  if (who == "peer") {
    shp::bench::NavfnPeer peer;
    const auto a = shp::bench::Lethal(s.raster), b = shp::bench::Lethal(variant);
    const int nx = s.raster.width(), ny = s.raster.height();
    const int robot = s.robot_y * nx + s.robot_x, goal = s.goal_y * nx + s.goal_x;
    peer.MakePlan(b, nx, ny, robot, goal);
    bool ok = true;
    CALLGRIND_TOGGLE_COLLECT;
    for (int r = 0; r < reps; ++r) ok = peer.MakePlan(r % 2 ? b : a, nx, ny, robot, goal) && ok;
    CALLGRIND_TOGGLE_COLLECT;
    std::printf("peer path %d length %.1f cells\n", ok ? 1 : 0, peer.PathLength());
    return 0;
  }
  shp::PotentialField field{shp::FieldOptions{}};
  const auto plan = [&](const spott_map::OccupancyRaster& raster, const Scenario& at) {
    field.SetOccupancy(raster);
    field.SetGoalPoint(at.Goal());
    field.SetStart(at.Robot());
    field.ColdStart();
    field.Solve(100000);
    return field.DescendPath(at.Robot());
  };
  if (mode == "cold") {
    plan(variant, s);
    CALLGRIND_TOGGLE_COLLECT;
    shp::PotentialField::Path path;
    for (int r = 0; r < reps; ++r) path = plan(r % 2 ? variant : s.raster, s);
    CALLGRIND_TOGGLE_COLLECT;
    std::printf("ours iterations %d converged %d path %d\n", field.report().sweeps,
                field.report().converged ? 1 : 0, path.reached_goal ? 1 : 0);
    return 0;
  }
  const Scenario c = Changed(s, mode == "shift");
  int iterations = 0;
  bool reached = false;
  for (int r = 0; r < reps; ++r) {
    plan(s.raster, s);
    const int before = field.report().sweeps;
    CALLGRIND_TOGGLE_COLLECT;
    field.SetOccupancy(c.raster);
    if (mode == "shift") field.SetGoalPoint(c.Goal());
    field.SetStart(c.Robot());
    field.Solve(100000);
    reached = field.DescendPath(c.Robot()).reached_goal;
    CALLGRIND_TOGGLE_COLLECT;
    iterations = field.report().sweeps - before;
  }
  std::printf("ours warm iterations %d converged %d path %d\n", iterations,
              field.report().converged ? 1 : 0, reached ? 1 : 0);
  return 0;
}
