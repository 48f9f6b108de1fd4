// Issue 16's "task command to first wheel motion" through ROS: bench/task_latency.launch (the
// map database, both planners, the arbiter and the TR+ controller, as stack.launch configures
// them) runs under a private master; this program is the robot and the user. It holds
// map -> base_link still (static tf) at (5, 8.25) in cim_office's west hallway, publishes a
// standing robot's odometry, sends a task command on /task and times the arbiter's first moving
// /cmd_vel (what the wheels obey; the simulator would apply it at its next physics step).
// The path: /task -> controller (parse, interpret from the pose and the map database, the TR+
// rules fire) -> Navigate -> harmonic planner (the global planner projects the goal onto the
// local window, the harmonic function is computed, steering) -> /cmd_vel/planner -> arbiter ->
// /cmd_vel. Then the task is cancelled and the wheels left to stop before the next command.
// Counters: p50_ms / p99_ms. No target in the paper; the issue asks for the figure.
#include <actionlib/client/simple_action_client.h>
#include <benchmark/benchmark.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/TaskAction.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "spott_ros/testing/private_master.h"

namespace {

using Clock = std::chrono::steady_clock;
using TaskClient = actionlib::SimpleActionClient<spott_msgs::TaskAction>;

constexpr double kStartX = 5.0, kStartY = 8.25;

class TaskProbe {
 public:
  explicit TaskProbe(ros::NodeHandle& nh) : client_("task", false) {
    odom_ = nh.advertise<nav_msgs::Odometry>("/odom", 5);
    cmd_ = nh.subscribe<geometry_msgs::Twist>(
        "/cmd_vel", 10,
        [this](const geometry_msgs::Twist::ConstPtr& t) {
          if (std::abs(t->linear.x) < 1e-3 && std::abs(t->angular.z) < 1e-3) return;
          std::lock_guard<std::mutex> lock(mutex_);
          last_moving_ = Clock::now();
          moving_ = true;
          cv_.notify_one();
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    // A standing robot: the controller waits for one before it interprets a task.
    odom_timer_ = nh.createWallTimer(ros::WallDuration(0.05), [this](const ros::WallTimerEvent&) {
      nav_msgs::Odometry o;
      o.header.stamp = ros::Time::now();
      o.header.frame_id = "odom";
      o.child_frame_id = "base_link";
      o.pose.pose.position.x = kStartX;
      o.pose.pose.position.y = kStartY;
      o.pose.pose.orientation.w = 1.0;
      odom_.publish(o);
    });
  }

  bool Connected() {
    return client_.isServerConnected() && cmd_.getNumPublishers() > 0 &&
           odom_.getNumSubscribers() > 0;
  }

  // Seconds from sending `command` to the first moving /cmd_vel, or < 0 on a timeout (with
  // the task's state in `why`).
  double Once(const std::string& command, std::string* why) {
    spott_msgs::TaskGoal goal;
    goal.command = command;
    std::unique_lock<std::mutex> lock(mutex_);
    moving_ = false;
    const auto start = Clock::now();
    client_.sendGoal(goal);
    const bool moved = cv_.wait_for(lock, std::chrono::seconds(20), [this] { return moving_; });
    const double s = std::chrono::duration<double>(Clock::now() - start).count();
    lock.unlock();
    if (!moved) {
      *why = "state " + client_.getState().toString() + ": " + client_.getState().getText();
      if (client_.getResult()) *why += " (" + client_.getResult()->message + ")";
    }
    client_.cancelGoal();
    client_.waitForResult(ros::Duration(5.0));
    return moved ? s : -1.0;
  }

  // Waits until no moving /cmd_vel has come for a second (the planner's source timed out and the
  // arbiter stopped the wheels).
  void Settle() {
    for (;;) {
      ros::WallDuration(0.1).sleep();
      std::lock_guard<std::mutex> lock(mutex_);
      if (Clock::now() - last_moving_ > std::chrono::seconds(1)) return;
    }
  }

 private:
  TaskClient client_;
  ros::Publisher odom_;
  ros::Subscriber cmd_;
  ros::WallTimer odom_timer_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool moving_ = false;
  Clock::time_point last_moving_;
};

TaskProbe* probe = nullptr;

void TaskToFirstMotion(benchmark::State& state, const std::string& command) {
  std::string why;
  for (int i = 0; i < 2; ++i) {  // warm up: connections, the first window and field
    if (probe->Once(command, &why) < 0) {
      state.SkipWithError(("no wheel motion within 20 s: " + why).c_str());
      return;
    }
    probe->Settle();
  }
  std::vector<double> samples;
  for (auto _ : state) {
    const double s = probe->Once(command, &why);
    if (s < 0) {
      state.SkipWithError(("no wheel motion within 20 s: " + why).c_str());
      return;
    }
    samples.push_back(s);
    state.SetIterationTime(s);
    probe->Settle();
  }
  std::sort(samples.begin(), samples.end());
  state.counters["p50_ms"] = 1e3 * samples[samples.size() / 2];
  state.counters["p99_ms"] = 1e3 * samples[samples.size() * 99 / 100];
}

// A point 2 m down the hallway, in the local window: no room search.
void BM_TaskToFirstMotion_Point(benchmark::State& state) {
  TaskToFirstMotion(state, "go to point(7, 8.25)");
}
// By a room's name: interpretation picks a goal region in the lab's free, reachable space; the
// global planner routes through a door beyond the window.
void BM_TaskToFirstMotion_Room(benchmark::State& state) {
  TaskToFirstMotion(state, "go in room(lab)");
}

BENCHMARK(BM_TaskToFirstMotion_Point)
    ->UseManualTime()
    ->Iterations(30)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TaskToFirstMotion_Room)
    ->UseManualTime()
    ->Iterations(30)
    ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  spott_ros::testing::PrivateMaster master;
  int ros_argc = 1;
  ros::init(ros_argc, argv, "task_latency_bench", ros::init_options::NoSigintHandler);
  if (!spott_ros::testing::PrivateMaster::WaitForMaster(10.0)) {
    std::fprintf(stderr, "task_latency_bench: the private rosmaster did not start\n");
    return 1;
  }
  tf2_ros::StaticTransformBroadcaster tf;
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "map";
  t.child_frame_id = "base_link";
  t.transform.translation.x = kStartX;
  t.transform.translation.y = kStartY;
  t.transform.rotation.w = 1.0;
  tf.sendTransform(t);
  // roslaunch takes the run id from a master it did not start; rosmaster --core sets none.
  ros::param::set("/run_id", "task_latency_bench_" + std::to_string(getpid()));
  master.Spawn({"roslaunch", "--wait", TASK_LATENCY_LAUNCH});
  ros::NodeHandle nh;
  TaskProbe task_probe(nh);
  probe = &task_probe;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while (!task_probe.Connected() && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.1).sleep();
  }
  if (!task_probe.Connected()) {
    std::fprintf(stderr, "task_latency_bench: the controller or the arbiter did not connect\n");
    return 1;
  }
  ros::WallDuration(3.0).sleep();  // latched maps reached every node; the controller runs
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  spinner.stop();
  ros::shutdown();
  return 0;
}
