#include "spott_global_planner/global_planner.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <sstream>

namespace spott_global_planner {

namespace {

constexpr std::size_t kMaxCausesNamed = 12;
const std::string kRobot = "robot";
const std::string kGoal = "goal";

bool Contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

std::string FormatPoint(const Vec2& p) {
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

}  // namespace

const char* ToString(SearchAlgorithm a) {
  return a == SearchAlgorithm::kAStar ? "astar" : "dijkstra";
}

std::optional<SearchAlgorithm> ParseSearchAlgorithm(const std::string& text) {
  if (text == "dijkstra") return SearchAlgorithm::kDijkstra;
  if (text == "astar") return SearchAlgorithm::kAStar;
  return std::nullopt;
}

const char* ToString(PlanError e) {
  switch (e) {
    case PlanError::kNone:
      return "none";
    case PlanError::kNoGraph:
      return "no graph";
    case PlanError::kInvalidPoint:
      return "invalid point";
    case PlanError::kStartOutsideRooms:
      return "start outside every room";
    case PlanError::kGoalOutsideRooms:
      return "goal outside every room";
    case PlanError::kUnknownRoom:
      return "unknown room";
    case PlanError::kNoPath:
      return "no path";
  }
  return "?";
}

GlobalPlanner::GlobalPlanner(RoomDoorGraph graph, SearchAlgorithm algorithm)
    : algorithm_(algorithm) {
  SetGraph(std::move(graph));
}

void GlobalPlanner::SetGraph(RoomDoorGraph graph) {
  graph_ = PlanningGraph(std::move(graph));
  EnsureScratch();
}

void GlobalPlanner::EnsureScratch() {
  const std::size_t states = 2 * static_cast<std::size_t>(graph_.door_count()) + 1;
  const std::size_t rooms = static_cast<std::size_t>(graph_.room_count());
  state_seen_.assign(states, 0);
  state_closed_.assign(states, 0);
  state_g_.assign(states, 0.0);
  state_parent_.assign(states, -1);
  room_seen_.assign(rooms, 0);
  room_closed_.assign(rooms, 0);
  room_g_.assign(rooms, 0.0);
  stamp_ = 0;
}

PlanResult GlobalPlanner::Plan(const Vec2& start, const Vec2& goal, const PassageSides& sides) {
  PlanResult result;
  if (!has_graph()) {
    result.error = PlanError::kNoGraph;
    result.message = "no room/door graph to plan in";
    return result;
  }
  if (!start.allFinite() || !goal.allFinite()) {
    result.error = PlanError::kInvalidPoint;
    result.message = std::string(!start.allFinite() ? "start " : "goal ") +
                     "has a coordinate that is not finite";
    return result;
  }
  const int start_room = graph_.RoomContaining(start);
  if (start_room < 0) {
    result.error = PlanError::kStartOutsideRooms;
    result.message = "start " + FormatPoint(start) + " is outside every room of the graph";
    return result;
  }
  const int goal_room = graph_.RoomContaining(goal);
  if (goal_room < 0) {
    result.error = PlanError::kGoalOutsideRooms;
    result.message = "goal " + FormatPoint(goal) + " is outside every room of the graph";
    return result;
  }
  return Search(start_room, goal_room, start, goal, sides);
}

PlanResult GlobalPlanner::PlanBetweenRooms(const std::string& start_room,
                                           const std::string& goal_room) {
  PlanResult result;
  if (!has_graph()) {
    result.error = PlanError::kNoGraph;
    result.message = "no room/door graph to plan in";
    return result;
  }
  const auto s = graph_.FindRoom(start_room);
  const auto g = graph_.FindRoom(goal_room);
  if (!s || !g) {
    result.error = PlanError::kUnknownRoom;
    result.message = "unknown room '" + (!s ? start_room : goal_room) + "'";
    return result;
  }
  return Search(*s, *g, graph_.RoomCentre(*s), graph_.RoomCentre(*g), PassageSides{});
}

PlanResult GlobalPlanner::Search(int start_room, int goal_room, const Vec2& start, const Vec2& goal,
                                 const PassageSides& sides) {
  PlanResult result;
  if (++stamp_ == 0) {  // wrapped: clear once every 2^32 queries
    EnsureScratch();
    stamp_ = 1;
  }
  const int start_state = 2 * graph_.door_count();
  const bool astar = algorithm_ == SearchAlgorithm::kAStar;
  const Vec2 goal_centre = graph_.RoomCentre(goal_room);
  const auto h = [&](int room) {
    return astar ? (graph_.RoomCentre(room) - goal_centre).norm() : 0.0;
  };
  heap_.clear();
  state_seen_[start_state] = stamp_;
  state_g_[start_state] = 0.0;
  state_parent_[start_state] = -1;
  if (!graph_.HasBlockedPassages(start_room)) {
    room_seen_[start_room] = stamp_;
    room_g_[start_room] = 0.0;
  }
  heap_.push_back(QueueEntry{h(start_room), 0.0, start_state, start_room});

  std::size_t expanded = 0;
  int found = -1;
  double found_g = 0.0;
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<QueueEntry>());
    const QueueEntry top = heap_.back();
    heap_.pop_back();
    const int s = top.state;
    const int room = top.room;
    const bool blocks = graph_.HasBlockedPassages(room);
    // A node without blocked passages is left the same way whatever door it was entered by:
    // it is settled once, and its best cost is kept per node. A node with blocked passages is
    // settled once per entry door, its costs kept per search state.
    if (!blocks) {
      if (room_closed_[room] == stamp_ || top.g > room_g_[room]) continue;
      room_closed_[room] = stamp_;
    } else if (state_closed_[s] == stamp_ || top.g > state_g_[s]) {
      continue;
    }
    state_closed_[s] = stamp_;
    ++expanded;
    const int entry_door = s == start_state ? -1 : (s >> 1);
    if (room == goal_room) {
      // The goal is reached unless an obstacle inside its node separates it from where the
      // search stands (the robot's side, or the door it entered by).
      const bool reaches = s == start_state
                               ? sides.start_reaches_goal_inside
                               : (!sides.goal_entries || Contains(*sides.goal_entries, entry_door));
      if (reaches) {
        found = s;
        found_g = top.g;
        break;
      }
    }
    for (const auto* arc = graph_.ArcsBegin(room); arc != graph_.ArcsEnd(room); ++arc) {
      const int door = arc->door();
      if (!graph_.DoorPassable(door)) continue;
      if (s == start_state && sides.start_exits && !Contains(*sides.start_exits, door)) continue;
      if (blocks && entry_door >= 0 && graph_.PassageBlocked(room, entry_door, door)) continue;
      const int to = arc->to_room;
      const int next = arc->to_state;
      const double g = top.g + arc->cost;
      if (!graph_.HasBlockedPassages(to)) {
        if (room_seen_[to] == stamp_ && room_g_[to] <= g) continue;
        room_seen_[to] = stamp_;
        room_g_[to] = g;
      } else {
        if (state_seen_[next] == stamp_ && state_g_[next] <= g) continue;
        state_seen_[next] = stamp_;
        state_g_[next] = g;
      }
      state_parent_[next] = s;
      heap_.push_back(QueueEntry{g + h(to), g, next, to});
      std::push_heap(heap_.begin(), heap_.end(), std::greater<QueueEntry>());
    }
  }

