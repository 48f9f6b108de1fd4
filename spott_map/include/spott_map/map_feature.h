// A primitive of the map database (SPOTT section III.A): a 2-D model or a geon, stored as
// vectors in absolute coordinates with a label naming its real-world equivalent.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "spott_map/geometry.h"
#include "spott_map/world.h"

namespace spott_map {

enum class FeatureType {
  kPoint,
  kLineSegment,
  kEllipse,
  kRectangle,
  kGeonCuboid,
  kGeonCylinder,
  kGeonEllipsoid
};

enum class FeatureSource { kCad, kSensed };

struct MapFeature {
  std::string id;
  FeatureType type = FeatureType::kPoint;
  FeatureSource source = FeatureSource::kSensed;
  std::string label;  ///< wall, door, chair, desk, partition, ... or empty when unknown.
  /// kPoint: points[0]; kLineSegment: points[0] -> points[1] (m, map frame).
  std::vector<Vec2> points;
  /// Area features and geons: centre and heading.
  Pose2 pose;
  /// Area features and geons: full extents along the feature's axes (m; ellipse: diameters).
  /// Line segments: size_y is the thickness (0 = thin). size_z is a height (m; 0 for 2-D).
  double size_x = 0.0;
  double size_y = 0.0;
  double size_z = 0.0;
  std::map<std::string, std::string> attributes;

  /// The outline of an area feature (rectangle/cuboid corners, ellipse/cylinder as 24 points);
  /// empty for points and segments.
  Polygon Outline() const;
  /// Bounding box of the geometry (m).
  Box Bounds() const;
  /// Distance from `p` to the geometry (0 inside an area feature; a thick segment is a box with
  /// flat ends).
  double DistanceTo(const Vec2& p) const;
};

/// The box of a segment of `thickness` (m): flat ends at the segment's ends, as walls are built.
Polygon ThickSegmentOutline(const Segment& s, double thickness);

MapFeature MakePoint(const std::string& id, const Vec2& p, const std::string& label);
MapFeature MakeSegment(const std::string& id, const Segment& s, const std::string& label,
                       double thickness = 0.0);

const char* ToString(FeatureType type);

/// Features of a world's CAD map: every wall as a segment labelled "wall" (source kCad).
/// Doors are not features; the graph holds them.
std::vector<MapFeature> CadFeatures(const World& world);

/// True when the two features are the same kind of primitive and `candidate` lies on
/// `existing` within `tolerance` (m): a point near it, a segment whose ends both lie within the
/// tolerance of the existing segment (a partial view of a wall is the same wall), an area feature
/// with the same centre and extents. This is not fusion: nothing is averaged.
bool IsSameFeature(const MapFeature& existing, const MapFeature& candidate, double tolerance);

}  // namespace spott_map
