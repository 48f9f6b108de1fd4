// Issue 16's "latency from a sensor message to the reflex's first /cmd_vel" through ROS: the
// tr_plus_controller node (its YAML, the Nomad 200's description, the shipped navigation
// program) and cmd_vel_arbiter run as child processes under a private master; this program is
// the robot: it holds map -> base_link still (static tf) and publishes a bumper contact ahead,
// then times the arbiter's first backward /cmd_vel (BUMPER_CHECK: move_away_from the contact).
// The path: /bumper -> controller (the TR+ rule fires) -> take_wheels service -> /cmd_vel/reflex
// -> arbiter -> /cmd_vel. The reflex gives up moving away after reflex/timeout_s (0.3 s here:
// the robot never moves) and releases the wheels; then the bumper is pressed again.
// Counters: p50_us / p99_us; the target is a median under 2 ms (issue 16).
#include <benchmark/benchmark.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <spott_msgs/BumperRing.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "spott_ros/testing/private_master.h"
#include "spott_ros/testing/ros_benchmark.h"

namespace {

class ReflexProbe {
 public:
  explicit ReflexProbe(ros::NodeHandle& nh) {
    bumper_ = nh.advertise<spott_msgs::BumperRing>("/bumper", 1);
    cmd_ = nh.subscribe<geometry_msgs::Twist>(
        "/cmd_vel", 10,
        [this](const geometry_msgs::Twist::ConstPtr& t) {
          std::lock_guard<std::mutex> lock(mutex_);
          if (t->linear.x < 0.0 || t->angular.z != 0.0) {
            backing_ = true;
            cv_.notify_one();
          } else {
            backing_ = false;
          }
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }
  bool Connected() const { return bumper_.getNumSubscribers() > 0 && cmd_.getNumPublishers() > 0; }

  void Press(bool pressed) {
    spott_msgs::BumperRing ring;
    ring.header.stamp = ros::Time::now();
    ring.header.frame_id = "base_link";
    for (int i = 0; i < 8; ++i) {  // eight segments; segment 0 straight ahead
      ring.segment_angles.push_back(i * 2.0 * M_PI / 8.0);
      ring.pressed.push_back(pressed && i == 0);
    }
    bumper_.publish(ring);
  }

  // Seconds from the press to the first moving-away /cmd_vel, or < 0 on a timeout.
  double Once() {
    std::unique_lock<std::mutex> lock(mutex_);
    backing_ = false;
    const auto start = std::chrono::steady_clock::now();
    Press(true);
    if (!cv_.wait_for(lock, std::chrono::seconds(2), [this] { return backing_; })) return -1.0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // Releases the bumper and waits until the reflex has given up and the wheels are still.
  void Settle() {
    Press(false);
    ros::WallDuration(0.6).sleep();
  }

 private:
  ros::Publisher bumper_;
  ros::Subscriber cmd_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool backing_ = false;
};

void BM_BumperToCmdVelThroughRos(benchmark::State& state) {
  ros::NodeHandle nh;
  ReflexProbe probe(nh);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!probe.Connected() && std::chrono::steady_clock::now() < deadline) {
    ros::WallDuration(0.1).sleep();
  }
  if (!probe.Connected()) {
    state.SkipWithError("the controller or the arbiter did not connect");
    return;
  }
  ros::WallDuration(2.0).sleep();  // the controller has its pose (tf) and has started
  for (int i = 0; i < 3; ++i) {    // warm up (connections, the service's persistent link)
    probe.Once();
    probe.Settle();
  }
  std::vector<double> samples;
  for (auto _ : state) {
    const double s = probe.Once();
    if (s < 0) {
      state.SkipWithError("no moving-away /cmd_vel within 2 s of the bumper contact");
      return;
    }
    samples.push_back(s);
    state.SetIterationTime(s);
    probe.Settle();
  }
  spott_ros::testing::RecordPercentiles(state, samples);
}

BENCHMARK(BM_BumperToCmdVelThroughRos)->UseManualTime()->Iterations(100);

}  // namespace

int main(int argc, char** argv) {
  spott_ros::testing::PrivateMaster master;
  int ros_argc = 1;
  ros::init(ros_argc, argv, "reflex_latency_bench", ros::init_options::NoSigintHandler);
  if (!spott_ros::testing::PrivateMaster::WaitForMaster(10.0)) {
    std::fprintf(stderr, "reflex_latency_bench: the private rosmaster did not start\n");
    return 1;
  }
  ros::param::set("/robot_description",
                  spott_ros::testing::ReadTextFile(ROBOT_SIM_DIR "/urdf/nomad200.urdf"));
  if (!spott_ros::testing::PrivateMaster::Run(
          {"rosparam", "load", CONTROLLER_YAML, "/tr_plus_controller"})) {
    std::fprintf(stderr, "reflex_latency_bench: rosparam load %s failed\n", CONTROLLER_YAML);
    return 1;
  }
  ros::param::set("/tr_plus_controller/program_file", std::string(PROGRAM_FILE));
  ros::param::set("/tr_plus_controller/assume_localized", true);
  ros::param::set("/tr_plus_controller/reflex/timeout_s", 0.3);
  tf2_ros::StaticTransformBroadcaster tf;
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "map";
  t.child_frame_id = "base_link";
  t.transform.translation.x = 5.0;
  t.transform.translation.y = 8.25;
  t.transform.rotation.w = 1.0;
  tf.sendTransform(t);
  if (!spott_ros::testing::PrivateMaster::Run(
          {"rosparam", "load", ARBITER_YAML, "/cmd_vel_arbiter"})) {
    std::fprintf(stderr, "reflex_latency_bench: rosparam load %s failed\n", ARBITER_YAML);
    return 1;
  }
  master.Spawn({ARBITER_EXE, "__name:=cmd_vel_arbiter"});
  master.Spawn({CONTROLLER_EXE, "__name:=tr_plus_controller"});
  return spott_ros::testing::RunBenchmarksSpinning(argc, argv);
}
