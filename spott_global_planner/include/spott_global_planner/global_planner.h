// SPOTT's global path planner (III.D.2): Dijkstra's algorithm over the room/door graph from the
// robot's node n_r to the goal's node n_g, giving <n_r, e_i, n_j, ..., n_g>. Edge weights come
// from geometry: node centre -> door centre -> node centre (m). An optional A* heuristic (the
// straight line between node centres, which never overestimates those polyline costs) gives the
// same costs with fewer expansions.
//
// Replanning (III): a closed door removes its edge; a blocked passage through a node removes
// only the way between those two doors of the node, so the search runs over (node, door it was
// entered by) wherever a node has blocked passages, and over nodes elsewhere. When no path is
// left the result names the causes: closed doors and blocked passages on the border of what can
// still be reached, or a graph that never joined the two nodes.
//
// Not thread-safe; search scratch space is reused between calls, so a query does not touch
// memory in proportion to the graph's size.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "spott_global_planner/planning_graph.h"

namespace spott_global_planner {

using spott_map::Vec2;

enum class SearchAlgorithm { kDijkstra, kAStar };
const char* ToString(SearchAlgorithm a);
std::optional<SearchAlgorithm> ParseSearchAlgorithm(const std::string& text);

/// A path <n_r, e_1, n_1, ..., e_l, n_g> through the graph.
struct GlobalPath {
  std::vector<int> room_indices;  ///< n_r ... n_g
  std::vector<int> door_indices;  ///< door_indices[i] joins room i and room i+1
  std::vector<std::string> rooms;
  std::vector<std::string> doors;
  /// Start, the door centres in order, goal (m, map frame).
  std::vector<Vec2> waypoints;
  /// Sum over the doors of |centre(n_i) - centre(e_i)| + |centre(e_i) - centre(n_i+1)| (m);
  /// 0 when start and goal share a node.
  double cost = 0.0;
  /// Search states expanded (for the benchmarks and tests).
  std::size_t expanded = 0;
};

/// Where start and goal stand inside a node that has blocked passages: an obstacle may leave the
/// robot (or the goal) on one side of it, reaching only some of the node's doors. Null pointers
/// mean no restriction (a node without blocked passages).
struct PassageSides {
  /// Doors (indices) the robot can leave its node by; null: every door.
  const std::vector<int>* start_exits = nullptr;
  /// Doors (indices) through which the goal can be reached inside its node; null: every door.
  const std::vector<int>* goal_entries = nullptr;
  /// Start and goal in one node: false when an obstacle separates them inside it.
  bool start_reaches_goal_inside = true;
};

enum class PlanError {
  kNone,
  kNoGraph,            ///< no graph was given yet, or it has no rooms
  kInvalidPoint,       ///< a coordinate is not finite
  kStartOutsideRooms,  ///< the start lies in no room
  kGoalOutsideRooms,   ///< the goal lies in no room
  kUnknownRoom,        ///< a room id that the graph does not have
  kNoPath,             ///< closed doors / blocked passages (or the graph) separate the nodes
};
const char* ToString(PlanError e);

struct PlanResult {
  std::optional<GlobalPath> path;
  PlanError error = PlanError::kNone;
  /// For a failure: a sentence for the user, naming the causes.
  std::string message;
  /// kNoPath: closed doors of reached nodes that lead to unreached nodes.
  std::vector<std::string> closed_doors;
  /// kNoPath: blocked passages out of reached nodes whose far side was not reached; an end
  /// named "robot" or "goal" is the robot's or the goal's side of its node.
  std::vector<BlockedPassage> blocked_passages;
  /// kNoPath: true when even with every door open and every passage free the graph has no
  /// door sequence between the two nodes.
  bool disconnected = false;
  bool ok() const { return path.has_value(); }
};

class GlobalPlanner {
 public:
  GlobalPlanner() = default;
  explicit GlobalPlanner(RoomDoorGraph graph,
                         SearchAlgorithm algorithm = SearchAlgorithm::kDijkstra);

  /// Replaces the graph (door states and blocked passages start from the graph's own).
  void SetGraph(RoomDoorGraph graph);
  bool has_graph() const { return graph_.room_count() > 0; }
  const PlanningGraph& graph() const { return graph_; }
  /// For door states and blocked passages.
  PlanningGraph& mutable_graph() { return graph_; }
  void set_algorithm(SearchAlgorithm a) { algorithm_ = a; }
  SearchAlgorithm algorithm() const { return algorithm_; }

  /// Plans from the node holding `start` to the node holding `goal` (m, map frame). `sides`
  /// restricts the doors by which the robot leaves and the goal is reached (see PassageSides).
  PlanResult Plan(const Vec2& start, const Vec2& goal, const PassageSides& sides = {});
  /// The node holding `p`, or -1.
  int RoomContaining(const Vec2& p) const { return graph_.RoomContaining(p); }
  /// Plans between two nodes given by id; the waypoints start and end at their centres.
  PlanResult PlanBetweenRooms(const std::string& start_room, const std::string& goal_room);

 private:
  PlanResult Search(int start_room, int goal_room, const Vec2& start, const Vec2& goal,
                    const PassageSides& sides);
  // Why a search failed (closed doors, blocked passages on the border of what it reached, the
  // robot or the goal cut off inside its node, no doors at all), into `result`.
  void Explain(int start_room, int goal_room, const PassageSides& sides, PlanResult& result);
  std::vector<char> ReachedNodes(int start_room) const;
  void AddClosedBorderDoors(const std::vector<char>& reached, PlanResult& result) const;
  void AddBlockedBorderPassages(const std::vector<char>& reached, PlanResult& result) const;
  void AddBlockedEnds(int start_room, int goal_room, const PassageSides& sides,
                      const std::vector<char>& reached, PlanResult& result) const;
  bool JoinedWithAllOpen(int start_room, int goal_room) const;
  std::string NoPathMessage(int start_room, int goal_room, const PlanResult& result) const;
  void EnsureScratch();

  PlanningGraph graph_;
  SearchAlgorithm algorithm_ = SearchAlgorithm::kDijkstra;

  // Search states: 2*door + 0 = "entered room_a through door", 2*door + 1 = "entered room_b
  // through door", and the start state last. Stamps mark what the current query has written, so
  // nothing is cleared between queries.
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> state_seen_, state_closed_;
  std::vector<double> state_g_;
  std::vector<int> state_parent_;
  std::vector<std::uint32_t> room_seen_, room_closed_;
  std::vector<double> room_g_;  // best g of a node without blocked passages
  struct QueueEntry {
    double f;
    double g;
    int state;
    int room;  // the node the state is in
    // Min-heap on f; among equal f the deeper entry (larger g), then the lower state, first.
    bool operator>(const QueueEntry& o) const {
      if (f != o.f) return f > o.f;
      if (g != o.g) return g < o.g;
      return state > o.state;
    }
  };
  std::vector<QueueEntry> heap_;
};

}  // namespace spott_global_planner
