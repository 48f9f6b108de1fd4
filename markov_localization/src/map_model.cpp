#include "markov_localization/map_model.h"
#include "markov_localization/validation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "spott_map/local_map.h"
#include "spott_map/map_database.h"
#include "spott_map/occupancy_raster.h"

namespace markov_localization {

std::vector<std::string> ValidateParameters(const MapModelParameters& p) {
  std::vector<std::string> errors;
  // Below 1 cm a building's cells overflow the int that counts them (static_cast<int>(ceil(size /
  // resolution)) is undefined beyond it) or the memory that holds them.
  if (!(p.resolution_m >= 0.01 && p.resolution_m <= 2.0))
    errors.push_back("resolution_m must be in [0.01, 2] m");
  if (!(p.state_clearance_m >= 0.0 && p.state_clearance_m <= 2.0))
    errors.push_back("state_clearance_m must be in [0, 2] m");
  if (!(p.door_thickness_m > 0.0 && p.door_thickness_m <= 1.0))
    errors.push_back("door_thickness_m must be in (0, 1] m");
  if (p.ray_cast_subdivision < 1 || p.ray_cast_subdivision > 8)
    errors.push_back("ray_cast_subdivision must be in [1, 8]");
  if (p.occupied_threshold < 1 || p.occupied_threshold > 100)
    errors.push_back("occupied_threshold must be in [1, 100]");
  if (p.free_threshold < 0 || p.free_threshold > p.occupied_threshold)
    errors.push_back("free_threshold must be in [0, occupied_threshold]");
  return errors;
}

MapModel MapModel::FromWorld(const spott_map::World& world, const MapModelParameters& params) {
  return FromDatabase(world, spott_map::MapDatabase::FromWorld(world), params);
}

MapModel MapModel::FromDatabase(const spott_map::World& world, const spott_map::MapDatabase& db,
                                const MapModelParameters& params) {
  const auto errors = ValidateParameters(params);
  ThrowIfInvalid(errors);
  const spott_map::Box bounds = world.Bounds().Inflated(2.0 * params.resolution_m);
  const Vec2 size = bounds.max - bounds.min;
  if (!(size.x() > 0.0 && size.y() > 0.0))
    throw std::invalid_argument("world '" + world.name + "' has no extent (no walls or rooms)");
  const int width = static_cast<int>(std::ceil(size.x() / params.resolution_m - 1e-6));
  const int height = static_cast<int>(std::ceil(size.y() / params.resolution_m - 1e-6));
  // Centre the grid on the world's box: a building symmetric about its centre is then
  // discretized symmetrically too. Otherwise the twins of a symmetric corridor fall on
  // different sub-cell offsets, and the sharp 24-beam likelihood lets that artefact pick one
  // twin with certainty (seen at 15 cm in bonn_department).
  const Vec2 centre = 0.5 * (bounds.min + bounds.max);
  const Vec2 origin = centre - 0.5 * params.resolution_m * Vec2(width, height);
  if (static_cast<double>(width) * height > 4.0e7)
    throw std::invalid_argument("world '" + world.name + "' is too large for resolution_m");
  const int sub = params.ray_cast_subdivision;
  spott_map::OccupancyRaster raster(origin, width * sub, height * sub, params.resolution_m / sub);
  spott_map::RasterizeDatabase(db, 0.0, params.door_thickness_m, raster);

  MapModel map;
  map.origin_ = origin;
  map.width_ = width;
  map.height_ = height;
  map.resolution_ = params.resolution_m;
  map.subdivision_ = sub;
  map.surface_inside_cells_ = true;  // the geometry meets the fine cells it marks
  map.fine_width_ = width * sub;
  map.fine_height_ = height * sub;
  map.fine_occupied_.assign(static_cast<std::size_t>(map.fine_width_) * map.fine_height_, 0);
  map.occupied_.assign(static_cast<std::size_t>(width) * height, 0);
  for (int fy = 0; fy < map.fine_height_; ++fy) {
    for (int fx = 0; fx < map.fine_width_; ++fx) {
      if (raster.at(fx, fy) != spott_map::Cell::kObstacle) continue;
      map.fine_occupied_[static_cast<std::size_t>(fy) * map.fine_width_ + fx] = 1;
      map.occupied_[map.Index(fx / sub, fy / sub)] = 1;
    }
  }
  // Outside every room is not a state either (the space beyond the outer walls).
  std::vector<std::uint8_t> outside(map.occupied_.size(), 0);
  for (int iy = 0; iy < height; ++iy)
    for (int ix = 0; ix < width; ++ix)
      outside[map.Index(ix, iy)] = world.RoomContaining(map.CellCentre(ix, iy)) == nullptr;
  map.ComputeFineClearance();
  map.ComputeStates(params.state_clearance_m, outside);
  if (map.num_state_cells_ == 0)
    throw std::invalid_argument("world '" + world.name + "' leaves no free cell for the robot");
  return map;
}

MapModel MapModel::FromOccupancy(const Vec2& origin, int width, int height, double resolution_m,
                                 const std::vector<std::int8_t>& data, int occupied_threshold,
                                 double state_clearance_m) {
  OccupancyMap grid;
  grid.origin = origin;
  grid.width = width;
  grid.height = height;
  grid.resolution_m = resolution_m;
  grid.data = data;
  MapModelParameters p;
  p.resolution_m = resolution_m;
  p.state_clearance_m = state_clearance_m;
  p.ray_cast_subdivision = 1;
  p.occupied_threshold = occupied_threshold;
  p.free_threshold = occupied_threshold;  // no intermediate unknown values
  std::vector<std::string> errors;
  if (width <= 0 || height <= 0) errors.push_back("width and height must be positive");
  if (width > 0 && height > 0 &&
      data.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    errors.push_back("data has " + std::to_string(data.size()) + " cells, expected width*height");
  ThrowIfInvalid(errors);
  return FromOccupancy(grid, p);
}

MapModel MapModel::FromOccupancy(const OccupancyMap& grid, const MapModelParameters& params) {
  std::vector<std::string> errors = ValidateParameters(params);
  for (const auto& e : ValidateOccupancyMap(grid)) errors.push_back("occupancy grid: " + e);
  // A rotated grid would rotate the belief's frame against the map frame; AMCL ignores the
  // rotation silently, which is worse. Refused with the reason.
  if (std::abs(std::remainder(grid.origin_yaw, 2.0 * M_PI)) > 1e-6)
    errors.push_back("occupancy grid: origin yaw " + std::to_string(grid.origin_yaw) +
                     " rad is not supported (only maps whose rows run along the map frame's x "
                     "axis; rotate the image)");
  ThrowIfInvalid(errors);
  const double src = grid.resolution_m, res = params.resolution_m;
  const int sub = params.ray_cast_subdivision;
  const double fres = res / sub;
  // The belief's grid in the occupancy grid's own (rotated) frame: same corner, same extent.
  const int width = static_cast<int>(std::ceil(grid.width * src / res - 1e-9));
  const int height = static_cast<int>(std::ceil(grid.height * src / res - 1e-9));
  if (static_cast<double>(width) * height > 4.0e7)
    throw std::invalid_argument("occupancy grid too large for resolution_m");
  MapModel map;
  map.origin_ = grid.origin;
  map.width_ = width;
  map.height_ = height;
  map.resolution_ = res;
  map.subdivision_ = sub;
  map.fine_width_ = width * sub;
  map.fine_height_ = height * sub;
  map.fine_occupied_.assign(static_cast<std::size_t>(map.fine_width_) * map.fine_height_, 0);
  map.occupied_.assign(static_cast<std::size_t>(width) * height, 0);
  // The grid's cell faces are fine-cell faces when the grid's cell is a whole number of fine
  // cells; otherwise a face lies inside the fine cell it marks.
  const double ratio = src / fres;
  map.surface_inside_cells_ = std::abs(ratio - std::round(ratio)) > 1e-6 || ratio < 1.0 - 1e-6;
  auto mark = [&](int fx, int fy) {
    if (fx < 0 || fy < 0 || fx >= map.fine_width_ || fy >= map.fine_height_) return;
    map.fine_occupied_[static_cast<std::size_t>(fy) * map.fine_width_ + fx] = 1;
    map.occupied_[map.Index(fx / sub, fy / sub)] = 1;
  };
  // Fine cells whose square overlaps an obstacle cell [i src, (i+1) src) (open overlap: a fine
  // cell that only touches it is free). The same frame, so the intervals are exact.
  auto first_overlap = [&](double lo) { return static_cast<int>(std::floor(lo / fres + 1e-9)); };
  auto last_overlap = [&](double hi) { return static_cast<int>(std::ceil(hi / fres - 1e-9)) - 1; };
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      if (grid.at(i, j) < params.occupied_threshold) continue;
      const int fx0 = first_overlap(i * src), fx1 = last_overlap((i + 1) * src);
      const int fy0 = first_overlap(j * src), fy1 = last_overlap((j + 1) * src);
      for (int fy = fy0; fy <= fy1; ++fy)
        for (int fx = fx0; fx <= fx1; ++fx) mark(fx, fy);
    }
  }
  // A belief cell is a state candidate when its centre lies in a free cell of the grid.
  std::vector<std::uint8_t> excluded(map.occupied_.size(), 1);
  for (int iy = 0; iy < height; ++iy)
    for (int ix = 0; ix < width; ++ix) {
      const int i = static_cast<int>(std::floor((ix + 0.5) * res / src));
      const int j = static_cast<int>(std::floor((iy + 0.5) * res / src));
      if (i < 0 || j < 0 || i >= grid.width || j >= grid.height) continue;
      const int v = grid.at(i, j);
      excluded[map.Index(ix, iy)] = !(v >= 0 && v < params.free_threshold);
    }
  map.ComputeFineClearance();
  map.ComputeStates(params.state_clearance_m, excluded);
  if (map.num_state_cells_ == 0)
    throw std::invalid_argument("occupancy grid leaves no free cell for the robot");
  return map;
}

