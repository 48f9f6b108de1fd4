// For Google Benchmark programs that measure nodes through ROS (with private_master.h): the
// pieces every such program repeats.
#pragma once

#include <benchmark/benchmark.h>
#include <ros/ros.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace spott_ros::testing {

/// The whole file ("" when it cannot be read), e.g. a URDF for /robot_description.
inline std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Latency samples (s) as the counters p50_us and p99_us.
inline void RecordPercentiles(benchmark::State& state, std::vector<double> samples) {
  if (samples.empty()) return;
  std::sort(samples.begin(), samples.end());
  state.counters["p50_us"] = 1e6 * samples[samples.size() / 2];
  state.counters["p99_us"] = 1e6 * samples[samples.size() * 99 / 100];
}

/// After ros::init: runs the registered benchmarks with two spinner threads serving the
/// program's callbacks; returns main's exit code.
inline int RunBenchmarksSpinning(int argc, char** argv) {
  ros::AsyncSpinner spinner(2);
  spinner.start();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  spinner.stop();
  ros::shutdown();
  return 0;
}

}  // namespace spott_ros::testing
