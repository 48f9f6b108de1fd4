// MAP_OBJECTS_WITH_SONAR's fusion of one cluster (sensor_mapper.h, sonar_echo_fit.h): the
// Nomad drives a hallway 2.4 m wide along its middle, 16 transducers read every 5 cm (0.15 m/s
// at 3 Hz), each echo placed on its axis in 0.1 m cells keeping the latest 8 echoes, a cell
// confirmed at 4 (the mapper's defaults); the south wall's confirmed cells are one cluster,
// fused as the mapper's Take fuses a cluster that grew.
//  - BM_FuseFromEchoes/L: the fusion by the echoes' physics (walls as the circles' common
//    tangents, corners as their common point), wall length L m.
//  - BM_FuseCellsOnly/L: the peer, the fusion before it (split and merge of the cells' axis
//    points: what the cells alone give), same cells.
// Counters: cells, echoes, segments and points out.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "../test/echo_scene.h"
#include "spott_tr_plus/controller/sensor_mapper.h"

namespace spott_tr_plus::controller {
namespace {

struct Cluster {
  std::vector<Vec2> cells;
  std::vector<std::vector<SonarEcho>> echoes;
};

Cluster SouthWall(double length) {
  test_scene::Scene scene;
  scene.walls.push_back({Vec2(0.0, 0.0), Vec2(length, 0.0)});
  const double door = 0.5 * length;  // a 0.9 m doorway in the north wall, its jambs echoing
  scene.walls.push_back({Vec2(0.0, 2.4), Vec2(door - 0.45, 2.4)});
  scene.walls.push_back({Vec2(door + 0.45, 2.4), Vec2(length, 2.4)});
  scene.corners = {Vec2(door - 0.45, 2.4), Vec2(door + 0.45, 2.4)};
  std::mt19937 rng(1);
  struct Cell {
    Vec2 sum{0.0, 0.0};
    int n = 0;
    std::vector<SonarEcho> echoes;
  };
  std::map<std::pair<int, int>, Cell> grid;
  for (double x = 0.0; x <= length; x += 0.05) {
    for (int k = 0; k < 16; ++k) {
      const double axis = k * M_PI / 8;
      const Vec2 from = Vec2(x, 1.2) + 0.23 * Vec2(std::cos(axis), std::sin(axis));
      const auto r = scene.Read(from, axis, rng);
      if (!r) continue;
      const Vec2 at = from + *r * Vec2(std::cos(axis), std::sin(axis));
      if (at.y() > 1.2) continue;  // the north wall's: another cluster
      Cell& c = grid[{static_cast<int>(std::floor(at.x() / 0.1)),
                      static_cast<int>(std::floor(at.y() / 0.1))}];
      c.sum += at;
      const SonarEcho e{from, axis, *r, test_scene::kHalfCone};
      if (c.echoes.size() < 8) {
        c.echoes.push_back(e);
      } else {
        c.echoes[c.n % 8] = e;
      }
      ++c.n;
    }
  }
  Cluster out;
  for (const auto& [key, c] : grid) {
    if (c.n < 4) continue;  // confirm_score
    out.cells.push_back(c.sum / c.n);
    out.echoes.push_back(c.echoes);
  }
  return out;
}

void Count(benchmark::State& state, const Cluster& c,
           const std::vector<spott_map::MapFeature>& out) {
  std::size_t echoes = 0, segments = 0;
  for (const auto& e : c.echoes) echoes += e.size();
  for (const auto& f : out) segments += f.type == spott_map::FeatureType::kLineSegment;
  state.counters["cells"] = static_cast<double>(c.cells.size());
  state.counters["echoes"] = static_cast<double>(echoes);
  state.counters["segments"] = static_cast<double>(segments);
  state.counters["points"] = static_cast<double>(out.size() - segments);
}

void BM_FuseFromEchoes(benchmark::State& state) {
  const Cluster c = SouthWall(static_cast<double>(state.range(0)));
  std::vector<spott_map::MapFeature> out;
  for (auto _ : state) {
    out = FuseIntoSegments(c.cells, 0.07, 0.1, &c.echoes);
    benchmark::DoNotOptimize(out.data());
  }
  Count(state, c, out);
}

void BM_FuseCellsOnly(benchmark::State& state) {
  const Cluster c = SouthWall(static_cast<double>(state.range(0)));
  std::vector<spott_map::MapFeature> out;
  for (auto _ : state) {
    out = FuseIntoSegments(c.cells, 0.07, 0.1);
    benchmark::DoNotOptimize(out.data());
  }
  Count(state, c, out);
}

BENCHMARK(BM_FuseFromEchoes)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FuseCellsOnly)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace spott_tr_plus::controller

BENCHMARK_MAIN();