  if (found < 0) {
    result.error = PlanError::kNoPath;
    Explain(start_room, goal_room, sides, result);
    return result;
  }
  GlobalPath path;
  path.cost = found_g;
  path.expanded = expanded;
  for (int s = found; s != start_state; s = state_parent_[s]) path.door_indices.push_back(s >> 1);
  std::reverse(path.door_indices.begin(), path.door_indices.end());
  path.room_indices.push_back(start_room);
  path.waypoints.push_back(start);
  int room = start_room;
  for (int d : path.door_indices) {
    const auto [a, b] = graph_.DoorRooms(d);
    room = room == a ? b : a;
    path.room_indices.push_back(room);
    path.waypoints.push_back(graph_.DoorCentre(d));
  }
  path.waypoints.push_back(goal);
  for (int r : path.room_indices) path.rooms.push_back(graph_.room(r).id);
  for (int d : path.door_indices) path.doors.push_back(graph_.door(d).id);
  result.path = std::move(path);
  return result;
}

void GlobalPlanner::Explain(int start_room, int goal_room, const PassageSides& sides,
                            PlanResult& result) {
  const std::vector<char> reached = ReachedNodes(start_room);
  AddClosedBorderDoors(reached, result);
  AddBlockedBorderPassages(reached, result);
  AddBlockedEnds(start_room, goal_room, sides, reached, result);
  result.disconnected = !JoinedWithAllOpen(start_room, goal_room);
  result.message = NoPathMessage(start_room, goal_room, result);
}

