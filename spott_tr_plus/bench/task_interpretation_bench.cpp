// Cost of interpreting a task command (SPOTT III-B), the first step between a task command and
// the robot's first motion: without a map (the geometry's goal point) and against the map of
// cim_office (30 x 20 m, 15 rooms, its objects recorded as obstacles), where the goal region is
// intersected with the free space the robot can reach (a raster of the whole floor, flooded from
// the robot) before its point is chosen. Counter: cells of the raster.
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "spott_map/map_database.h"
#include "spott_map/world_loader.h"
#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus {
namespace {

struct Office {
  spott_map::World world;
  spott_map::MapDatabase db;
  PlaceResolver resolve;
  Office() {
    const spott_map::WorldLoadResult r = spott_map::LoadWorldFile(WORLDS_DIR "/cim_office.yaml");
    if (!r.ok()) std::abort();
    world = *r.world;
    db = spott_map::MapDatabase::FromWorld(world);
    for (const spott_map::WorldObject& o : world.objects) {
      spott_map::MapFeature f;
      f.id = o.id;
      f.type = spott_map::FeatureType::kRectangle;
      f.pose = o.pose;
      f.size_x = o.size_x;
      f.size_y = o.size_y;
      db.AddFeature(f);
    }
    resolve = MapPlaceResolver(db, world.places);
  }
};

const Office& TheOffice() {
  static const Office office;
  return office;
}

// Task 0: go in room(lab) from the west hallway; task 1: go behind desk(desk_106).
const char* kTasks[] = {"go in room(lab)", "go behind desk(desk_106)"};

void BM_InterpretWithoutMap(benchmark::State& state) {
  const Office& o = TheOffice();
  const TaskCommand c = *ParseTaskCommand(kTasks[state.range(0)]).command;
  const TaskInterpretationParameters p;
  for (auto _ : state) {
    TaskInterpretResult r = InterpretTask(c, 2.0, 8.2, 0.0, p, o.resolve);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_InterpretWithoutMap)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// range(1): raster cell side in mm.
void BM_InterpretWithMap(benchmark::State& state) {
  const Office& o = TheOffice();
  const TaskCommand c = *ParseTaskCommand(kTasks[state.range(0)]).command;
  TaskInterpretationParameters p;
  p.free_space_resolution_m = state.range(1) / 1000.0;
  TaskMap map;
  map.database = &o.db;
  map.padding_m = 0.325;
  for (auto _ : state) {
    TaskInterpretResult r = InterpretTask(c, 2.0, 8.2, 0.0, p, map, o.resolve);
    if (!r.ok()) state.SkipWithError(FormatDiagnostics(r.diagnostics).c_str());
    benchmark::DoNotOptimize(r);
  }
  const spott_map::Box b = o.world.Bounds();
  state.counters["cells"] = (b.max.x() - b.min.x()) * (b.max.y() - b.min.y()) /
                            (p.free_space_resolution_m * p.free_space_resolution_m);
}
BENCHMARK(BM_InterpretWithMap)
    ->Args({0, 50})
    ->Args({1, 50})
    ->Args({0, 100})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace spott_tr_plus

BENCHMARK_MAIN();
