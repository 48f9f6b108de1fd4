// The arbiter's latency through ROS, from a source's message on /cmd_vel/planner to the
// arbiter's /cmd_vel, beside peers doing the same hop in their own process: topic_tools' relay
// (the least a separate node can add) and topic_tools' mux (ROS's input selector, twist_mux's
// ancestor). The program starts a private rosmaster and the three nodes as child processes.
// Counters: p50_us / p99_us of the round trip publisher -> node -> subscriber (this process).
// Also the core alone (no ROS): one Command() of the arbiter.
#include <benchmark/benchmark.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "cmd_vel_arbiter/arbiter.h"
#include "spott_ros/testing/private_master.h"
#include "spott_ros/testing/ros_benchmark.h"

namespace {

// Round trips publisher -> node -> subscriber, one message in flight at a time.
class RoundTrip {
 public:
  RoundTrip(ros::NodeHandle& nh, const std::string& in, const std::string& out) {
    pub_ = nh.advertise<geometry_msgs::Twist>(in, 1);
    sub_ = nh.subscribe<geometry_msgs::Twist>(
        out, 1,
        [this](const geometry_msgs::Twist::ConstPtr&) {
          std::lock_guard<std::mutex> lock(mutex_);
          arrived_ = true;
          cv_.notify_one();
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }
  bool Connected() const { return pub_.getNumSubscribers() > 0 && sub_.getNumPublishers() > 0; }
  // topic_tools' relay and mux advertise their output only once a first input message has told
  // them its type: send one while waiting for the connection.
  void Prime() { pub_.publish(geometry_msgs::Twist()); }
  // Seconds for one message, or < 0 on a timeout.
  double Once(double v) {
    geometry_msgs::Twist t;
    t.linear.x = v;
    std::unique_lock<std::mutex> lock(mutex_);
    arrived_ = false;
    const auto start = std::chrono::steady_clock::now();
    pub_.publish(t);
    if (!cv_.wait_for(lock, std::chrono::seconds(1), [this] { return arrived_; })) return -1.0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

 private:
  ros::Publisher pub_;
  ros::Subscriber sub_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool arrived_ = false;
};

void Measure(benchmark::State& state, const std::string& in, const std::string& out) {
  ros::NodeHandle nh;
  RoundTrip trip(nh, in, out);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!trip.Connected() && std::chrono::steady_clock::now() < deadline) {
    trip.Prime();
    ros::WallDuration(0.05).sleep();
  }
  if (!trip.Connected()) {
    state.SkipWithError(("no connection " + in + " -> " + out).c_str());
    return;
  }
  for (int i = 0; i < 200; ++i) trip.Once(0.1);  // warm up (connections, caches)
  std::vector<double> samples;
  for (auto _ : state) {
    const double s = trip.Once(0.1 + 1e-6 * (samples.size() % 100));
    if (s < 0) {
      state.SkipWithError("a message was lost");
      return;
    }
    samples.push_back(s);
    state.SetIterationTime(s);
  }
  spott_ros::testing::RecordPercentiles(state, samples);
}

void BM_ArbiterThroughRos(benchmark::State& state) {
  Measure(state, "/cmd_vel/planner", "/cmd_vel");
}
void BM_PeerTopicToolsRelay(benchmark::State& state) { Measure(state, "/relay_in", "/relay_out"); }
void BM_PeerTopicToolsMux(benchmark::State& state) { Measure(state, "/mux_in", "/mux_out"); }

void BM_ArbiterCoreCommand(benchmark::State& state) {
  cmd_vel_arbiter::ArbiterParameters p;
  p.sources = {{"planner", 10, 0.5}, {"wander", 40, 0.5}, {"reflex", 100, 0.5}};
  cmd_vel_arbiter::Arbiter a(p);
  std::string why;
  double now = 0.0;
  for (auto _ : state) {
    now += 0.001;
    benchmark::DoNotOptimize(a.Command("planner", {0.2, 0.1}, now, &why));
  }
}

BENCHMARK(BM_ArbiterCoreCommand);
BENCHMARK(BM_ArbiterThroughRos)->UseManualTime()->Iterations(2000);
BENCHMARK(BM_PeerTopicToolsRelay)->UseManualTime()->Iterations(2000);
BENCHMARK(BM_PeerTopicToolsMux)->UseManualTime()->Iterations(2000);

}  // namespace

int main(int argc, char** argv) {
  // A private master on a port of our own and the nodes under test.
  spott_ros::testing::PrivateMaster master;
  ros::WallDuration(1.5).sleep();
  master.Spawn({ARBITER_EXE, "__name:=cmd_vel_arbiter", "_sources/planner/priority:=10",
                "_sources/reflex/priority:=100", "_limits/max_linear_mps:=1.0",
                "_limits/max_angular_rps:=2.0"});
  master.Spawn({"/usr/lib/topic_tools/relay", "/relay_in", "/relay_out"});
  master.Spawn({"/usr/lib/topic_tools/mux", "/mux_out", "/mux_in", "/mux_other"});
  int ros_argc = 1;
  ros::init(ros_argc, argv, "latency_bench", ros::init_options::NoSigintHandler);
  spott_ros::testing::PrivateMaster::WaitForMaster(10.0);
  return spott_ros::testing::RunBenchmarksSpinning(argc, argv);
}
