// Update cost of the grid (README, "Figures"): full sensor update, motion update and selective
// update once localized, over a 30 x 30 m building at 15 cm and 2 degrees (the paper's 7.2
// million states) with a 24-beam sonar ring, and over bonn_department.
//
// Targets (issue 7): full sensor update < 100 ms, motion update < 15 ms, selective update when
// localized < 3.5 ms. The paper: < 0.1 s per scan on a 200 MHz Pentium Pro when localized.
// Peer: AMCL (the ROS particle filter) is not in Debian bookworm and cannot be run here; the
// issue's AMCL figure (about 0.5 ms per update, 100,000 particles from a uniform start) is
// printed as a counter for comparison, not measured.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <thread>

#include "../src/update_kernels.h"
#include "../src/worker_pool.h"
#include "markov_localization/markov_grid.h"
#include "spott_map/world_loader.h"

namespace ml = markov_localization;

namespace {

struct Setup {
  ml::MapModel map;
  ml::SensorModelParameters sp;
  std::unique_ptr<ml::SensorModel> sensor;
  ml::Pose2 inside;  // a pose to localize at
};

// 30 x 30 m: 200 x 200 cells of 15 cm; outer walls and a 6 x 6 grid of 5 m rooms with 1 m gaps.
Setup& Building30() {
  static Setup* s = [] {
    auto* s = new Setup;
    const int n = 200;
    std::vector<std::int8_t> data(n * n, 0);
    for (int iy = 0; iy < n; ++iy)
      for (int ix = 0; ix < n; ++ix) {
        const bool border = ix == 0 || iy == 0 || ix == n - 1 || iy == n - 1;
        const bool wall_x = ix % 33 == 0 && (iy % 33) > 6;  // walls with 1 m openings
        const bool wall_y = iy % 33 == 0 && (ix % 33) > 6 && ix < 150;
        if (border || wall_x || wall_y) data[iy * n + ix] = 100;
      }
    s->map = ml::MapModel::FromOccupancy(ml::Vec2(0, 0), n, n, 0.15, data, 50, 0.0);
    s->sp.beam_angles_rad = ml::SonarRingAngles(24);
    s->sp.max_range_m = 5.0;
    s->sensor = std::make_unique<ml::SensorModel>(s->map, 180, s->sp);
    s->inside = ml::Pose2{12.0, 13.0, 0.3};
    return s;
  }();
  return *s;
}

Setup& Bonn() {
  static Setup* s = [] {
    auto* s = new Setup;
    auto world = spott_map::LoadWorldFile(std::string(WORLDS_DIR) + "/bonn_department.yaml");
    s->map = ml::MapModel::FromWorld(*world.world, ml::MapModelParameters{});
    s->sp.beam_angles_rad = ml::SonarRingAngles(24);
    s->sp.max_range_m = 5.0;
    s->sensor = std::make_unique<ml::SensorModel>(s->map, 180, s->sp);
    s->inside = ml::Pose2{17.5, 5.0, -M_PI / 2};
    return s;
  }();
  return *s;
}

Setup& Pick(int which) { return which == 0 ? Building30() : Bonn(); }

std::vector<double> Scan(const Setup& s, const ml::Pose2& pose) {
  std::vector<double> r;
  for (double a : s.sp.beam_angles_rad)
    r.push_back(s.map.RayCast(pose.Position(), pose.yaw + a, 5.0));
  return r;
}

void Counters(benchmark::State& state, const ml::MarkovGrid& grid) {
  state.SetLabel(std::string(ml::kernels::IsaName(ml::kernels::ActiveIsa())) +
                 (ml::WorkerThreadsEnabled() ? ", 2 threads" : ", 1 thread"));
  state.counters["states_M"] = grid.NumStates() / 1e6;
  state.counters["grid_cells_M"] = grid.nx() * grid.ny() * grid.nt() / 1e6;
  state.counters["amcl_issue_ms"] = 0.5;  // quoted from the issue, not measured here
}

// Eq. (2) over every state of a uniform belief, once per iteration.
void FullSensorUpdates(benchmark::State& state, Setup& s) {
  ml::MarkovGridParameters p;
  p.selective_update = false;
  ml::MarkovGrid grid(s.map, *s.sensor, p);
  const auto scan = Scan(s, s.inside);
  for (auto _ : state) {
    state.PauseTiming();
    grid.SetUniform();
    state.ResumeTiming();
    benchmark::DoNotOptimize(grid.SensorUpdate(scan));
  }
  Counters(state, grid);
}

void BM_FullSensorUpdate(benchmark::State& state) {
  Setup& s = Pick(state.range(0));
  FullSensorUpdates(state, s);
  state.counters["target_ms"] = 100;
}

void BM_MotionUpdateUniform(benchmark::State& state) {
  Setup& s = Pick(state.range(0));
  ml::MarkovGridParameters p;
  ml::MarkovGrid grid(s.map, *s.sensor, p);
  for (auto _ : state) grid.MotionUpdate(ml::Motion{0.15, 0.0, 0.0});
  Counters(state, grid);
  state.counters["target_ms"] = 15;
}

void BM_SelectiveTrackingStep(benchmark::State& state) {
  Setup& s = Pick(state.range(0));
  ml::MarkovGridParameters p;
  ml::MarkovGrid grid(s.map, *s.sensor, p);
  grid.SetGaussian(s.inside, 0.2, 0.05);
  const auto scan = Scan(s, s.inside);
  for (int i = 0; i < 3; ++i) grid.SensorUpdate(scan);
  // One tracking step per iteration: 5 cm of motion (back and forth, so the robot stays put)
  // and the scan at the new pose; the motion is timed too.
  ml::Pose2 ahead = s.inside;
  ahead.x += 0.05 * std::cos(ahead.yaw);
  ahead.y += 0.05 * std::sin(ahead.yaw);
  const auto scan_ahead = Scan(s, ahead);
  std::size_t evaluated = 0;
  bool forward = true;
  for (auto _ : state) {
    grid.MotionUpdate(ml::Motion{forward ? 0.05 : -0.05, 0.0, 0.0});
    evaluated = grid.SensorUpdate(forward ? scan_ahead : scan).states_evaluated;
    forward = !forward;
  }
  Counters(state, grid);
  state.counters["active_parts"] = grid.ActiveParts();
  state.counters["evaluated"] = static_cast<double>(evaluated);
  state.counters["target_ms"] = 3.5;
}

void BM_SelectiveMotionLocalized(benchmark::State& state) {
  Setup& s = Pick(state.range(0));
  ml::MarkovGridParameters p;
  ml::MarkovGrid grid(s.map, *s.sensor, p);
  grid.SetGaussian(s.inside, 0.2, 0.05);
  const auto scan = Scan(s, s.inside);
  for (int i = 0; i < 3; ++i) grid.SensorUpdate(scan);
  double sign = 1.0;
  for (auto _ : state) {
    grid.MotionUpdate(ml::Motion{0.05 * sign, 0.0, 0.0});
    sign = -sign;
  }
  Counters(state, grid);
  state.counters["active_parts"] = grid.ActiveParts();
}

// The full sensor update with each instruction-set version of its kernels (arg 0: 0 plain C++,
// 1 AVX2, 2 AVX-512) on one or two threads (arg 1), over the 30 x 30 m building: what a CPU
// without AVX-512 or AVX2, or a single core, gets. (The motion update's loops are versioned by
// the compiler's target_clones, chosen by the loader: not switchable here; they are bound by
// memory traffic rather than arithmetic.)
bool UseIsaAndThreads(benchmark::State& state, int threads) {
  ml::EnableWorkerThreads(threads > 1);
  const auto isa = static_cast<ml::kernels::Isa>(state.range(0));
  if (ml::kernels::ForceIsa(isa) == isa) return true;
  state.SkipWithError("not supported by this CPU");
  return false;
}

void Restore() {
  ml::kernels::ForceIsa(ml::kernels::SupportedIsa());
  ml::EnableWorkerThreads(std::thread::hardware_concurrency() >= 2);
}

void BM_FullSensorUpdateByIsa(benchmark::State& state) {
  Setup& s = Building30();
  if (UseIsaAndThreads(state, static_cast<int>(state.range(1)))) FullSensorUpdates(state, s);
  Restore();
}

// The motion update on one or two threads (arg), 30 x 30 m.
void BM_MotionUpdateUniformByThreads(benchmark::State& state) {
  Setup& s = Building30();
  ml::EnableWorkerThreads(state.range(0) > 1);
  {
    ml::MarkovGrid grid(s.map, *s.sensor, ml::MarkovGridParameters{});
    for (auto _ : state) grid.MotionUpdate(ml::Motion{0.15, 0.0, 0.0});
    Counters(state, grid);
  }
  Restore();
}

}  // namespace

// Arg 0: the 30 x 30 m building; arg 1: bonn_department.
BENCHMARK(BM_FullSensorUpdate)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(5);
BENCHMARK(BM_MotionUpdateUniform)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(5);
BENCHMARK(BM_SelectiveTrackingStep)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();
BENCHMARK(BM_SelectiveMotionLocalized)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();
BENCHMARK(BM_FullSensorUpdateByIsa)
    ->ArgsProduct({{0, 1, 2}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(3);
BENCHMARK(BM_MotionUpdateUniformByThreads)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(5);
BENCHMARK_MAIN();
