// How fast is planning over the room/door graph, projection onto the local window, and
// replanning after a door closes, on generated buildings of 100, 10,000 and 1,000,000 rooms?
// Target (issue 6): under 1 ms per plan at 10,000 rooms on one core. The paper gives no figure
// for its global planner. Peer: the Boost Graph Library's Dijkstra on the same graph (same edge
// costs, stopped at the goal), run in this program so the README can quote the ratio.
//
// Queries: 64 seeded random (start room, goal room) pairs, points at the rooms' centres, cycled.
#include <benchmark/benchmark.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths_no_color_map.hpp>

#include <map>
#include <memory>
#include <random>

#include "spott_global_planner/global_planner.h"
#include "spott_global_planner/goal_projection.h"
#include "spott_global_planner/synthetic_building.h"
#include "spott_global_planner/window_tracker.h"

namespace {

using spott_global_planner::GlobalPlanner;
using spott_global_planner::PlanResult;
using spott_global_planner::SearchAlgorithm;
using spott_map::Vec2;

struct Building {
  spott_global_planner::SyntheticBuildingParameters params;
  spott_map::RoomDoorGraph graph;
  std::vector<std::pair<int, int>> queries;  // room indices
};

// Buildings are made once per size (the 1,000,000-room one takes seconds).
const Building& GetBuilding(int side) {
  static std::map<int, std::unique_ptr<Building>> cache;
  auto& slot = cache[side];
  if (!slot) {
    slot = std::make_unique<Building>();
    slot->params.rows = side;
    slot->params.cols = side;
    slot->params.seed = 42;
    slot->graph = spott_global_planner::MakeSyntheticBuilding(slot->params);
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> room(0, side * side - 1);
    for (int i = 0; i < 64; ++i) slot->queries.emplace_back(room(rng), room(rng));
  }
  return *slot;
}

Vec2 Centre(const Building& b, int room) {
  const int r = room / b.params.cols, c = room % b.params.cols;
  return Vec2((c + 0.5) * b.params.room_size_m, (r + 0.5) * b.params.room_size_m);
}

void BM_Plan(benchmark::State& state, SearchAlgorithm algorithm) {
  const Building& b = GetBuilding(static_cast<int>(state.range(0)));
  GlobalPlanner planner(b.graph, algorithm);
  std::size_t i = 0, expanded = 0, plans = 0;
  for (auto _ : state) {
    const auto& [s, g] = b.queries[i++ % b.queries.size()];
    const PlanResult r = planner.Plan(Centre(b, s), Centre(b, g));
    if (!r.ok()) state.SkipWithError("no path");
    expanded += r.path->expanded;
    ++plans;
    benchmark::DoNotOptimize(r.path->cost);
  }
  state.counters["rooms"] = static_cast<double>(b.graph.rooms().size());
  state.counters["expanded"] = static_cast<double>(expanded) / std::max<std::size_t>(plans, 1);
}

void BM_PlanDijkstra(benchmark::State& state) { BM_Plan(state, SearchAlgorithm::kDijkstra); }
void BM_PlanAStar(benchmark::State& state) { BM_Plan(state, SearchAlgorithm::kAStar); }

// The peer: BGL Dijkstra over the same rooms and door costs, stopped when the goal is settled.
struct GoalReached {};
struct StopAtGoal : boost::default_dijkstra_visitor {
  std::size_t goal;
  explicit StopAtGoal(std::size_t g) : goal(g) {}
  template <class Vertex, class Graph>
  void examine_vertex(Vertex v, const Graph&) {
    if (v == goal) throw GoalReached{};
  }
};

void BM_PeerBoostDijkstra(benchmark::State& state) {
  const Building& b = GetBuilding(static_cast<int>(state.range(0)));
  using Graph =
      boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                            boost::property<boost::edge_weight_t, double>>;
  // Same costs as the planner: room centre -> door centre -> room centre.
  const spott_global_planner::PlanningGraph index(b.graph);
  Graph g(static_cast<std::size_t>(index.room_count()));
  for (int d = 0; d < index.door_count(); ++d) {
    const auto [ra, rb] = index.DoorRooms(d);
    const double cost = (index.RoomCentre(ra) - index.DoorCentre(d)).norm() +
                        (index.DoorCentre(d) - index.RoomCentre(rb)).norm();
    boost::add_edge(static_cast<std::size_t>(ra), static_cast<std::size_t>(rb), cost, g);
  }
  std::vector<std::size_t> pred(boost::num_vertices(g));
  std::vector<double> dist(boost::num_vertices(g));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [s, goal] = b.queries[i++ % b.queries.size()];
    try {
      boost::dijkstra_shortest_paths_no_color_map(
          g, static_cast<std::size_t>(s),
          boost::predecessor_map(pred.data())
              .distance_map(dist.data())
              .visitor(StopAtGoal(static_cast<std::size_t>(goal))));
    } catch (const GoalReached&) {
    }
    benchmark::DoNotOptimize(dist[static_cast<std::size_t>(goal)]);
  }
  state.counters["rooms"] = static_cast<double>(b.graph.rooms().size());
}

