#include "spott_global_planner/synthetic_building.h"

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace spott_global_planner {

using spott_map::Door;
using spott_map::Room;
using spott_map::Vec2;

namespace {

// Union-find over room indices, for the spanning tree.
struct Sets {
  std::vector<int> parent;
  explicit Sets(int n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int Find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool Join(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

}  // namespace

spott_map::RoomDoorGraph MakeSyntheticBuilding(const SyntheticBuildingParameters& p) {
  if (p.rows < 1 || p.cols < 1 || !(p.room_size_m > p.door_width_m) || !(p.door_width_m > 0.0)) {
    throw std::invalid_argument("MakeSyntheticBuilding: bad parameters");
  }
  const double s = p.room_size_m;
  const auto id = [&](int r, int c) { return "r" + std::to_string(r) + "_" + std::to_string(c); };
  std::vector<Room> rooms;
  rooms.reserve(static_cast<std::size_t>(p.rows) * p.cols);
  for (int r = 0; r < p.rows; ++r) {
    for (int c = 0; c < p.cols; ++c) {
      Room room;
      room.id = id(r, c);
      room.kind = spott_map::RoomKind::kRoom;
      room.polygon = {Vec2(c * s, r * s), Vec2((c + 1) * s, r * s), Vec2((c + 1) * s, (r + 1) * s),
                      Vec2(c * s, (r + 1) * s)};
      rooms.push_back(std::move(room));
    }
  }
  // Every neighbour pair, shuffled; Kruskal on random order gives a random spanning tree.
  struct Pair {
    int a, b;
    bool horizontal;  // a is left of b (else a is below b)
  };
  std::vector<Pair> pairs;
  for (int r = 0; r < p.rows; ++r) {
    for (int c = 0; c < p.cols; ++c) {
      const int i = r * p.cols + c;
      if (c + 1 < p.cols) pairs.push_back({i, i + 1, true});
      if (r + 1 < p.rows) pairs.push_back({i, i + p.cols, false});
    }
  }
  std::mt19937_64 rng(p.seed);
  std::shuffle(pairs.begin(), pairs.end(), rng);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Sets sets(p.rows * p.cols);
  std::vector<Door> doors;
  for (const Pair& pr : pairs) {
    const bool tree = sets.Join(pr.a, pr.b);
    if (!tree && unit(rng) >= p.extra_door_share) continue;
    const int ra = pr.a / p.cols, ca = pr.a % p.cols;
    Door d;
    d.id = "d" + std::to_string(doors.size());
    d.room_a = rooms[pr.a].id;
    d.room_b = rooms[pr.b].id;
    d.width = p.door_width_m;
    const double half = 0.5 * p.door_width_m;
    if (pr.horizontal) {
      const double x = (ca + 1) * s;
      const double y = (ra + 0.5) * s;
      d.center = Vec2(x, y);
      d.opening = spott_map::Segment{Vec2(x, y - half), Vec2(x, y + half)};
    } else {
      const double x = (ca + 0.5) * s;
      const double y = (ra + 1) * s;
      d.center = Vec2(x, y);
      d.opening = spott_map::Segment{Vec2(x - half, y), Vec2(x + half, y)};
    }
    doors.push_back(std::move(d));
  }
  return spott_map::RoomDoorGraph(std::move(rooms), std::move(doors));
}

}  // namespace spott_global_planner
