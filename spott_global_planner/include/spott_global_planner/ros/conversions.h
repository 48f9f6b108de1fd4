// Conversions between the global planner's core types and spott_msgs, and its rviz markers.
#pragma once

#include <optional>
#include <string>

#include <ros/time.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/ProjectedGoal.h>
#include <visualization_msgs/MarkerArray.h>

#include "spott_global_planner/global_planner.h"
#include "spott_global_planner/goal_projection.h"

namespace spott_global_planner::ros_conversions {

spott_msgs::GlobalPath ToMsg(const GlobalPath& path, const std::string& frame_id,
                             const ros::Time& stamp);
spott_msgs::ProjectedGoal ToMsg(const ProjectedGoal& goal, const std::string& frame_id,
                                const ros::Time& stamp);

/// Rooms and doors in order: "hall_e -> d_lab_e -> lab" ("" for an empty path).
std::string PathSummary(const GlobalPath& path);

/// The window b_pf as its four corners, counter-clockwise from min.
geometry_msgs::Polygon WindowToPolygon(const spott_map::Box& window);
/// The box spanned by a polygon's points; nullopt for an empty or non-finite polygon.
std::optional<spott_map::Box> WindowFromPolygon(const geometry_msgs::Polygon& polygon);

/// rviz markers (namespace in brackets): the graph [graph_nodes, graph_edges: node centres and
/// door centres joined, closed doors red, blocked passages magenta], the path [path], and, when
/// `projection` is given, the window [window], the border segment [border], the projected goal
/// p_k or the goal [projected_goal] and the case and rule as text [projection_case].
visualization_msgs::MarkerArray ToMarkers(const PlanningGraph& graph, const GlobalPath* path,
                                          const ProjectedGoal* projection,
                                          const std::string& frame_id, const ros::Time& stamp);

}  // namespace spott_global_planner::ros_conversions