std::vector<char> GlobalPlanner::ReachedNodes(int start_room) const {
  // What the failed search reached: a node is reached when any of its states was settled.
  std::vector<char> reached(static_cast<std::size_t>(graph_.room_count()), 0);
  reached[start_room] = 1;
  for (int d = 0; d < graph_.door_count(); ++d) {
    const auto [a, b] = graph_.DoorRooms(d);
    if (state_closed_[2 * d] == stamp_) reached[a] = 1;
    if (state_closed_[2 * d + 1] == stamp_) reached[b] = 1;
  }
  for (int r = 0; r < graph_.room_count(); ++r) {
    if (room_closed_[r] == stamp_) reached[r] = 1;
  }
  return reached;
}

void GlobalPlanner::AddClosedBorderDoors(const std::vector<char>& reached,
                                         PlanResult& result) const {
  for (int d = 0; d < graph_.door_count(); ++d) {
    const auto [a, b] = graph_.DoorRooms(d);
    if (!graph_.DoorPassable(d) && reached[a] != reached[b]) {
      result.closed_doors.push_back(graph_.door(d).id);
    }
  }
}

void GlobalPlanner::AddBlockedBorderPassages(const std::vector<char>& reached,
                                             PlanResult& result) const {
  // Blocked passages leaving a reached state towards a node that was not reached.
  for (int r = 0; r < graph_.room_count(); ++r) {
    if (!reached[r] || !graph_.HasBlockedPassages(r)) continue;
    for (const BlockedPassage& p : graph_.BlockedPassagesOf(r)) {
      const int da = *graph_.FindDoor(p.door_a);
      const int db = *graph_.FindDoor(p.door_b);
      const auto far_side = [&](int d) {
        const auto [a, b] = graph_.DoorRooms(d);
        return a == r ? b : a;
      };
      const auto entered = [&](int d) {
        const auto [a, b] = graph_.DoorRooms(d);
        return state_closed_[2 * d + (b == r ? 1 : 0)] == stamp_;
      };
      const bool a_to_b = entered(da) && graph_.DoorPassable(db) && !reached[far_side(db)];
      const bool b_to_a = entered(db) && graph_.DoorPassable(da) && !reached[far_side(da)];
      if (a_to_b || b_to_a) result.blocked_passages.push_back(p);
    }
  }
}

