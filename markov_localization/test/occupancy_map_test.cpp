// ROS maps: map_server files (YAML + PGM) and occupancy grids rasterized at the belief's
// resolution, with nav_msgs/OccupancyGrid's conventions (origin = lower-left corner of cell
// (0, 0), row 0 at the bottom, the image's first row at the top).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>

#include "markov_localization/occupancy_map.h"
#include "spott_map/local_map.h"
#include "spott_map/occupancy_raster.h"
#include "test_helpers.h"

namespace markov_localization {
namespace {

std::string TempDir() {
  char pattern[] = "/tmp/ml_map_test_XXXXXX";
  const char* dir = mkdtemp(pattern);
  return dir ? dir : "/tmp";
}

void Write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

TEST(OccupancyMap, MapServerFilesRoundTrip) {
  OccupancyMap m;
  m.origin = Vec2(-1.5, 2.25);
  m.resolution_m = 0.05;
  m.width = 4;
  m.height = 3;
  m.data = {0, 100, -1, 0, 100, 100, 0, -1, 0, 0, 0, 100};
  const std::string dir = TempDir();
  std::string error;
  ASSERT_TRUE(WriteMapServerMap(m, dir + "/m.yaml", "m.pgm", &error)) << error;
  const MapFileResult r = LoadMapServerMap(dir + "/m.yaml");
  ASSERT_TRUE(r.ok()) << spott_map::FormatErrors(r.errors);
  EXPECT_EQ(r.map->width, 4);
  EXPECT_EQ(r.map->height, 3);
  EXPECT_DOUBLE_EQ(r.map->resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(r.map->origin.x(), -1.5);
  EXPECT_DOUBLE_EQ(r.map->origin.y(), 2.25);
  EXPECT_EQ(r.map->data, m.data);
}

TEST(OccupancyMap, ThePgmsFirstRowIsTheTopOfTheMap) {
  const std::string dir = TempDir();
  // 3 x 2 pixels: top row black (occupied), bottom row white (free), one grey (unknown).
  Write(dir + "/a.pgm", "P2\n# comment\n3 2\n255\n0 0 0\n254 205 254\n");
  Write(dir + "/a.yaml",
        "image: a.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const MapFileResult r = LoadMapServerMap(dir + "/a.yaml");
  ASSERT_TRUE(r.ok()) << spott_map::FormatErrors(r.errors);
  EXPECT_EQ(r.map->at(0, 1), 100);  // the image's first row: y in [0.1, 0.2)
  EXPECT_EQ(r.map->at(2, 1), 100);
  EXPECT_EQ(r.map->at(0, 0), 0);
  EXPECT_EQ(r.map->at(1, 0), -1);
  // negate 1 swaps black and white; mode raw reads the pixel as the value.
  Write(dir + "/b.yaml",
        "image: a.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 1\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const MapFileResult b = LoadMapServerMap(dir + "/b.yaml");
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(b.map->at(0, 1), 0);
  EXPECT_EQ(b.map->at(0, 0), 100);
}

TEST(OccupancyMap, BadFilesSayWhereAndWhat) {
  const std::string dir = TempDir();
  Write(dir + "/ok.pgm", "P5\n2 2\n255\n\xfe\xfe\xfe\xfe");
  auto errors_of = [&](const std::string& yaml) {
    Write(dir + "/bad.yaml", yaml);
    const MapFileResult r = LoadMapServerMap(dir + "/bad.yaml");
    EXPECT_FALSE(r.ok());
    return spott_map::FormatErrors(r.errors);
  };
  const std::string good_tail = "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  // An unknown key: file, line and column, and the likely intended key.
  std::string e = errors_of("image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n" +
                            good_tail + "resolutoin: 2\n");
  EXPECT_NE(e.find("bad.yaml:7:1"), std::string::npos) << e;
  EXPECT_NE(e.find("resolution"), std::string::npos) << e;
  e = errors_of("image: ok.pgm\nresolution: -1\norigin: [0, 0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("bad.yaml:2"), std::string::npos) << e;
  e = errors_of("image: ok.pgm\nresolution: 0.05\norigin: [0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("origin"), std::string::npos) << e;
  e = errors_of("image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 2\n" + good_tail);
  EXPECT_NE(e.find("negate must be 0 or 1"), std::string::npos) << e;
  e = errors_of("image: map.png\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("only PGM"), std::string::npos) << e;
  e = errors_of("image: missing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("cannot read the image"), std::string::npos) << e;
  e = errors_of("resolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("missing required key 'image'"), std::string::npos) << e;
  e = errors_of("image: [oops\n");
  EXPECT_NE(e.find("YAML syntax error"), std::string::npos) << e;
  // Images: truncated raster, 16-bit, not a PGM.
  Write(dir + "/t.pgm", "P5\n4 4\n255\n\x01\x02");
  e = errors_of("image: t.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
  EXPECT_NE(e.find("t.pgm"), std::string::npos) << e;
  Write(dir + "/w.pgm", "P5\n1 1\n65535\n\x01\x02");
  e = errors_of("image: w.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("8-bit"), std::string::npos) << e;
  Write(dir + "/n.pgm", "GIF89a");
  e = errors_of("image: n.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n" + good_tail);
  EXPECT_NE(e.find("not a PGM"), std::string::npos) << e;
}

// A 3 x 1 m free strip at 5 cm with a wall in the grid's cells of x in [1.00, 1.05).
OccupancyMap Strip(const Vec2& origin) {
  OccupancyMap m;
  m.origin = origin;
  m.resolution_m = 0.05;
  m.width = 60;
  m.height = 20;
  m.data.assign(m.width * m.height, 0);
  for (int j = 0; j < m.height; ++j) m.data[j * m.width + 20] = 100;
  for (int i = 0; i < m.width; ++i) m.data[i] = m.data[(m.height - 1) * m.width + i] = 100;
  return m;
}

TEST(OccupancyMap, GridIsRasterizedAtTheBeliefsResolutionWithCornerOrigin) {
  MapModelParameters p;
  p.resolution_m = 0.15;
  p.ray_cast_subdivision = 5;  // fine cells of 3 cm
  p.state_clearance_m = 0.0;
  for (const Vec2& origin : {Vec2(0.0, 0.0), Vec2(0.5, -0.25)}) {
    const MapModel map = MapModel::FromOccupancy(Strip(origin), p);
    EXPECT_EQ(map.width(), 20);  // 3 m / 0.15 m
    EXPECT_EQ(map.height(), 7);  // ceil(1 m / 0.15 m)
    EXPECT_DOUBLE_EQ(map.resolution(), 0.15);
    EXPECT_NEAR(map.origin().x(), origin.x(), 1e-12);
    // From the centre of belief cell 2 (x = 0.375 from the corner) east: the wall's cells start
    // at 1.00 m; the fine cell [0.99, 1.02) is the first it overlaps, so the beam stops at its
    // face, 0.615 m, and never beyond the wall's true face (0.625 m).
    const Vec2 from = map.CellCentre(2, 3);
    EXPECT_NEAR(from.x() - origin.x(), 0.375, 1e-12);
    EXPECT_NEAR(map.RayCast(from, 0.0, 5.0), 0.615, 1e-9);
    EXPECT_TRUE(map.surface_inside_cells());  // 5 cm is not a whole number of 3 cm cells
    // West the strip's free cells reach x = 0 (the grid's edge): max range.
    EXPECT_DOUBLE_EQ(map.RayCast(from, M_PI, 5.0), 5.0);
    // The wall's belief cell (x 0.90-1.05 from the corner) holds an obstacle; with 10 cm of
    // clearance its centre (1.5 cm from the wall's fine cells) is no state, cell 2's is.
    EXPECT_TRUE(map.Occupied(6, 3));
    MapModelParameters q = p;
    q.state_clearance_m = 0.1;
    const MapModel cleared = MapModel::FromOccupancy(Strip(origin), q);
    EXPECT_FALSE(cleared.IsState(6, 3));
    EXPECT_TRUE(cleared.IsState(2, 3));
  }
}

TEST(OccupancyMap, UnknownCellsAreNoStatesAndRotatedGridsAreRefused) {
  OccupancyMap m = Strip(Vec2(0, 0));
  for (int j = 1; j < m.height - 1; ++j)
    for (int i = 30; i < 60; ++i) m.data[j * m.width + i] = -1;  // x >= 1.5 m unknown
  MapModelParameters p;
  p.resolution_m = 0.1;
  p.state_clearance_m = 0.0;
  const MapModel map = MapModel::FromOccupancy(m, p);
  EXPECT_TRUE(map.IsStateAt(Vec2(1.25, 0.5)));
  EXPECT_FALSE(map.IsStateAt(Vec2(1.75, 0.5)));
  // Unknown does not reflect beams: from x = 1.25 east the beam runs to the grid's end.
  EXPECT_DOUBLE_EQ(map.RayCast(Vec2(1.25, 0.55), 0.0, 5.0), 5.0);
  m.origin_yaw = 0.3;
  try {
    MapModel::FromOccupancy(m, p);
    FAIL() << "a rotated grid was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("origin yaw"), std::string::npos) << e.what();
  }
  m.origin_yaw = 0.0;
  m.data.pop_back();
  EXPECT_THROW(MapModel::FromOccupancy(m, p), std::invalid_argument);
}

TEST(OccupancyMap, AWorldAndItsMapServerExportCastTheSameRays) {
  // bonn_department as the CAD map and as its 5 cm map_server export, both at the belief's
  // 20 cm with 5 x subdivision: the same rays from the same points agree to a few cm, with no
  // systematic offset (a half-cell error of the conventions would show as one).
  const spott_map::World world = testing::LoadWorld("bonn_department");
  MapModelParameters p;
  p.resolution_m = 0.2;
  p.ray_cast_subdivision = 5;
  const MapModel from_world = MapModel::FromWorld(world, p);
  OccupancyMap grid;
  grid.resolution_m = 0.05;
  grid.origin = Vec2(-0.5, -0.5);
  grid.width = 28 * 20 + 20;
  grid.height = 21 * 20 + 20;
  grid.data.assign(grid.width * grid.height, -1);
  const spott_map::MapDatabase db = spott_map::MapDatabase::FromWorld(world);
  spott_map::OccupancyRaster raster(grid.origin, grid.width, grid.height, grid.resolution_m);
  spott_map::RasterizeDatabase(db, 0.0, p.door_thickness_m, raster);
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const bool inside = world.RoomContaining(raster.CellCentre(i, j)) != nullptr;
      grid.data[j * grid.width + i] =
          raster.at(i, j) == spott_map::Cell::kObstacle ? 100 : (inside ? 0 : -1);
    }
  const MapModel from_grid = MapModel::FromOccupancy(grid, p);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> ux(1.0, 26.0), uy(1.0, 19.0), ua(-M_PI, M_PI);
  int n = 0, close = 0;
  double sum = 0.0;
  double dir_sum[4] = {0, 0, 0, 0};  // rays mostly east, west, north, south
  int dir_n[4] = {0, 0, 0, 0};
  while (n < 4000) {
    const Vec2 q(ux(rng), uy(rng));
    if (!from_world.IsStateAt(q)) continue;
    const double a = ua(rng);
    const double r1 = from_world.RayCast(q, a, 8.0), r2 = from_grid.RayCast(q, a, 8.0);
    if (r1 >= 8.0 || r2 >= 8.0) continue;
    ++n;
    sum += r2 - r1;
    close += std::abs(r2 - r1) < 0.1;
    const int d = std::cos(a) > 0.9    ? 0
                  : std::cos(a) < -0.9 ? 1
                  : std::sin(a) > 0.9  ? 2
                  : std::sin(a) < -0.9 ? 3
                                       : -1;
    if (d >= 0) dir_sum[d] += r2 - r1, ++dir_n[d];
  }
  EXPECT_GT(close, 0.97 * n);
  // The export was rasterized twice (5 cm, then the 4 cm fine cells): its walls can only be
  // thicker, by a few cm on average.
  EXPECT_LT(sum / n, 0.0);
  EXPECT_GT(sum / n, -0.06);
  // No shift: rays east and west (north and south) are shortened alike; a half-cell error of
  // the origin convention would shorten one and lengthen the other by 2.5 cm.
  EXPECT_NEAR(dir_sum[0] / dir_n[0], dir_sum[1] / dir_n[1], 0.015);
  EXPECT_NEAR(dir_sum[2] / dir_n[2], dir_sum[3] / dir_n[3], 0.015);
}

}  // namespace
}  // namespace markov_localization
