#include "spott_global_planner/planning_session.h"

#include <sstream>
#include <stdexcept>

namespace spott_global_planner {

namespace {

bool SameProjection(const ProjectedGoal& a, const ProjectedGoal& b) {
  const auto same = [](const Vec2& p, const Vec2& q) { return (p - q).norm() <= 1e-9; };
  return a.projection_case == b.projection_case && a.on_border == b.on_border &&
         same(a.goal, b.goal) && same(a.border.a, b.border.a) && same(a.border.b, b.border.b) &&
         same(a.window.min, b.window.min) && same(a.window.max, b.window.max) &&
         a.edge_id == b.edge_id && a.node_id == b.node_id;
}

}  // namespace

std::vector<std::string> ValidateParameters(const GlobalPlannerParameters& p) {
  std::vector<std::string> v;
  for (const auto& s : ValidateParameters(p.window)) v.push_back("window/" + s);
  for (const auto& s : ValidateParameters(p.passage)) v.push_back("passage/" + s);
  return v;
}

PlanningSession::PlanningSession(const GlobalPlannerParameters& params)
    : params_(params), tracker_(params.window), monitor_(params.passage) {
  const auto violations = ValidateParameters(params);
  if (!violations.empty()) {
    std::string text = "invalid global planner parameters:";
    for (const auto& s : violations) text += " " + s + ";";
    throw std::invalid_argument(text);
  }
  planner_.set_algorithm(params.algorithm);
}

void PlanningSession::SetGraph(RoomDoorGraph graph) {
  const bool had = planner_.has_graph();
  planner_.SetGraph(std::move(graph));
  monitor_.Reset();
  if (params_.detect_blocked_passages && !features_.empty()) {
    monitor_.Update(planner_.mutable_graph(), features_);
  }
  tracker_.Reset();
  if (had) map_changed_ = true;
}

bool PlanningSession::SetDoorState(const std::string& door_id, DoorState state) {
  const auto d = planner_.graph().FindDoor(door_id);
  if (!d) return false;
  const bool was = planner_.graph().DoorPassable(*d);
  if (!planner_.mutable_graph().SetDoorState(door_id, state)) return false;
  if (planner_.graph().DoorPassable(*d) != was) map_changed_ = true;
  return true;
}

std::vector<std::string> PlanningSession::SetFeatures(
    const std::vector<spott_map::MapFeature>& features) {
  features_ = features;
  std::vector<std::string> changed;
  if (!params_.detect_blocked_passages || !planner_.has_graph()) return changed;
  for (int r : monitor_.Update(planner_.mutable_graph(), features_)) {
    changed.push_back(planner_.graph().room(r).id);
  }
  if (!changed.empty()) map_changed_ = true;
  return changed;
}

PlanResult PlanningSession::SetGoal(const Vec2& goal) {
  PlanResult check;
  if (!goal.allFinite()) {
    check.error = PlanError::kInvalidPoint;
    check.message = "goal has a coordinate that is not finite: goal refused";
    return check;
  }
  if (!planner_.has_graph()) {
    // Nothing to check it against yet: kept, and planned (or failed) once the graph arrives.
    goal_ = goal;
    check.message = "no room/door graph yet: the goal waits for one";
    return check;
  }
  if (planner_.graph().RoomContaining(goal) < 0) {
    check.error = PlanError::kGoalOutsideRooms;
    std::ostringstream msg;
    msg.precision(3);
    msg << std::fixed << "goal (" << goal.x() << ", " << goal.y()
        << ") is outside every room of the graph: goal refused";
    check.message = msg.str();
    return check;
  }
  goal_ = goal;
  return check;
}

void PlanningSession::ClearGoal() { goal_.reset(); }

SessionUpdate PlanningSession::Update(const Vec2& robot, const spott_map::Box* window) {
  SessionUpdate out;
  if (!goal_) {
    out.state = SessionState::kNoGoal;
  } else {
    // Inside a node with blocked passages the robot and the goal may stand on one side of an
    // obstacle: only the doors on their side count.
    std::optional<std::vector<int>> exits, entries;
    PassageSides sides;
    const int n_r = planner_.RoomContaining(robot);
    const int n_g = planner_.RoomContaining(*goal_);
    if (params_.detect_blocked_passages && n_r >= 0 && n_g >= 0) {
      exits = monitor_.DoorsReachedFrom(n_r, robot);
      entries = monitor_.DoorsReachedFrom(n_g, *goal_);
      sides.start_exits = exits ? &*exits : nullptr;
      sides.goal_entries = entries ? &*entries : nullptr;
      if (n_r == n_g) sides.start_reaches_goal_inside = monitor_.SameSide(n_r, robot, *goal_);
    }
    PlanResult result = planner_.Plan(robot, *goal_, sides);
    if (result.ok()) {
      out.state = SessionState::kPlanned;
      const int n_r = result.path->room_indices.front();
      tracker_.Update(robot, &planner_.graph().room(n_r).polygon);
      // A window that no longer holds the robot is stale (the local planner has not moved it
      // yet): the modelled one is used until it catches up.
      const bool usable = window && window->Contains(robot);
      const spott_map::Box& b = usable ? *window : tracker_.window();
      // A border strip narrower than the padded robot is all padding for the local planner.
      out.projection = ProjectGoalOntoWindow(planner_.graph(), *result.path, robot, *goal_, b,
                                             2.0 * params_.passage.padding_m);
      out.path = std::move(result.path);
    } else {
      out.state = SessionState::kFailed;
      out.failure = std::move(result);
    }
  }
  const std::vector<std::string> doors = out.path ? out.path->doors : std::vector<std::string>{};
  out.path_changed = out.state != last_state_ || doors != last_doors_;
  out.projection_changed = out.projection.has_value() != last_projection_.has_value() ||
                           (out.projection && !SameProjection(*out.projection, *last_projection_));
  if (map_changed_ && out.path_changed && last_state_ == SessionState::kPlanned) {
    out.replanned = true;
    ++replans_;
  }
  out.replans = replans_;
  map_changed_ = false;
  last_state_ = out.state;
  last_doors_ = doors;
  last_projection_ = out.projection;
  return out;
}

}  // namespace spott_global_planner
