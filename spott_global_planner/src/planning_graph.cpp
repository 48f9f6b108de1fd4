#include "spott_global_planner/planning_graph.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace spott_global_planner {

using spott_map::Vec2;

PlanningGraph::PlanningGraph(RoomDoorGraph graph) : graph_(std::move(graph)) {
  const auto& rooms = graph_.rooms();
  const auto& doors = graph_.doors();
  room_index_.reserve(rooms.size());
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    room_index_.emplace(rooms[i].id, static_cast<int>(i));
    room_centre_.push_back(spott_map::Centroid(rooms[i].polygon));
  }
  door_index_.reserve(doors.size());
  door_rooms_.reserve(doors.size());
  passable_.reserve(doors.size());
  std::vector<int> degree(rooms.size() + 1, 0);
  for (std::size_t i = 0; i < doors.size(); ++i) {
    door_index_.emplace(doors[i].id, static_cast<int>(i));
    // RoomDoorGraph already refused doors naming unknown rooms.
    const int a = room_index_.at(doors[i].room_a);
    const int b = room_index_.at(doors[i].room_b);
    door_rooms_.emplace_back(a, b);
    passable_.push_back(RoomDoorGraph::Passable(doors[i]) ? 1 : 0);
    ++degree[a];
    ++degree[b];
  }
  arc_start_.assign(rooms.size() + 1, 0);
  for (std::size_t r = 0; r < rooms.size(); ++r) arc_start_[r + 1] = arc_start_[r] + degree[r];
  arcs_.resize(static_cast<std::size_t>(arc_start_.back()));
  std::vector<int> fill(arc_start_.begin(), arc_start_.end() - 1);
  for (std::size_t i = 0; i < doors.size(); ++i) {
    const auto [a, b] = door_rooms_[i];
    const Vec2& d = doors[i].center;
    const double cost = (room_centre_[a] - d).norm() + (d - room_centre_[b]).norm();
    const int state = 2 * static_cast<int>(i);
    arcs_[fill[a]++] = Arc{state + 1, b, cost};  // into room_b
    arcs_[fill[b]++] = Arc{state, a, cost};      // into room_a
  }
  blocked_of_room_.assign(rooms.size(), {});
  room_blocks_.assign(rooms.size(), 0);
  BuildLocator();
}

std::optional<int> PlanningGraph::FindRoom(const std::string& id) const {
  auto it = room_index_.find(id);
  if (it == room_index_.end()) return std::nullopt;
  return it->second;
}

std::optional<int> PlanningGraph::FindDoor(const std::string& id) const {
  auto it = door_index_.find(id);
  if (it == door_index_.end()) return std::nullopt;
  return it->second;
}

void PlanningGraph::BuildLocator() {
  const auto& rooms = graph_.rooms();
  grid_nx_ = grid_ny_ = 0;
  grid_start_.clear();
  grid_rooms_.clear();
  if (rooms.empty()) return;
  std::vector<spott_map::Box> boxes;
  boxes.reserve(rooms.size());
  spott_map::Box all = spott_map::BoundingBox(rooms.front().polygon);
  double area = 0.0;
  for (const Room& r : rooms) {
    boxes.push_back(spott_map::BoundingBox(r.polygon));
    all.min = all.min.cwiseMin(boxes.back().min);
    all.max = all.max.cwiseMax(boxes.back().max);
    area += (boxes.back().max - boxes.back().min).prod();
  }
  // About one room box per cell, and at most ~4 cells per room overall.
  const Vec2 extent = (all.max - all.min).cwiseMax(Vec2(1e-6, 1e-6));
  grid_cell_ = std::sqrt(std::max(area / static_cast<double>(rooms.size()), 1e-12));
  const double max_cells = 4.0 * static_cast<double>(rooms.size()) + 16.0;
  while ((extent.x() / grid_cell_ + 1.0) * (extent.y() / grid_cell_ + 1.0) > max_cells) {
    grid_cell_ *= 1.5;
  }
  grid_origin_ = all.min;
  grid_nx_ = static_cast<int>(std::floor(extent.x() / grid_cell_)) + 1;
  grid_ny_ = static_cast<int>(std::floor(extent.y() / grid_cell_)) + 1;
  const auto cell_range = [this](const spott_map::Box& b) {
    const int x0 =
        std::clamp(static_cast<int>((b.min.x() - grid_origin_.x()) / grid_cell_), 0, grid_nx_ - 1);
    const int x1 =
        std::clamp(static_cast<int>((b.max.x() - grid_origin_.x()) / grid_cell_), 0, grid_nx_ - 1);
    const int y0 =
        std::clamp(static_cast<int>((b.min.y() - grid_origin_.y()) / grid_cell_), 0, grid_ny_ - 1);
    const int y1 =
        std::clamp(static_cast<int>((b.max.y() - grid_origin_.y()) / grid_cell_), 0, grid_ny_ - 1);
    return std::array<int, 4>{x0, x1, y0, y1};
  };
  const std::size_t ncells = static_cast<std::size_t>(grid_nx_) * grid_ny_;
  std::vector<int> count(ncells + 1, 0);
  for (const auto& b : boxes) {
    const auto [x0, x1, y0, y1] = cell_range(b);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) ++count[static_cast<std::size_t>(y) * grid_nx_ + x + 1];
    }
  }
  for (std::size_t i = 0; i < ncells; ++i) count[i + 1] += count[i];
  grid_start_ = count;
  grid_rooms_.resize(static_cast<std::size_t>(count.back()));
  for (std::size_t r = 0; r < boxes.size(); ++r) {
    const auto [x0, x1, y0, y1] = cell_range(boxes[r]);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        grid_rooms_[count[static_cast<std::size_t>(y) * grid_nx_ + x]++] = static_cast<int>(r);
      }
    }
  }
}

