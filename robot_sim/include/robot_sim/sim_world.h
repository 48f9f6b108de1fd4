// The simulated building: a Bullet collision world and an OctoMap of the same geometry, built
// from a spott_map world file (walls extruded to the wall height, closed door leaves, objects
// extruded to their heights). Opening or closing a door and adding or removing an obstacle
// update both. Map frame, metres (REP-103/105). Not thread-safe.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "spott_map/world.h"

class btCollisionObject;
class btCollisionShape;
class btCollisionWorld;
class btDefaultCollisionConfiguration;
class btCollisionDispatcher;
class btBroadphaseInterface;

namespace octomap {
class OcTree;
}

namespace robot_sim {

struct SimWorldParameters {
  double wall_height_m = 2.5;           ///< Walls and door leaves are this tall (m), (0, 10].
  double door_leaf_thickness_m = 0.05;  ///< A closed door's leaf (m), > 0.
  /// Voxel side (m), [0.01, 1]: the tree (16 levels) reaches 32768 voxels from the origin.
  double octomap_resolution_m = 0.05;
  /// How the simulator builds a door whose state the world file leaves unknown (the map
  /// database may not know it; the building always does).
  bool unknown_doors_closed = true;
};

/// Returns one message per violated parameter, naming it.
std::vector<std::string> ValidateParameters(const SimWorldParameters& p);

/// A solid in the world: an extruded box or cylinder standing on the floor.
struct Solid {
  enum class Kind { kWall, kDoorLeaf, kObject, kRobot };
  Kind kind = Kind::kObject;
  std::string id;
  bool cylinder = false;
  spott_map::Pose2 pose;  ///< Centre of the footprint and heading (map frame).
  double size_x = 0.0;    ///< Full extent along its x axis (m); cylinder: diameter.
  double size_y = 0.0;
  double height = 0.0;
};

/// The result of a ray cast. Rays are cast against Bullet's broadphase (a dynamic AABB tree
/// over the solids) with a closed-form narrow phase for the upright boxes and cylinders.
struct RayHit {
  double distance = 0.0;   ///< From the ray's origin (m).
  Eigen::Vector3d point;   ///< Map frame (m).
  Eigen::Vector3d normal;  ///< Unit surface normal at the hit, facing the ray.
  const btCollisionObject* object = nullptr;
};

/// An occupied OctoMap leaf: centre (map frame, m) and side (m).
struct VoxelLeaf {
  Eigen::Vector3d centre;
  double size = 0.0;
};

class SimWorld {
 public:
  explicit SimWorld(const SimWorldParameters& params);
  ~SimWorld();
  SimWorld(const SimWorld&) = delete;
  SimWorld& operator=(const SimWorld&) = delete;

  /// Builds walls, door leaves of closed doors, and objects. Replaces what was there (robots
  /// excepted).
  void Build(const spott_map::World& world);

  /// Opens or closes door `id`; false (and nothing changes) for an unknown door or an opening.
  bool SetDoorClosed(const std::string& door_id, bool closed, std::string* error);
  /// Adds an obstacle; false when the id is taken or the size is not positive and finite.
  bool AddObstacle(const Solid& solid, std::string* error);
  /// Removes an obstacle added at run time or listed in the world file.
  bool RemoveObstacle(const std::string& id, std::string* error);
  bool HasDoor(const std::string& door_id) const;
  std::optional<bool> DoorClosed(const std::string& door_id) const;

  /// Nearest hit along the segment from `from` to `to` (map frame), ignoring `ignore`.
  std::optional<RayHit> CastRay(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                const btCollisionObject* ignore = nullptr) const;
  /// The same question through Bullet's own ray test (GJK convex cast; for the benchmark).
  std::optional<RayHit> CastRayBullet(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                      const btCollisionObject* ignore = nullptr) const;
  /// The same question asked of the OctoMap (for the benchmark: which is faster here).
  std::optional<double> CastRayOctomap(const Eigen::Vector3d& from, const Eigen::Vector3d& dir,
                                       double max_range) const;

  /// True when a vertical cylinder of `radius` and `height` standing at (x, y) overlaps a solid
  /// other than `ignore` (penetration deeper than `slack`, m).
  bool CylinderCollides(double x, double y, double radius, double height,
                        const btCollisionObject* ignore, double slack = 1e-4) const;
  /// Contact directions (map-frame angles about +z from the cylinder's centre) of every solid
  /// within `reach` (m) of the cylinder's shell.
  std::vector<double> ContactAngles(double x, double y, double radius, double height, double reach,
                                    const btCollisionObject* ignore) const;

  /// A robot body (vertical cylinder) that other robots' rays and bodies see.
  btCollisionObject* AddRobotBody(const std::string& id, double radius, double height);
  void MoveRobotBody(btCollisionObject* body, double x, double y, double yaw);

  /// True when (x, y) lies inside a room or hallway of the world (inside the map).
  bool InsideMap(double x, double y) const;
  /// The id of a solid that a cylinder at (x, y) would overlap, or "" (for kidnap errors).
  std::string SolidAt(double x, double y, double radius, double height,
                      const btCollisionObject* ignore) const;

  const octomap::OcTree& octree() const { return *octree_; }
  /// Writes the OctoMap as a binary .bt file; false on an I/O error.
  bool WriteOctomap(const std::string& path) const;
  /// The occupied leaves (pruned leaves cover several voxels), for rviz.
  std::vector<VoxelLeaf> OccupiedLeaves() const;
  /// Incremented on every change of geometry (so nodes republish markers).
  int revision() const { return revision_; }
  std::size_t solid_count() const { return solids_.size(); }
  const SimWorldParameters& params() const { return params_; }

 private:
  struct Entry {
    Solid solid;
    std::unique_ptr<btCollisionShape> shape;
    std::unique_ptr<btCollisionObject> object;
  };
  struct FootprintHit {
    std::string id;
    double gap;               ///< Distance from the circle to the footprint (< 0: overlap).
    Eigen::Vector2d closest;  ///< Closest point of the footprint (map frame).
  };
  /// Solids whose footprint comes within `reach` of the circle (broadphase + closed form).
  std::vector<FootprintHit> QueryFootprint(double x, double y, double radius, double reach,
                                           const btCollisionObject* ignore) const;
  Entry* Insert(const Solid& solid);
  void Erase(const std::string& id);
  void Voxelize(const Solid& solid, bool occupied);
  void ClearAll();

  SimWorldParameters params_;
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btCollisionWorld> world_;
  std::unique_ptr<octomap::OcTree> octree_;
  std::map<std::string, Entry> solids_;           ///< By id (walls, leaves "door:<id>", objects).
  std::map<std::string, spott_map::Door> doors_;  ///< Doors with a leaf, by id.
  std::vector<spott_map::Polygon> rooms_;
  int revision_ = 0;
};

}  // namespace robot_sim
