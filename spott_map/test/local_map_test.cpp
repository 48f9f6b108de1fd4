#include "spott_map/local_map.h"

#include <gtest/gtest.h>

#include "test_worlds.h"

namespace spott_map {
namespace {

TEST(Rasterize, KnownWallGivesTheHandCountedCellsWithPadding) {
  // 0.1 m cells from (-1, -1). The wall runs along the middle of row 10 (y in [0, 0.1]) over
  // columns 10..29. A cell is padding when any point of it is nearer than 0.24 m: rows 8..12
  // (their near edges 0.05 and 0.15 m off the line), and beyond each end two columns (near
  // edges 0.05 and 0.15 m off the end) in every one of those rows.
  OccupancyRaster raster(Vec2(-1, -1), 40, 25, 0.1);
  RasterizeFeature(MakeSegment("w", Segment{Vec2(0.05, 0.05), Vec2(1.95, 0.05)}, "wall"), 0.24,
                   raster);
  EXPECT_EQ(raster.CountCells(Cell::kObstacle), 20u);
  for (int ix = 10; ix <= 29; ++ix) EXPECT_EQ(raster.at(ix, 10), Cell::kObstacle) << ix;
  EXPECT_EQ(raster.at(9, 10), Cell::kPadding);
  EXPECT_EQ(raster.at(8, 10), Cell::kPadding);
  EXPECT_EQ(raster.at(7, 10), Cell::kFree);
  EXPECT_EQ(raster.at(31, 10), Cell::kPadding);
  EXPECT_EQ(raster.at(32, 10), Cell::kFree);
  EXPECT_EQ(raster.at(20, 12), Cell::kPadding);
  EXPECT_EQ(raster.at(20, 13), Cell::kFree);
  // The corner cell 0.15 m up and 0.15 m out: its near corner is 0.21 m away (its centre 0.28 m).
  EXPECT_EQ(raster.at(8, 12), Cell::kPadding);
  EXPECT_EQ(raster.at(7, 12), Cell::kFree);  // 0.15 up, 0.25 out: 0.29 m
  EXPECT_EQ(raster.at(7, 11), Cell::kFree);  // 0.05 up, 0.25 out: 0.255 m
  EXPECT_EQ(raster.at(9, 13), Cell::kFree);  // 0.25 up
  // Rows 8..12, columns 8..31: 120 cells, 20 of them obstacle.
  EXPECT_EQ(raster.CountCells(Cell::kPadding), 100u);
}

// Every point of a cell left free keeps the padding from the geometry: a robot whose centre is
// anywhere in it (not only at its centre) clears the obstacle by the localization error allowed.
TEST(Rasterize, EveryPointOfAFreeCellKeepsThePadding) {
  const double padding = 0.2285 + 0.075;
  for (const double phase : {0.0, 0.03, 0.05, 0.08}) {
    OccupancyRaster raster(Vec2(-2.0 + phase, -1.5 + phase), 40, 30, 0.1);
    // A jamb: the end of a 0.15 m wall, and a box.
    const MapFeature wall =
        MakeSegment("w", Segment{Vec2(-2.0, 0.0), Vec2(-0.45, 0.0)}, "wall", 0.15);
    MapFeature box;
    box.type = FeatureType::kRectangle;
    box.pose = Pose2{1.0, 0.5, 0.4};
    box.size_x = 0.5;
    box.size_y = 0.3;
    RasterizeFeature(wall, padding, raster);
    RasterizeFeature(box, padding, raster);
    for (int iy = 0; iy < raster.height(); ++iy) {
      for (int ix = 0; ix < raster.width(); ++ix) {
        if (raster.at(ix, iy) != Cell::kFree) continue;
        const Vec2 c = raster.CellCentre(ix, iy);
        for (const double dx : {-0.05, 0.0, 0.05}) {
          for (const double dy : {-0.05, 0.0, 0.05}) {
            const Vec2 q = c + Vec2(dx, dy);
            EXPECT_GE(std::min(wall.DistanceTo(q), box.DistanceTo(q)), padding - 1e-9)
                << "cell " << ix << ", " << iy << " phase " << phase;
          }
        }
      }
    }
  }
}

TEST(Rasterize, ThickWallAndAreaFeatures) {
  OccupancyRaster raster(Vec2(0, 0), 20, 20, 0.1);
  MapFeature box;
  box.type = FeatureType::kRectangle;
  box.pose = Pose2{1.0, 1.0, 0.0};
  box.size_x = 0.4;  // x in [0.8, 1.2]
  box.size_y = 0.2;  // y in [0.9, 1.1]
  // Cells that only touch the outline at an edge are left out of the checks: rounding decides.
  RasterizeFeature(box, 0.0, raster);
  EXPECT_EQ(raster.at(10, 10), Cell::kObstacle);
  EXPECT_EQ(raster.at(8, 9), Cell::kObstacle);
  EXPECT_EQ(raster.at(13, 10), Cell::kFree);
  EXPECT_EQ(raster.at(10, 12), Cell::kFree);
  // A 0.3 m thick wall along y = 0.55 marks the rows its thickness covers: y in [0.4, 0.7].
  OccupancyRaster walls(Vec2(0, 0), 20, 20, 0.1);
  RasterizeFeature(MakeSegment("w", Segment{Vec2(0.05, 0.55), Vec2(1.95, 0.55)}, "wall", 0.3), 0.0,
                   walls);
  EXPECT_EQ(walls.at(10, 4), Cell::kObstacle);
  EXPECT_EQ(walls.at(10, 6), Cell::kObstacle);
  EXPECT_EQ(walls.at(10, 2), Cell::kFree);
  EXPECT_EQ(walls.at(10, 8), Cell::kFree);
}

// Doors between 0.15 m walls, as the shipped worlds build them (walls are boxes with flat ends):
// with every point of a free cell keeping the padding, a door keeps a free column of 0.1 m cells
// wherever the lattice falls when the span left between the padded jambs is at least two cells.
// The shipped worlds' 0.9 m doors for the Nomad 200 (radius 0.2285 m) and the B21 (0.2625 m) with
// the stack's localization error of 0.075 m (spans 0.293 and 0.225 m); a 0.8 m door, common in
// homes, for the Nomad with 0.05 m (0.243 m).
TEST(Rasterize, DoorsStayPassableWhenTheSpanBetweenThePaddedJambsIsTwoCells) {
  struct Case {
    double door, radius, error;
  };
  for (const Case& k :
       {Case{0.9, 0.2285, 0.075}, Case{0.9, 0.2625, 0.075}, Case{0.8, 0.2285, 0.05}}) {
    for (const double phase : {0.0, 0.02, 0.05, 0.07}) {
      OccupancyRaster raster(Vec2(-2.0 + phase, -1.0), 40, 20, 0.1);
      // The wall y = 0 from x = -2 to 2, with the opening x in [-door / 2, door / 2].
      const double h = 0.5 * k.door;
      RasterizeFeature(MakeSegment("w1", Segment{Vec2(-2.0, 0.0), Vec2(-h, 0.0)}, "wall", 0.15),
                       k.radius + k.error, raster);
      RasterizeFeature(MakeSegment("w2", Segment{Vec2(h, 0.0), Vec2(2.0, 0.0)}, "wall", 0.15),
                       k.radius + k.error, raster);
      bool column = false;
      for (int ix = 0; ix < raster.width() && !column; ++ix) {
        bool free = true;
        for (int iy = 0; iy < raster.height(); ++iy) free &= raster.at(ix, iy) == Cell::kFree;
        column = free;
      }
      EXPECT_TRUE(column) << "door " << k.door << ", radius " << k.radius << ", error " << k.error
                          << ", lattice phase " << phase;
    }
  }
}

TEST(Rasterize, WallEndsAreFlat) {
  // A 0.15 m thick wall ending at x = -0.02: the cell x in [0, 0.1], y in [0, 0.1] beyond its
  // end, level with it, is 0.02 m from the box and free at a padding of 0.015 m (a rounded end,
  // reaching 0.075 m further, would meet it: obstacle).
  OccupancyRaster raster(Vec2(-1.0, -0.5), 20, 10, 0.1);
  const MapFeature wall =
      MakeSegment("w", Segment{Vec2(-1.0, 0.0), Vec2(-0.02, 0.0)}, "wall", 0.15);
  RasterizeFeature(wall, 0.015, raster);
  EXPECT_EQ(raster.at(10, 5), Cell::kFree);
  EXPECT_EQ(raster.at(9, 5), Cell::kObstacle);
  EXPECT_NEAR(wall.DistanceTo(Vec2(0.05, 0.05)), 0.07, 1e-12);
  EXPECT_NEAR(wall.DistanceTo(Vec2(-0.5, 0.2)), 0.125, 1e-12);
  EXPECT_EQ(wall.DistanceTo(Vec2(-0.5, 0.0)), 0.0);
}

TEST(LocalMap, ClosedDoorIsAnObstacleAndOpeningItFreesTheWay) {
  LocalMapParameters p;
  p.window_size_m = 4.0;
  p.resolution_m = 0.1;
  p.robot_radius_m = 0.0;
  p.max_localization_error_m = 0.0;
  MapDatabase db = MapDatabase::FromWorld(testing::TwoRoomsWorld());
  LocalMap local(p);
  local.Recentre(db, Vec2(7.0, 2.0));  // around d_lab, which is closed
  auto cell = local.raster().CellOf(Vec2(7.0, 2.0));
  ASSERT_TRUE(cell);
  EXPECT_EQ(local.raster().at(cell->first, cell->second), Cell::kObstacle);
  ASSERT_TRUE(db.SetDoorState("d_lab", DoorState::kOpen));
  EXPECT_NE(local.revision(), db.revision());
  local.Refresh(db);
  EXPECT_EQ(local.raster().at(cell->first, cell->second), Cell::kFree);
  EXPECT_EQ(local.revision(), db.revision());
}

TEST(LocalMap, WindowIsCentredOnTheLatticeAndKnowsWhenToMove) {
  LocalMapParameters p;  // 7 m at 0.2 m: the paper's 35 x 35
  MapDatabase db = MapDatabase::FromWorld(testing::TwoRoomsWorld());
  LocalMap local(p);
  local.Recentre(db, Vec2(5.03, 3.01));
  EXPECT_EQ(local.raster().width(), 35);
  EXPECT_EQ(local.raster().height(), 35);
  const Vec2 o = local.raster().origin();
  EXPECT_NEAR(std::remainder(o.x(), 0.2), 0.0, 1e-9);
  EXPECT_NEAR(std::remainder(o.y(), 0.2), 0.0, 1e-9);
  EXPECT_LT((local.centre() - Vec2(5.03, 3.01)).norm(), 0.15);
  EXPECT_FALSE(local.NeedsRecentre(Vec2(5, 3)));
  EXPECT_TRUE(local.NeedsRecentre(Vec2(5 + 3.0, 3)));  // 0.5 m from the east border
  EXPECT_TRUE(local.NeedsRecentre(Vec2(20, 3)));       // outside
  // The vector half holds the walls that meet the window.
  EXPECT_FALSE(local.features().empty());
  for (const MapFeature& f : local.features()) EXPECT_TRUE(f.Bounds().Intersects(local.bounds()));
}

TEST(LocalMap, PaddingIsRobotRadiusPlusLocalizationError) {
  LocalMapParameters p;
  p.window_size_m = 4.0;
  p.resolution_m = 0.05;
  p.robot_radius_m = 0.3;
  p.max_localization_error_m = 0.2;
  MapDatabase db;
  db.AddFeature(MakeSegment("w", Segment{Vec2(-5, 0), Vec2(5, 0)}, "wall"));
  LocalMap local(p);
  local.Recentre(db, Vec2(0, 0));
  const auto free_at = [&](double y) {
    auto c = local.raster().CellOf(Vec2(0.025, y));
    return local.raster().at(c->first, c->second) == Cell::kFree;
  };
  EXPECT_FALSE(free_at(0.475));  // centre 0.475 m from the wall: inside 0.5 m padding
  EXPECT_TRUE(free_at(0.525));
}

TEST(LocalMap, InvalidParametersAreRefusedByName) {
  LocalMapParameters p;
  p.resolution_m = -0.1;
  p.robot_radius_m = std::nan("");
  const auto v = ValidateParameters(p);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0], "resolution_m must be > 0 (got -0.1)");
  EXPECT_EQ(v[1].substr(0, 26), "robot_radius_m must be >= ");
  EXPECT_THROW(LocalMap{p}, std::invalid_argument);
  LocalMapParameters margin;
  margin.recentre_margin_m = 5.0;
  EXPECT_EQ(ValidateParameters(margin),
            (std::vector<std::string>{"recentre_margin_m must be < window_size_m / 2 (got 5)"}));
}

// Found by harmonic_planner_parameters_fuzz: a resolution of 2e-322 m passed the 8192-cell limit,
// because cells() rounded 7 m / 2e-322 m into an int first (wrapped around).
TEST(LocalMap, ACellCountBeyondAnIntIsRefusedNotWrappedAround) {
  LocalMapParameters p;
  for (double res : {2e-322, 1e-300, 1e-9, 7.0 / 8193}) {
    p.resolution_m = res;
    const auto v = ValidateParameters(p);
    ASSERT_EQ(v.size(), 1u) << res;
    EXPECT_EQ(v[0].rfind("window_size_m must be at most 8192 cells", 0), 0u) << v[0];
  }
  p.resolution_m = 7.0 / 8192;
  EXPECT_TRUE(ValidateParameters(p).empty());
  EXPECT_EQ(p.cells(), 8192);
}

}  // namespace
}  // namespace spott_map
