// For benchmark programs that measure nodes through ROS: a rosmaster of the program's own on a
// private port and the nodes under test as child processes, all stopped when it goes. Create it
// before ros::init (it points ROS_MASTER_URI at the private master).
#pragma once

#include <ros/master.h>
#include <ros/wall_timer.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace spott_ros::testing {

class PrivateMaster {
 public:
  PrivateMaster() {
    const std::string port = std::to_string(20000 + getpid() % 20000);
    setenv("ROS_MASTER_URI", ("http://127.0.0.1:" + port).c_str(), 1);
    setenv("ROS_HOSTNAME", "127.0.0.1", 1);
    Spawn({"rosmaster", "--core", "-p", port});
  }
  ~PrivateMaster() {
    for (auto it = pids_.rbegin(); it != pids_.rend(); ++it) kill(-*it, SIGTERM);
    for (pid_t p : pids_) waitpid(p, nullptr, 0);
  }
  PrivateMaster(const PrivateMaster&) = delete;
  PrivateMaster& operator=(const PrivateMaster&) = delete;

  /// Starts `argv` (the executable first, found on PATH) in a process group of its own; it is
  /// stopped with the master.
  void Spawn(const std::vector<std::string>& argv) { pids_.push_back(Start(argv)); }

  /// Runs `argv` to its end (e.g. `rosparam load FILE NS`); true when it exited 0.
  static bool Run(const std::vector<std::string>& argv) {
    const pid_t pid = Start(argv);
    int status = 0;
    return waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  }

  /// After ros::init: waits for the master to answer.
  static bool WaitForMaster(double timeout_s) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (!ros::master::check()) {
      if (ros::WallTime::now() > deadline) return false;
      ros::WallDuration(0.1).sleep();
    }
    return true;
  }

 private:
  static pid_t Start(const std::vector<std::string>& argv) {
    const pid_t pid = fork();
    if (pid == 0) {
      std::vector<char*> args;
      for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      setpgid(0, 0);
      execvp(args[0], args.data());
      _exit(127);
    }
    return pid;
  }
  std::vector<pid_t> pids_;
};

}  // namespace spott_ros::testing
