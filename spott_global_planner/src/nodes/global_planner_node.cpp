// global_planner: SPOTT's global path planner (III.D.2) as a ROS node. Plans over the room/door
// graph from the robot's node to the goal's, projects the goal onto the local planner's window
// (Fig. 14) and replans when a door closes or an obstacle blocks a passage through a node.
//
// Subscribes: room_door_graph (spott_msgs/RoomDoorGraph, latched by the map's owner),
// map_updates (door states), map_features (for blocked passages), global_goal
// (spott_msgs/GlobalGoal, from the Navigate server only), local_window
// (geometry_msgs/PolygonStamped, the harmonic planner's window, optional). Reads tf
// frame_id -> robot_frame.
// Publishes (latched): global_path, projected_goal, global_plan_status (each carrying the
// goal_id of the GlobalGoal they answer, re-sent for every new goal id), global_planner_markers.
// Service: ~plan_global_path (spott_msgs/PlanGlobalPath). See the package README.
#include <geometry_msgs/PolygonStamped.h>
#include <ros/ros.h>
#include <spott_msgs/GlobalGoal.h>
#include <spott_msgs/GlobalPlanStatus.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/PlanGlobalPath.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <tf2_ros/transform_listener.h>

#include <optional>

#include "spott_global_planner/planning_session.h"
#include "spott_global_planner/ros/conversions.h"
#include "spott_global_planner/ros/parameters.h"
#include "spott_map/ros/conversions.h"
#include "spott_ros/input_refusals.h"
#include "spott_ros/parameter_reader.h"
#include "spott_ros/robot_geometry.h"
#include "spott_ros/robot_pose.h"