void MapModel::ComputeStates(double clearance_m, const std::vector<std::uint8_t>& excluded) {
  state_.assign(occupied_.size(), 1);
  // A cell is a state when its centre is at least the clearance away from every obstacle
  // square of the fine raster (and, with clearance 0, the centre itself is free).
  const double fres = resolution_ / subdivision_;
  const int r = static_cast<int>(std::ceil(clearance_m / fres)) + 1;
  for (int iy = 0; iy < height_; ++iy) {
    for (int ix = 0; ix < width_; ++ix) {
      const std::size_t i = Index(ix, iy);
      if (excluded[i]) {
        state_[i] = 0;
        continue;
      }
      // Centre in fine-cell units.
      const double cx = (ix + 0.5) * subdivision_, cy = (iy + 0.5) * subdivision_;
      const int fcx = static_cast<int>(cx), fcy = static_cast<int>(cy);
      bool blocked = false;
      for (int fy = fcy - r; fy <= fcy + r && !blocked; ++fy) {
        if (fy < 0 || fy >= fine_height_) continue;
        for (int fx = fcx - r; fx <= fcx + r; ++fx) {
          if (fx < 0 || fx >= fine_width_ || !FineOccupied(fx, fy)) continue;
          const double ex = std::max({0.0, fx - cx, cx - (fx + 1)}) * fres;
          const double ey = std::max({0.0, fy - cy, cy - (fy + 1)}) * fres;
          if (ex * ex + ey * ey < clearance_m * clearance_m || (ex == 0.0 && ey == 0.0)) {
            blocked = true;
            break;
          }
        }
      }
      if (blocked) state_[i] = 0;
    }
  }
  // The border row never holds a state: beams and motion need a neighbour on every side.
  for (int ix = 0; ix < width_; ++ix) state_[Index(ix, 0)] = state_[Index(ix, height_ - 1)] = 0;
  for (int iy = 0; iy < height_; ++iy) state_[Index(0, iy)] = state_[Index(width_ - 1, iy)] = 0;
  num_state_cells_ = 0;
  for (auto s : state_) num_state_cells_ += s;
}

