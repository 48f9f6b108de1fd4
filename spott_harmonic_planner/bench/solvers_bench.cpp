// Speed of the harmonic solvers against a navfn-style Dijkstra wavefront (bench/wavefront_peer.h)
// on the same padded grids, in one run. Each benchmark times the peer on its grid before its own
// loop and reports peer_us and ratio = ours / peer. Questions answered (README "Figures"):
//   Paper35/*       the paper's case: 35 x 35 window, 3 obstacles and a goal, cold converge
//   FirstAnswer35   first usable steering answer (heuristic potential, before any sweep)
//   Office/*        256 and 512 office windows, cold converge
//   Warm256/*       re-converge after one obstacle appears (warm start)
//   Scaling/*       cold converge per solver, grids 32 .. 1024
// Convergence: absolute max residual of p below 1e-6 unless the name says Relative (1e-6
// relative, every cell to its own magnitude). Path quality on 100 random maps is printed first.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>

#include "../test/test_maps.h"
#include "spott_harmonic_planner/potential_field.h"
#include "wavefront_peer.h"

namespace shp = spott_harmonic_planner;
using shp::testing_maps::Block;
using shp::testing_maps::RandomOffice;

namespace {

// Thread CPU time (us): the machine is shared, so ours and the peer's are both CPU time (the
// ratio is then not skewed by other processes' load; Google Benchmark's CPU column agrees).
double CpuMicroseconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e6 + t.tv_nsec * 1e-3;
}

struct Scenario {
  spott_map::OccupancyRaster raster;
  shp::Vec2 goal;  // cell centre coordinates (resolution 1)
  shp::Vec2 robot;
};

Scenario Paper35() {
  Scenario s{shp::testing_maps::EmptyRaster(35, 35), shp::Vec2(30.5, 17.5), shp::Vec2(3.5, 17.5)};
  Block(s.raster, 8, 11, 12, 22);  // three padded obstacles between robot and goal
  Block(s.raster, 17, 2, 21, 14);
  Block(s.raster, 18, 21, 23, 30);
  return s;
}

// Free cell nearest to a wanted spot (searching outward).
shp::Vec2 FreeNear(const spott_map::OccupancyRaster& r, int x, int y) {
  for (int rad = 0; rad < r.width(); ++rad) {
    for (int dy = -rad; dy <= rad; ++dy) {
      for (int dx = -rad; dx <= rad; ++dx) {
        const int px = x + dx, py = y + dy;
        if (px > 0 && py > 0 && px < r.width() - 1 && py < r.height() - 1 && !r.Blocked(px, py)) {
          return shp::Vec2(px + 0.5, py + 0.5);
        }
      }
    }
  }
  return shp::Vec2(x + 0.5, y + 0.5);
}

Scenario Office(int n, std::uint32_t seed = 3) {
  Scenario s{RandomOffice(n, std::max(3, n / 12), 2 + n / 256, 2, seed), {}, {}};
  s.goal = FreeNear(s.raster, n - n / 8, n / 2);
  s.robot = FreeNear(s.raster, n / 8, n / 2);
  return s;
}

std::vector<std::uint8_t> Blocked(const spott_map::OccupancyRaster& r) {
  std::vector<std::uint8_t> b(static_cast<std::size_t>(r.width()) * r.height());
  for (int y = 0; y < r.height(); ++y) {
    for (int x = 0; x < r.width(); ++x) {
      const bool border = x == 0 || y == 0 || x == r.width() - 1 || y == r.height() - 1;
      b[static_cast<std::size_t>(y) * r.width() + x] = border || r.Blocked(x, y);
    }
  }
  return b;
}

