#include "fig18_campaign.h"

#include <actionlib/client/simple_action_client.h>
#include <nav_msgs/Odometry.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/TaskAction.h>

#include <cmath>
#include <cstdio>
#include <mutex>

#include "demo_navigation.h"
#include "spott_map/room_door_graph.h"

namespace spott_launch {

namespace {

// Rooms reachable from `from` through doors whose state is known to be open (the simulator
// builds doors of unknown state closed: they are not a way the campaign may count on).
std::vector<std::string> ReachableThroughOpenDoors(const spott_map::World& world,
                                                   const std::string& from) {
  std::vector<std::string> reached{from};
  for (std::size_t i = 0; i < reached.size(); ++i) {
    for (const spott_map::Door& d : world.doors) {
      const bool open =
          d.kind == spott_map::DoorKind::kOpening || d.state == spott_map::DoorState::kOpen;
      if (!open) continue;
      std::string other;
      if (d.room_a == reached[i]) other = d.room_b;
      if (d.room_b == reached[i]) other = d.room_a;
      if (!other.empty() && std::find(reached.begin(), reached.end(), other) == reached.end()) {
        reached.push_back(other);
      }
    }
  }
  return reached;
}

}  // namespace

Fig18Case Fig18CaseFor(const spott_map::World& world, int seed, double clearance_m,
                       double min_distance_m) {
  std::mt19937 rng(static_cast<unsigned>(seed) * 2654435761u + 17u);
  const spott_map::Room* start_room = world.RoomContaining(world.robot_start.Position());
  const std::vector<std::string> rooms =
      ReachableThroughOpenDoors(world, start_room ? start_room->id : world.rooms.front().id);
  const auto sample = [&](const std::string& room_id) {
    const spott_map::Room* room = world.FindRoom(room_id);
    const spott_map::Box b = spott_map::BoundingBox(room->polygon);
    for (int k = 0; k < 10000; ++k) {
      const spott_map::Vec2 p(std::uniform_real_distribution<double>(b.min.x(), b.max.x())(rng),
                              std::uniform_real_distribution<double>(b.min.y(), b.max.y())(rng));
      if (!spott_map::PointInPolygon(p, room->polygon)) continue;
      if (spott_map::DistanceToBoundary(p, room->polygon) < clearance_m) continue;
      if (DistanceToNearestSolid(world, p) < clearance_m) continue;
      return std::optional<spott_map::Vec2>(p);
    }
    return std::optional<spott_map::Vec2>();
  };
  Fig18Case c;
  c.seed = seed;
  for (int attempt = 0; attempt < 1000; ++attempt) {
    std::uniform_int_distribution<std::size_t> pick(0, rooms.size() - 1);
    const std::string a = rooms[pick(rng)], b = rooms[pick(rng)];
    if (a == b) continue;
    const auto s = sample(a), g = sample(b);
    if (!s || !g || (*s - *g).norm() < min_distance_m) continue;
    c.start =
        spott_map::Pose2{s->x(), s->y(), std::uniform_real_distribution<double>(-M_PI, M_PI)(rng)};
    c.goal = *g;
    c.start_room = a;
    c.goal_room = b;
    char text[96];
    std::snprintf(text, sizeof(text), "go to point(%.2f, %.2f)", g->x(), g->y());
    c.command = text;
    return c;
  }
  return c;
}

Fig18Run RunFig18Case(ros::NodeHandle& nh, const Fig18Case& c, double timeout_s,
                      double tolerance_m) {
  Fig18Run run;
  run.c = c;
  run.straight_m = (c.goal - c.start.Position()).norm();
  std::mutex mutex;
  spott_map::Vec2 truth(0, 0), estimate(1e9, 1e9);
  bool have_truth = false;
  double length = 0.0;
  int contacts = 0;
  bool pressed = false;
  ros::Subscriber truth_sub = nh.subscribe<nav_msgs::Odometry>(
      "/sim/ground_truth", 50, [&](const nav_msgs::Odometry::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        const spott_map::Vec2 p(m->pose.pose.position.x, m->pose.pose.position.y);
        if (have_truth) length += (p - truth).norm();
        truth = p;
        have_truth = true;
      });
  ros::Subscriber bumper_sub = nh.subscribe<spott_msgs::BumperRing>(
      "/bumper", 10, [&](const spott_msgs::BumperRing::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        bool now_pressed = false;
        for (bool p : m->pressed) now_pressed = now_pressed || p;
        if (now_pressed) ++contacts;
        // Where each contact began, and how far off the estimate was then: the campaign's
        // failures are told apart by these lines in the run's log.
        if (now_pressed && !pressed) {
          ROS_WARN(
              "fig18_run: contact begins at truth (%.2f, %.2f), estimate (%.2f, %.2f): "
              "localization error %.2f m",
              truth.x(), truth.y(), estimate.x(), estimate.y(), (estimate - truth).norm());
        }
        pressed = now_pressed;
      });
  ros::Subscriber status_sub = nh.subscribe<spott_msgs::LocalizationStatus>(
      "localization_status", 5, [&](const spott_msgs::LocalizationStatus::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        estimate = spott_map::Vec2(m->estimate.x, m->estimate.y);
      });
  ros::AsyncSpinner spinner(2);
  spinner.start();
  actionlib::SimpleActionClient<spott_msgs::TaskAction> client("task", true);
  if (!ros::Time::waitForValid(ros::WallDuration(60.0)) ||
      !client.waitForServer(ros::Duration(60.0))) {
    run.outcome = "the stack did not come up (/clock, /task)";
    return run;
  }
  // markov_localization starts at the run's start (stack.launch passes start_pose as its
  // initial pose); wait until its estimate says so.
  // With localization:=truth nothing publishes the status: no wait.
  const ros::WallTime begin = ros::WallTime::now();
  const ros::WallTime settle = begin + ros::WallDuration(30.0);
  while (ros::WallTime::now() < settle) {
    if (ros::WallTime::now() - begin > ros::WallDuration(5.0) && status_sub.getNumPublishers() == 0)
      break;
    {
      std::lock_guard<std::mutex> lock(mutex);
      if ((estimate - c.start.Position()).norm() < 0.2) break;
    }
    ros::WallDuration(0.2).sleep();
  }
  ros::Duration(2.0).sleep();
  {
    std::lock_guard<std::mutex> lock(mutex);
    length = 0.0;
    contacts = 0;
  }
  spott_msgs::TaskGoal goal;
  goal.command = c.command;
  const ros::Time started = ros::Time::now();
  client.sendGoal(goal);
  if (!client.waitForResult(ros::Duration(timeout_s))) {
    client.cancelGoal();
    client.waitForResult(ros::Duration(5.0));
    run.outcome = "timed out";
  }
  run.sim_time_s = (ros::Time::now() - started).toSec();
  ros::WallDuration(0.2).sleep();
  const auto r = client.getResult();
  if (r && run.outcome.empty())
    run.outcome = r->outcome + (r->message.empty() ? "" : ": " + r->message);
  std::lock_guard<std::mutex> lock(mutex);
  run.path_length_m = length;
  run.contacts = contacts;
  run.final_error_m = (truth - c.goal).norm();
  run.arrived = r && r->outcome == "reached" && run.final_error_m <= tolerance_m && contacts == 0;
  return run;
}

std::string Fig18Line(const Fig18Run& r) {
  char text[512];
  std::snprintf(text, sizeof(text),
                "%d %s %s %s %.1f %.2f %.2f %.3f %.2f %d start=(%.2f,%.2f,%.2f) goal=(%.2f,%.2f) "
                "%s",
                r.c.seed, r.c.start_room.c_str(), r.c.goal_room.c_str(),
                r.arrived ? "arrived" : "FAILED", r.sim_time_s, r.path_length_m, r.straight_m,
                r.mean_speed_mps(), r.final_error_m, r.contacts, r.c.start.x, r.c.start.y,
                r.c.start.yaw, r.c.goal.x(), r.c.goal.y(), r.outcome.c_str());
  return text;
}

}  // namespace spott_launch
