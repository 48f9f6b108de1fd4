#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <cmath>
#include <cstdio>

#include "robot_sim/sim_world.h"
#include "test_world.h"

namespace robot_sim {
namespace {

using Eigen::Vector3d;

class SimWorldTest : public ::testing::Test {
 protected:
  SimWorldTest() : world_(Params()) { world_.Build(testing::TestWorld()); }
  static SimWorldParameters Params() {
    SimWorldParameters p;
    p.octomap_resolution_m = 0.1;
    p.wall_height_m = 1.0;
    return p;
  }
  SimWorld world_;
};

TEST_F(SimWorldTest, RayHitsWallFaceAtHandComputedDistance) {
  // From (5, 3) east: the door is north-south at x = 10 but the ray at y = 4 meets the wall,
  // whose west face is at x = 9.95.
  const auto hit = world_.CastRay(Vector3d(5, 4, 0.5), Vector3d(20, 4, 0.5));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 4.95, 1e-3);
  EXPECT_NEAR(hit->normal.x(), -1.0, 1e-6);  // facing the ray
}

TEST_F(SimWorldTest, ClosedDoorBlocksAndOpenDoorPasses) {
  // The closed leaf (0.05 m thick) is centred on x = 10: its west face at 9.975.
  auto hit = world_.CastRay(Vector3d(5, 3, 0.5), Vector3d(20, 3, 0.5));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 4.975, 1e-3);
  ASSERT_TRUE(world_.SetDoorClosed("d1", false, nullptr));
  hit = world_.CastRay(Vector3d(5, 3, 0.5), Vector3d(20, 3, 0.5));
  ASSERT_TRUE(hit);  // now the east room's far wall, inside face at 13.95
  EXPECT_NEAR(hit->distance, 8.95, 1e-3);
  EXPECT_EQ(world_.DoorClosed("d1"), std::optional<bool>(false));
}

TEST_F(SimWorldTest, DoorChangeUpdatesOctomapToo) {
  const octomap::OcTree& tree = world_.octree();
  auto occupied = [&](double x, double y, double z) {
    const octomap::OcTreeNode* n = tree.search(x, y, z);
    return n && tree.isNodeOccupied(n);
  };
  EXPECT_TRUE(occupied(10.0, 3.0, 0.45));
  world_.SetDoorClosed("d1", false, nullptr);
  EXPECT_FALSE(occupied(10.0, 3.0, 0.45));
  EXPECT_TRUE(occupied(10.0, 1.0, 0.45));  // the wall beside the door stays
  world_.SetDoorClosed("d1", true, nullptr);
  EXPECT_TRUE(occupied(10.0, 3.0, 0.45));
}

TEST_F(SimWorldTest, UnknownDoorIsAnError) {
  std::string error;
  EXPECT_FALSE(world_.SetDoorClosed("nope", true, &error));
  EXPECT_NE(error.find("nope"), std::string::npos);
}

TEST_F(SimWorldTest, AddedObstacleIsSeenByRaysAndOctomapAndRemovedAgain) {
  Solid box;
  box.id = "box";
  box.pose = {4, 3, 0};
  box.size_x = box.size_y = 1.0;
  box.height = 0.8;
  ASSERT_TRUE(world_.AddObstacle(box, nullptr));
  auto hit = world_.CastRay(Vector3d(2, 3, 0.5), Vector3d(9, 3, 0.5));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 1.5, 1e-3);
  const auto oct = world_.CastRayOctomap(Vector3d(2, 3, 0.5), Vector3d(1, 0, 0), 9);
  ASSERT_TRUE(oct);
  EXPECT_NEAR(*oct, 1.5, 0.15);  // within a voxel or so
  std::string error;
  EXPECT_FALSE(world_.AddObstacle(box, &error));  // id taken
  ASSERT_TRUE(world_.RemoveObstacle("box", nullptr));
  hit = world_.CastRay(Vector3d(2, 3, 0.5), Vector3d(12, 3, 0.5));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 7.975, 1e-3);  // the door leaf again
  EXPECT_FALSE(world_.RemoveObstacle("box", &error));
  EXPECT_FALSE(world_.RemoveObstacle("wall_1", &error));  // walls are not obstacles
}

TEST_F(SimWorldTest, ObstacleWithBadSizeIsRefused) {
  Solid box;
  box.id = "bad";
  box.size_x = NAN;
  box.size_y = 1;
  box.height = 1;
  std::string error;
  EXPECT_FALSE(world_.AddObstacle(box, &error));
  EXPECT_FALSE(error.empty());
}

TEST_F(SimWorldTest, LowObjectsLetHigherRaysPass) {
  // The crate is 0.5 m tall: a ray at 0.3 m hits it, one at 0.7 m passes over.
  auto low = world_.CastRay(Vector3d(7, 3, 0.3), Vector3d(7, -1, 0.3));
  ASSERT_TRUE(low);
  EXPECT_NEAR(low->distance, 1.75, 1e-3);
  auto high = world_.CastRay(Vector3d(7, 3, 0.7), Vector3d(7, -1, 0.7));
  ASSERT_TRUE(high);
  EXPECT_NEAR(high->distance, 2.95, 1e-3);
}

TEST_F(SimWorldTest, CylinderCollisionAndContactDirections) {
  // A 0.25 m robot at (9.6, 4.5): 0.1 m from the west face of the x = 10 wall (9.95 - 0.25).
  EXPECT_FALSE(world_.CylinderCollides(9.6, 4.5, 0.25, 0.5, nullptr));
  EXPECT_TRUE(world_.CylinderCollides(9.8, 4.5, 0.25, 0.5, nullptr));
  EXPECT_TRUE(world_.ContactAngles(9.6, 4.5, 0.25, 0.5, 0.01, nullptr).empty());
  const auto angles = world_.ContactAngles(9.695, 4.5, 0.25, 0.5, 0.01, nullptr);
  ASSERT_FALSE(angles.empty());
  for (double a : angles) EXPECT_NEAR(a, 0.0, 0.05);  // the wall is due east
}

TEST_F(SimWorldTest, InsideMapAndSolidAt) {
  EXPECT_TRUE(world_.InsideMap(5, 3));
  EXPECT_FALSE(world_.InsideMap(-1, 3));
  EXPECT_EQ(world_.SolidAt(7, 1, 0.2, 0.5, nullptr), "crate");
  EXPECT_EQ(world_.SolidAt(5, 3, 0.2, 0.5, nullptr), "");
}

TEST_F(SimWorldTest, OctomapIsWrittenAsBt) {
  const std::string path = ::testing::TempDir() + "/robot_sim_test.bt";
  ASSERT_TRUE(world_.WriteOctomap(path));
  octomap::OcTree loaded(path);
  EXPECT_EQ(loaded.size(), world_.octree().size());
  std::remove(path.c_str());
  EXPECT_FALSE(world_.OccupiedLeaves().empty());
}

TEST(SimWorldParametersTest, EveryViolationIsNamed) {
  SimWorldParameters p;
  p.wall_height_m = -1;
  p.octomap_resolution_m = 0;
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find("wall_height_m"), std::string::npos);
  EXPECT_NE(errors[1].find("octomap_resolution_m"), std::string::npos);
}

}  // namespace
}  // namespace robot_sim
