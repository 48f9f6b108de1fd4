// Long corridors (paper footnote 16): where the plain potential u (obstacles 1, goal 0) first goes
// flat, in double and in float, and that the complement storage p = 1 - u does not. Prints a table
// (corridor 5 free cells wide, goal on one end, relative residual 1e-6), then times the 100:1
// corridor per solver.
#include <benchmark/benchmark.h>

#include <cstdio>

#include "../test/test_maps.h"
#include "spott_harmonic_planner/potential_field.h"

namespace shp = spott_harmonic_planner;

namespace {

shp::PotentialField Corridor(int length, int width, shp::SolverKind kind) {
  shp::FieldOptions o;
  o.solver.kind = kind;
  o.norm = shp::ResidualNorm::kRelative;
  o.tolerance = 1e-6;
  shp::PotentialField f(o);
  f.SetOccupancy(shp::testing_maps::EmptyRaster(length + 2, width + 2));
  f.SetGoalSegment({shp::Vec2(0.0, 0.0), shp::Vec2(0.0, width + 2.0)}, 0.6);
  f.ColdStart();
  f.Solve(1000000);
  return f;
}

template <typename T>
int Flat(const shp::PotentialField& f, bool complement) {
  std::vector<T> v(f.values().size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i] = complement ? -static_cast<T>(f.values()[i]) : static_cast<T>(1.0 - f.values()[i]);
  }
  return shp::CountFlatCells(f, v);
}

void PrintFlatnessTable() {
  const int w = 5;
  int first[4] = {0, 0, 0, 0};
  const char* names[4] = {"plain u, double", "plain u, float", "complement p, float",
                          "complement p, double"};
  for (int ratio = 1; ratio <= 260; ++ratio) {
    const auto f = Corridor(ratio * w, w, shp::SolverKind::kAdi);
    const int flat[4] = {Flat<double>(f, false), Flat<float>(f, false), Flat<float>(f, true),
                         Flat<double>(f, true)};
    for (int k = 0; k < 4; ++k) {
      if (!first[k] && flat[k] > 0) first[k] = ratio;
    }
    if (first[0] && first[1] && first[2] && ratio >= 100 && (first[3] || ratio == 260)) break;
  }
  std::printf("Corridor %d free cells wide: first length:width ratio with a flat free cell\n", w);
  for (int k = 0; k < 4; ++k) {
    if (first[k]) {
      std::printf("  %-22s %d:1\n", names[k], first[k]);
    } else {
      std::printf("  %-22s none up to 260:1\n", names[k]);
    }
  }
  std::printf("\n");
}

void BM_Corridor100(benchmark::State& state) {
  const auto kind = static_cast<shp::SolverKind>(state.range(0));
  int sweeps = 0, flat = 0;
  for (auto _ : state) {
    const auto f = Corridor(500, 5, kind);
    sweeps = f.report().sweeps;
    flat = Flat<double>(f, true);
  }
  state.counters["sweeps"] = sweeps;
  state.counters["flat_cells"] = flat;
  state.SetLabel(shp::ToString(kind));
}
BENCHMARK(BM_Corridor100)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  PrintFlatnessTable();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
