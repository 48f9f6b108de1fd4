// The harmonic planner against navfn's algorithm (bench/navfn_peer.h) on the same grids, in one
// program, CPU time (README "Figures"). Every timed benchmark also times the peer on the same
// grid (median of its own repetitions, thread CPU time) and reports:
//   peer_us    the peer's plan (navfn's makePlan: cost translation, Dijkstra, path)
//   ratio      ours / peer
//   passes     ours in read+write passes over the window (double), the yardstick
//   sweeps     solver iterations; converged: 1 when the field met the tolerance
// Ours is the library's default field (= the node's: multigrid_cg, relative residual 1e-6),
// timed as a plan: SetOccupancy (a new map), SetGoalPoint, ColdStart, Solve, DescendPath.
//   Cold/{open,rect}/n     grids of 35 .. 1024 cells
//   Corridor/ratio/window  straight 5-wide corridors of 20:1, 50:1, 100:1 in windows 128 .. 1024
//   Warm/{change,shift}/n  re-convergence after a 3 x 3 obstacle on the path / a 2-cell window
//                          shift (counter cold_us: the cold plan of the same grid, to_cold)
//   RealCase/{cold,warm}   the stack's window: 70 x 70 cells of 0.1 m, office-like
// Printed first (not timed): path quality on the rectangle grids, and the longest corridor with
// a full path for ours and the peer.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "navfn_peer.h"
#include "scenarios.h"
#include "spott_harmonic_planner/potential_field.h"

namespace shp = spott_harmonic_planner;
using shp::bench::NavfnPeer;
using shp::bench::Scenario;

namespace {

double CpuUs() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e6 + t.tv_nsec * 1e-3;
}

