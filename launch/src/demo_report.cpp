#include "demo_report.h"

#include "leg_messages.h"

#include <algorithm>
#include <iomanip>
#include <mutex>
#include <optional>
#include <sstream>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/callback_queue.h>
#include <ros/package.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/MissionActionGoal.h>
#include <spott_msgs/NavigateActionGoal.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/SetDoorState.h>
#include <spott_msgs/TaskActionGoal.h>

#include "spott_map/local_map.h"
#include "spott_map/ros/conversions.h"
#include "spott_map/world_loader.h"
#include "spott_ros/robot_geometry.h"

namespace spott_launch {

namespace {

namespace conv = spott_map::ros_conversions;

// Waits for the next message on a (latched) topic.
template <class Msg>
std::optional<Msg> WaitForMessage(ros::NodeHandle& nh, const std::string& topic, double timeout_s) {
  boost::shared_ptr<const Msg> msg =
      ros::topic::waitForMessage<Msg>(topic, nh, ros::Duration(timeout_s));
  if (!msg) return std::nullopt;
  return *msg;
}

std::vector<std::string> Reachable(const spott_map::RoomDoorGraph& g, const std::string& from) {
  std::vector<std::string> r = g.ReachableFrom(from);
  std::sort(r.begin(), r.end());
  return r;
}

// The doors of `room` that are closed, as "d_102 closed".
std::string ClosedDoorsOf(const spott_map::RoomDoorGraph& g, const std::string& room) {
  std::string text;
  for (const spott_map::Door* d : g.DoorsOf(room)) {
    if (d->state != spott_map::DoorState::kClosed) continue;
    text += (text.empty() ? "" : ", ") + d->id;
  }
  return text.empty() ? "no direct closed door" : "behind closed " + text;
}

std::vector<std::string> AsciiWindow(const spott_map::MapDatabase& db, const spott_map::Vec2& at,
                                     double robot_radius_m) {
  spott_map::LocalMapParameters p;  // SPOTT's 35 x 35 window of 0.2 m cells
  p.robot_radius_m = robot_radius_m;
  spott_map::LocalMap local(p);
  local.Recentre(db, at);
  const auto robot = local.raster().CellOf(at);
  std::vector<std::string> rows;
  for (int iy = local.raster().height() - 1; iy >= 0; --iy) {
    std::string row;
    for (int ix = 0; ix < local.raster().width(); ++ix) {
      if (robot && robot->first == ix && robot->second == iy) {
        row += 'R';
        continue;
      }
      switch (local.raster().at(ix, iy)) {
        case spott_map::Cell::kObstacle:
          row += '#';
          break;
        case spott_map::Cell::kPadding:
          row += '+';
          break;
        case spott_map::Cell::kFree:
          row += '.';
          break;
      }
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

namespace {

// /sim/faults on a queue of its own: faults keep being logged while the demo waits on actions.
class FaultLog {
 public:
  explicit FaultLog(ros::NodeHandle& parent) : nh_(parent) {
    nh_.setCallbackQueue(&queue_);
    sub_ = nh_.subscribe("/sim/faults", 20, &FaultLog::OnFault, this);
    spinner_.start();
  }
  ~FaultLog() { spinner_.stop(); }
  std::vector<DemoReport::Fault> Take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return faults_;
  }

 private:
  void OnFault(const diagnostic_msgs::DiagnosticArray& msg) {
    const auto faults = FaultsFrom(msg);
    std::lock_guard<std::mutex> lock(mutex_);
    faults_.insert(faults_.end(), faults.begin(), faults.end());
  }
  ros::NodeHandle nh_;
  ros::CallbackQueue queue_;
  ros::Subscriber sub_;
  ros::AsyncSpinner spinner_{1, &queue_};
  std::mutex mutex_;
  std::vector<DemoReport::Fault> faults_;
};

}  // namespace

DemoReport RunDemo(ros::NodeHandle& nh, const DemoOptions& options) {
  FaultLog fault_log(nh);
  DemoReport report = RunDemoSteps(nh, options);
  report.faults = fault_log.Take();
  return report;
}

DemoReport RunDemoSteps(ros::NodeHandle& nh, const DemoOptions& options) {
  // The legs' goal topic, advertised now, seconds before the first goal: a recorder (the bag of
  // ./spott run) connects to it meanwhile. The action client advertises it only when the legs
  // begin, and a recorder then missed the first goal 1 run in 3. roscpp shares one publication
  // per topic in a node, so the client later publishes through these connections.
  const ros::Publisher early_goal_topic =
      !options.missions.empty() ? nh.advertise<spott_msgs::MissionActionGoal>("mission/goal", 10)
      : options.tasks.empty()
          ? nh.advertise<spott_msgs::NavigateActionGoal>("harmonic_planner/navigate/goal", 10)
          : nh.advertise<spott_msgs::TaskActionGoal>("task/goal", 10);
  const std::string& world_file = options.world_file;
  const std::vector<std::string>& doors_to_close = options.doors_to_close;
  const double timeout_s = options.timeout_s;
  DemoReport report;
  // The report says which parts of the designed stack this build lacks, rather than a list
  // written by hand that goes stale.
  for (const char* package :
       {"robot_sim", "markov_localization", "spott_global_planner", "spott_harmonic_planner",
        "spott_move_base", "cmd_vel_arbiter", "spott_tr_plus", "rpl_executive"}) {
    const bool runs =
        std::find(options.running.begin(), options.running.end(), package) != options.running.end();
    (ros::package::getPath(package).empty() ? report.stack_packages_missing
     : runs                                 ? report.stack_packages_running
                                            : report.stack_packages_not_run)
        .push_back(package);
  }
  const ros::WallTime start = ros::WallTime::now();
  const auto fail = [&](const std::string& why) {
    report.failure = why;
    report.elapsed_s = (ros::WallTime::now() - start).toSec();
    return report;
  };
  const spott_map::WorldLoadResult scenario = spott_map::LoadWorldFile(world_file);
  if (!scenario.ok()) return fail(spott_map::FormatErrors(scenario.errors));

  auto graph_msg = WaitForMessage<spott_msgs::RoomDoorGraph>(nh, "room_door_graph", timeout_s);
  if (!graph_msg) return fail("no room_door_graph from the world server");
  auto map_msg = WaitForMessage<nav_msgs::OccupancyGrid>(nh, "map", timeout_s);
  if (!map_msg) return fail("no map from the world server");
  auto features_msg = WaitForMessage<spott_msgs::MapFeatureArray>(nh, "map_features", timeout_s);
  if (!features_msg) return fail("no map_features from the world server");

  std::string error;
  auto graph = conv::FromMsg(*graph_msg, &error);
  if (!graph) return fail("room_door_graph: " + error);
  spott_map::MapDatabase db;
  db.SetGraph(*graph);
  for (const auto& f : features_msg->features) {
    auto feature = conv::FromMsg(f, &error);
    if (!feature) return fail(error);
    db.AddFeature(*feature);
  }

  report.world = graph_msg->world;
  for (const auto& r : graph_msg->rooms) {
    ++report.rooms;
    report.hallways += r.kind == spott_msgs::Room::HALLWAY;
  }
  for (const auto& d : graph_msg->doors) {
    if (d.kind == spott_msgs::Door::KIND_OPENING) {
      ++report.openings;
    } else if (d.state == spott_msgs::Door::OPEN) {
      ++report.doors_open;
    } else if (d.state == spott_msgs::Door::CLOSED) {
      ++report.doors_closed;
    } else {
      ++report.doors_unknown;
    }
  }
  report.cad_features = static_cast<int>(features_msg->features.size());
  report.map_width = static_cast<int>(map_msg->info.width);
  report.map_height = static_cast<int>(map_msg->info.height);
  report.map_resolution = map_msg->info.resolution;
  report.map_occupied =
      static_cast<int>(std::count(map_msg->data.begin(), map_msg->data.end(), 100));
  report.objects_not_in_cad = static_cast<int>(scenario.world->objects.size());

  const spott_map::Vec2 start_position = scenario.world->robot_start.Position();
  // No room at all: a stack without an a priori map (its database starts empty).
  const spott_map::Room* start_room = graph->RoomContaining(start_position);
  if (!start_room && !graph->rooms().empty())
    return fail("the robot start is outside every room of the served graph");
  report.start_room = start_room ? start_room->id : "";
  if (start_room) report.reachable = Reachable(*graph, start_room->id);
  for (const spott_map::Room& r : graph->rooms()) {
    if (std::find(report.reachable.begin(), report.reachable.end(), r.id) ==
        report.reachable.end()) {
      report.unreachable.push_back(r.id + " (" + ClosedDoorsOf(*graph, r.id) + ")");
    }
  }
  // The robot's own radius (a B-12's padding is thinner than a Nomad's), as every node takes it.
  std::string radius_error;
  if (const auto radius = spott_ros::FootprintRadiusFromParameter(nh, "robot_description",
                                                                  "base_link", &radius_error)) {
    report.robot_radius_m = *radius;
  } else {
    ROS_WARN("demo report: no robot radius (%s): the window is padded for %.3f m",
             radius_error.c_str(), report.robot_radius_m);
  }
  report.local_window = AsciiWindow(db, start_position, report.robot_radius_m);

  // Close doors one after the other through the world server, as a user (or the simulator's
  // fault schedule) would, and watch the served graph change.
  ros::ServiceClient set_door =
      nh.serviceClient<spott_msgs::SetDoorState>("world_server/set_door_state");
  if (!set_door.waitForExistence(ros::Duration(timeout_s))) {
    return fail("world_server/set_door_state is not offered");
  }
  std::vector<std::string> before = report.reachable;
  std::vector<std::pair<std::string, std::uint8_t>> restore;
  for (const std::string& door : start_room ? doors_to_close : std::vector<std::string>{}) {
    DemoReport::DoorExperiment e;
    e.door = door;
    if (const spott_map::Door* d = graph->FindDoor(door))
      restore.emplace_back(door, conv::ToMsg(d->state));
    spott_msgs::SetDoorState srv;
    srv.request.door_id = door;
    srv.request.state = spott_msgs::Door::CLOSED;
    if (!set_door.call(srv)) return fail("set_door_state call failed");
    e.accepted = srv.response.success;
    e.message = srv.response.message;
    if (e.accepted) {
      auto updated = ros::topic::waitForMessage<spott_msgs::RoomDoorGraph>(
          "room_door_graph", nh, ros::Duration(timeout_s));
      if (!updated) return fail("no room_door_graph after closing " + door);
      auto g = conv::FromMsg(*updated, &error);
      if (!g) return fail(error);
      const std::vector<std::string> after = Reachable(*g, start_room->id);
      for (const std::string& r : before) {
        if (std::find(after.begin(), after.end(), r) == after.end()) {
          e.newly_unreachable.push_back(r);
        }
      }
      before = after;
    }
    report.door_experiments.push_back(e);
  }
  for (const auto& [door, state] : restore) {
    spott_msgs::SetDoorState srv;
    srv.request.door_id = door;
    srv.request.state = state;
    set_door.call(srv);
  }
  if (options.wait_for_recorder) {
    // The server and the recorder: both connected before the first goal.
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (ros::ok() && early_goal_topic.getNumSubscribers() < 2 && ros::WallTime::now() < give_up)
      ros::WallDuration(0.05).sleep();
    if (early_goal_topic.getNumSubscribers() < 2)
      ROS_WARN("demo_report: the recorder did not subscribe to %s within %.0f s",
               early_goal_topic.getTopic().c_str(), timeout_s);
  }
  if (!options.tasks.empty()) {
    report.navigation = RunTasks(nh, *scenario.world, options.tasks, options.leg_timeout_s,
                                 timeout_s, options.goal_tolerance_m, options.estimate_from_tf);
  } else if (!options.goals.empty()) {
    report.navigation =
        RunNavigation(nh, *scenario.world, options.goals, options.leg_timeout_s, timeout_s,
                      options.goal_tolerance_m, options.estimate_from_tf);
  } else if (!options.missions.empty()) {
    report.navigation = RunMissions(nh, *scenario.world, options.missions, options.leg_timeout_s,
                                    timeout_s, options.goal_tolerance_m, options.estimate_from_tf);
  }
  report.ok = true;
  report.elapsed_s = (ros::WallTime::now() - start).toSec();
  return report;
}

std::string FormatReport(const DemoReport& r) {
  std::ostringstream out;
  const std::string rule(72, '=');
  out << "\n" << rule << "\n SPOTT-ROS demo report: world " << r.world << "\n" << rule << "\n";
  out << " Running: world_server (spott_map: the map database of SPOTT section III.A)";
  for (const std::string& p : r.stack_packages_running) out << ", " << p;
  out << "\n";
  const auto list = [&out](const char* title, const std::vector<std::string>& packages) {
    if (packages.empty()) return;
    out << title;
    for (const std::string& p : packages) out << " " << p;
    out << "\n";
  };
  list(" Built, not yet run by this demo:", r.stack_packages_not_run);
  list(" Not built yet:", r.stack_packages_missing);
  out << "\n";
  if (!r.ok) {
    out << " FAILED: " << r.failure << "\n";
    return out.str();
  }
  out << " Map database\n   rooms: " << r.rooms << " (" << r.hallways << " hallway portions)\n"
      << "   doors: " << r.doors_open << " open, " << r.doors_closed << " closed, "
      << r.doors_unknown << " unknown (assumed open), " << r.openings << " openings\n"
      << "   CAD wall features: " << r.cad_features << "\n"
      << "   occupancy map: " << r.map_width << " x " << r.map_height << " cells of " << std::fixed
      << std::setprecision(2) << r.map_resolution << " m, " << r.map_occupied << " occupied\n"
      << "   objects not in the CAD map (for the robot to discover): " << r.objects_not_in_cad
      << "\n\n";
  if (r.start_room.empty()) {
    out << " No a priori map: no room, door or wall is known; the robot maps what it senses\n";
  } else {
    out << " Robot start is in " << r.start_room
        << "; reachable through passable doors: " << r.reachable.size() << " of " << r.rooms
        << " rooms\n";
  }
  for (const std::string& u : r.unreachable) out << "   unreachable: " << u << "\n";
  out << "\n Closing doors through world_server/set_door_state:\n";
  for (const auto& e : r.door_experiments) {
    out << "   " << e.door << ": " << (e.accepted ? "closed" : "refused: " + e.message);
    if (e.accepted) {
      if (e.newly_unreachable.empty()) {
        out << "; every room is still reachable";
      } else {
        out << "; now unreachable:";
        for (const std::string& u : e.newly_unreachable) out << " " << u;
      }
    }
    out << "\n";
  }
  spott_map::LocalMapParameters window;  // the parameters AsciiWindow uses
  window.robot_radius_m = r.robot_radius_m;
  out << std::defaultfloat << std::setprecision(6) << "\n Local window at the start (SPOTT's "
      << window.cells() << " x " << window.cells() << " cells of " << window.resolution_m
      << " m; '#' wall, '+' padding\n of robot radius " << window.robot_radius_m
      << " m + localization error " << window.max_localization_error_m
      << " m, '.' free, 'R' robot):\n";
  for (const std::string& row : r.local_window) out << "   " << row << "\n";
  out << FormatNavigation(r.navigation);
  if (!r.faults.empty()) {
    out << "\n Faults (the simulator's schedule, /sim/faults):\n";
    for (const auto& f : r.faults) {
      out << "   " << std::fixed << std::setprecision(1) << f.sim_time_s << " s: " << f.what
          << (f.applied ? "" : " (REFUSED)") << "\n";
    }
  }
  out << "\n Demo finished in " << std::fixed << std::setprecision(1) << r.elapsed_s << " s.\n"
      << rule << "\n";
  return out.str();
}

}  // namespace spott_launch
