// Cost of following a door's change (README, "Figures"): the node rebuilds the sensor tables when
// the controller senses a door closed or open. Peer: the full build it did before (every state
// cell, every heading), in the same run. cim_office at the node's 15 cm / 2 degrees, the Nomad's
// 16 sonars (0.52 rad cones, specular beyond 0.35 rad), d_lab_w (1.8 m) closed and opened.
#include <benchmark/benchmark.h>

#include <memory>

#include "markov_localization/localizer.h"
#include "spott_map/world_loader.h"

namespace ml = markov_localization;

namespace {

struct Maps {
  std::shared_ptr<const ml::MapModel> open, closed;
  ml::SensorModelParameters sonar;
  std::shared_ptr<const ml::LocalizationModels> open_models, closed_models;
};

Maps& CimOffice() {
  static Maps* m = [] {
    auto* m = new Maps;
    const auto world = spott_map::LoadWorldFile(std::string(WORLDS_DIR) + "/cim_office.yaml");
    ml::MapModelParameters mp;
    mp.resolution_m = 0.15;
    mp.ray_cast_subdivision = 5;
    m->open = std::make_shared<const ml::MapModel>(ml::MapModel::FromWorld(*world.world, mp));
    spott_map::MapDatabase db = spott_map::MapDatabase::FromWorld(*world.world);
    db.SetDoorState("d_lab_w", spott_map::DoorState::kClosed);
    m->closed =
        std::make_shared<const ml::MapModel>(ml::MapModel::FromDatabase(*world.world, db, mp));
    m->sonar.beam_angles_rad = ml::SonarRingAngles(16);
    m->sonar.sensor_offset_m = 0.2285;
    m->sonar.max_range_m = 6.5;
    m->sonar.beam_width_rad = 0.52;
    m->sonar.critical_angle_rad = 0.35;
    m->open_models = ml::LocalizationModels::Build(m->open, {m->sonar}, 180);
    m->closed_models = ml::LocalizationModels::Build(m->closed, {m->sonar}, 180);
    return m;
  }();
  return *m;
}

enum class Build { kFullClosed, kClosedFromOpen, kOpenFromClosed };

// kFullClosed is the peer: what the node did on every map update before.
void BM_DoorChange(benchmark::State& state, Build build) {
  Maps& m = CimOffice();
  const bool closing = build != Build::kOpenFromClosed;
  const auto& map = closing ? m.closed : m.open;
  const std::shared_ptr<const ml::LocalizationModels> previous = build == Build::kFullClosed
                                                                     ? nullptr
                                                                 : closing ? m.open_models
                                                                           : m.closed_models;
  std::shared_ptr<const ml::LocalizationModels> built;
  for (auto _ : state) {
    built = ml::LocalizationModels::Build(map, {m.sonar}, 180, previous);
    benchmark::DoNotOptimize(built.get());
  }
  state.counters["rays_cast"] = static_cast<double>(built->sensors[0]->rays_cast());
  state.counters["rays_full"] = static_cast<double>(map->NumStateCells() * 180);
}
BENCHMARK_CAPTURE(BM_DoorChange, closed_full_build, Build::kFullClosed)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_DoorChange, closed_from_the_open_models, Build::kClosedFromOpen)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(10);
BENCHMARK_CAPTURE(BM_DoorChange, opened_from_the_closed_models, Build::kOpenFromClosed)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(10);

}  // namespace

BENCHMARK_MAIN();
