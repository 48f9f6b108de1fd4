#include "spott_map/map_feature.h"

#include <cmath>
#include <limits>

namespace spott_map {

namespace {

bool IsArea(FeatureType type) {
  return type != FeatureType::kPoint && type != FeatureType::kLineSegment;
}

bool IsRound(FeatureType type) {
  return type == FeatureType::kEllipse || type == FeatureType::kGeonCylinder ||
         type == FeatureType::kGeonEllipsoid;
}

}  // namespace

Polygon MapFeature::Outline() const {
  if (!IsArea(type)) return {};
  WorldObject shape;
  shape.kind = IsRound(type) ? ObjectKind::kCylinder : ObjectKind::kCuboid;
  shape.pose = pose;
  shape.size_x = size_x;
  shape.size_y = size_y;
  return shape.Footprint();
}

Box MapFeature::Bounds() const {
  if (IsArea(type)) return BoundingBox(Outline());
  if (points.empty()) return Box{};
  Box box = BoundingBox(points);
  if (type == FeatureType::kLineSegment) box = box.Inflated(0.5 * size_y);
  return box;
}

double MapFeature::DistanceTo(const Vec2& p) const {
  switch (type) {
    case FeatureType::kPoint:
      return points.empty() ? std::numeric_limits<double>::infinity() : (p - points[0]).norm();
    case FeatureType::kLineSegment: {
      if (points.size() < 2) return std::numeric_limits<double>::infinity();
      const Segment s{points[0], points[1]};
      if (size_y <= 0.0) return DistancePointSegment(p, s);
      const Polygon box = ThickSegmentOutline(s, size_y);  // flat ends, like a wall
      return PointInPolygon(p, box) ? 0.0 : DistanceToBoundary(p, box);
    }
    default: {
      const Polygon outline = Outline();
      if (PointInPolygon(p, outline)) return 0.0;
      return DistanceToBoundary(p, outline);
    }
  }
}

Polygon ThickSegmentOutline(const Segment& s, double thickness) {
  const Vec2 d = s.b - s.a;
  const double n = d.norm();
  const Vec2 side =
      n > 0.0 ? Vec2(-d.y(), d.x()) * (0.5 * thickness / n) : Vec2(0.0, 0.5 * thickness);
  return {s.a - side, s.b - side, s.b + side, s.a + side};
}

MapFeature MakePoint(const std::string& id, const Vec2& p, const std::string& label) {
  MapFeature f;
  f.id = id;
  f.type = FeatureType::kPoint;
  f.label = label;
  f.points = {p};
  return f;
}

MapFeature MakeSegment(const std::string& id, const Segment& s, const std::string& label,
                       double thickness) {
  MapFeature f;
  f.id = id;
  f.type = FeatureType::kLineSegment;
  f.label = label;
  f.points = {s.a, s.b};
  f.size_y = thickness;
  return f;
}

const char* ToString(FeatureType type) {
  switch (type) {
    case FeatureType::kPoint:
      return "point";
    case FeatureType::kLineSegment:
      return "line";
    case FeatureType::kEllipse:
      return "ellipse";
    case FeatureType::kRectangle:
      return "rectangle";
    case FeatureType::kGeonCuboid:
      return "cuboid";
    case FeatureType::kGeonCylinder:
      return "cylinder";
    case FeatureType::kGeonEllipsoid:
      break;
  }
  return "ellipsoid";
}

std::vector<MapFeature> CadFeatures(const World& world) {
  std::vector<MapFeature> features;
  for (const Wall& wall : world.walls) {
    MapFeature f = MakeSegment(wall.id, wall.segment, "wall", wall.thickness);
    f.source = FeatureSource::kCad;
    features.push_back(f);
  }
  return features;
}

bool IsSameFeature(const MapFeature& existing, const MapFeature& candidate, double tolerance) {
  if (existing.type != candidate.type) return false;
  switch (existing.type) {
    case FeatureType::kPoint:
      return !existing.points.empty() && !candidate.points.empty() &&
             (existing.points[0] - candidate.points[0]).norm() <= tolerance;
    case FeatureType::kLineSegment: {
      if (existing.points.size() < 2 || candidate.points.size() < 2) return false;
      const Segment e{existing.points[0], existing.points[1]};
      return DistancePointSegment(candidate.points[0], e) <= tolerance &&
             DistancePointSegment(candidate.points[1], e) <= tolerance;
    }
    default: {
      const bool centre =
          (existing.pose.Position() - candidate.pose.Position()).norm() <= tolerance;
      const double dyaw = std::abs(NormalizeAngle(existing.pose.yaw - candidate.pose.yaw));
      // A rectangle turned by a half turn is the same rectangle; with swapped extents, a
      // quarter turn is too.
      const bool straight = std::abs(existing.size_x - candidate.size_x) <= tolerance &&
                            std::abs(existing.size_y - candidate.size_y) <= tolerance &&
                            (dyaw <= 0.1 || std::abs(dyaw - M_PI) <= 0.1);
      const bool swapped = std::abs(existing.size_x - candidate.size_y) <= tolerance &&
                           std::abs(existing.size_y - candidate.size_x) <= tolerance &&
                           std::abs(dyaw - 0.5 * M_PI) <= 0.1;
      const bool height = std::abs(existing.size_z - candidate.size_z) <= tolerance;
      return centre && height && (straight || swapped);
    }
  }
}

}  // namespace spott_map