bool MapModel::SameRaster(const MapModel& other) const {
  return width_ == other.width_ && height_ == other.height_ && resolution_ == other.resolution_ &&
         origin_ == other.origin_ && subdivision_ == other.subdivision_ &&
         surface_inside_cells_ == other.surface_inside_cells_ && fine_width_ == other.fine_width_ &&
         fine_height_ == other.fine_height_ && fine_occupied_.size() == other.fine_occupied_.size();
}

std::optional<spott_map::Box> MapModel::OccupancyChangedFrom(const MapModel& other) const {
  int x0 = fine_width_, y0 = fine_height_, x1 = -1, y1 = -1;
  for (int fy = 0; fy < fine_height_; ++fy) {
    const std::size_t row = static_cast<std::size_t>(fy) * fine_width_;
    for (int fx = 0; fx < fine_width_; ++fx) {
      if (fine_occupied_[row + fx] == other.fine_occupied_[row + fx]) continue;
      x0 = std::min(x0, fx);
      y0 = std::min(y0, fy);
      x1 = std::max(x1, fx);
      y1 = std::max(y1, fy);
    }
  }
  if (x1 < 0) return std::nullopt;
  const double fres = resolution_ / subdivision_;
  return spott_map::Box{origin_ + fres * Vec2(x0, y0), origin_ + fres * Vec2(x1 + 1, y1 + 1)};
}

