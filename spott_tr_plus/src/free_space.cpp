#include "free_space.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "spott_map/local_map.h"

namespace spott_tr_plus {
namespace internal {

namespace {

// A closed door's leaf drawn across its opening, as the local map draws it.
constexpr double kDoorThicknessM = 0.05;

spott_map::OccupancyRaster RasterOver(const spott_map::MapDatabase& db, double padding_m,
                                      double resolution_m, std::size_t max_cells) {
  spott_map::Box box{{0, 0}, {0, 0}};
  bool first = true;
  for (const spott_map::Room& r : db.graph().rooms()) {
    if (r.polygon.empty()) continue;
    const spott_map::Box b = spott_map::BoundingBox(r.polygon);
    if (first) {
      box = b;
      first = false;
    } else {
      box.min = box.min.cwiseMin(b.min);
      box.max = box.max.cwiseMax(b.max);
    }
  }
  box = box.Inflated(padding_m + 2 * resolution_m);
  double res = resolution_m;
  auto cells = [&](double r) {
    return std::make_pair(static_cast<int>(std::ceil((box.max.x() - box.min.x()) / r)),
                          static_cast<int>(std::ceil((box.max.y() - box.min.y()) / r)));
  };
  while (static_cast<double>(cells(res).first) * cells(res).second > static_cast<double>(max_cells))
    res *= 2;
  const auto [w, h] = cells(res);
  return spott_map::OccupancyRaster(box.min, std::max(w, 1), std::max(h, 1), res);
}

}  // namespace

FreeSpace::FreeSpace(const spott_map::MapDatabase& db, double padding_m, double resolution_m,
                     std::size_t max_cells)
    : db_(db),
      padding_m_(std::max(padding_m, 0.0)),
      raster_(RasterOver(db, padding_m_, resolution_m, max_cells)) {
  spott_map::RasterizeDatabase(db, padding_m_, kDoorThicknessM, raster_);
  const int w = raster_.width(), h = raster_.height();
  room_.assign(static_cast<std::size_t>(w) * h, -1);
  const auto& rooms = db.graph().rooms();
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    if (rooms[i].polygon.size() < 3) continue;
    const spott_map::Box b = spott_map::BoundingBox(rooms[i].polygon);
    const auto lo = raster_.CellOf(b.min.cwiseMax(raster_.origin()));
    const auto hi =
        raster_.CellOf(b.max.cwiseMin(raster_.Bounds().max - spott_map::Vec2(1e-9, 1e-9)));
    if (!lo || !hi) continue;
    for (int iy = lo->second; iy <= hi->second; ++iy) {
      for (int ix = lo->first; ix <= hi->first; ++ix) {
        int& slot = room_[static_cast<std::size_t>(iy) * w + ix];
        if (slot < 0 && spott_map::PointInPolygon(raster_.CellCentre(ix, iy), rooms[i].polygon)) {
          slot = static_cast<int>(i);
        }
      }
    }
  }
  free_.assign(room_.size(), 0);
  for (int iy = 0; iy < h; ++iy) {
    for (int ix = 0; ix < w; ++ix) {
      const std::size_t c = static_cast<std::size_t>(iy) * w + ix;
      free_[c] = room_[c] >= 0 && !raster_.Blocked(ix, iy);
    }
  }
  reached_.assign(room_.size(), 0);
}

spott_map::Vec2 FreeSpace::Centre(int cell) const {
  return raster_.CellCentre(cell % raster_.width(), cell / raster_.width());
}

int FreeSpace::CellOf(const spott_map::Vec2& p) const {
  const auto c = raster_.CellOf(p);
  return c ? c->second * raster_.width() + c->first : -1;
}

bool FreeSpace::FloodFrom(const spott_map::Vec2& robot, double seed_radius_m) {
  std::fill(reached_.begin(), reached_.end(), 0);
  robot_room_ = -1;
  if (const spott_map::Room* r = db_.graph().RoomContaining(robot)) {
    const auto& rooms = db_.graph().rooms();
    robot_room_ = static_cast<int>(r - rooms.data());
  }
  // The free cell nearest to the robot within the seed radius.
  const int w = raster_.width(), h = raster_.height();
  const double res = raster_.resolution();
  const int reach = static_cast<int>(std::ceil(seed_radius_m / res));
  const auto home = raster_.CellOf(robot);
  if (!home) return false;
  int seed = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const int ix = home->first + dx, iy = home->second + dy;
      if (!raster_.Contains(ix, iy)) continue;
      const int c = iy * w + ix;
      if (!free_[c]) continue;
      const double d = (raster_.CellCentre(ix, iy) - robot).norm();
      if (d <= seed_radius_m && d < best) {
        best = d;
        seed = c;
      }
    }
  }
  if (seed < 0) return false;
  std::deque<int> queue{seed};
  reached_[seed] = 1;
  while (!queue.empty()) {
    const int c = queue.front();
    queue.pop_front();
    const int ix = c % w, iy = c / w;
    const int next[4][2] = {{ix + 1, iy}, {ix - 1, iy}, {ix, iy + 1}, {ix, iy - 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
      const int k = n[1] * w + n[0];
      if (!free_[k] || reached_[k]) continue;
      reached_[k] = 1;
      queue.push_back(k);
    }
  }
  return true;
}

bool FreeSpace::Clear(const spott_map::Vec2& p) const {
  const spott_map::Box around = spott_map::Box{p, p}.Inflated(padding_m_ + 1e-9);
  for (const spott_map::MapFeature* f : db_.FeaturesIn(around)) {
    if (f->DistanceTo(p) <= padding_m_) return false;
  }
  for (const spott_map::Door& d : db_.graph().doors()) {
    if (d.state != spott_map::DoorState::kClosed) continue;
    if (spott_map::DistancePointSegment(p, d.opening) - 0.5 * kDoorThicknessM <= padding_m_) {
      return false;
    }
  }
  return true;
}

}  // namespace internal
}  // namespace spott_tr_plus
