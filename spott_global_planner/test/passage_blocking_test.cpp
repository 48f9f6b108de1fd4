// Passages through a node (SPOTT III: "the path from one access way to another ... is blocked by
// a newly discovered obstacle") on the hallway H = [0,12]x[4,6] of test_building.h, whose doors
// dAH, dBH, dCH open its bottom side at x = 2, 6 and 10 (1 m wide).
#include "spott_global_planner/passage_blocking.h"

#include <gtest/gtest.h>

#include "spott_global_planner/global_planner.h"
#include "test_building.h"

namespace spott_global_planner {
namespace {

using spott_map::MapFeature;
using spott_map::Segment;
using spott_map::Vec2;
using Pairs = std::vector<std::pair<int, int>>;

MapFeature Box(const std::string& id, const Vec2& centre, double sx, double sy) {
  MapFeature f;
  f.id = id;
  f.type = spott_map::FeatureType::kRectangle;
  f.label = "partition";
  f.pose = spott_map::Pose2{centre.x(), centre.y(), 0.0};
  f.size_x = sx;
  f.size_y = sy;
  return f;
}

// H's walls as the CAD map has them: the top side whole, the bottom side with gaps at doors.
std::vector<MapFeature> HallwayWalls() {
  std::vector<MapFeature> walls;
  walls.push_back(spott_map::MakeSegment("top", Segment{Vec2(0, 6), Vec2(12, 6)}, "wall"));
  const std::pair<double, double> parts[4] = {{0, 1.5}, {2.5, 5.5}, {6.5, 9.5}, {10.5, 12}};
  int i = 0;
  for (const auto& [x0, x1] : parts) {
    walls.push_back(spott_map::MakeSegment("bottom" + std::to_string(i++),
                                           Segment{Vec2(x0, 4), Vec2(x1, 4)}, "wall"));
  }
  return walls;
}

class Passages : public ::testing::Test {
 protected:
  Passages() : graph_(test::MakeTestBuilding()) {
    room_ = graph_.source().FindRoom("H");
    for (const char* id : {"dAH", "dBH", "dCH"}) doors_.push_back(graph_.source().FindDoor(id));
  }
  PassageAnalysis Analyse(std::vector<MapFeature> extra) {
    features_ = HallwayWalls();
    for (auto& f : extra) features_.push_back(std::move(f));
    std::vector<const MapFeature*> obstacles;
    for (const auto& f : features_) obstacles.push_back(&f);
    return AnalysePassages(*room_, doors_, obstacles, params_);
  }