// Median CPU time (us) of the peer's plan on the scenario.
double PeerMicroseconds(const Scenario& s) {
  const auto blocked = Blocked(s.raster);
  const int goal = static_cast<int>(s.goal.y()) * s.raster.width() + static_cast<int>(s.goal.x());
  shp::bench::WavefrontPeer peer;
  std::vector<double> t;
  const int reps = s.raster.width() >= 512 ? 7 : 31;
  for (int i = 0; i < reps; ++i) {
    const double a = CpuMicroseconds();
    peer.Plan(blocked, s.raster.width(), s.raster.height(), goal);
    benchmark::DoNotOptimize(peer.potential().data());
    t.push_back(CpuMicroseconds() - a);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

shp::FieldOptions Options(shp::SolverKind kind, shp::ResidualNorm norm, shp::Stencil stencil) {
  shp::FieldOptions o;
  o.solver.kind = kind;
  o.solver.stencil = stencil;
  o.norm = norm;
  o.tolerance = 1e-6;
  return o;
}

void RunCold(benchmark::State& state, const Scenario& s, const shp::FieldOptions& o) {
  const double peer_us = PeerMicroseconds(s);
  shp::PotentialField field(o);
  int sweeps = 0;
  bool converged = true;
  const double a = CpuMicroseconds();
  std::int64_t n = 0;
  for (auto _ : state) {
    field.SetOccupancy(s.raster);  // a new window: mask, clearance, solver set-up
    field.SetGoalPoint(s.goal);
    field.ColdStart();
    const auto r = field.Solve(100000);
    sweeps = r.sweeps;
    converged = converged && r.converged;
    benchmark::DoNotOptimize(field.values().data());
    ++n;
  }
  const double ours_us = (CpuMicroseconds() - a) / n;
  state.counters["peer_us"] = peer_us;
  state.counters["ratio"] = ours_us / peer_us;
  state.counters["sweeps"] = sweeps;
  state.counters["converged"] = converged ? 1 : 0;
  state.counters["cells"] = s.raster.width() * s.raster.height();
}

void BM_Paper35(benchmark::State& state) {
  RunCold(state, Paper35(),
          Options(static_cast<shp::SolverKind>(state.range(0)),
                  static_cast<shp::ResidualNorm>(state.range(1)),
                  static_cast<shp::Stencil>(state.range(2))));
  state.SetLabel(std::string(shp::ToString(static_cast<shp::SolverKind>(state.range(0)))) +
                 (state.range(1) ? " relative" : " absolute") +
                 (state.range(2) ? " nine_point" : " five_point"));
}
BENCHMARK(BM_Paper35)->ArgsProduct({{0, 1, 2, 3}, {0, 1}, {0, 1}})->Unit(benchmark::kMicrosecond);

// The first steering answer: the heuristic potential at the robot, window and goal loaded.
void BM_FirstAnswer35(benchmark::State& state) {
  const Scenario s = Paper35();
  shp::PotentialField field(
      Options(shp::SolverKind::kMultigrid, shp::ResidualNorm::kAbsolute, shp::Stencil::kFivePoint));
  field.SetOccupancy(s.raster);
  field.SetGoalPoint(s.goal);
  for (auto _ : state) benchmark::DoNotOptimize(field.HeuristicDirection(s.robot));
  state.counters["peer_us"] = PeerMicroseconds(s);
}
BENCHMARK(BM_FirstAnswer35)->Unit(benchmark::kMicrosecond);

// The same answer counted from a new goal (SetGoalPoint rebuilds the mask: O(cells)).
void BM_FirstAnswerWithNewGoal35(benchmark::State& state) {
  const Scenario s = Paper35();
  shp::PotentialField field(
      Options(shp::SolverKind::kMultigrid, shp::ResidualNorm::kAbsolute, shp::Stencil::kFivePoint));
  field.SetOccupancy(s.raster);
  for (auto _ : state) {
    field.SetGoalPoint(s.goal);
    benchmark::DoNotOptimize(field.HeuristicDirection(s.robot));
  }
}
BENCHMARK(BM_FirstAnswerWithNewGoal35)->Unit(benchmark::kMicrosecond);

void BM_Office(benchmark::State& state) {
  RunCold(state, Office(static_cast<int>(state.range(1))),
          Options(static_cast<shp::SolverKind>(state.range(0)), shp::ResidualNorm::kAbsolute,
                  shp::Stencil::kFivePoint));
  state.SetLabel(shp::ToString(static_cast<shp::SolverKind>(state.range(0))));
}
BENCHMARK(BM_Office)->ArgsProduct({{0, 1, 2, 3}, {256, 512}})->Unit(benchmark::kMillisecond);

void BM_Warm256(benchmark::State& state) {
  const auto kind = static_cast<shp::SolverKind>(state.range(0));
  const Scenario s = Office(256);
  Scenario changed = s;
  const shp::Vec2 mid = 0.5 * (s.goal + s.robot);
  Block(changed.raster, static_cast<int>(mid.x()) - 4, static_cast<int>(mid.y()) + 6,
        static_cast<int>(mid.x()) + 4, static_cast<int>(mid.y()) + 14);  // a sensed obstacle
  shp::PotentialField field(Options(kind, shp::ResidualNorm::kAbsolute, shp::Stencil::kFivePoint));
  field.SetOccupancy(s.raster);
  field.SetGoalPoint(s.goal);
  field.ColdStart();
  field.Solve(100000);
  const std::vector<double> converged = field.values();
  int sweeps = 0;
  for (auto _ : state) {
    state.PauseTiming();
    field.SetOccupancy(s.raster);
    field.ColdStart();
    field.Solve(100000);
    const int before = field.report().sweeps;
    state.ResumeTiming();
    field.SetOccupancy(changed.raster);  // keeps the converged values
    const auto r = field.Solve(100000);
    sweeps = r.sweeps - before;
  }
  state.counters["peer_us"] = PeerMicroseconds(changed);
  state.counters["sweeps"] = sweeps;
  state.SetLabel(shp::ToString(kind));
}
BENCHMARK(BM_Warm256)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_Scaling(benchmark::State& state) {
  RunCold(state, Office(static_cast<int>(state.range(1))),
          Options(static_cast<shp::SolverKind>(state.range(0)), shp::ResidualNorm::kAbsolute,
                  shp::Stencil::kFivePoint));
  state.SetLabel(shp::ToString(static_cast<shp::SolverKind>(state.range(0))));
}
BENCHMARK(BM_Scaling)
    ->ArgsProduct({{2, 3}, {32, 64, 128, 256, 512, 1024}})
    ->ArgsProduct({{0, 1}, {32, 64, 128, 256, 512}})
    ->Unit(benchmark::kMillisecond);

// --- Path quality on 100 random office-like maps (printed before the timings).
int ChamferClearance(const std::vector<std::uint8_t>& blocked, int nx, int ny, int cell,
                     std::vector<float>& dt) {
  if (dt.empty()) {
    dt.assign(blocked.size(), 1e9f);
    for (std::size_t i = 0; i < blocked.size(); ++i) {
      if (blocked[i]) dt[i] = 0;
    }
    for (int pass = 0; pass < 2; ++pass) {
      for (int k = 0; k < nx * ny; ++k) {
        const int i = pass == 0 ? k : nx * ny - 1 - k;
        const int x = i % nx, y = i / nx, s = pass == 0 ? -1 : 1;
        const auto relax = [&](int dx, int dy, float w) {
          const int px = x + dx, py = y + dy;
          if (px >= 0 && py >= 0 && px < nx && py < ny)
            dt[i] = std::min(dt[i], dt[py * nx + px] + w);
        };
        relax(s, 0, 1.0f);
        relax(0, s, 1.0f);
        relax(s, s, 1.41421356f);
        relax(-s, s, 1.41421356f);
      }
    }
  }
  return static_cast<int>(dt[cell]);
}

void PrintPathQuality() {
  const int n = 128;
  double ratio_sum = 0.0, worst_ratio = 0.0, clearance_gain_sum = 0.0;
  int maps = 0, better_by_one = 0;
  std::mt19937 rng(2024);
  for (std::uint32_t seed = 100; maps < 100 && seed < 1000; ++seed) {
    Scenario s{RandomOffice(n, 10, 2, 2, seed), {}, {}};
    std::uniform_int_distribution<int> pos(2, n - 3);
    s.goal = FreeNear(s.raster, pos(rng), pos(rng));
    s.robot = FreeNear(s.raster, pos(rng), pos(rng));
    if ((s.goal - s.robot).norm() < n / 3.0) continue;
    shp::PotentialField field(Options(shp::SolverKind::kMultigrid, shp::ResidualNorm::kRelative,
                                      shp::Stencil::kFivePoint));
    field.SetOccupancy(s.raster);
    field.SetGoalPoint(s.goal);
    field.ColdStart();
    if (std::getenv("DEBUG_QUALITY")) std::fprintf(stderr, "seed %u solving\n", seed);
    if (!field.Solve(100000).converged) continue;
    if (std::getenv("DEBUG_QUALITY"))
      std::fprintf(stderr, "seed %u solved %d\n", seed, field.report().sweeps);
    const auto path = field.DescendPath(s.robot);
    if (!path.reached_goal) continue;  // unreachable from this start: skip the map
    const auto blocked = Blocked(s.raster);
    shp::bench::WavefrontPeer peer;
    const int goal = static_cast<int>(s.goal.y()) * n + static_cast<int>(s.goal.x());
    const int start = static_cast<int>(s.robot.y()) * n + static_cast<int>(s.robot.x());
    peer.Plan(blocked, n, n, goal);
    const auto cells = peer.Path(blocked, start);
    if (cells.empty()) continue;
    double peer_len = 0.0;
    std::vector<float> dt;
    int peer_clear = 1 << 30, ours_clear = 1 << 30;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (k > 0) {
        const int dx = cells[k] % n - cells[k - 1] % n, dy = cells[k] / n - cells[k - 1] / n;
        peer_len += std::hypot(dx, dy);
      }
      peer_clear = std::min(peer_clear, ChamferClearance(blocked, n, n, cells[k], dt));
    }
    for (const auto& p : path.points) {
      const int cell = static_cast<int>(p.y()) * n + static_cast<int>(p.x());
      ours_clear = std::min(ours_clear, ChamferClearance(blocked, n, n, cell, dt));
    }
    const double ratio = path.length_m / std::max(peer_len, 1.0);
    ratio_sum += ratio;
    worst_ratio = std::max(worst_ratio, ratio);
    clearance_gain_sum += ours_clear - peer_clear;
    better_by_one += ours_clear - peer_clear >= 1 ? 1 : 0;
    ++maps;
  }
  std::printf(
      "Path quality, %d random %dx%d office maps (padded 2 cells), harmonic (multigrid, relative "
      "1e-6) vs Dijkstra wavefront peer:\n  length ratio mean %.3f worst %.3f (target <= 1.10)\n"
      "  min clearance gain mean %.2f cells; maps with >= 1 cell more: %d/%d (target: >= 1 "
      "cell)\n\n",
      maps, n, n, ratio_sum / maps, worst_ratio, clearance_gain_sum / maps, better_by_one, maps);
}

}  // namespace

int main(int argc, char** argv) {
  if (!std::getenv("SKIP_PATH_QUALITY")) PrintPathQuality();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
