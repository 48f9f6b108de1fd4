// What does the map database cost? World loading and validation, cutting the local window
// (SPOTT's 35 x 35 and a 256 x 256 office window), and de-duplicating sensed features.
#include <benchmark/benchmark.h>

#include <sstream>

#include "spott_map/local_map.h"
#include "spott_map/world_loader.h"

namespace spott_map {
namespace {

// A building of n x n rooms of 4 x 4 m along hallways, written as a world file: each row of
// rooms sits above a 2 m hallway and opens onto it.
std::string GridWorldText(int n) {
  std::ostringstream w;
  w << "world:\n  name: grid_" << n << "\nwalls:\n  from_rooms: true\nrooms:\n";
  const double row_height = 6.0;
  for (int r = 0; r < n; ++r) {
    const double y0 = r * row_height;
    w << "  - {id: hall_" << r << ", kind: hallway, polygon: [[0, " << y0 << "], [" << 4 * n << ", "
      << y0 << "], [" << 4 * n << ", " << y0 + 2 << "], [0, " << y0 + 2 << "]]}\n";
    for (int c = 0; c < n; ++c) {
      w << "  - {id: room_" << r << "_" << c << ", polygon: [[" << 4 * c << ", " << y0 + 2 << "], ["
        << 4 * c + 4 << ", " << y0 + 2 << "], [" << 4 * c + 4 << ", " << y0 + 6 << "], [" << 4 * c
        << ", " << y0 + 6 << "]]}\n";
    }
  }
  w << "doors:\n";
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      w << "  - {id: d_" << r << "_" << c << ", between: [hall_" << r << ", room_" << r << "_" << c
        << "], center: [" << 4 * c + 2 << ", " << r * row_height + 2 << "], width: 0.9}\n";
    }
    if (r + 1 < n) {
      w << "  - {id: s_" << r << ", between: [room_" << r << "_0, hall_" << r + 1
        << "], center: [1, " << (r + 1) * row_height << "], width: 0.9}\n";
    }
  }
  w << "robot_start:\n  pose: [1, 1, 0]\n";
  return w.str();
}

void BM_LoadWorld(benchmark::State& state) {
  const std::string text = GridWorldText(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    WorldLoadResult r = LoadWorldFromString(text, "grid.yaml");
    if (!r.ok()) state.SkipWithError(FormatErrors(r.errors).c_str());
    benchmark::DoNotOptimize(r);
  }
  state.counters["rooms"] = static_cast<double>(state.range(0) * (state.range(0) + 1));
}
BENCHMARK(BM_LoadWorld)->Arg(3)->Arg(6)->Arg(12)->Unit(benchmark::kMillisecond);

// Cutting the window: args are cells per side and resolution in millimetres.
void BM_CutLocalWindow(benchmark::State& state) {
  const World world = *LoadWorldFromString(GridWorldText(6), "grid.yaml").world;
  const MapDatabase db = MapDatabase::FromWorld(world);
  LocalMapParameters p;
  p.resolution_m = state.range(1) / 1000.0;
  p.window_size_m = state.range(0) * p.resolution_m;
  p.recentre_margin_m = 0.1 * p.window_size_m;
  LocalMap local(p);
  for (auto _ : state) {
    local.Recentre(db, Vec2(10.0, 9.0));
    benchmark::DoNotOptimize(local.raster().cells().data());
  }
  state.counters["features_in_window"] = static_cast<double>(local.features().size());
  state.counters["blocked_cells"] = static_cast<double>(local.raster().CountCells(Cell::kObstacle) +
                                                        local.raster().CountCells(Cell::kPadding));
}
BENCHMARK(BM_CutLocalWindow)
    ->Args({35, 200})  // SPOTT's 35 x 35 window
    ->Args({256, 50})  // a 12.8 m office window at 5 cm
    ->Args({512, 50})
    ->Unit(benchmark::kMicrosecond);

void BM_AddSensedFeatureToDatabase(benchmark::State& state) {
  const World world = *LoadWorldFromString(GridWorldText(6), "grid.yaml").world;
  MapDatabase db = MapDatabase::FromWorld(world);
  const int already = static_cast<int>(state.range(0));
  for (int i = 0; i < already; ++i) {
    db.AddSensedFeature(MakePoint("", Vec2(0.37 * i, 0.11 * i), "chair"), 0.05);
  }
  int i = 0;
  for (auto _ : state) {
    // Alternate a repeat of a wall (found) and a point far from everything (scan to the end).
    const auto r = (i++ % 2 == 0) ? db.AddSensedFeature(
                                        MakeSegment("", Segment{Vec2(1, 0), Vec2(3, 0)}, ""), 0.05)
                                  : db.AddSensedFeature(MakePoint("", Vec2(-50, -50), ""), 0.05);
    benchmark::DoNotOptimize(r);
  }
  state.counters["features"] = static_cast<double>(db.features().size());
}
BENCHMARK(BM_AddSensedFeatureToDatabase)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace spott_map

BENCHMARK_MAIN();