  PlanningGraph graph_;
  const spott_map::Room* room_ = nullptr;
  std::vector<const spott_map::Door*> doors_;
  std::vector<MapFeature> features_;
  PassageParameters params_;  // 5 cm cells, 0.325 m padding
};

// Found by global_planner_parameters_fuzz: passage/resolution_m 1e-300 m was accepted and
// AnalysePassages cast the raster's infinite width into an int (undefined).
TEST_F(Passages, ARasterTooFineToCountIsNotAnalysed) {
  params_.resolution_m = 1e-300;
  const PassageAnalysis a = Analyse({});
  EXPECT_FALSE(a.analysed);
  EXPECT_TRUE(a.blocked.empty());
  EXPECT_EQ(a.door_reachable, std::vector<bool>(3, true));
}

TEST_F(Passages, EmptyHallwayJoinsEveryPairOfDoors) {
  const PassageAnalysis a = Analyse({});
  EXPECT_TRUE(a.analysed);
  EXPECT_TRUE(a.blocked.empty());
  EXPECT_EQ(a.door_reachable, (std::vector<bool>{true, true, true}));
}

TEST_F(Passages, PartitionAcrossTheHallwayBlocksOnlyThePassagesItSeparates) {
  // A partition across H at x in [3.5,4.5] cuts dAH (x = 2) from dBH and dCH; dBH and dCH stay
  // joined.
  const PassageAnalysis a = Analyse({Box("p", Vec2(4, 5), 1.0, 3.0)});
  EXPECT_EQ(a.blocked, (Pairs{{0, 1}, {0, 2}}));
  EXPECT_EQ(a.door_reachable, (std::vector<bool>{true, true, true}));
}

TEST_F(Passages, GapNarrowerThanTwiceThePaddingBlocksAndAWiderOneDoesNot) {
  // An obstacle from the top wall down to y = 4.5 leaves a 0.5 m gap above the bottom wall:
  // less than 2 x 0.325 m, so the padded robot cannot pass.
  EXPECT_EQ(Analyse({Box("p", Vec2(4, 5.25), 1.0, 1.5)}).blocked, (Pairs{{0, 1}, {0, 2}}));
  // Down to y = 5 it leaves 1 m: free.
  EXPECT_TRUE(Analyse({Box("p", Vec2(4, 5.5), 1.0, 1.0)}).blocked.empty());
}

TEST_F(Passages, ObstacleInFrontOfADoorCutsItFromEveryOtherDoor) {
  const PassageAnalysis a = Analyse({Box("crate", Vec2(10, 4.3), 1.6, 0.6)});
  EXPECT_EQ(a.door_reachable, (std::vector<bool>{true, true, false}));
  EXPECT_EQ(a.blocked, (Pairs{{0, 2}, {1, 2}}));
}

TEST_F(Passages, MonitorSetsTheGraphsBlockedPassagesAndReanalysesOnlyOnChange) {
  PassageMonitor monitor(params_);
  std::vector<MapFeature> features = HallwayWalls();
  EXPECT_TRUE(monitor.Update(graph_, features).empty());
  features.push_back(Box("p", Vec2(4, 5), 1.0, 3.0));
  const std::vector<int> changed = monitor.Update(graph_, features);
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(graph_.room(changed[0]).id, "H");
  const auto blocked = graph_.BlockedPassages();
  ASSERT_EQ(blocked.size(), 2u);
  EXPECT_EQ(blocked[0], (BlockedPassage{"H", "dAH", "dBH"}));
  EXPECT_EQ(blocked[1], (BlockedPassage{"H", "dAH", "dCH"}));
  EXPECT_TRUE(monitor.Update(graph_, features).empty());  // nothing new
  features.pop_back();
  EXPECT_EQ(monitor.Update(graph_, features).size(), 1u);
  EXPECT_TRUE(graph_.BlockedPassages().empty());
}

TEST_F(Passages, PlannerRoutesAroundABlockedPassageFoundByTheMonitor) {
  GlobalPlanner planner(test::MakeTestBuilding());
  ASSERT_TRUE(planner.mutable_graph().SetDoorState("dBC", spott_map::DoorState::kClosed));
  // Before: A-dAH-H-dCH-C. A partition in H between dAH and the other doors forces the way
  // through B: A-dAB-B-dBH-H-dCH-C.
  std::vector<MapFeature> features = HallwayWalls();
  features.push_back(Box("p", Vec2(4, 5), 1.0, 3.0));
  PassageMonitor monitor(params_);
  monitor.Update(planner.mutable_graph(), features);
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.path->doors, (std::vector<std::string>{"dAB", "dBH", "dCH"}));
}

TEST(PassageParameters, EveryViolationIsNamed) {
  PassageParameters p;
  p.resolution_m = 0.0;
  p.padding_m = -1.0;
  p.door_depth_m = 0.0;
  p.max_cells = 0;
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0], "resolution_m must be > 0 (got 0)");
  EXPECT_EQ(v[1], "padding_m must be >= 0 (got -1)");
  EXPECT_EQ(v[2], "door_depth_m must be > 0 (got 0)");
  EXPECT_EQ(v[3], "max_cells must be >= 1 (got 0)");
  EXPECT_THROW(PassageMonitor{p}, std::invalid_argument);
}

}  // namespace
}  // namespace spott_global_planner