// Plan, then project the goal onto a 7 m window around the robot (case 3 for almost every
// query): what the node does per pose update.
void BM_PlanAndProject(benchmark::State& state) {
  const Building& b = GetBuilding(static_cast<int>(state.range(0)));
  GlobalPlanner planner(b.graph, SearchAlgorithm::kDijkstra);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [s, g] = b.queries[i++ % b.queries.size()];
    const Vec2 robot = Centre(b, s);
    const Vec2 goal = Centre(b, g);
    const PlanResult r = planner.Plan(robot, goal);
    const auto window = spott_global_planner::WindowAround(robot, 7.0, 0.2);
    const auto p =
        spott_global_planner::ProjectGoalOntoWindow(planner.graph(), *r.path, robot, goal, window);
    benchmark::DoNotOptimize(p.border.a);
  }
  state.counters["rooms"] = static_cast<double>(b.graph.rooms().size());
}

// Replanning after one door closes: the first door of the current path is closed and the path
// planned again (timed); the door is reopened outside the timing.
void BM_ReplanAfterDoorCloses(benchmark::State& state) {
  const Building& b = GetBuilding(static_cast<int>(state.range(0)));
  GlobalPlanner planner(b.graph, SearchAlgorithm::kDijkstra);
  std::size_t i = 0, failed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const auto& [s, g] = b.queries[i++ % b.queries.size()];
    const PlanResult before = planner.Plan(Centre(b, s), Centre(b, g));
    const std::string door = before.path->doors.empty() ? "" : before.path->doors.front();
    state.ResumeTiming();
    if (!door.empty()) planner.mutable_graph().SetDoorState(door, spott_map::DoorState::kClosed);
    const PlanResult after = planner.Plan(Centre(b, s), Centre(b, g));
    if (!after.ok()) ++failed;  // the door was a bridge: the failure names it
    benchmark::DoNotOptimize(after.error);
    state.PauseTiming();
    if (!door.empty()) planner.mutable_graph().SetDoorState(door, spott_map::DoorState::kUnknown);
    state.ResumeTiming();
  }
  state.counters["rooms"] = static_cast<double>(b.graph.rooms().size());
  state.counters["no_path_share"] =
      static_cast<double>(failed) / std::max<double>(1.0, static_cast<double>(state.iterations()));
}

// Sides of the square buildings: 10 x 10 and 100 x 100 rooms (as many iterations as Google
// Benchmark needs), and 1000 x 1000 rooms with exactly the 64 queries once each, so that every
// program at that size answers the same questions.
#define SPOTT_SIZES(fn)                                            \
  BENCHMARK(fn)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond); \
  BENCHMARK(fn)->Arg(1000)->Iterations(64)->Unit(benchmark::kMillisecond)

SPOTT_SIZES(BM_PlanDijkstra);
SPOTT_SIZES(BM_PlanAStar);
SPOTT_SIZES(BM_PeerBoostDijkstra);
SPOTT_SIZES(BM_PlanAndProject);
SPOTT_SIZES(BM_ReplanAfterDoorCloses);

}  // namespace

BENCHMARK_MAIN();