double MedianUs(const std::function<void()>& fn, int reps) {
  std::vector<double> t;
  for (int i = 0; i < reps; ++i) {
    const double a = CpuUs();
    fn();
    t.push_back(CpuUs() - a);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

int Reps(const Scenario& s) {
  const long cells = static_cast<long>(s.raster.width()) * s.raster.height();
  return cells >= 512 * 512 ? 9 : cells >= 128 * 128 ? 31 : 101;
}

// The same grid with one more blocked cell in a far corner: alternating the two makes every
// SetOccupancy a new map (nothing can be kept from the last plan).
spott_map::OccupancyRaster Variant(const spott_map::OccupancyRaster& r) {
  spott_map::OccupancyRaster v = r;
  v.Mark(1, 1, spott_map::Cell::kObstacle);
  return v;
}

double PeerUs(const Scenario& s) {
  const auto a = shp::bench::Lethal(s.raster), b = shp::bench::Lethal(Variant(s.raster));
  NavfnPeer peer;
  const int nx = s.raster.width();
  const int robot = s.robot_y * nx + s.robot_x, goal = s.goal_y * nx + s.goal_x;
  bool flip = false;
  return MedianUs(
      [&]() {
        flip = !flip;
        peer.MakePlan(flip ? a : b, nx, s.raster.height(), robot, goal);
        benchmark::DoNotOptimize(peer.path().data());
      },
      Reps(s));
}

// One read + write pass over the window in double (y = 0.5 x).
double PassUs(const Scenario& s) {
  std::vector<double> x(static_cast<std::size_t>(s.raster.width()) * s.raster.height(), 1.0),
      y(x.size());
  return MedianUs(
      [&]() {
        for (std::size_t i = 0; i < x.size(); ++i) y[i] = 0.5 * x[i];
        benchmark::DoNotOptimize(y.data());
      },
      Reps(s));
}

struct PlanResult {
  shp::IterationReport report;
  bool reached = false;
};

PlanResult ColdPlan(shp::PotentialField& field, const spott_map::OccupancyRaster& raster,
                    const Scenario& s) {
  field.SetOccupancy(raster);
  field.SetGoalPoint(s.Goal());
  field.SetStart(s.Robot());  // as navfn's makePlan gets the start
  field.ColdStart();
  PlanResult r;
  r.report = field.Solve(100000);
  r.reached = field.DescendPath(s.Robot()).reached_goal;
  return r;
}

void Report(benchmark::State& state, const Scenario& s, double ours_us, const PlanResult& r) {
  const double peer = PeerUs(s);
  state.counters["peer_us"] = peer;
  state.counters["ratio"] = ours_us / peer;
  state.counters["passes"] = ours_us / PassUs(s);
  state.counters["sweeps"] = r.report.sweeps;
  state.counters["converged"] = r.report.converged && r.reached ? 1 : 0;
}

// Times the cold plan in the benchmark loop (CPU time); returns ours in us (mean).
double RunCold(benchmark::State& state, const Scenario& s, PlanResult* last) {
  shp::PotentialField field{shp::FieldOptions{}};
  const auto variant = Variant(s.raster);
  bool flip = false;
  const double a = CpuUs();
  std::int64_t n = 0;
  for (auto _ : state) {
    flip = !flip;
    *last = ColdPlan(field, flip ? s.raster : variant, s);
    benchmark::DoNotOptimize(field.values().data());
    ++n;
  }
  return (CpuUs() - a) / static_cast<double>(n);
}

void BM_Cold(benchmark::State& state) {
  const int n = static_cast<int>(state.range(1));
  const Scenario s = state.range(0) == 0 ? shp::bench::Open(n) : shp::bench::Rect(n);
  PlanResult r;
  const double us = RunCold(state, s, &r);
  Report(state, s, us, r);
  state.SetLabel(state.range(0) == 0 ? "open" : "rect");
}
BENCHMARK(BM_Cold)
    ->ArgsProduct({{0, 1}, {35, 64, 128, 256, 512, 1024}})
    ->Unit(benchmark::kMicrosecond);

void BM_Corridor(benchmark::State& state) {
  const int ratio = static_cast<int>(state.range(0)), window = static_cast<int>(state.range(1));
  const Scenario s = shp::bench::Corridor(window, 5 * ratio, 5);
  PlanResult r;
  const double us = RunCold(state, s, &r);
  Report(state, s, us, r);
  state.counters["free_cells"] = 5.0 * 5 * ratio;
}
BENCHMARK(BM_Corridor)
    ->Args({20, 128})
    ->Args({20, 256})
    ->Args({20, 512})
    ->Args({20, 1024})
    ->Args({50, 256})
    ->Args({50, 512})
    ->Args({50, 1024})
    ->Args({100, 512})
    ->Args({100, 1024})
    ->Unit(benchmark::kMicrosecond);

// A 3 x 3 obstacle appears on the path half way (a sensed obstacle), or the window moves by two
// cells (the robot advanced; the goal stays put in the map): re-converge from the last field.
void Warm(benchmark::State& state, const Scenario& s, bool shift) {
  Scenario changed = s;
  if (shift) {
    changed.raster = spott_map::OccupancyRaster(s.raster.origin() + spott_map::Vec2(2, 0) * s.Res(),
                                                s.raster.width(), s.raster.height(), s.Res());
    for (int y = 0; y < s.raster.height(); ++y) {
      for (int x = 0; x + 2 < s.raster.width(); ++x) {
        if (s.raster.Blocked(x + 2, y)) changed.raster.Mark(x, y, spott_map::Cell::kObstacle);
      }
    }
    changed.goal_x -= 2;
    changed.robot_x -= 2;
  } else {
    const int mx = (s.robot_x + s.goal_x) / 2, my = (s.robot_y + s.goal_y) / 2;
    const auto free = shp::bench::FreeNear(s.raster, mx, my);
    shp::testing_maps::Block(changed.raster, free.first - 1, free.second - 1, free.first + 1,
                             free.second + 1);
  }
  shp::PotentialField field{shp::FieldOptions{}};
  PlanResult r;
  const double cold_us = MedianUs([&]() { r = ColdPlan(field, s.raster, s); }, Reps(s));
  std::int64_t n = 0;
  double total = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    ColdPlan(field, s.raster, s);
    const int before = field.report().sweeps;
    state.ResumeTiming();
    const double a = CpuUs();
    field.SetOccupancy(changed.raster);
    if (shift) field.SetGoalPoint(changed.Goal());  // same point in the map, new cell
    field.SetStart(changed.Robot());
    r.report = field.Solve(100000);
    r.reached = field.DescendPath(changed.Robot()).reached_goal;
    total += CpuUs() - a;
    r.report.sweeps -= before;
    ++n;
  }
  const double us = total / static_cast<double>(n);
  Report(state, changed, us, r);
  state.counters["cold_us"] = cold_us;
  state.counters["to_cold"] = us / cold_us;
}

void BM_Warm(benchmark::State& state) {
  const int n = static_cast<int>(state.range(1));
  Warm(state, shp::bench::Rect(n), state.range(0) == 1);
  state.SetLabel(state.range(0) == 1 ? "shift" : "change");
}
BENCHMARK(BM_Warm)->ArgsProduct({{0, 1}, {70, 256}})->Unit(benchmark::kMicrosecond);

// The stack: 7 m windows of 0.1 m cells (padding 0.325 m = 3 cells), office-like.
Scenario RealCase() { return shp::bench::Office(70, 3, 11, 0.1); }

void BM_RealCaseCold(benchmark::State& state) {
  const Scenario s = RealCase();
  PlanResult r;
  const double us = RunCold(state, s, &r);
  Report(state, s, us, r);
}
BENCHMARK(BM_RealCaseCold)->Unit(benchmark::kMicrosecond);

void BM_RealCaseWarm(benchmark::State& state) { Warm(state, RealCase(), false); }
BENCHMARK(BM_RealCaseWarm)->Unit(benchmark::kMicrosecond);

// --- Printed before the timings.

// Clearance (cells, chamfer 1 / sqrt 2 between centres) of every cell to the nearest lethal one.
std::vector<float> ClearanceMap(const std::vector<std::uint8_t>& lethal, int nx, int ny) {
  std::vector<float> d(lethal.size(), 1e9f);
  for (std::size_t i = 0; i < lethal.size(); ++i) {
    if (lethal[i]) d[i] = 0.0f;
  }
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < nx * ny; ++k) {
      const int i = pass == 0 ? k : nx * ny - 1 - k;
      const int x = i % nx, y = i / nx, s = pass == 0 ? -1 : 1;
      const auto relax = [&](int dx, int dy, float w) {
        const int px = x + dx, py = y + dy;
        if (px >= 0 && py >= 0 && px < nx && py < ny) d[i] = std::min(d[i], d[py * nx + px] + w);
      };
      relax(s, 0, 1.0f);
      relax(0, s, 1.0f);
      relax(s, s, 1.41421356f);
      relax(-s, s, 1.41421356f);
    }
  }
  return d;
}

