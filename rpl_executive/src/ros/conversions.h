// Conversions between the executives' core types and ROS messages (tested on their own in
// test/ros/conversions_test.cpp). No node state here.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <sensor_msgs/BatteryState.h>
#include <sensor_msgs/LaserScan.h>
#include <spott_msgs/Fluent.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MonitorEvent.h>
#include <spott_msgs/PlanTask.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/WorldPlaces.h>
#include <visualization_msgs/MarkerArray.h>

#include "rpl_executive/noreils_chatila/executive.h"
#include "rpl_executive/noreils_chatila/pilot.h"
#include "rpl_executive/noreils_chatila/robot_modules.h"
#include "rpl_executive/noreils_chatila/sensor_data.h"
#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/navigation_plan.h"

namespace rpl_executive::ros_conversions {

// ---- input checks (issue 21) -------------------------------------------------------------------
// What the node refuses at its edge, as "field: why" ("" = usable). A refused message changes
// nothing; the node counts it on /diagnostics (spott_ros::InputRefusals).

/// The localization's estimate must be finite and its certainty a probability.
std::string StatusProblem(const spott_msgs::LocalizationStatus& status);
/// The room/door graph as world_server's validation has it (spott_map: finite points within
/// 10 km, rooms of >= 3 points, doors with two opening ends and a known state).
std::string GraphProblem(const spott_msgs::RoomDoorGraph& graph);
// Rings and scans: spott_ros::RangeRingProblem, LaserScanProblem; places:
// spott_map::ros_conversions::PlacesProblem.
/// A command to relay: every number finite.
std::string TwistProblem(const geometry_msgs::Twist& twist);

// ---- RPL ----------------------------------------------------------------------------------------

/// NIL and T as BOOL, numbers as NUMBER, everything else as STRING (printed as the reader reads
/// it back: "(19.6 6)", ":ARRIVED", "\"text\"").
spott_msgs::Fluent ToMsg(const rpl::FluentState& fluent);
/// The live task tree; `where` as file:line:column of `file`.
std::vector<spott_msgs::PlanTask> ToMsgs(const std::vector<rpl::TaskInfo>& tasks,
                                         const std::string& file);
/// A THREAD-ENDED event as an ended thread (DONE, FAILED with the cause, EVAPORATED); nullopt for
/// other events.
std::optional<spott_msgs::PlanTask> EndedThread(const rpl::Event& event);
/// The task tree and the fluents as indented text (the rviz text view and the log).
std::string TaskTreeText(const std::vector<spott_msgs::PlanTask>& tasks,
                         const std::vector<spott_msgs::Fluent>& fluents);
/// "NAME value" (the Mission goal's bindings): the value read as RPL data; error names the
/// binding.
std::optional<std::pair<std::string, rpl::Value>> ParseBinding(const std::string& binding,
                                                               std::string* error);
/// world_server's room/door graph as the navigation plans' building (unknown doors count as
/// open, as the planners of the stack take them).
rpl::office::BuildingMap FromMsg(const spott_msgs::RoomDoorGraph& graph);

// ---- Noreils-Chatila ----------------------------------------------------------------------------

/// The belt's geometry from a ring message (mounts in base_link, half the field of view).
noreils_chatila::SonarRing RingFromMsg(const spott_msgs::RangeRing& ring);
/// The ranges (NaN for a dropped-out sensor: no echo). A reading below 0 or beyond max_range is
/// impossible and discarded as dropped out (sensor_msgs/Range's rule); `*discarded` (if given)
/// gets the first such index, or -1.
noreils_chatila::SonarScan ScanFromMsg(const spott_msgs::RangeRing& ring, int* discarded = nullptr);
/// A laser scan whose frame sits at `yaw_in_base_rad` about base_link's origin (the scan's own
/// translation from base_link is not representable in the core's LaserScan and is ignored).
noreils_chatila::LaserScan FromMsg(const sensor_msgs::LaserScan& scan, double yaw_in_base_rad);
/// The charge in percent (the message carries a fraction); nullopt when it is not finite.
std::optional<noreils_chatila::BatteryDatum> FromMsg(const sensor_msgs::BatteryState& battery);
/// world_server's paths as mission values in mission units: ((x y) ... (x y heading)) with x, y
/// in cm and the final heading in tenths of a degree (PATH's (360 320 2700)).
noreils_chatila::Value PathToValue(const spott_msgs::NamedPath& path);
std::vector<noreils_chatila::Point2> PolygonFromMsg(const geometry_msgs::Polygon& polygon);
/// TERMINAL, NON_TERMINAL or STATIC (a static monitor is reported STATIC whatever its reflex).
spott_msgs::MonitorEvent ToMsg(const noreils_chatila::MonitorEvent& event,
                               const std::string& mission, const std::string& frame,
                               const ros::Time& stamp);
geometry_msgs::Twist ToTwist(const noreils_chatila::VelocityCommand& command);
/// A draw operator as rviz markers in `frame` (map): G_pos a robot arrow at r-position, G_echoes
/// one sphere per echo of r-us-data placed from r-position with the belt's mounts, any other
/// format a text marker with the value. Markers get ids from `*next_id` (advanced).
visualization_msgs::MarkerArray DrawToMarkers(const noreils_chatila::DrawCommand& draw,
                                              const noreils_chatila::SonarRing& ring,
                                              const std::string& frame, const ros::Time& stamp,
                                              int* next_id);

// ---- both ---------------------------------------------------------------------------------------

/// A text marker (the plan's text view) above `x`, `y` in `frame`.
visualization_msgs::Marker TextViewMarker(const std::string& text, const std::string& frame,
                                          double x_m, double y_m, const ros::Time& stamp);

}  // namespace rpl_executive::ros_conversions