namespace spott_global_planner {
namespace {

namespace conv = ros_conversions;
namespace map_conv = spott_map::ros_conversions;

using ros_parameters::NodeParameters;

// Ids and outlines of rooms and doors: equal signatures mean only door states can differ.
std::string Structure(const spott_msgs::RoomDoorGraph& g) {
  std::string s;
  for (const auto& r : g.rooms) {
    s += r.id + '(';
    for (const auto& p : r.polygon.points) s += std::to_string(p.x) + ',' + std::to_string(p.y);
    s += ')';
  }
  for (const auto& d : g.doors) {
    s += d.id + ':' + d.room_a + '-' + d.room_b + '/' + std::to_string(d.kind) + '@' +
         std::to_string(d.centre.x) + ',' + std::to_string(d.centre.y) + 'w' +
         std::to_string(d.width) + ';';
  }
  return s;
}

class GlobalPlannerNode {
 public:
  GlobalPlannerNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const NodeParameters& params)
      : params_(params),
        session_(params.core),
        tf_listener_(tf_buffer_),
        refusals_(nh, "global_planner") {
    path_pub_ = nh.advertise<spott_msgs::GlobalPath>("global_path", 1, true);
    goal_pub_ = nh.advertise<spott_msgs::ProjectedGoal>("projected_goal", 1, true);
    status_pub_ = nh.advertise<spott_msgs::GlobalPlanStatus>("global_plan_status", 1, true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("global_planner_markers", 1, true);
    graph_sub_ = nh.subscribe("room_door_graph", 1, &GlobalPlannerNode::OnGraph, this);
    updates_sub_ = nh.subscribe("map_updates", 10, &GlobalPlannerNode::OnMapUpdate, this);
    features_sub_ = nh.subscribe("map_features", 1, &GlobalPlannerNode::OnFeatures, this);
    goal_sub_ = nh.subscribe("global_goal", 10, &GlobalPlannerNode::OnGoal, this);
    window_sub_ = nh.subscribe("local_window", 1, &GlobalPlannerNode::OnLocalWindow, this);
    plan_srv_ = pnh.advertiseService("plan_global_path", &GlobalPlannerNode::OnPlan, this);
    timer_ = nh.createTimer(ros::Duration(1.0 / params_.update_rate_hz),
                            [this](const ros::TimerEvent&) { Update(); });
    PublishStatus(spott_msgs::GlobalPlanStatus::NO_GOAL, "waiting for a goal", nullptr);
  }

 private:
  void OnGraph(const spott_msgs::RoomDoorGraph& msg) {
    if (!msg.header.frame_id.empty() && msg.header.frame_id != params_.frame_id) {
      refusals_.Refuse("room_door_graph", "header.frame_id",
                       "'" + msg.header.frame_id + "' is not '" + params_.frame_id + "'");
      return;
    }
    std::string error;
    std::optional<spott_map::RoomDoorGraph> graph = map_conv::FromMsg(msg, &error);
    if (!graph) {
      refusals_.Refuse("room_door_graph", "rooms/doors",
                       "world '" + msg.world + "': " + error + " (keeping the " +
                           (session_.has_graph() ? "last one)" : "none)"));
      return;
    }
    if (graph->rooms().empty() && session_.has_graph()) {
      // A graph without rooms would leave nothing to plan in: keep the one we have.
      refusals_.Refuse("room_door_graph", "rooms", "an empty graph (keeping the last one)");
      return;
    }
    const std::string structure = Structure(msg);
    if (session_.has_graph() && structure == structure_) {
      for (const spott_map::Door& d : graph->doors()) session_.SetDoorState(d.id, d.state);
    } else {
      session_.SetGraph(std::move(*graph));
      structure_ = structure;
      ROS_INFO("global_planner: graph of world '%s': %zu nodes, %zu doors", msg.world.c_str(),
               msg.rooms.size(), msg.doors.size());
    }
    Update();
  }

  void OnMapUpdate(const spott_msgs::MapUpdate& msg) {
    for (const auto& d : msg.doors) {
      const auto state = map_conv::DoorStateFromMsg(d.state);
      if (!state) {
        refusals_.Refuse(
            "map_updates", "doors[].state",
            "invalid state " + std::to_string(d.state) + " for door '" + d.door_id + "'");
      } else if (!session_.SetDoorState(d.door_id, *state)) {
        ROS_WARN("global_planner: map update: unknown door '%s' (or an opening closed)",
                 d.door_id.c_str());
      }
    }
    Update();
  }

  void OnFeatures(const spott_msgs::MapFeatureArray& msg) {
    if (msg.features.empty() && have_features_) {  // features are removed with a MapUpdate
      refusals_.Refuse("map_features", "features", "an empty array would remove every obstacle");
      return;
    }
    std::vector<spott_map::MapFeature> features;
    for (const auto& f : msg.features) {
      std::string error;
      if (auto feature = map_conv::FromMsg(f, &error)) {
        features.push_back(std::move(*feature));
      } else {
        refusals_.Refuse("map_features", "features[]", error);
      }
    }
    have_features_ = have_features_ || !features.empty();
    for (const std::string& room : session_.SetFeatures(features)) {
      ROS_INFO("global_planner: passages through node '%s' changed", room.c_str());
    }
    Update();
  }

  // A new goal id is answered in full (status, path, projection), even when the target is the
  // one of the last goal: the Navigate server waits for answers carrying its id.
  void OnGoal(const spott_msgs::GlobalGoal& msg) {
    if (msg.goal_id.empty()) {
      session_.ClearGoal();
      goal_id_.clear();
      PublishStatus(spott_msgs::GlobalPlanStatus::NO_GOAL, "no goal", nullptr);
      return;
    }
    goal_id_ = msg.goal_id;
    answered_ = false;
    if (!msg.header.frame_id.empty() && msg.header.frame_id != params_.frame_id) {
      RefuseGoal("goal is in frame '" + msg.header.frame_id + "', not '" + params_.frame_id +
                 "': goal refused");
      return;
    }
    const PlanResult check = session_.SetGoal(map_conv::FromPoint(msg.target));
    if (check.error != PlanError::kNone) {
      RefuseGoal(check.message);
      return;
    }
    ROS_INFO("global_planner: goal %s (%.2f, %.2f)%s%s", goal_id_.c_str(), msg.target.x,
             msg.target.y, check.message.empty() ? "" : ": ", check.message.c_str());
    Update();
  }

  void RefuseGoal(const std::string& why) {
    ROS_WARN("global_planner: %s", why.c_str());
    session_.ClearGoal();  // the Navigate server ended the previous goal when it sent this one
    answered_ = true;
    PublishStatus(spott_msgs::GlobalPlanStatus::REFUSED, why, nullptr);
  }

  void OnLocalWindow(const geometry_msgs::PolygonStamped& msg) {
    if (!params_.follow_local_window) return;
    const auto box = conv::WindowFromPolygon(msg.polygon);
    if (!box || !((box->max - box->min).array() > 0.0).all()) {
      ROS_WARN_THROTTLE(10.0, "global_planner: ignoring an empty or non-finite local_window");
      return;
    }
    local_window_ = box;
  }

  bool OnPlan(spott_msgs::PlanGlobalPath::Request& req, spott_msgs::PlanGlobalPath::Response& res) {
    const PlanResult r =
        session_.PlanOnce(map_conv::FromPoint(req.start), map_conv::FromPoint(req.goal));
    res.success = r.ok();
    res.message =
        r.ok() ? "planned through " + std::to_string(r.path->doors.size()) + " doors" : r.message;
    if (r.ok()) res.path = conv::ToMsg(*r.path, params_.frame_id, ros::Time::now());
    if (!r.ok()) ROS_WARN("global_planner: plan_global_path: %s", r.message.c_str());
    return true;
  }

  void Update() {
    if (!session_.has_graph()) return;
    spott_ros::RobotPose pose;
    try {
      pose = spott_ros::LookupRobotPose(
          tf_buffer_, {params_.frame_id, params_.odom_frame, params_.robot_frame});
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(10.0, "global_planner: no robot pose (%s -> %s): %s",
                        params_.frame_id.c_str(), params_.robot_frame.c_str(), e.what());
      return;
    }
    const spott_map::Vec2 robot(pose.pose.x, pose.pose.y);
    const SessionUpdate u = session_.Update(robot, local_window_ ? &*local_window_ : nullptr);
    const ros::Time now = ros::Time::now();
    const bool answer = !goal_id_.empty() && !answered_;  // a new goal id: send everything
    answered_ = true;
    if (u.replanned) {
      ROS_INFO("global_planner: replanned (%zu so far): %s", u.replans,
               u.path ? "new path found" : "no path left");
    }
    if (u.path_changed || answer) {
      spott_msgs::GlobalPath path = u.path ? conv::ToMsg(*u.path, params_.frame_id, now)
                                           : conv::ToMsg(GlobalPath{}, params_.frame_id, now);
      path.goal_id = goal_id_;
      path_pub_.publish(path);
    }
    if (u.projection && (u.projection_changed || answer)) {
      spott_msgs::ProjectedGoal projection = conv::ToMsg(*u.projection, params_.frame_id, now);
      projection.goal_id = goal_id_;
      goal_pub_.publish(projection);
    }
    if (u.path_changed || u.projection_changed || answer) {
      markers_pub_.publish(conv::ToMarkers(session_.planner().graph(), u.path ? &*u.path : nullptr,
                                           u.projection ? &*u.projection : nullptr,
                                           params_.frame_id, now));
    }
    // A refusal stays the latched answer to its goal until the next goal.
    const bool refused = last_status_.state == spott_msgs::GlobalPlanStatus::REFUSED &&
                         last_status_.goal_id == goal_id_;
    if (!refused && (u.path_changed || answer || u.replans != last_status_.replans)) {
      switch (u.state) {
        case SessionState::kNoGoal:
          PublishStatus(spott_msgs::GlobalPlanStatus::NO_GOAL, "no goal", &u);
          break;
        case SessionState::kPlanned:
          PublishStatus(spott_msgs::GlobalPlanStatus::PLANNED,
                        "path through " + std::to_string(u.path->doors.size()) + " doors", &u);
          break;
        case SessionState::kFailed:
          ROS_WARN("global_planner: %s", u.failure.message.c_str());
          PublishStatus(spott_msgs::GlobalPlanStatus::FAILED, u.failure.message, &u);
          break;
      }
    }
  }

  void PublishStatus(std::uint8_t state, const std::string& message, const SessionUpdate* u) {
    spott_msgs::GlobalPlanStatus s;
    s.header.frame_id = params_.frame_id;
    s.header.stamp = ros::Time::now();
    s.goal_id = goal_id_;
    s.state = state;
    s.message = message;
    if (u && u->path) s.path_summary = conv::PathSummary(*u->path);
    s.replans = u ? static_cast<std::uint32_t>(u->replans) : last_status_.replans;
    if (u && u->state == SessionState::kFailed) {
      s.closed_doors = u->failure.closed_doors;
      for (const BlockedPassage& p : u->failure.blocked_passages) {
        s.blocked_passages.push_back(p.room + ":" + p.door_a + ":" + p.door_b);
      }
    }
    last_status_ = s;
    status_pub_.publish(s);
  }

  NodeParameters params_;
  PlanningSession session_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  std::string structure_;
  std::string goal_id_;   ///< Of the GlobalGoal being planned for; "" = none.
  bool answered_ = true;  ///< Its status, path and projection went out.
  std::optional<spott_map::Box> local_window_;
  spott_msgs::GlobalPlanStatus last_status_;
  ros::Publisher path_pub_, goal_pub_, status_pub_, markers_pub_;
  ros::Subscriber graph_sub_, updates_sub_, features_sub_, goal_sub_, window_sub_;
  ros::ServiceServer plan_srv_;
  ros::Timer timer_;
  bool have_features_ = false;
  spott_ros::InputRefusals refusals_;
};

}  // namespace
}  // namespace spott_global_planner

int main(int argc, char** argv) {
  ros::init(argc, argv, "global_planner");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  using spott_global_planner::ros_parameters::NodeParameters;
  spott_ros::ParameterReader reader = spott_ros::ParameterReader::FromNode(pnh);
  NodeParameters params;
  spott_global_planner::ros_parameters::ReadParameters(reader, params);
  std::string error;
  const auto radius = spott_ros::FootprintRadiusFromParameter(nh, params.robot_description,
                                                              params.robot_frame, &error);
  if (!radius) reader.Fail("robot_description: " + error);
  params.core.passage.padding_m = radius.value_or(0.0) + params.max_localization_error_m;
  spott_global_planner::ros_parameters::ValidateCore(reader, params);
  const auto violations = reader.Finish();
  if (!violations.empty()) {
    for (const auto& v : violations) ROS_FATAL("global_planner: parameter %s", v.c_str());
    return 1;
  }
  ROS_INFO("global_planner: passage padding %.4f m (robot radius %.4f + localization error %.3f)",
           params.core.passage.padding_m, *radius, params.max_localization_error_m);
  spott_global_planner::GlobalPlannerNode node(nh, pnh, params);
  ros::spin();
  return 0;
}