// Segments of a path that meet a lethal cell (sampled every 1/100 cell); points in cell units.
template <typename P>
int CuttingSteps(const std::vector<P>& pts, const std::vector<std::uint8_t>& lethal, int nx,
                 double scale, double offset) {
  int cutting = 0;
  for (std::size_t k = 1; k < pts.size(); ++k) {
    const double ax = pts[k - 1].x() * scale + offset, ay = pts[k - 1].y() * scale + offset;
    const double bx = pts[k].x() * scale + offset, by = pts[k].y() * scale + offset;
    const int samples = 1 + static_cast<int>(100 * std::hypot(bx - ax, by - ay));
    for (int j = 0; j <= samples; ++j) {
      const double t = static_cast<double>(j) / samples;
      const int x = static_cast<int>(std::floor(ax + t * (bx - ax)));
      const int y = static_cast<int>(std::floor(ay + t * (by - ay)));
      if (lethal[static_cast<std::size_t>(y) * nx + x]) {
        ++cutting;
        break;
      }
    }
  }
  return cutting;
}

struct XY {
  double px, py;
  double x() const { return px; }
  double y() const { return py; }
};

void PrintPathQuality() {
  std::printf(
      "Path quality on the rectangle grids (ours: default field, DescendPath; navfn peer: "
      "calcPath)\n  %6s %8s %8s %6s %9s %9s %7s %7s\n",
      "n", "ours_m", "navfn_m", "length", "ours_clr", "navfn_clr", "cuts", "n_cuts");
  for (int n : {35, 64, 128, 256, 512, 1024}) {
    const Scenario s = shp::bench::Rect(n);
    shp::PotentialField field{shp::FieldOptions{}};
    ColdPlan(field, s.raster, s);
    const auto path = field.DescendPath(s.Robot());
    const auto lethal = shp::bench::Lethal(s.raster);
    NavfnPeer peer;
    peer.MakePlan(lethal, n, n, s.robot_y * n + s.robot_x, s.goal_y * n + s.goal_x);
    const auto d = ClearanceMap(lethal, n, n);
    const auto clearance = [&](double x, double y) {  // cell coordinates
      return d[static_cast<std::size_t>(std::floor(y)) * n + static_cast<int>(std::floor(x))];
    };
    float ours_clear = 1e9f, peer_clear = 1e9f;
    for (const auto& p : path.points) ours_clear = std::min(ours_clear, clearance(p.x(), p.y()));
    std::vector<XY> peer_pts;
    for (const auto& p : peer.path()) {
      // navfn's path coordinates are cell indices plus offsets (cell centre at +0.5).
      peer_pts.push_back({p.x + 0.5, p.y + 0.5});
      peer_clear = std::min(peer_clear, clearance(p.x + 0.5, p.y + 0.5));
    }
    const int cuts = CuttingSteps(path.points, lethal, n, 1.0, 0.0);
    const int peer_cuts = CuttingSteps(peer_pts, lethal, n, 1.0, 0.0);
    std::printf("  %6d %8.1f %8.1f %6.3f %9.2f %9.2f %7d %7d%s\n", n, path.length_m,
                peer.PathLength(), path.length_m / peer.PathLength(), ours_clear, peer_clear, cuts,
                peer_cuts, path.reached_goal ? "" : "  (ours did not reach the goal)");
  }
  std::printf(
      "  (clearance: distance in cells from the path's cells to the nearest lethal cell's "
      "centre)\n\n");
}