bool MapModel::FineOccupiedAt(const Vec2& p) const {
  const double fres = resolution_ / subdivision_;
  const int fx = static_cast<int>(std::floor((p.x() - origin_.x()) / fres));
  const int fy = static_cast<int>(std::floor((p.y() - origin_.y()) / fres));
  if (fx < 0 || fy < 0 || fx >= fine_width_ || fy >= fine_height_) return false;
  return FineOccupied(fx, fy);
}

Vec2 MapModel::CellCentre(int ix, int iy) const {
  return origin_ + Vec2((ix + 0.5) * resolution_, (iy + 0.5) * resolution_);
}

std::optional<std::pair<int, int>> MapModel::CellOf(const Vec2& p) const {
  const double fx = (p.x() - origin_.x()) / resolution_;
  const double fy = (p.y() - origin_.y()) / resolution_;
  if (!(fx >= 0.0 && fy >= 0.0)) return std::nullopt;
  const int ix = static_cast<int>(fx);
  const int iy = static_cast<int>(fy);
  if (!Contains(ix, iy)) return std::nullopt;
  return std::make_pair(ix, iy);
}

bool MapModel::IsStateAt(const Vec2& p) const {
  const auto cell = CellOf(p);
  return cell && IsState(cell->first, cell->second);
}

double MapModel::RayCast(const Vec2& from, double angle_rad, double max_range_m) const {
  const Hit h = RayCastHit(from, angle_rad, max_range_m);
  return h.hit ? h.range_m : max_range_m;
}

void MapModel::ComputeFineClearance() {
  // Two chamfer passes with unit steps to all 8 neighbours: exact for the Chebyshev distance.
  const int w = fine_width_, h = fine_height_;
  std::vector<int> d(static_cast<std::size_t>(w) * h);
  for (int fy = 0; fy < h; ++fy)
    for (int fx = 0; fx < w; ++fx) {
      const std::size_t i = static_cast<std::size_t>(fy) * w + fx;
      // Beyond the edge a beam ends (at max range): as near as an obstacle for the skip.
      d[i] = fine_occupied_[i] ? 0 : std::min({fx + 1, fy + 1, w - fx, h - fy});
    }
  for (int fy = 0; fy < h; ++fy)
    for (int fx = 0; fx < w; ++fx) {
      const std::size_t i = static_cast<std::size_t>(fy) * w + fx;
      int v = d[i];
      if (fx > 0) v = std::min(v, d[i - 1] + 1);
      if (fy > 0) {
        v = std::min(v, d[i - w] + 1);
        if (fx > 0) v = std::min(v, d[i - w - 1] + 1);
        if (fx + 1 < w) v = std::min(v, d[i - w + 1] + 1);
      }
      d[i] = v;
    }
  for (int fy = h - 1; fy >= 0; --fy)
    for (int fx = w - 1; fx >= 0; --fx) {
      const std::size_t i = static_cast<std::size_t>(fy) * w + fx;
      int v = d[i];
      if (fx + 1 < w) v = std::min(v, d[i + 1] + 1);
      if (fy + 1 < h) {
        v = std::min(v, d[i + w] + 1);
        if (fx + 1 < w) v = std::min(v, d[i + w + 1] + 1);
        if (fx > 0) v = std::min(v, d[i + w - 1] + 1);
      }
      d[i] = v;
    }
  fine_clearance_.resize(d.size());
  for (std::size_t i = 0; i < d.size(); ++i)
    fine_clearance_[i] = static_cast<std::uint8_t>(std::min(d[i], 255));
}

