// Fuzzes planning, blocked-passage analysis and goal projection on graphs built from bytes:
// up to 8 rooms (rectangles or triangles, coordinates on a 0.1 m lattice in [0, 25.5] m), up to
// 12 doors between any two of them with any state and opening, up to 3 obstacles, a robot, a
// goal and a window. Whatever the bytes, nothing may crash, and what comes back must hang
// together: a path's doors join its consecutive rooms, its cost is finite, a projection's
// border segment and point are finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "spott_global_planner/global_planner.h"
#include "spott_global_planner/goal_projection.h"
#include "spott_global_planner/passage_blocking.h"
#include "spott_global_planner/planning_session.h"

namespace {

class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t Next() { return pos_ < size_ ? data_[pos_++] : 0; }
  double Coord() { return Next() / 10.0; }
  bool Empty() const { return pos_ >= size_; }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

void Check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using spott_map::Vec2;
  Bytes in(data, size);
  std::vector<spott_map::Room> rooms;
  const int nrooms = 1 + in.Next() % 8;
  for (int i = 0; i < nrooms; ++i) {
    spott_map::Room r;
    r.id = "r" + std::to_string(i);
    const Vec2 a(in.Coord(), in.Coord());
    const Vec2 b(in.Coord(), in.Coord());
    if (in.Next() % 4 == 0) {
      r.polygon = {a, b, Vec2(in.Coord(), in.Coord())};
    } else {
      r.polygon = {a, Vec2(b.x(), a.y()), b, Vec2(a.x(), b.y())};
    }
    rooms.push_back(std::move(r));
  }
  std::vector<spott_map::Door> doors;
  const int ndoors = in.Next() % 13;
  for (int i = 0; i < ndoors; ++i) {
    spott_map::Door d;
    d.id = "d" + std::to_string(i);
    d.room_a = rooms[in.Next() % nrooms].id;
    d.room_b = rooms[in.Next() % nrooms].id;
    d.kind = in.Next() % 5 == 0 ? spott_map::DoorKind::kOpening : spott_map::DoorKind::kDoor;
    d.state = static_cast<spott_map::DoorState>(in.Next() % 3);
    d.center = Vec2(in.Coord(), in.Coord());
    d.opening = spott_map::Segment{d.center, Vec2(in.Coord(), in.Coord())};
    d.width = d.opening.Length();
    doors.push_back(std::move(d));
  }
  std::vector<spott_map::MapFeature> features;
  const int nfeatures = in.Next() % 4;
  for (int i = 0; i < nfeatures; ++i) {
    spott_map::MapFeature f;
    f.id = "f" + std::to_string(i);
    f.type = spott_map::FeatureType::kRectangle;
    f.pose = spott_map::Pose2{in.Coord(), in.Coord(), in.Next() / 40.0};
    f.size_x = in.Coord() / 4.0;
    f.size_y = in.Coord() / 4.0;
    features.push_back(std::move(f));
  }
  const Vec2 robot(in.Coord(), in.Coord());
  const Vec2 goal(in.Coord(), in.Coord());
  const double window_size = 0.2 + in.Coord() / 2.0;

  spott_global_planner::GlobalPlannerParameters params;
  params.algorithm = in.Next() % 2 ? spott_global_planner::SearchAlgorithm::kAStar
                                   : spott_global_planner::SearchAlgorithm::kDijkstra;
  params.window.window_size_m = window_size;
  params.window.recentre_margin_m = 0.0;
  params.window.fit_node = in.Next() % 2;
  params.window.max_window_size_m = 30.0;
  params.passage.resolution_m = 0.1;
  params.passage.max_cells = 20000;
  spott_global_planner::PlanningSession session(params);
  session.SetGraph(spott_map::RoomDoorGraph(rooms, doors));
  session.SetFeatures(features);
  if (session.SetGoal(goal).error != spott_global_planner::PlanError::kNone) return 0;
  const auto u = session.Update(robot);
  if (!u.path) return 0;
  const auto& path = *u.path;
  const auto& graph = session.planner().graph();
  Check(path.room_indices.size() == path.door_indices.size() + 1);
  Check(std::isfinite(path.cost) && path.cost >= 0.0);
  for (std::size_t i = 0; i < path.door_indices.size(); ++i) {
    const auto [a, b] = graph.DoorRooms(path.door_indices[i]);
    const int from = path.room_indices[i], to = path.room_indices[i + 1];
    Check((a == from && b == to) || (a == to && b == from));
    Check(graph.DoorPassable(path.door_indices[i]));
  }
  Check(u.projection.has_value());
  const auto& p = *u.projection;
  Check(p.border.a.allFinite() && p.border.b.allFinite() && p.projected_point.allFinite());
  return 0;
}
