#include "robot_sim/sim_world.h"

#include <btBulletCollisionCommon.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "spott_map/geometry.h"
#include "spott_map/world_loader.h"

namespace robot_sim {

namespace {

// Bullet's default collision margin (4 cm) rounds box corners; the sensors need the faces.
constexpr btScalar kMargin = 0.001;

btTransform PoseTransform(const spott_map::Pose2& pose, double z) {
  return btTransform(btQuaternion(btVector3(0, 0, 1), pose.yaw), btVector3(pose.x, pose.y, z));
}

std::unique_ptr<btCollisionShape> ShapeOf(const Solid& s) {
  std::unique_ptr<btCollisionShape> shape;
  if (s.cylinder) {
    shape = std::make_unique<btCylinderShapeZ>(btVector3(s.size_x / 2, s.size_x / 2, s.height / 2));
  } else {
    shape = std::make_unique<btBoxShape>(btVector3(s.size_x / 2, s.size_y / 2, s.height / 2));
  }
  shape->setMargin(kMargin);
  return shape;
}

bool Finite(double v) { return std::isfinite(v); }

struct RayIgnoring : btCollisionWorld::ClosestRayResultCallback {
  RayIgnoring(const btVector3& from, const btVector3& to, const btCollisionObject* ignore)
      : ClosestRayResultCallback(from, to), ignore_(ignore) {}
  bool needsCollision(btBroadphaseProxy* proxy) const override {
    if (proxy->m_clientObject == ignore_) return false;
    return ClosestRayResultCallback::needsCollision(proxy);
  }
  const btCollisionObject* ignore_;
};

// Every solid is an upright extrusion standing on the floor (z from 0 to its height): a box or a
// vertical cylinder. Rays and robot footprints against such solids have closed forms, which are
// several times faster than Bullet's general convex casts (bench/real_time_bench.cpp); Bullet's
// broadphase (a dynamic AABB tree) still picks the candidates.

// Ray o + t d (t in [0, t_max]) against a solid; the entry distance and outward normal.
bool IntersectSolid(const Solid& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                    double t_max, double* t_hit, Eigen::Vector3d* normal) {
  const double c = std::cos(s.pose.yaw), sn = std::sin(s.pose.yaw);
  // Into the solid's frame, origin at the centre of its footprint on the floor.
  const double ox = c * (o.x() - s.pose.x) + sn * (o.y() - s.pose.y);
  const double oy = -sn * (o.x() - s.pose.x) + c * (o.y() - s.pose.y);
  const double dx = c * d.x() + sn * d.y(), dy = -sn * d.x() + c * d.y();
  double t_near = -std::numeric_limits<double>::infinity();
  double t_far = std::numeric_limits<double>::infinity();
  int axis = -1;  // 0: x, 1: y, 2: z, 3: cylinder side
  double side_sign = 0;
  auto slab = [&](double origin, double dir, double lo, double hi, int which) {
    if (std::abs(dir) < 1e-15) return origin >= lo && origin <= hi;
    double t0 = (lo - origin) / dir, t1 = (hi - origin) / dir;
    double sign = -1;
    if (t0 > t1) {
      std::swap(t0, t1);
      sign = 1;
    }
    if (t0 > t_near) {
      t_near = t0;
      axis = which;
      side_sign = sign;
    }
    t_far = std::min(t_far, t1);
    return t_near <= t_far;
  };
  if (!slab(o.z(), d.z(), 0.0, s.height, 2)) return false;
  if (s.cylinder) {
    const double r = s.size_x / 2;
    const double a = dx * dx + dy * dy, b = ox * dx + oy * dy, k = ox * ox + oy * oy - r * r;
    if (a < 1e-15) {
      if (k > 0) return false;
    } else {
      const double disc = b * b - a * k;
      if (disc < 0) return false;
      const double root = std::sqrt(disc);
      const double t0 = (-b - root) / a, t1 = (-b + root) / a;
      if (t0 > t_near) {
        t_near = t0;
        axis = 3;
      }
      t_far = std::min(t_far, t1);
    }
  } else {
    if (!slab(ox, dx, -s.size_x / 2, s.size_x / 2, 0)) return false;
    if (!slab(oy, dy, -s.size_y / 2, s.size_y / 2, 1)) return false;
  }
  // A ray that starts inside a solid does not see it (a mount buried in an obstacle).
  if (t_near > t_far || t_near < 0 || t_near > t_max) return false;
  *t_hit = t_near;
  Eigen::Vector3d n_local;
  if (axis == 3) {
    n_local = Eigen::Vector3d(ox + t_near * dx, oy + t_near * dy, 0).normalized();
  } else {
    n_local = Eigen::Vector3d::Zero();
    n_local[axis] = side_sign;
  }
  *normal = Eigen::Vector3d(c * n_local.x() - sn * n_local.y(), sn * n_local.x() + c * n_local.y(),
                            n_local.z());
  return true;
}

// Closest point of a solid's footprint to (x, y) in the plane, and the distance (0 inside).
double FootprintDistance(const Solid& s, double x, double y, Eigen::Vector2d* closest) {
  if (s.cylinder) {
    const Eigen::Vector2d v(x - s.pose.x, y - s.pose.y);
    const double r = s.size_x / 2, n = v.norm();
    *closest = Eigen::Vector2d(s.pose.x, s.pose.y) + (n > 1e-12 ? v / n * std::min(r, n) : v);
    return std::max(0.0, n - r);
  }
  const double c = std::cos(s.pose.yaw), sn = std::sin(s.pose.yaw);
  const double lx = c * (x - s.pose.x) + sn * (y - s.pose.y);
  const double ly = -sn * (x - s.pose.x) + c * (y - s.pose.y);
  const double qx = std::clamp(lx, -s.size_x / 2, s.size_x / 2);
  const double qy = std::clamp(ly, -s.size_y / 2, s.size_y / 2);
  *closest = Eigen::Vector2d(s.pose.x + c * qx - sn * qy, s.pose.y + sn * qx + c * qy);
  return std::hypot(lx - qx, ly - qy);
}

struct AnalyticRay : btBroadphaseRayCallback {
  bool process(const btBroadphaseProxy* proxy) override {
    const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    if (object == ignore) return true;
    const auto* solid = static_cast<const Solid*>(object->getUserPointer());
    double t;
    Eigen::Vector3d n;
    if (solid && IntersectSolid(*solid, origin, dir, best_t, &t, &n) && t < best_t) {
      best_t = t;
      best_normal = n;
      best_object = object;
    }
    return true;
  }
  Eigen::Vector3d origin, dir;
  const btCollisionObject* ignore = nullptr;
  double best_t = 0.0;
  Eigen::Vector3d best_normal;
  const btCollisionObject* best_object = nullptr;
};

// Solids whose footprint comes within `reach` of a circle of `radius` at (x, y).
struct FootprintQuery : btBroadphaseAabbCallback {
  bool process(const btBroadphaseProxy* proxy) override {
    const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    if (object == ignore) return true;
    const auto* solid = static_cast<const Solid*>(object->getUserPointer());
    if (!solid) return true;
    Eigen::Vector2d closest;
    const double d = FootprintDistance(*solid, x, y, &closest);
    if (d - radius < reach) found.push_back({solid, d - radius, closest});
    return true;
  }
  struct Found {
    const Solid* solid;
    double gap;  // < 0: penetration depth
    Eigen::Vector2d closest;
  };
  double x = 0, y = 0, radius = 0, reach = 0;
  const btCollisionObject* ignore = nullptr;
  std::vector<Found> found;
};

}  // namespace

std::vector<std::string> ValidateParameters(const SimWorldParameters& p) {
  std::vector<std::string> errors;
  if (!(p.wall_height_m > 0 && p.wall_height_m <= 10)) {
    errors.push_back("wall_height_m must be in (0, 10] m");
  }
  if (!(p.door_leaf_thickness_m > 0) || !(p.door_leaf_thickness_m < 1)) {
    errors.push_back("door_leaf_thickness_m must be in (0, 1) m");
  }
  // OctoMap's tree has 16 levels: it reaches 32768 voxels from the origin (327 m at 0.01 m), and
  // Voxelize steps through every voxel of a solid: a finer tree drops a building's far parts and
  // its loops barely advance (not at all below 1e-13 m).
  if (!(p.octomap_resolution_m >= 0.01 && p.octomap_resolution_m <= 1)) {
    errors.push_back("octomap_resolution_m must be in [0.01, 1] m");
  }
  return errors;
}

SimWorld::SimWorld(const SimWorldParameters& params) : params_(params) {
  config_ = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
  broadphase_ = std::make_unique<btDbvtBroadphase>();
  world_ = std::make_unique<btCollisionWorld>(dispatcher_.get(), broadphase_.get(), config_.get());
  octree_ = std::make_unique<octomap::OcTree>(params_.octomap_resolution_m);
}

SimWorld::~SimWorld() {
  for (auto& [id, entry] : solids_) world_->removeCollisionObject(entry.object.get());
}

void SimWorld::ClearAll() {
  for (auto it = solids_.begin(); it != solids_.end();) {
    if (it->second.solid.kind == Solid::Kind::kRobot) {
      ++it;
      continue;
    }
    world_->removeCollisionObject(it->second.object.get());
    it = solids_.erase(it);
  }
  octree_->clear();
  doors_.clear();
  rooms_.clear();
}

void SimWorld::Build(const spott_map::World& world) {
  ClearAll();
  for (const spott_map::Wall& wall : world.walls) {
    const spott_map::Vec2 d = wall.segment.b - wall.segment.a;
    if (d.norm() < 1e-6) continue;
    Solid s;
    s.kind = Solid::Kind::kWall;
    s.id = wall.id;
    const spott_map::Vec2 mid = wall.segment.Midpoint();
    s.pose = {mid.x(), mid.y(), std::atan2(d.y(), d.x())};
    s.size_x = d.norm();
    s.size_y = wall.thickness;
    s.height = params_.wall_height_m;
    Insert(s);
  }
  for (const spott_map::Door& door : world.doors) {
    if (door.kind != spott_map::DoorKind::kDoor) continue;
    doors_[door.id] = door;
    const bool closed =
        door.state == spott_map::DoorState::kClosed ||
        (door.state == spott_map::DoorState::kUnknown && params_.unknown_doors_closed);
    if (closed) SetDoorClosed(door.id, true, nullptr);
  }
  for (const spott_map::WorldObject& object : world.objects) {
    Solid s;
    s.kind = Solid::Kind::kObject;
    s.id = object.id;
    s.cylinder = object.kind == spott_map::ObjectKind::kCylinder;
    s.pose = object.pose;
    s.size_x = object.size_x;
    s.size_y = s.cylinder ? object.size_x : object.size_y;
    s.height = object.height;
    Insert(s);
  }
  for (const spott_map::Room& room : world.rooms) rooms_.push_back(room.polygon);
  octree_->updateInnerOccupancy();
  ++revision_;
}

SimWorld::Entry* SimWorld::Insert(const Solid& solid) {
  if (solids_.count(solid.id)) return nullptr;
  Entry entry;
  entry.solid = solid;
  entry.shape = ShapeOf(solid);
  entry.object = std::make_unique<btCollisionObject>();
  entry.object->setCollisionShape(entry.shape.get());
  entry.object->setWorldTransform(PoseTransform(solid.pose, solid.height / 2));
  world_->addCollisionObject(entry.object.get());
  auto [it, inserted] = solids_.emplace(solid.id, std::move(entry));
  if (!inserted) return nullptr;
  it->second.object->setUserPointer(&it->second.solid);
  if (solid.kind != Solid::Kind::kRobot) Voxelize(solid, true);
  return &it->second;
}

void SimWorld::Erase(const std::string& id) {
  auto it = solids_.find(id);
  if (it == solids_.end()) return;
  const Solid removed = it->second.solid;
  world_->removeCollisionObject(it->second.object.get());
  solids_.erase(it);
  Voxelize(removed, false);
  // Voxels shared with a neighbour (a wall the obstacle touched) belong to it again.
  const double reach =
      std::hypot(removed.size_x, removed.size_y) / 2 + 2 * params_.octomap_resolution_m;
  for (const auto& [other_id, entry] : solids_) {
    const Solid& o = entry.solid;
    if (o.kind == Solid::Kind::kRobot) continue;
    const double o_reach = std::hypot(o.size_x, o.size_y) / 2;
    if (std::hypot(o.pose.x - removed.pose.x, o.pose.y - removed.pose.y) < reach + o_reach) {
      Voxelize(o, true);
    }
  }
  octree_->updateInnerOccupancy();
}

void SimWorld::Voxelize(const Solid& s, bool occupied) {
  const double res = params_.octomap_resolution_m;
  const double c = std::cos(s.pose.yaw), sn = std::sin(s.pose.yaw);
  const double hx = s.size_x / 2, hy = s.size_y / 2;
  const double ex = std::abs(c) * hx + std::abs(sn) * hy;  // half extents of the AABB
  const double ey = std::abs(sn) * hx + std::abs(c) * hy;
  // A removed solid leaves known free space (octomap's deleteNode asserts on some trees).
  const float value =
      occupied ? octree_->getClampingThresMaxLog() : octree_->getClampingThresMinLog();
  // Voxel centres are at (k + 0.5) * res.
  // Every voxel that overlaps the solid is occupied.
  for (double x = (std::floor((s.pose.x - ex) / res) + 0.5) * res; x <= s.pose.x + ex + res / 2;
       x += res) {
    for (double y = (std::floor((s.pose.y - ey) / res) + 0.5) * res; y <= s.pose.y + ey + res / 2;
         y += res) {
      const double dx = x - s.pose.x, dy = y - s.pose.y;
      const double lx = c * dx + sn * dy, ly = -sn * dx + c * dy;  // in the solid's frame
      const bool inside = s.cylinder
                              ? std::hypot(lx, ly) <= hx + 0.5 * res
                              : std::abs(lx) <= hx + 0.5 * res && std::abs(ly) <= hy + 0.5 * res;
      if (!inside) continue;
      for (double z = 0.5 * res; z < s.height; z += res) {
        octomap::OcTreeKey key;
        if (!octree_->coordToKeyChecked(x, y, z, key)) continue;
        octree_->setNodeValue(key, value, true);
      }
    }
  }
}

bool SimWorld::HasDoor(const std::string& door_id) const { return doors_.count(door_id) > 0; }

std::optional<bool> SimWorld::DoorClosed(const std::string& door_id) const {
  if (!HasDoor(door_id)) return std::nullopt;
  return solids_.count("door:" + door_id) > 0;
}

bool SimWorld::SetDoorClosed(const std::string& door_id, bool closed, std::string* error) {
  auto it = doors_.find(door_id);
  if (it == doors_.end()) {
    if (error) *error = "no door '" + door_id + "' with a leaf in this world";
    return false;
  }
  const std::string leaf_id = "door:" + door_id;
  const bool is_closed = solids_.count(leaf_id) > 0;
  if (closed == is_closed) return true;
  if (closed) {
    const spott_map::Segment& o = it->second.opening;
    const spott_map::Vec2 d = o.b - o.a, mid = o.Midpoint();
    Solid s;
    s.kind = Solid::Kind::kDoorLeaf;
    s.id = leaf_id;
    s.pose = {mid.x(), mid.y(), std::atan2(d.y(), d.x())};
    s.size_x = std::max(d.norm(), 0.01);
    s.size_y = params_.door_leaf_thickness_m;
    s.height = params_.wall_height_m;
    Insert(s);
    octree_->updateInnerOccupancy();
  } else {
    Erase(leaf_id);
  }
  ++revision_;
  return true;
}

bool SimWorld::AddObstacle(const Solid& solid, std::string* error) {
  if (solid.id.empty() || solids_.count(solid.id)) {
    if (error)
      *error = solid.id.empty() ? "obstacle id is empty" : "id '" + solid.id + "' is taken";
    return false;
  }
  const bool sizes_ok = solid.size_x > 0 && solid.size_x < 100 && solid.height > 0 &&
                        solid.height < 100 &&
                        (solid.cylinder || (solid.size_y > 0 && solid.size_y < 100));
  // Within a world file's bounds: an obstacle 1e185 m away sent the OctoMap insertion into an
  // endless loop (sim_requests_fuzz), and no indoor floor reaches that far.
  const double bound = spott_map::kWorldMaxCoordinate;
  const bool pose_ok =
      Finite(solid.pose.yaw) && std::abs(solid.pose.x) <= bound && std::abs(solid.pose.y) <= bound;
  if (!sizes_ok || !pose_ok) {
    if (error)
      *error = "obstacle '" + solid.id +
               "': sizes must be in (0, 100) m and the pose finite, x and y within " +
               std::to_string(static_cast<int>(bound)) + " m of the origin";
    return false;
  }
  Solid s = solid;
  s.kind = Solid::Kind::kObject;
  if (s.cylinder) s.size_y = s.size_x;
  Insert(s);
  octree_->updateInnerOccupancy();
  ++revision_;
  return true;
}

bool SimWorld::RemoveObstacle(const std::string& id, std::string* error) {
  auto it = solids_.find(id);
  if (it == solids_.end() || it->second.solid.kind != Solid::Kind::kObject) {
    if (error) *error = "no obstacle '" + id + "'";
    return false;
  }
  Erase(id);
  ++revision_;
  return true;
}

std::optional<RayHit> SimWorld::CastRay(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                        const btCollisionObject* ignore) const {
  const Eigen::Vector3d delta = to - from;
  const double length = delta.norm();
  if (!(length > 0)) return std::nullopt;
  AnalyticRay cb;
  cb.origin = from;
  cb.dir = delta / length;
  cb.ignore = ignore;
  cb.best_t = length;
  const btVector3 a(from.x(), from.y(), from.z()), b(to.x(), to.y(), to.z());
  const btVector3 dir(cb.dir.x(), cb.dir.y(), cb.dir.z());
  for (int i = 0; i < 3; ++i) {
    cb.m_rayDirectionInverse[i] = dir[i] == 0 ? BT_LARGE_FLOAT : 1 / dir[i];
    cb.m_signs[i] = cb.m_rayDirectionInverse[i] < 0.0;
  }
  cb.m_lambda_max = dir.dot(b - a);
  broadphase_->rayTest(a, b, cb);
  if (!cb.best_object) return std::nullopt;
  RayHit hit;
  hit.distance = cb.best_t;
  hit.point = from + cb.dir * cb.best_t;
  hit.normal = cb.best_normal;
  hit.object = cb.best_object;
  return hit;
}

std::optional<RayHit> SimWorld::CastRayBullet(const Eigen::Vector3d& from,
                                              const Eigen::Vector3d& to,
                                              const btCollisionObject* ignore) const {
  const btVector3 a(from.x(), from.y(), from.z()), b(to.x(), to.y(), to.z());
  RayIgnoring cb(a, b, ignore);
  world_->rayTest(a, b, cb);
  if (!cb.hasHit()) return std::nullopt;
  RayHit hit;
  hit.distance = cb.m_closestHitFraction * (to - from).norm();
  hit.point =
      Eigen::Vector3d(cb.m_hitPointWorld.x(), cb.m_hitPointWorld.y(), cb.m_hitPointWorld.z());
  Eigen::Vector3d n(cb.m_hitNormalWorld.x(), cb.m_hitNormalWorld.y(), cb.m_hitNormalWorld.z());
  if (n.norm() > 0) n.normalize();
  if (n.dot(to - from) > 0) n = -n;
  hit.normal = n;
  hit.object = cb.m_collisionObject;
  return hit;
}

std::optional<double> SimWorld::CastRayOctomap(const Eigen::Vector3d& from,
                                               const Eigen::Vector3d& dir, double max_range) const {
  octomap::point3d end;
  if (!octree_->castRay(octomap::point3d(from.x(), from.y(), from.z()),
                        octomap::point3d(dir.x(), dir.y(), dir.z()), end, true, max_range)) {
    return std::nullopt;
  }
  return (Eigen::Vector3d(end.x(), end.y(), end.z()) - from).norm();
}

std::vector<SimWorld::FootprintHit> SimWorld::QueryFootprint(
    double x, double y, double radius, double reach, const btCollisionObject* ignore) const {
  FootprintQuery q;
  q.x = x;
  q.y = y;
  q.radius = radius;
  q.reach = reach;
  q.ignore = ignore;
  const double r = radius + std::max(reach, 0.0) + 1e-3;
  broadphase_->aabbTest(btVector3(x - r, y - r, -1.0), btVector3(x + r, y + r, 1e3), q);
  std::vector<FootprintHit> hits;
  for (const auto& f : q.found) hits.push_back({f.solid->id, f.gap, f.closest});
  return hits;
}

bool SimWorld::CylinderCollides(double x, double y, double radius, double /*height*/,
                                const btCollisionObject* ignore, double slack) const {
  // Every solid and every robot stands on the floor, so heights always overlap.
  for (const auto& h : QueryFootprint(x, y, radius, -slack, ignore)) {
    if (h.gap < -slack) return true;
  }
  return false;
}

std::vector<double> SimWorld::ContactAngles(double x, double y, double radius, double /*height*/,
                                            double reach, const btCollisionObject* ignore) const {
  std::vector<double> angles;
  for (const auto& h : QueryFootprint(x, y, radius, reach, ignore)) {
    angles.push_back(std::atan2(h.closest.y() - y, h.closest.x() - x));
  }
  return angles;
}

btCollisionObject* SimWorld::AddRobotBody(const std::string& id, double radius, double height) {
  Solid s;
  s.kind = Solid::Kind::kRobot;
  s.id = "robot:" + id;
  s.cylinder = true;
  s.size_x = s.size_y = 2 * radius;
  s.height = height;
  Entry* e = Insert(s);
  return e ? e->object.get() : nullptr;
}

void SimWorld::MoveRobotBody(btCollisionObject* body, double x, double y, double yaw) {
  const btScalar half_height = static_cast<const btCylinderShapeZ*>(body->getCollisionShape())
                                   ->getHalfExtentsWithMargin()
                                   .z();
  body->setWorldTransform(PoseTransform({x, y, yaw}, half_height));
  static_cast<Solid*>(body->getUserPointer())->pose = {x, y, yaw};
  world_->updateSingleAabb(body);
}

bool SimWorld::InsideMap(double x, double y) const {
  for (const auto& polygon : rooms_) {
    if (spott_map::PointInPolygon(spott_map::Vec2(x, y), polygon, 1e-6)) return true;
  }
  return false;
}

std::string SimWorld::SolidAt(double x, double y, double radius, double /*height*/,
                              const btCollisionObject* ignore) const {
  for (const auto& h : QueryFootprint(x, y, radius, 0.0, ignore)) {
    if (h.gap < -1e-4) return h.id;
  }
  return "";
}

bool SimWorld::WriteOctomap(const std::string& path) const {
  return const_cast<octomap::OcTree&>(*octree_).writeBinary(path);
}

std::vector<VoxelLeaf> SimWorld::OccupiedLeaves() const {
  std::vector<VoxelLeaf> leaves;
  for (auto it = octree_->begin_leafs(), end = octree_->end_leafs(); it != end; ++it) {
    if (!octree_->isNodeOccupied(*it)) continue;
    const octomap::point3d c = it.getCoordinate();
    leaves.push_back({Eigen::Vector3d(c.x(), c.y(), c.z()), it.getSize()});
  }
  return leaves;
}

}  // namespace robot_sim
