#include "spott_map/local_map.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spott_map {

namespace {

std::string Violation(const char* name, const char* rule, double value) {
  std::ostringstream out;
  out << name << " must be " << rule << " (got " << value << ")";
  return out.str();
}

}  // namespace

int LocalMapParameters::cells() const {
  return static_cast<int>(std::lround(window_size_m / resolution_m));
}

std::vector<std::string> ValidateParameters(const LocalMapParameters& p) {
  std::vector<std::string> v;
  const auto positive = [&v](const char* name, double value) {
    if (!(std::isfinite(value) && value > 0.0)) v.push_back(Violation(name, "> 0", value));
  };
  const auto non_negative = [&v](const char* name, double value) {
    if (!(std::isfinite(value) && value >= 0.0)) v.push_back(Violation(name, ">= 0", value));
  };
  positive("window_size_m", p.window_size_m);
  positive("resolution_m", p.resolution_m);
  non_negative("robot_radius_m", p.robot_radius_m);
  non_negative("max_localization_error_m", p.max_localization_error_m);
  non_negative("recentre_margin_m", p.recentre_margin_m);
  non_negative("door_thickness_m", p.door_thickness_m);
  if (v.empty()) {
    if (p.resolution_m > p.window_size_m) {
      v.push_back(Violation("resolution_m", "<= window_size_m", p.resolution_m));
    } else if (p.window_size_m / p.resolution_m > 8192.5) {  // before cells() rounds it to an int
      v.push_back(
          Violation("window_size_m", "at most 8192 cells of resolution_m across", p.window_size_m));
    }
    if (p.recentre_margin_m >= 0.5 * p.window_size_m) {
      v.push_back(Violation("recentre_margin_m", "< window_size_m / 2", p.recentre_margin_m));
    }
  }
  return v;
}

void RasterizeDatabase(const MapDatabase& db, double padding_m, double door_thickness_m,
                       OccupancyRaster& raster) {
  const Box area = raster.Bounds().Inflated(padding_m + raster.resolution());
  for (const MapFeature* f : db.FeaturesIn(area)) RasterizeFeature(*f, padding_m, raster);
  for (const Door& door : db.graph().doors()) {
    if (door.state != DoorState::kClosed) continue;
    RasterizeFeature(MakeSegment(door.id, door.opening, "door", door_thickness_m), padding_m,
                     raster);
  }
}

LocalMap::LocalMap(const LocalMapParameters& params) : params_(params) {
  const std::vector<std::string> violations = ValidateParameters(params);
  if (!violations.empty()) {
    std::string text = "invalid local map parameters:";
    for (const std::string& s : violations) text += " " + s + ";";
    throw std::invalid_argument(text);
  }
}

void LocalMap::Recentre(const MapDatabase& db, const Vec2& centre) {
  const double res = params_.resolution_m;
  const int n = params_.cells();
  const Vec2 origin = LatticeWindow(centre, n, res).min;
  raster_ = OccupancyRaster(origin, n, n, res);
  centre_ = origin + Vec2(0.5 * n * res, 0.5 * n * res);
  Refresh(db);
}

void LocalMap::Refresh(const MapDatabase& db) {
  raster_.Clear();
  RasterizeDatabase(db, params_.padding_m(), params_.door_thickness_m, raster_);
  features_.clear();
  for (const MapFeature* f : db.FeaturesIn(raster_.Bounds())) features_.push_back(*f);
  revision_ = db.revision();
}

bool LocalMap::NeedsRecentre(const Vec2& robot) const {
  const Box inner = raster_.Bounds().Inflated(-params_.recentre_margin_m);
  return !inner.Contains(robot);
}

}  // namespace spott_map
