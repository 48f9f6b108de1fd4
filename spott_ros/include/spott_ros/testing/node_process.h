// Test helpers for rostests: run a node's executable as a child process (to check that it
// refuses bad parameters by name and exits), and wait for the latest message on a topic.
// Header-only; used by the rostests of every package.
#pragma once

#include <sys/wait.h>
#include <cstdio>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include <ros/ros.h>

namespace spott_ros::testing {

struct NodeRun {
  int exit_code = -1;  ///< -1: did not exit by itself (killed by the timeout) or not started.
  std::string output;  ///< stdout and stderr.
};

/// Runs `executable` with `args` (e.g. "_window/resoluton_m:=0.1 __name:=probe"), under the
/// running master, for at most `timeout_s` seconds.
inline NodeRun RunNode(const std::string& executable, const std::string& args,
                       double timeout_s = 30.0) {
  NodeRun run;
  const std::string cmd = "timeout " + std::to_string(static_cast<int>(timeout_s)) + " " +
                          executable + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) run.output.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status) && WEXITSTATUS(status) != 124) run.exit_code = WEXITSTATUS(status);
  return run;
}

/// Messages of a topic as they arrive (spinning the global queue while waiting): WaitFor looks
/// at every message received since the last match, so a short-lived message is not missed when
/// another follows it quickly (latched topics re-sent on every change). Safe beside an
/// AsyncSpinner on the same queue: the callback then runs on a spinner thread while the test
/// thread waits. Unlocked, and with the queue destroyed before the subscription, that aborted a
/// test process (SIGABRT, no message) as the next test began in a CI run of bad_input.test.
template <class Msg>
class Latest {
 public:
  Latest(ros::NodeHandle& nh, const std::string& topic, int queue = 10)
      : sub_(nh.subscribe(topic, queue, &Latest::On, this)) {}
  ~Latest() { sub_.shutdown(); }  // waits for a callback in progress
  Latest(const Latest&) = delete;
  Latest& operator=(const Latest&) = delete;

  bool WaitFor(const std::function<bool(const Msg&)>& ok, double seconds = 15.0) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok()) {
      ros::spinOnce();
      for (std::optional<Msg> next = Next(); next; next = Next()) {
        msg_ = std::move(next);
        if (ok(*msg_)) return true;
      }
      if (msg_ && ok(*msg_)) return true;
      if (ros::WallTime::now() >= end) return false;
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }
  /// The last message looked at by WaitFor (the match when it returned true).
  const std::optional<Msg>& msg() const { return msg_; }

 private:
  void On(const Msg& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(m);
  }
  std::optional<Msg> Next() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pending_.empty()) return std::nullopt;
    std::optional<Msg> m(std::move(pending_.front()));
    pending_.pop_front();
    return m;
  }
  std::mutex mutex_;
  std::deque<Msg> pending_;
  std::optional<Msg> msg_;  ///< Only the waiting thread touches it.
  ros::Subscriber sub_;     ///< Last: shut down before the members its callback uses.
};

}  // namespace spott_ros::testing
