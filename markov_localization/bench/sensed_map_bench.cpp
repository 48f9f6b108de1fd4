// Cost of one fix of sensed_map_localization (README, "Figures"): the echoes of a 10 s window
// (the Nomad's 16 sonars at 5 Hz, 800 readings, driving 5 m along cim_office's 2.5 m hallway)
// matched to the sensed map's segments (the hallway's two walls in 1 m pieces and 20 more
// elsewhere), the odometry 0.1 m and 1 degree off. Paper: "a few seconds" per localization of a
// 1990s workstation, every 10 s.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "markov_localization/sensed_map_tracker.h"
#include "spott_map/pose_algebra.h"

namespace ml = markov_localization;
using spott_map::Pose2;
using spott_map::Segment;
using spott_map::Vec2;

namespace {

constexpr double kFov = 25.0 * M_PI / 180.0;

void BM_SensedMapFix(benchmark::State& state) {
  const bool heading = state.range(0) != 0;
  std::vector<Segment> walls;
  for (double x = 0.0; x < 30.0; x += 1.0) {
    walls.push_back({{x, 7.075}, {x + 1.0, 7.075}});
    walls.push_back({{x, 9.425}, {x + 1.0, 9.425}});
  }
  for (int i = 0; i < 20; ++i) walls.push_back({{i * 1.5, 12.0}, {i * 1.5 + 1.0, 12.5}});
  std::vector<Pose2> mounts;
  for (int i = 0; i < 16; ++i) {
    const double a = i * M_PI / 8.0;
    mounts.push_back({0.2 * std::cos(a), 0.2 * std::sin(a), a});
  }
  ml::SensedMapTrackerParameters p;
  p.correct_heading = heading;
  const Pose2 error{0.1, 0.1, M_PI / 180.0};
  for (auto _ : state) {
    state.PauseTiming();
    ml::SensedMapTracker tracker(p, Pose2{});
    tracker.SetSegments(walls);
    double t = 0.0;
    Pose2 odom;
    for (int k = 0; k < 50; ++k, t += 0.2) {
      const Pose2 truth{10.0 + 0.1 * k, 8.25 + 0.02 * std::sin(k * 0.3), 0.0};
      odom = spott_map::Compose(spott_map::MapToOdom(Pose2{}, error), truth);
      std::vector<double> ranges;
      for (const Pose2& m : mounts) {
        const Pose2 at = spott_map::Compose(truth, m);
        const double s = std::sin(at.yaw);
        // The side transducers hear the walls, the others something 1.5-2.9 m off (furniture,
        // a corner): 800 readings, each tested against every segment.
        ranges.push_back(std::abs(s) > 0.97 ? (s > 0 ? 9.425 - at.y : at.y - 7.075)
                                            : 1.5 + 0.1 * static_cast<double>(ranges.size()));
      }
      tracker.AddRing(t, odom, mounts, ranges, 0.15, 6.5, kFov);
    }
    state.ResumeTiming();
    benchmark::DoNotOptimize(tracker.Localize(t, odom));
  }
}
BENCHMARK(BM_SensedMapFix)->Arg(0)->Arg(1)->ArgNames({"heading"})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
