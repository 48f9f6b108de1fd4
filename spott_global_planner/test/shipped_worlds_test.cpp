// The planner on the worlds spott_launch ships (launch/worlds) and on generated buildings:
// paths agree with an independent reference (a plain O(V^2) Dijkstra over the same costs and
// spott_map's own reachability), the CAD walls alone block no passage between doors, and every
// projection satisfies what Fig. 14 demands of it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "spott_global_planner/global_planner.h"
#include "spott_global_planner/goal_projection.h"
#include "spott_global_planner/passage_blocking.h"
#include "spott_global_planner/synthetic_building.h"
#include "spott_global_planner/window_tracker.h"
#include "spott_map/map_feature.h"
#include "spott_map/world_loader.h"

namespace spott_global_planner {
namespace {

using spott_map::Box;
using spott_map::Vec2;

spott_map::World Load(const std::string& name) {
  const std::string path = std::string(SPOTT_WORLDS_DIR) + "/" + name + ".yaml";
  spott_map::WorldLoadResult r = spott_map::LoadWorldFile(path);
  if (!r.ok()) {
    ADD_FAILURE() << path << ":\n" << spott_map::FormatErrors(r.errors);
    return {};
  }
  return std::move(*r.world);
}

// Shortest costs from `start` by the textbook O(V^2) Dijkstra over passable doors.
std::vector<double> ReferenceCosts(const PlanningGraph& g, int start) {
  const int n = g.room_count();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<char> done(n, 0);
  dist[start] = 0.0;
  for (int it = 0; it < n; ++it) {
    int u = -1;
    for (int v = 0; v < n; ++v) {
      if (!done[v] && (u < 0 || dist[v] < dist[u])) u = v;
    }
    if (u < 0 || std::isinf(dist[u])) break;
    done[u] = 1;
    for (int d = 0; d < g.door_count(); ++d) {
      if (!g.DoorPassable(d)) continue;
      const auto [a, b] = g.DoorRooms(d);
      if (a != u && b != u) continue;
      const int v = a == u ? b : a;
      const double c =
          (g.RoomCentre(u) - g.DoorCentre(d)).norm() + (g.DoorCentre(d) - g.RoomCentre(v)).norm();
      dist[v] = std::min(dist[v], dist[u] + c);
    }
  }
  return dist;
}

// What Fig. 14 demands of a projection, whatever the case.
void CheckProjection(const PlanningGraph& g, const GlobalPath& path, const Vec2& robot,
                     const Vec2& goal, const Box& window, const ProjectedGoal& p) {
  const bool same_node = path.door_indices.empty();  // the goal is reached inside n_r
  const bool goal_inside = window.Contains(goal);
  if (same_node && goal_inside) {
    EXPECT_EQ(p.projection_case, ProjectionCase::kSameNodeInWindow);
  }
  if (same_node && !goal_inside) {
    EXPECT_EQ(p.projection_case, ProjectionCase::kSameNodeOutsideWindow);
  }
  if (!same_node) {
    EXPECT_TRUE(p.projection_case == ProjectionCase::kGeneral ||
                p.projection_case == ProjectionCase::kGoalInWindow);
  }
  if (p.projection_case == ProjectionCase::kGoalInWindow) {
    EXPECT_TRUE(goal_inside);
    for (int d : path.door_indices) EXPECT_TRUE(EdgeWithinWindow(g.door(d), window));
  }
  if (!p.on_border) {
    EXPECT_TRUE(p.projection_case == ProjectionCase::kSameNodeInWindow ||
                p.projection_case == ProjectionCase::kGoalInWindow);
    return;
  }
  const double tol = 1e-6;
  // The border segment lies on one side of the window ...
  const auto sides = WindowSides(window);
  const spott_map::Segment& side = sides[static_cast<int>(p.side)];
  EXPECT_LE(spott_map::DistancePointSegment(p.border.a, side), tol) << robot.transpose();
  EXPECT_LE(spott_map::DistancePointSegment(p.border.b, side), tol) << robot.transpose();
  // ... in the node it was projected for (n_r in case 2, n_k in case 3) ...
  const auto& polygon = g.room(p.node).polygon;
  EXPECT_TRUE(spott_map::PointInPolygon(p.border.Midpoint(), polygon, tol))
      << "robot " << robot.transpose() << " goal " << goal.transpose() << " node " << p.node_id;
  // ... and, where the paper's own geometry applied, it holds p_k.
  if (p.rule.empty()) {
    EXPECT_LE(spott_map::DistancePointSegment(p.projected_point, p.border), tol)
        << "robot " << robot.transpose() << " goal " << goal.transpose();
  }
  // Case 3 names an edge of the path that is not within the window, and the edges before it are.
  if (p.projection_case == ProjectionCase::kGeneral && p.edge >= 0) {
    EXPECT_FALSE(EdgeWithinWindow(g.door(p.edge), window));
    for (int d : path.door_indices) {
      if (d == p.edge) break;
      EXPECT_TRUE(EdgeWithinWindow(g.door(d), window));
    }
  }
}

class ShippedWorld : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedWorld, PathsMatchTheReferenceDijkstraAndReachability) {
  const spott_map::World world = Load(GetParam());
  ASSERT_FALSE(world.rooms.empty());
  const spott_map::RoomDoorGraph source(world);
  GlobalPlanner planner(source);
  const PlanningGraph& g = planner.graph();
  for (int s = 0; s < g.room_count(); ++s) {
    const std::vector<double> reference = ReferenceCosts(g, s);
    const auto reachable = source.ReachableFrom(g.room(s).id);
    for (int t = 0; t < g.room_count(); ++t) {
      const PlanResult r = planner.PlanBetweenRooms(g.room(s).id, g.room(t).id);
      const bool expect =
          std::find(reachable.begin(), reachable.end(), g.room(t).id) != reachable.end();
      ASSERT_EQ(r.ok(), expect) << g.room(s).id << " -> " << g.room(t).id << ": " << r.message;
      if (r.ok()) {
        EXPECT_NEAR(r.path->cost, reference[t], 1e-9) << g.room(s).id << " -> " << g.room(t).id;
      } else {
        EXPECT_TRUE(std::isinf(reference[t]));
        EXPECT_FALSE(r.closed_doors.empty()) << r.message;  // only closed doors separate them
      }
    }
  }
}

TEST_P(ShippedWorld, CadWallsAloneBlockNoPassageBetweenDoors) {
  const spott_map::World world = Load(GetParam());
  GlobalPlanner planner{spott_map::RoomDoorGraph(world)};
  PassageMonitor monitor{PassageParameters{}};
  monitor.Update(planner.mutable_graph(), spott_map::CadFeatures(world));
  for (const BlockedPassage& p : planner.graph().BlockedPassages()) {
    ADD_FAILURE() << GetParam() << ": walls block node " << p.room << " between " << p.door_a
                  << " and " << p.door_b;
  }
}

TEST_P(ShippedWorld, ProjectionsFromEveryRoomToEveryRoomKeepFig14sRules) {
  const spott_map::World world = Load(GetParam());
  GlobalPlanner planner{spott_map::RoomDoorGraph(world)};
  const PlanningGraph& g = planner.graph();
  std::mt19937_64 rng(11);
  int checked = 0, on_border = 0;
  for (int s = 0; s < g.room_count(); ++s) {
    const Box sb = spott_map::BoundingBox(g.room(s).polygon);
    for (int t = 0; t < g.room_count(); ++t) {
      const Box tb = spott_map::BoundingBox(g.room(t).polygon);
      for (int k = 0; k < 4; ++k) {
        std::uniform_real_distribution<double> ux(sb.min.x(), sb.max.x()),
            uy(sb.min.y(), sb.max.y());
        std::uniform_real_distribution<double> gx(tb.min.x(), tb.max.x()),
            gy(tb.min.y(), tb.max.y());
        const Vec2 robot(ux(rng), uy(rng));
        const Vec2 goal(gx(rng), gy(rng));
        if (g.RoomContaining(robot) != s || g.RoomContaining(goal) != t) continue;
        const PlanResult r = planner.Plan(robot, goal);
        if (!r.ok()) continue;  // behind a closed door
        const Box window = WindowAround(robot, 7.0, 0.2);
        const ProjectedGoal p = ProjectGoalOntoWindow(g, *r.path, robot, goal, window);
        CheckProjection(g, *r.path, robot, goal, window, p);
        ++checked;
        on_border += p.on_border ? 1 : 0;
      }
    }
  }
  // Enough of both kinds were checked for the test to mean something.
  EXPECT_GE(checked, 2 * g.room_count()) << GetParam();
  EXPECT_GE(on_border, g.room_count()) << GetParam();
  RecordProperty("projections_checked", checked);
}

INSTANTIATE_TEST_SUITE_P(Worlds, ShippedWorld,
                         ::testing::Values("cim_office", "bonn_department", "hilare_room"));

TEST(GeneratedBuilding, RandomProjectionsKeepFig14sRules) {
  SyntheticBuildingParameters params;
  params.rows = 6;
  params.cols = 6;
  params.room_size_m = 4.0;
  params.seed = 3;
  GlobalPlanner planner(MakeSyntheticBuilding(params));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(0.01, 23.99), size(0.6, 9.0);
  int cases[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 2000; ++i) {
    const Vec2 robot(coord(rng), coord(rng));
    const Vec2 goal(coord(rng), coord(rng));
    const PlanResult r = planner.Plan(robot, goal);
    ASSERT_TRUE(r.ok());
    const Box window = WindowAround(robot, size(rng), 0.2);
    const ProjectedGoal p = ProjectGoalOntoWindow(planner.graph(), *r.path, robot, goal, window);
    CheckProjection(planner.graph(), *r.path, robot, goal, window, p);
    ++cases[static_cast<int>(p.projection_case)];
    if (HasFailure()) FAIL() << "query " << i;
  }
  // Every case came up.
  for (int c = 1; c <= 4; ++c) EXPECT_GT(cases[c], 0) << "case " << c;
}

// Fig. 18's seed 6 on cim_office: the robot in office_201 at (1.77, 12.43), bound for the lab
// through d_201 (4, 9.5), hall_w and d_lab_w (12.5, 9.5); its 7 m window [-1.7, 5.3] x [9, 16]
// holds only hall_w's strip y in [9, 9.5]. The line from hall_w's centre to d_lab_w misses the
// window and the line from the robot crosses the east side at y = 11.46, outside hall_w: hall_w's
// portions of the border are its 0.5 m of the east side (1.96 m away, but all padding for a
// Nomad: 2 x 0.325 m) and its 5.3 m of the bottom side (2.46 m away). The bottom side is taken.
TEST(ShippedWorlds, AStripOfTheNodeNarrowerThanTheRobotIsNoBorderGoal) {
  const spott_map::World world = Load("cim_office");
  GlobalPlanner planner{spott_map::RoomDoorGraph(world)};
  const Vec2 robot(1.77, 12.43), goal(12.44, 12.91);
  const PlanResult r = planner.Plan(robot, goal);
  ASSERT_TRUE(r.ok()) << r.message;
  const ProjectedGoal p = ProjectGoalOntoWindow(planner.graph(), *r.path, robot, goal,
                                                Box{Vec2(-1.7, 9.0), Vec2(5.3, 16.0)}, 0.65);
  EXPECT_EQ(p.edge_id, "d_lab_w");
  EXPECT_EQ(p.node_id, "hall_w");
  ASSERT_TRUE(p.on_border);
  EXPECT_NEAR(p.border.a.y(), 9.0, 1e-9);
  EXPECT_NEAR(p.border.b.y(), 9.0, 1e-9);
  EXPECT_NEAR(std::abs(p.border.b.x() - p.border.a.x()), 5.3, 1e-9);
  // Of any length, the nearest: the strip.
  const ProjectedGoal q = ProjectGoalOntoWindow(planner.graph(), *r.path, robot, goal,
                                                Box{Vec2(-1.7, 9.0), Vec2(5.3, 16.0)});
  EXPECT_NEAR(q.border.a.x(), 5.3, 1e-9);
  EXPECT_NEAR(std::abs(q.border.b.y() - q.border.a.y()), 0.5, 1e-9);
}

}  // namespace
}  // namespace spott_global_planner
