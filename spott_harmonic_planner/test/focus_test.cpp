// Convergence judged where descent from the start (the robot) can go, and the ascent check that
// every judged cell has a strictly higher neighbour.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../src/mg_kernels.h"
#include "spott_harmonic_planner/potential_field.h"
#include "test_maps.h"

namespace spott_harmonic_planner {
namespace {

using testing_maps::Block;
using testing_maps::EmptyRaster;

// One free row of three cells between an obstacle (p = 0) and the goal (p = 1), with values that
// are not harmonic: the first cell (0.3) has no higher neighbour (0 and 0.2).
TEST(AscentDeficit, CountsJudgedCellsWithoutAHigherNeighbour) {
  const int nx = 5;
  std::vector<double> u(static_cast<std::size_t>(nx) * 3, 0.0);
  u[nx + 0] = 0.0;  // obstacle
  u[nx + 1] = 0.3;
  u[nx + 2] = 0.2;
  u[nx + 3] = 0.1;
  u[nx + 4] = 1.0;  // goal
  const internal::Run run{1, 1, 4};
  // The residual pass counts the same cells (ResidualNorms with the deficit).
  const auto fused = [&](double floor) {
    return internal::kernels::ResidualNorms(u.data(), nx, &run, 1, false, floor, true).deficit;
  };
  // Every cell judged: cell 1 stops descent (0.3 > 0.2 and 0).
  EXPECT_EQ(internal::kernels::AscentDeficit(u.data(), nx, &run, 1, 0.0), 1u);
  EXPECT_EQ(fused(0.0), 1u);
  EXPECT_EQ(fused(0.25), 1u);
  EXPECT_EQ(fused(0.35), 0u);
  // Focus at 0.25: cell 1 (0.3) is judged and stuck; cells 2, 3 are below the focus.
  EXPECT_EQ(internal::kernels::AscentDeficit(u.data(), nx, &run, 1, 0.25), 1u);
  // Focus at 0.35: cell 1 is below it, nothing judged is stuck.
  EXPECT_EQ(internal::kernels::AscentDeficit(u.data(), nx, &run, 1, 0.35), 0u);
  // The harmonic values (hand-computed: p1 = p2 / 4, p2 = (p1 + p3) / 4, p3 = (p2 + 1) / 4 give
  // p2 = 1/14, p1 = 1/56, p3 = 15/56) pass; a value <= 0 fails even with a higher neighbour.
  u[nx + 1] = 1.0 / 56;
  u[nx + 2] = 1.0 / 14;
  u[nx + 3] = 15.0 / 56;
  EXPECT_EQ(internal::kernels::AscentDeficit(u.data(), nx, &run, 1, 0.0), 0u);
  EXPECT_EQ(fused(0.0), 0u);
  u[nx + 1] = -1e-9;
  EXPECT_EQ(internal::kernels::AscentDeficit(u.data(), nx, &run, 1, 0.0), 1u);
  EXPECT_EQ(internal::kernels::AscentDeficit(u.data(), nx, &run, 1, 0.01), 0u);
  EXPECT_EQ(fused(0.0), 1u);
  EXPECT_EQ(fused(0.01), 0u);
  // A run of nine (vectors of four and single cells): the same counts.
  const int wide = 11;
  std::vector<double> w(static_cast<std::size_t>(wide) * 3, 0.0);
  const double values[9] = {0.5, 0.4, 0.45, 0.3, 0.2, 0.25, 0.1, -0.1, 0.05};
  for (int k = 0; k < 9; ++k) w[wide + 1 + k] = values[k];
  w[wide + 10] = 1.0;
  const internal::Run row{1, 1, 10};
  // Stuck: 0.5 (0 and 0.4 around it), 0.45 (0.4, 0.3), 0.25 (0.2, 0.1) and -0.1 (<= 0); 3 of
  // them are >= 0.15, 2 >= 0.42.
  const std::pair<double, std::size_t> expected[] = {{0.0, 4}, {0.15, 3}, {0.42, 2}};
  for (const auto& [floor, count] : expected) {
    EXPECT_EQ(internal::kernels::AscentDeficit(w.data(), wide, &row, 1, floor), count) << floor;
    EXPECT_EQ(internal::kernels::ResidualNorms(w.data(), wide, &row, 1, false, floor, true).deficit,
              count)
        << floor;
  }
}

// A 64 x 64 window: the goal on the right, the robot on the left in the open, and a closed
// room in the top left corner entered through a passage one cell wide and 21 long (p falls by
// 2 - sqrt(3) = 0.27 per cell along it): p in the room is many decades below p at the robot.
spott_map::OccupancyRaster RoomBehindAPassage() {
  auto r = EmptyRaster(64, 64);
  Block(r, 1, 40, 30, 40);   // the room's south wall
  Block(r, 30, 40, 30, 60);  // its east wall, with a door at (30, 61)
  Block(r, 30, 62, 30, 62);
  Block(r, 32, 41, 32, 62);  // the passage x = 31, from y = 40 up to the door
  return r;
}

FieldOptions Tight() {
  FieldOptions o;
  o.tolerance = 1e-6;
  return o;
}

TEST(StartFocus, ResolvesTheCellsDescentFromTheStartCanReach) {
  const auto raster = RoomBehindAPassage();
  const Vec2 goal(56.5, 20.5), robot(8.5, 20.5), in_room(10.5, 50.5);
  PotentialField whole(Tight());
  whole.SetOccupancy(raster);
  ASSERT_TRUE(whole.SetGoalPoint(goal));
  whole.ColdStart();
  ASSERT_TRUE(whole.Solve(1000).converged);
  const double p_robot = whole.GoalProbability(8, 20);
  ASSERT_LT(whole.GoalProbability(10, 50), 1e-6 * p_robot) << "the room is a deep tail";

  PotentialField focus(Tight());
  focus.SetOccupancy(raster);
  ASSERT_TRUE(focus.SetGoalPoint(goal));
  ASSERT_TRUE(focus.SetStart(robot));
  focus.ColdStart();
  const IterationReport report = focus.Solve(1000);
  ASSERT_TRUE(report.converged);
  EXPECT_LT(report.sweeps, whole.report().sweeps) << "the room's tail is not solved for";
  // Where descent from the robot can go (p >= 0.1 p(robot)) the two fields agree to a small
  // multiple of the tolerance, relative to each cell.
  double worst = 0.0;
  for (int y = 1; y < 63; ++y) {
    for (int x = 1; x < 63; ++x) {
      const double p = whole.GoalProbability(x, y);
      if (whole.cell(x, y) != FieldCell::kFree || p < 0.1 * p_robot) continue;
      worst = std::max(worst, std::abs(focus.GoalProbability(x, y) - p) / p);
    }
  }
  EXPECT_LT(worst, 1e-4);
  const auto a = focus.DescendPath(robot), b = whole.DescendPath(robot);
  ASSERT_TRUE(a.reached_goal);
  EXPECT_NEAR(a.length_m, b.length_m, 1e-6);

  // The robot moves into the room (a lower p): not converged for it any more; solved on, the
  // room is resolved relative to its own values too.
  EXPECT_TRUE(focus.SetStart(in_room));
  EXPECT_FALSE(focus.report().converged);
  ASSERT_TRUE(focus.Solve(1000).converged);
  const double p_room = whole.GoalProbability(10, 50);
  EXPECT_NEAR(focus.GoalProbability(10, 50), p_room, 1e-4 * p_room);
  EXPECT_TRUE(focus.DescendPath(in_room).reached_goal);
  // Back at the robot (a higher p): still converged, no iteration needed.
  const int sweeps = focus.report().sweeps;
  EXPECT_TRUE(focus.SetStart(robot));
  EXPECT_TRUE(focus.report().converged);
  EXPECT_EQ(focus.Solve(1000).sweeps, sweeps);
  // A start in an obstacle is no start: the whole field is judged again.
  EXPECT_FALSE(focus.SetStart(Vec2(20.5, 40.5)));
  EXPECT_FALSE(focus.HasStart());
}

TEST(StartFocus, FractionOutsideZeroToOneIsRefusedByName) {
  FieldOptions o;
  o.start_fraction = 1.5;
  const auto v = ValidateFieldOptions(o);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NE(v[0].find("start_fraction"), std::string::npos) << v[0];
  o.start_fraction = 0.0;  // every cell judged relative, as without a start
  EXPECT_TRUE(ValidateFieldOptions(o).empty());
}

}  // namespace
}  // namespace spott_harmonic_planner
