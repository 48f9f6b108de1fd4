#include "demo_navigation.h"

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/PointStamped.h>
#include <nav_msgs/Odometry.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/NavigateAction.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <mutex>
#include <sstream>

#include "spott_map/geometry.h"

namespace spott_launch {
namespace {

using NavigateClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;

// What the simulator says while a leg runs; filled by subscriber callbacks.
struct LegWatcher {
  std::mutex mutex;
  const spott_map::World* world = nullptr;
  bool have_pose = false;
  spott_map::Vec2 position{0.0, 0.0};
  double yaw = 0.0;
  double path_length_m = 0.0;
  int estimates = 0, lost_reports = 0;
  double sum_position_error_m = 0.0, max_position_error_m = 0.0;
  double sum_heading_error_rad = 0.0, max_heading_error_rad = 0.0;
  double min_wall_distance_m = std::numeric_limits<double>::infinity();
  int bumper_hits = 0;
  std::string global_path;  ///< The first plan made for the current goal.
  std::string last_path;    ///< The latest plan (latched: unchanged plans are not re-sent).
  ros::Time goal_time;

  void Reset(const ros::Time& now) {
    std::lock_guard<std::mutex> lock(mutex);
    global_path.clear();
    goal_time = now;
    path_length_m = 0.0;
    min_wall_distance_m = std::numeric_limits<double>::infinity();
    bumper_hits = 0;
    estimates = lost_reports = 0;
    sum_position_error_m = max_position_error_m = 0.0;
    sum_heading_error_rad = max_heading_error_rad = 0.0;
  }
  void OnTruth(const nav_msgs::Odometry& odom) {
    const spott_map::Vec2 p(odom.pose.pose.position.x, odom.pose.pose.position.y);
    std::lock_guard<std::mutex> lock(mutex);
    if (have_pose) path_length_m += (p - position).norm();
    position = p;
    yaw = 2.0 * std::atan2(odom.pose.pose.orientation.z, odom.pose.pose.orientation.w);
    have_pose = true;
    min_wall_distance_m = std::min(min_wall_distance_m, DistanceToNearestSolid(*world, p));
  }
  // The localization's estimate against the latest ground truth (both at about the same time:
  // the status follows each sonar ring, the truth comes at the simulator's rate).
  void OnStatus(const spott_msgs::LocalizationStatus& status) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!have_pose) return;
    const double e = (spott_map::Vec2(status.estimate.x, status.estimate.y) - position).norm();
    const double h = std::abs(spott_map::NormalizeAngle(status.estimate.theta - yaw));
    ++estimates;
    lost_reports += status.lost ? 1 : 0;
    sum_position_error_m += e;
    sum_heading_error_rad += h;
    max_position_error_m = std::max(max_position_error_m, e);
    max_heading_error_rad = std::max(max_heading_error_rad, h);
  }
  void OnBumper(const spott_msgs::BumperRing& ring) {
    if (std::none_of(ring.pressed.begin(), ring.pressed.end(), [](bool b) { return b; })) return;
    std::lock_guard<std::mutex> lock(mutex);
    ++bumper_hits;
  }
  void OnGlobalPath(const spott_msgs::GlobalPath& path) {
    std::string text;
    for (std::size_t i = 0; i < path.rooms.size(); ++i) {
      text += (i == 0 ? "" : " -> ") + path.rooms[i];
      if (i < path.doors.size()) text += " -> " + path.doors[i];
    }
    std::lock_guard<std::mutex> lock(mutex);
    last_path = text.empty() ? "(no path)" : text;
    if (global_path.empty() && path.header.stamp >= goal_time) global_path = last_path;
  }
};

std::string OutcomeText(const spott_msgs::NavigateResult& result) {
  switch (result.outcome) {
    case spott_msgs::NavigateResult::SUCCEEDED:
      return "reached";
    case spott_msgs::NavigateResult::UNREACHABLE:
      return "unreachable: " + result.reason;
    case spott_msgs::NavigateResult::PREEMPTED:
      return "preempted";
    default:
      return "failed: " + result.reason;
  }
}

}  // namespace

