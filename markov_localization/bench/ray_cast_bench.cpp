// Cost of casting beams on the fine raster (README, "Figures"): the pose refinement of one
// update (ScanLogLikelihood up to 19 times: every beam's cone cast again at every probe; the
// largest part of a sonar update's CPU while tracking, issue 14), the sensor model's tables
// (one ray per state and heading, what the node's start waits for), and single rays.
// bonn_department at 15 cm / 2 degrees on the node's raster (ray_cast_subdivision 5), the B21's
// ring: 24 sonars, 0.52 rad cones, critical angle 0.35 rad, 6.5 m.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>

#include "../src/worker_pool.h"
#include "markov_localization/pose_refinement.h"
#include "spott_map/world_loader.h"

namespace ml = markov_localization;

namespace {

struct Bonn {
  ml::MapModel map;
  ml::SensorModelParameters sonar;
  std::unique_ptr<ml::SensorModel> sensor;
};

ml::SensorModelParameters B21Sonar() {
  ml::SensorModelParameters p;
  p.beam_angles_rad = ml::SonarRingAngles(24);
  p.max_range_m = 6.5;
  p.beam_width_rad = 0.52;
  p.critical_angle_rad = 0.35;
  p.sensor_offset_m = 0.26;
  return p;
}

ml::MapModel BonnMap() {
  auto world = spott_map::LoadWorldFile(std::string(WORLDS_DIR) + "/bonn_department.yaml");
  ml::MapModelParameters mp;
  mp.ray_cast_subdivision = 5;
  return ml::MapModel::FromWorld(*world.world, mp);
}

Bonn& Get() {
  static Bonn* s = [] {
    auto* s = new Bonn;
    s->map = BonnMap();
    s->sonar = B21Sonar();
    s->sensor = std::make_unique<ml::SensorModel>(s->map, 180, s->sonar);
    return s;
  }();
  return *s;
}

// Poses in the corridor and rooms where the robot drives (the eval's route), and their scans.
std::vector<ml::Pose2> Poses() {
  return {{24.0, 10.0, M_PI}, {17.5, 5.0, -M_PI / 2}, {12.0, 10.1, 0.2}, {6.0, 10.0, 3.0}};
}

void BM_SonarPoseRefinement(benchmark::State& state) {
  Bonn& s = Get();
  std::vector<std::vector<double>> scans;
  for (const auto& p : Poses()) {
    scans.emplace_back();
    for (int b = 0; b < s.sensor->num_beams(); ++b)
      scans.back().push_back(s.sensor->ExpectedRange(s.map, p, b));
  }
  const auto poses = Poses();
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % poses.size();
    const std::vector<ml::SensorReading> readings{{s.sensor.get(), &scans[k]}};
    // Started 4 cm and 1.5 degrees off, as after a cell-centred estimate.
    const ml::Pose2 start{poses[k].x + 0.04, poses[k].y - 0.03, poses[k].yaw + 0.026};
    benchmark::DoNotOptimize(
        ml::RefinePose(s.map, readings, start, 2.0 * M_PI / 180, ml::PoseRefinementParameters{}));
  }
}

void BM_SonarTables(benchmark::State& state) {
  Bonn& s = Get();
  ml::EnableWorkerThreads(false);
  for (auto _ : state) benchmark::DoNotOptimize(ml::SensorModel(s.map, 180, s.sonar));
  ml::EnableWorkerThreads(true);
  state.counters["rays_M"] = s.map.NumStateCells() * 180 / 1e6;
}

// Single rays from random states in random directions, up to 6.5 m.
void BM_RayCastHit(benchmark::State& state) {
  Bonn& s = Get();
  std::mt19937 rng(1);
  std::vector<std::pair<ml::Vec2, double>> rays;
  std::uniform_int_distribution<int> x(0, s.map.width() - 1), y(0, s.map.height() - 1);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  while (rays.size() < 4096) {
    const int ix = x(rng), iy = y(rng);
    if (s.map.IsState(ix, iy)) rays.emplace_back(s.map.CellCentre(ix, iy), angle(rng));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [from, a] = rays[i++ % rays.size()];
    benchmark::DoNotOptimize(s.map.RayCastHit(from, a, 6.5));
  }
}

}  // namespace

BENCHMARK(BM_SonarPoseRefinement)->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK(BM_SonarTables)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_RayCastHit)->Unit(benchmark::kNanosecond)->MeasureProcessCPUTime();
BENCHMARK_MAIN();