MapModel::Hit MapModel::RayCastHit(const Vec2& from, double angle_rad, double max_range_m) const {
  return RayCastHit(from, Vec2(std::cos(angle_rad), std::sin(angle_rad)), max_range_m);
}

MapModel::Hit MapModel::RayCastHit(const Vec2& from, const Vec2& dir, double max_range_m) const {
  // Amanatides-Woo traversal of the cells the beam crosses.
  const double dx = dir.x(), dy = dir.y();
  const double fres = resolution_ / subdivision_;
  double fx = (from.x() - origin_.x()) / fres;
  double fy = (from.y() - origin_.y()) / fres;
  int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
  auto inside = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < fine_width_ && y < fine_height_;
  };
  Hit miss{max_range_m, 0.0, false, false};
  if (!inside(ix, iy)) return miss;
  if (FineOccupied(ix, iy)) return Hit{0.0, 0.0, true, std::abs(dx) >= std::abs(dy)};
  const double inf = std::numeric_limits<double>::infinity();
  const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  const double t_delta_x = dx != 0.0 ? std::abs(1.0 / dx) : inf;
  const double t_delta_y = dy != 0.0 ? std::abs(1.0 / dy) : inf;
  double t_max_x = dx > 0 ? (ix + 1 - fx) * t_delta_x : (dx < 0 ? (fx - ix) * t_delta_x : inf);
  double t_max_y = dy > 0 ? (iy + 1 - fy) * t_delta_y : (dy < 0 ? (fy - iy) * t_delta_y : inf);
  const double max_cells = max_range_m / fres;
  // The box of cells known free and inside: around the last cell looked up, as far as its
  // clearance c (every cell within c - 1 is free). The beam jumps to the first cell outside it
  // in one step: a box of one cell is one step of the traversal, a larger one counts the
  // steps along each axis (multiplied out rather than added up, so at an exact corner the
  // side taken may differ from the step-by-step sum's rounding: both cells touch the beam).
  int c = fine_clearance_[static_cast<std::size_t>(iy) * fine_width_ + ix];
  const double adx = std::abs(dx), ady = std::abs(dy);
  while (true) {
    // The box is centred on the current cell: c steps along an axis leave it. The beam's t at
    // the leaving step of each axis:
    const double tx = dx != 0.0 ? t_max_x + (c - 1) * t_delta_x : inf;
    const double ty = dy != 0.0 ? t_max_y + (c - 1) * t_delta_y : inf;
    double t;
    bool x_face;
    if (tx < ty) {  // x leaves first, after the y steps at t <= tx (at most c - 1)
      const int ky =
          t_max_y <= tx ? std::min(c - 1, static_cast<int>((tx - t_max_y) * ady) + 1) : 0;
      ix += c * step_x;
      iy += ky * step_y;
      t = tx;
      t_max_x = tx + t_delta_x;
      if (ky > 0) t_max_y += ky * t_delta_y;  // (0 x inf along an axis)
      x_face = true;
    } else {  // y leaves first (a tie goes to y, as in the step-by-step traversal)
      const int kx =
          t_max_x < ty ? std::min(c - 1, static_cast<int>(std::ceil((ty - t_max_x) * adx))) : 0;
      iy += c * step_y;
      ix += kx * step_x;
      t = ty;
      t_max_y = ty + t_delta_y;
      if (kx > 0) t_max_x += kx * t_delta_x;
      x_face = false;
    }
    if (t >= max_cells || !inside(ix, iy)) return miss;
    c = fine_clearance_[static_cast<std::size_t>(iy) * fine_width_ + ix];
    if (c == 0) {
      const double exit = std::min(t_max_x, t_max_y);  // leaving the cell hit
      return Hit{t * fres, surface_inside_cells_ ? 0.5 * (exit - t) * fres : 0.0, true, x_face};
    }
  }
}

}  // namespace markov_localization