double DistanceToNearestSolid(const spott_map::World& world, const spott_map::Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const spott_map::Wall& wall : world.walls) {
    best = std::min(best, std::max(0.0, spott_map::DistancePointSegment(p, wall.segment) -
                                            wall.thickness / 2.0));
  }
  for (const spott_map::WorldObject& object : world.objects) {
    const spott_map::Polygon footprint = object.Footprint();
    const double d =
        spott_map::PointInPolygon(p, footprint) ? 0.0 : spott_map::DistanceToBoundary(p, footprint);
    best = std::min(best, d);
  }
  return best;
}

NavigationReport RunNavigation(ros::NodeHandle& nh, const spott_map::World& world,
                               const std::vector<std::string>& goals, double leg_timeout_s,
                               double connect_timeout_s) {
  NavigationReport report;
  if (!ros::Time::waitForValid(ros::WallDuration(connect_timeout_s))) {
    report.skipped = "no /clock from the simulator";
    return report;
  }
  LegWatcher watcher;
  watcher.world = &world;
  ros::CallbackQueue queue;
  ros::NodeHandle watch_nh(nh);
  watch_nh.setCallbackQueue(&queue);
  ros::Subscriber truth_sub =
      watch_nh.subscribe("/sim/ground_truth", 50, &LegWatcher::OnTruth, &watcher);
  ros::Subscriber bumper_sub = watch_nh.subscribe("/bumper", 10, &LegWatcher::OnBumper, &watcher);
  ros::Subscriber path_sub =
      watch_nh.subscribe("global_path", 5, &LegWatcher::OnGlobalPath, &watcher);
  ros::Subscriber status_sub =
      watch_nh.subscribe("localization_status", 20, &LegWatcher::OnStatus, &watcher);
  ros::AsyncSpinner watch_spinner(1, &queue);
  watch_spinner.start();
  ros::Publisher goal_pub = nh.advertise<geometry_msgs::PointStamped>("global_goal", 1, true);

  NavigateClient client(nh, "harmonic_planner/navigate", true);
  if (!client.waitForServer(ros::Duration(connect_timeout_s))) {
    report.skipped = "harmonic_planner/navigate is not offered";
    return report;
  }
  report.ran = true;
  for (const std::string& name : goals) {
    NavigationLeg leg;
    leg.goal = name;
    const spott_map::Place* place = world.FindPlace(name);
    if (!place) {
      leg.outcome = "failed: no place '" + name + "' in the world file";
      report.legs.push_back(leg);
      continue;
    }
    leg.target = place->pose;
    const ros::Time started = ros::Time::now();
    watcher.Reset(started);

    geometry_msgs::PointStamped goal_point;
    goal_point.header.frame_id = "map";
    goal_point.header.stamp = started;
    goal_point.point.x = place->pose.x;
    goal_point.point.y = place->pose.y;
    goal_pub.publish(goal_point);
    // Give the global planner a moment to plan and project before the local planner starts, so
    // the first steps already head for the right door.
    const ros::WallTime wait_until = ros::WallTime::now() + ros::WallDuration(3.0);
    while (ros::WallTime::now() < wait_until) {
      {
        std::lock_guard<std::mutex> lock(watcher.mutex);
        if (!watcher.global_path.empty()) break;
      }
      ros::WallDuration(0.05).sleep();
    }

    client.sendGoal(NavigateGoalTo(place->pose, /*ignore_heading=*/false));
    bool done = false;
    while (ros::ok() && (ros::Time::now() - started).toSec() < leg_timeout_s) {
      if (client.getState().isDone()) {
        done = true;
        break;
      }
      ros::WallDuration(0.05).sleep();
    }
    leg.sim_time_s = (ros::Time::now() - started).toSec();
    if (done) {
      const auto result = client.getResult();
      leg.outcome = result ? OutcomeText(*result) : "failed: no result";
      leg.reached = result && result->outcome == spott_msgs::NavigateResult::SUCCEEDED;
    } else {
      client.cancelGoal();
      char text[64];
      std::snprintf(text, sizeof(text), "timed out after %.0f s of simulated time", leg_timeout_s);
      leg.outcome = text;
    }
    std::lock_guard<std::mutex> lock(watcher.mutex);
    leg.global_path = watcher.global_path.empty() ? watcher.last_path : watcher.global_path;
    leg.path_length_m = watcher.path_length_m;
    leg.final_error_m = (watcher.position - place->pose.Position()).norm();
    leg.final_position = watcher.position;
    leg.min_wall_distance_m = watcher.min_wall_distance_m;
    leg.bumper_hits = watcher.bumper_hits;
    leg.estimates = watcher.estimates;
    leg.lost_reports = watcher.lost_reports;
    if (watcher.estimates > 0) {
      leg.mean_position_error_m = watcher.sum_position_error_m / watcher.estimates;
      leg.mean_heading_error_rad = watcher.sum_heading_error_rad / watcher.estimates;
      leg.max_position_error_m = watcher.max_position_error_m;
      leg.max_heading_error_rad = watcher.max_heading_error_rad;
    }
    report.legs.push_back(leg);
  }
  return report;
}