int PlanningGraph::RoomContaining(const Vec2& p) const {
  if (grid_nx_ == 0 || !p.allFinite()) return -1;
  const double fx = (p.x() - grid_origin_.x()) / grid_cell_;
  const double fy = (p.y() - grid_origin_.y()) / grid_cell_;
  // A point on the far edge of the rooms' box still belongs to the last cell.
  const double eps = 1e-9;
  if (fx < -eps || fy < -eps || fx > grid_nx_ + eps || fy > grid_ny_ + eps) return -1;
  const int x = std::clamp(static_cast<int>(fx), 0, grid_nx_ - 1);
  const int y = std::clamp(static_cast<int>(fy), 0, grid_ny_ - 1);
  const std::size_t cell = static_cast<std::size_t>(y) * grid_nx_ + x;
  for (int k = grid_start_[cell]; k < grid_start_[cell + 1]; ++k) {
    const int r = grid_rooms_[k];  // rooms in graph order: the first listed wins
    if (spott_map::PointInPolygon(p, room(r).polygon, 1e-9)) return r;
  }
  return -1;
}

bool PlanningGraph::SetDoorState(const std::string& door_id, DoorState state) {
  const auto d = FindDoor(door_id);
  if (!d || !graph_.SetDoorState(door_id, state)) return false;
  passable_[*d] = RoomDoorGraph::Passable(door(*d)) ? 1 : 0;
  return true;
}

std::vector<std::string> PlanningGraph::ClosedDoors() const {
  std::vector<std::string> ids;
  for (int d = 0; d < door_count(); ++d) {
    if (!DoorPassable(d)) ids.push_back(door(d).id);
  }
  return ids;
}

std::uint64_t PlanningGraph::PairKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

void PlanningGraph::SetBlockedPassages(int room, const std::vector<std::pair<int, int>>& pairs) {
  if (room < 0 || room >= room_count()) throw std::out_of_range("SetBlockedPassages: bad room");
  std::vector<std::uint64_t> keys;
  for (const auto& [a, b] : pairs) {
    if (a < 0 || b < 0 || a >= door_count() || b >= door_count()) {
      throw std::out_of_range("SetBlockedPassages: bad door index");
    }
    keys.push_back(PairKey(a, b));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  room_blocks_[room] = keys.empty() ? 0 : 1;
  blocked_of_room_[room] = std::move(keys);
}

bool PlanningGraph::PassageBlocked(int room, int door_a, int door_b) const {
  const auto& keys = blocked_of_room_[room];
  return !keys.empty() && std::binary_search(keys.begin(), keys.end(), PairKey(door_a, door_b));
}

std::vector<BlockedPassage> PlanningGraph::BlockedPassagesOf(int r) const {
  std::vector<BlockedPassage> out;
  for (std::uint64_t key : blocked_of_room_[r]) {
    const int a = static_cast<int>(key >> 32);
    const int b = static_cast<int>(key & 0xffffffffu);
    out.push_back(BlockedPassage{room(r).id, door(a).id, door(b).id});
  }
  return out;
}

std::vector<BlockedPassage> PlanningGraph::BlockedPassages() const {
  std::vector<BlockedPassage> out;
  for (int r = 0; r < room_count(); ++r) {
    for (auto& p : BlockedPassagesOf(r)) out.push_back(std::move(p));
  }
  return out;
}

}  // namespace spott_global_planner
