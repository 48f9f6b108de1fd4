// The global planner's loop without ROS: it holds the goal, plans from the robot's node each
// update, projects the goal onto the window, and notices replanning (a path that changed
// because a door closed or a passage was blocked, III: "the global path planner must replan
// the global path"). The node feeds it the graph, door states, features, the pose and the
// window, and publishes what it returns.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_global_planner/global_planner.h"
#include "spott_global_planner/goal_projection.h"
#include "spott_global_planner/passage_blocking.h"
#include "spott_global_planner/window_tracker.h"

namespace spott_global_planner {

struct GlobalPlannerParameters {
  SearchAlgorithm algorithm = SearchAlgorithm::kDijkstra;
  WindowParameters window;
  bool detect_blocked_passages = true;
  PassageParameters passage;
};

/// Every violated constraint, each naming its parameter with the prefix the node's YAML uses
/// ("window/window_size_m must be > 0 (got 0)").
std::vector<std::string> ValidateParameters(const GlobalPlannerParameters& p);

enum class SessionState { kNoGoal, kPlanned, kFailed };

struct SessionUpdate {
  SessionState state = SessionState::kNoGoal;
  std::optional<GlobalPath> path;           ///< kPlanned
  std::optional<ProjectedGoal> projection;  ///< kPlanned
  PlanResult failure;                       ///< kFailed: error, message and causes
  bool path_changed = false;        ///< rooms/doors differ from the last update's (or state did)
  bool projection_changed = false;  ///< case, border or window differ from the last update's
  bool replanned = false;           ///< the path changed after a door or passage change
  std::size_t replans = 0;          ///< replans so far
};

class PlanningSession {
 public:
  /// Throws std::invalid_argument listing every violated parameter.
  explicit PlanningSession(const GlobalPlannerParameters& params);

  /// Replaces the graph (keeps the goal).
  void SetGraph(RoomDoorGraph graph);
  bool has_graph() const { return planner_.has_graph(); }
  /// Sets a door's state; false (and nothing changes) for an unknown door or a closed opening.
  bool SetDoorState(const std::string& door_id, DoorState state);
  /// Re-analyses the passages of nodes whose features changed. Returns the changed nodes' ids.
  std::vector<std::string> SetFeatures(const std::vector<spott_map::MapFeature>& features);

  /// Sets the goal (m, map frame). A goal outside every room is refused with the reason and the
  /// previous goal is kept. Before any graph has arrived the goal is kept unchecked (message
  /// says so); Update then plans to it, or fails naming the cause, once the graph is there.
  PlanResult SetGoal(const Vec2& goal);
  void ClearGoal();
  const std::optional<Vec2>& goal() const { return goal_; }

  /// Plans from `robot` to the goal and projects it onto `window` (the local planner's), or onto
  /// the tracked one when `window` is null or no longer holds the robot.
  SessionUpdate Update(const Vec2& robot, const spott_map::Box* window = nullptr);

  /// A one-off plan that leaves the session's goal alone (the node's service).
  PlanResult PlanOnce(const Vec2& start, const Vec2& goal) { return planner_.Plan(start, goal); }

  const GlobalPlanner& planner() const { return planner_; }
  const WindowTracker& window_tracker() const { return tracker_; }

 private:
  GlobalPlannerParameters params_;
  GlobalPlanner planner_;
  WindowTracker tracker_;
  PassageMonitor monitor_;
  std::vector<spott_map::MapFeature> features_;
  std::optional<Vec2> goal_;
  bool map_changed_ = false;  // doors or passages changed since the last update
  SessionState last_state_ = SessionState::kNoGoal;
  std::vector<std::string> last_doors_;
  std::optional<ProjectedGoal> last_projection_;
  std::size_t replans_ = 0;
};

}  // namespace spott_global_planner
