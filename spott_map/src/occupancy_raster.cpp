#include "spott_map/occupancy_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace spott_map {

OccupancyRaster::OccupancyRaster(const Vec2& origin, int width, int height, double resolution)
    : origin_(origin), width_(width), height_(height), resolution_(resolution) {
  if (width < 0 || height < 0 || !(resolution > 0.0)) {
    throw std::invalid_argument("OccupancyRaster: width, height >= 0 and resolution > 0");
  }
  cells_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), Cell::kFree);
}

Box OccupancyRaster::Bounds() const {
  return Box{origin_, origin_ + Vec2(width_ * resolution_, height_ * resolution_)};
}

void OccupancyRaster::Mark(int ix, int iy, Cell value) {
  Cell& c = cells_[Index(ix, iy)];
  if (static_cast<std::uint8_t>(value) > static_cast<std::uint8_t>(c)) c = value;
}

void OccupancyRaster::Clear() { std::fill(cells_.begin(), cells_.end(), Cell::kFree); }

Vec2 OccupancyRaster::CellCentre(int ix, int iy) const {
  return origin_ + Vec2((ix + 0.5) * resolution_, (iy + 0.5) * resolution_);
}

std::optional<std::pair<int, int>> OccupancyRaster::CellOf(const Vec2& p) const {
  const double fx = std::floor((p.x() - origin_.x()) / resolution_);
  const double fy = std::floor((p.y() - origin_.y()) / resolution_);
  if (!(fx >= 0.0 && fy >= 0.0 && fx < width_ && fy < height_)) return std::nullopt;
  return std::make_pair(static_cast<int>(fx), static_cast<int>(fy));
}

std::size_t OccupancyRaster::CountCells(Cell value) const {
  return static_cast<std::size_t>(std::count(cells_.begin(), cells_.end(), value));
}

double DistanceBoxSegment(const Box& box, const Segment& s) {
  // Liang-Barsky: does the segment enter the box at all?
  const Vec2 d = s.b - s.a;
  double t0 = 0.0;
  double t1 = 1.0;
  bool meets = true;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {s.a.x() - box.min.x(), box.max.x() - s.a.x(), s.a.y() - box.min.y(),
                       box.max.y() - s.a.y()};
  for (int i = 0; i < 4 && meets; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) meets = false;
    } else {
      const double t = q[i] / p[i];
      if (p[i] < 0.0) {
        t0 = std::max(t0, t);
      } else {
        t1 = std::min(t1, t);
      }
      if (t0 > t1) meets = false;
    }
  }
  if (meets) return 0.0;
  const Vec2 corners[4] = {box.min, Vec2(box.max.x(), box.min.y()), box.max,
                           Vec2(box.min.x(), box.max.y())};
  double best = std::numeric_limits<double>::infinity();
  for (const Vec2& c : corners) best = std::min(best, DistancePointSegment(c, s));
  for (const Vec2& e : {s.a, s.b}) {
    const Vec2 clamped = e.cwiseMax(box.min).cwiseMin(box.max);
    best = std::min(best, (e - clamped).norm());
  }
  return best;
}

namespace {

// The geometry of one feature prepared for many distance queries (area outlines built once).
class FeatureShape {
 public:
  explicit FeatureShape(const MapFeature& f) : f_(f) {
    if (f.type != FeatureType::kPoint && f.type != FeatureType::kLineSegment) {
      outline_ = f.Outline();
    } else if (f.type == FeatureType::kLineSegment && f.size_y > 0.0) {
      // A wall is a box with flat ends (as the simulator builds it): rounded ends would reach
      // half a thickness into every door opening.
      outline_ = ThickSegmentOutline(Segment{f.points[0], f.points[1]}, f.size_y);
    }
  }

  double DistanceTo(const Vec2& p) const {
    switch (f_.type) {
      case FeatureType::kPoint:
        return (p - f_.points[0]).norm();
      case FeatureType::kLineSegment:
        if (outline_.empty()) return DistancePointSegment(p, Segment{f_.points[0], f_.points[1]});
        [[fallthrough]];
      default:
        return PointInPolygon(p, outline_) ? 0.0 : DistanceToBoundary(p, outline_);
    }
  }

  // Distance from a cell's square to the geometry (0 when they meet).
  double DistanceTo(const Box& cell) const {
    switch (f_.type) {
      case FeatureType::kPoint: {
        const Vec2 clamped = f_.points[0].cwiseMax(cell.min).cwiseMin(cell.max);
        return (f_.points[0] - clamped).norm();
      }
      case FeatureType::kLineSegment:
        if (outline_.empty()) return DistanceBoxSegment(cell, Segment{f_.points[0], f_.points[1]});
        [[fallthrough]];
      default: {
        if (PointInPolygon(0.5 * (cell.min + cell.max), outline_)) return 0.0;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < outline_.size(); ++i) {
          best = std::min(best, DistanceBoxSegment(cell, PolygonEdge(outline_, i)));
        }
        return best;
      }
    }
  }

 private:
  const MapFeature& f_;
  Polygon outline_;
};

}  // namespace

void RasterizeFeature(const MapFeature& feature, double padding_m, OccupancyRaster& raster) {
  if ((feature.type == FeatureType::kPoint && feature.points.empty()) ||
      (feature.type == FeatureType::kLineSegment && feature.points.size() < 2)) {
    return;
  }
  const FeatureShape shape(feature);
  const double res = raster.resolution();
  const Box reach = feature.Bounds().Inflated(std::max(padding_m, 0.0) + res);
  const Vec2 lo = (reach.min - raster.origin()) / res;
  const Vec2 hi = (reach.max - raster.origin()) / res;
  if (!lo.allFinite() || !hi.allFinite()) return;  // a malformed feature draws nothing
  const auto cell_index = [](double v, int n) {
    return static_cast<int>(std::floor(std::clamp(v, -1.0, static_cast<double>(n))));
  };
  const int x0 = std::max(0, cell_index(lo.x(), raster.width()));
  const int y0 = std::max(0, cell_index(lo.y(), raster.height()));
  const int x1 = std::min(raster.width() - 1, cell_index(hi.x(), raster.width()));
  const int y1 = std::min(raster.height() - 1, cell_index(hi.y(), raster.height()));
  const double half_diagonal = res * std::sqrt(0.5);
  for (int iy = y0; iy <= y1; ++iy) {
    for (int ix = x0; ix <= x1; ++ix) {
      const double d = shape.DistanceTo(raster.CellCentre(ix, iy));
      // Only a cell whose centre is within half a diagonal of the geometry (or of the padding's
      // edge) can meet it: the square is no nearer than that.
      if (d >= padding_m + half_diagonal) continue;
      const Box cell{raster.origin() + Vec2(ix * res, iy * res),
                     raster.origin() + Vec2((ix + 1) * res, (iy + 1) * res)};
      const double square = d < padding_m && d > half_diagonal ? d : shape.DistanceTo(cell);
      // Touching counts (within round-off, so that mirror-image cells of a symmetric building
      // get the same answer).
      if (square <= 1e-9) {
        raster.Mark(ix, iy, Cell::kObstacle);
      } else if (square < padding_m) {
        // Padding when any point of the cell is nearer than the padding: a robot whose centre
        // is anywhere in a free cell keeps it. By the centre alone a robot passing a jamb's
        // corner could be half a diagonal (0.071 m at 0.1 m cells) nearer, which is about all
        // the padding allows for the localization's error.
        raster.Mark(ix, iy, Cell::kPadding);
      }
    }
  }
}

}  // namespace spott_map