spott_msgs::NavigateGoal NavigateGoalTo(const spott_map::Pose2& target, bool ignore_heading) {
  spott_msgs::NavigateGoal goal;
  goal.target.header.frame_id = "map";
  goal.target.header.stamp = ros::Time::now();
  goal.target.pose.position.x = target.x;
  goal.target.pose.position.y = target.y;
  goal.target.pose.orientation.z = std::sin(target.yaw / 2.0);
  goal.target.pose.orientation.w = std::cos(target.yaw / 2.0);
  goal.speed_mode = spott_msgs::NavigateGoal::NORMAL;
  goal.direction_bias = std::numeric_limits<double>::quiet_NaN();
  goal.ignore_heading = ignore_heading;
  return goal;
}

std::string FormatNavigation(const NavigationReport& report) {
  if (!report.ran && report.skipped.empty()) return "";
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  out << "\n Navigation (global_planner -> harmonic_planner -> robot_sim; measured on the\n"
      << " simulator's ground truth, which nothing in the stack reads):\n";
  if (!report.ran) {
    out << "   not run: " << report.skipped << "\n";
    return out.str();
  }
  int reached = 0;
  for (const NavigationLeg& leg : report.legs) {
    reached += leg.reached;
    out << "   to " << leg.goal << " (" << leg.target.x << ", " << leg.target.y
        << "): " << leg.outcome << "\n";
    if (!leg.global_path.empty()) out << "     global path: " << leg.global_path << "\n";
    out << std::setprecision(1) << "     " << leg.sim_time_s << " s simulated, "
        << leg.path_length_m << " m driven, ended at (" << leg.final_position.x() << ", "
        << leg.final_position.y() << "), " << std::setprecision(2) << leg.final_error_m
        << " m from the target; closest approach to a wall or object " << leg.min_wall_distance_m
        << " m (centre), bumper contacts: " << leg.bumper_hits << "\n";
    if (leg.estimates > 0) {
      out << "     localization error (markov_localization vs ground truth, " << leg.estimates
          << " estimates): mean " << leg.mean_position_error_m << " m / " << std::setprecision(1)
          << leg.mean_heading_error_rad * 180.0 / M_PI << " deg, max " << std::setprecision(2)
          << leg.max_position_error_m << " m / " << std::setprecision(1)
          << leg.max_heading_error_rad * 180.0 / M_PI << " deg; said lost " << leg.lost_reports
          << " times\n"
          << std::setprecision(2);
    }
  }
  out << "   " << reached << " of " << report.legs.size() << " goals reached\n";
  return out.str();
}

}  // namespace spott_launch