void PrintLongestCorridor() {
  std::printf(
      "Long corridors, 5 wide, window (length + 2) x 7: converged / full path (ours), path (navfn "
      "peer)\n  %7s %10s %10s %14s %10s\n",
      "ratio", "converged", "ours_path", "ln p far end", "navfn");
  for (int ratio : {100, 250, 285, 300, 350, 400, 1000, 1200}) {
    const int length = 5 * ratio;
    Scenario s{shp::testing_maps::EmptyRaster(length + 2, 7)};
    s.goal_x = 1;
    s.goal_y = 3;
    s.robot_x = length;
    s.robot_y = 3;
    shp::PotentialField field{shp::FieldOptions{}};
    field.SetOccupancy(s.raster);
    field.SetGoalSegment({spott_map::Vec2(0, 0), spott_map::Vec2(0, 7)}, 0.6);
    field.ColdStart();
    const auto r = field.Solve(100000);
    const auto path = field.DescendPath(s.Robot());
    NavfnPeer peer;
    // navfn gets the same goal: the whole left end (its cells 1, 1 .. 1, 5 all at 0 would need a
    // multi-cell goal; the middle cell is used, one cell longer than ours at most).
    const bool ok =
        peer.MakePlan(shp::bench::Lethal(s.raster), length + 2, 7,
                      s.robot_y * (length + 2) + s.robot_x, s.goal_y * (length + 2) + s.goal_x);
    std::printf("  %5d:1 %10s %10s %14.1f %10s\n", ratio, r.converged ? "yes" : "no",
                path.reached_goal ? "yes" : "no", field.LogGoalProbability(length, 3),
                ok ? "yes" : "no");
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  PrintPathQuality();
  PrintLongestCorridor();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