void GlobalPlanner::AddBlockedEnds(int start_room, int goal_room, const PassageSides& sides,
                                   const std::vector<char>& reached, PlanResult& result) const {
  // Obstacles inside the start or goal node that cut the robot or the goal off from doors.
  const auto far_of = [&](int d, int r) {
    const auto [a, b] = graph_.DoorRooms(d);
    return a == r ? b : a;
  };
  if (sides.start_exits) {
    for (const auto* arc = graph_.ArcsBegin(start_room); arc != graph_.ArcsEnd(start_room); ++arc) {
      if (graph_.DoorPassable(arc->door()) && !Contains(*sides.start_exits, arc->door()) &&
          !reached[far_of(arc->door(), start_room)]) {
        result.blocked_passages.push_back(
            BlockedPassage{graph_.room(start_room).id, kRobot, graph_.door(arc->door()).id});
      }
    }
  }
  if (sides.goal_entries) {
    for (const auto* arc = graph_.ArcsBegin(goal_room); arc != graph_.ArcsEnd(goal_room); ++arc) {
      if (graph_.DoorPassable(arc->door()) && !Contains(*sides.goal_entries, arc->door()) &&
          reached[far_of(arc->door(), goal_room)]) {
        result.blocked_passages.push_back(
            BlockedPassage{graph_.room(goal_room).id, graph_.door(arc->door()).id, kGoal});
      }
    }
  }
  if (start_room == goal_room && !sides.start_reaches_goal_inside) {
    result.blocked_passages.push_back(BlockedPassage{graph_.room(start_room).id, kRobot, kGoal});
  }
}

bool GlobalPlanner::JoinedWithAllOpen(int start_room, int goal_room) const {
  // Would the graph join the nodes with every door open and every passage free?
  std::vector<char> seen(static_cast<std::size_t>(graph_.room_count()), 0);
  std::vector<int> stack{start_room};
  seen[start_room] = 1;
  while (!stack.empty()) {
    const int r = stack.back();
    stack.pop_back();
    for (const auto* arc = graph_.ArcsBegin(r); arc != graph_.ArcsEnd(r); ++arc) {
      if (!seen[arc->to_room]) {
        seen[arc->to_room] = 1;
        stack.push_back(arc->to_room);
      }
    }
  }
  return seen[goal_room] != 0;
}

std::string GlobalPlanner::NoPathMessage(int start_room, int goal_room,
                                         const PlanResult& result) const {
  std::ostringstream msg;
  msg << "no path from node '" << graph_.room(start_room).id << "' to node '"
      << graph_.room(goal_room).id << "'";
  if (result.disconnected) {
    msg << ": the graph has no sequence of doors between them";
    return msg.str();
  }
  std::vector<std::string> causes;
  if (!result.closed_doors.empty()) {
    std::string text = result.closed_doors.size() == 1 ? "door " : "doors ";
    for (std::size_t i = 0; i < result.closed_doors.size() && i < kMaxCausesNamed; ++i) {
      text += (i ? ", " : "") + result.closed_doors[i];
    }
    if (result.closed_doors.size() > kMaxCausesNamed) {
      text += " and " + std::to_string(result.closed_doors.size() - kMaxCausesNamed) + " more";
    }
    text += result.closed_doors.size() == 1 ? " is closed" : " are closed";
    causes.push_back(text);
  }
  for (std::size_t i = 0; i < result.blocked_passages.size() && i < kMaxCausesNamed; ++i) {
    const BlockedPassage& p = result.blocked_passages[i];
    const auto name = [](const std::string& end) {
      return end == kRobot || end == kGoal ? "the " + end : "door " + end;
    };
    const bool doors = name(p.door_a)[0] == 'd' && name(p.door_b)[0] == 'd';
    causes.push_back("node '" + p.room + "' is blocked between " +
                     (doors ? "doors " + p.door_a + " and " + p.door_b
                            : name(p.door_a) + " and " + name(p.door_b)));
  }
  if (result.blocked_passages.size() > kMaxCausesNamed) {
    causes.push_back(std::to_string(result.blocked_passages.size() - kMaxCausesNamed) +
                     " more blocked passages");
  }
  msg << ": ";
  for (std::size_t i = 0; i < causes.size(); ++i) msg << (i ? "; " : "") << causes[i];
  return msg.str();
}

}  // namespace spott_global_planner
