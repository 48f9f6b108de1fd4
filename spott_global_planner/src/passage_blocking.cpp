#include "spott_global_planner/passage_blocking.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spott_map/occupancy_raster.h"

namespace spott_global_planner {

using spott_map::Vec2;

std::vector<std::string> ValidateParameters(const PassageParameters& p) {
  std::vector<std::string> v;
  const auto say = [&v](const char* name, const char* rule, double value) {
    std::ostringstream out;
    out << name << " must be " << rule << " (got " << value << ")";
    v.push_back(out.str());
  };
  if (!(std::isfinite(p.resolution_m) && p.resolution_m > 0.0)) {
    say("resolution_m", "> 0", p.resolution_m);
  }
  if (!(std::isfinite(p.padding_m) && p.padding_m >= 0.0)) say("padding_m", ">= 0", p.padding_m);
  if (!(std::isfinite(p.door_depth_m) && p.door_depth_m > 0.0)) {
    say("door_depth_m", "> 0", p.door_depth_m);
  }
  if (p.max_cells < 1) say("max_cells", ">= 1", p.max_cells);
  return v;
}

PassageAnalysis AnalysePassages(const spott_map::Room& room,
                                const std::vector<const spott_map::Door*>& doors,
                                const std::vector<const spott_map::MapFeature*>& obstacles,
                                const PassageParameters& params) {
  PassageAnalysis out;
  out.door_reachable.assign(doors.size(), false);
  if (room.polygon.size() < 3) {
    out.analysed = false;
    return out;
  }
  const double res = params.resolution_m;
  const spott_map::Box box = spott_map::BoundingBox(room.polygon).Inflated(res);
  // Counted in doubles first: a fine raster's sides need not fit an int.
  const double wd = std::ceil((box.max.x() - box.min.x()) / res);
  const double hd = std::ceil((box.max.y() - box.min.y()) / res);
  if (!(wd * hd <= params.max_cells)) {
    out.analysed = false;
    out.door_reachable.assign(doors.size(), true);
    return out;
  }
  const int w = static_cast<int>(wd);
  const int h = static_cast<int>(hd);
  spott_map::OccupancyRaster raster(box.min, w, h, res);
  // Outside the node is not a way through it.
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!spott_map::PointInPolygon(raster.CellCentre(x, y), room.polygon, 1e-9)) {
        raster.Mark(x, y, spott_map::Cell::kObstacle);
      }
    }
  }
  for (const spott_map::MapFeature* f : obstacles) {
    spott_map::RasterizeFeature(*f, params.padding_m, raster);
  }
  // 4-connected components of the free cells.
  std::vector<int> label(static_cast<std::size_t>(w) * h, -1);
  std::vector<int> stack;
  int next_label = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (label[i] >= 0 || raster.Blocked(x, y)) continue;
      label[i] = next_label;
      stack.assign(1, static_cast<int>(i));
      while (!stack.empty()) {
        const int c = stack.back();
        stack.pop_back();
        const int cx = c % w;
        const int cy = c / w;
        const int nx[4] = {cx - 1, cx + 1, cx, cx};
        const int ny[4] = {cy, cy, cy - 1, cy + 1};
        for (int k = 0; k < 4; ++k) {
          if (!raster.Contains(nx[k], ny[k]) || raster.Blocked(nx[k], ny[k])) continue;
          const std::size_t j = static_cast<std::size_t>(ny[k]) * w + nx[k];
          if (label[j] >= 0) continue;
          label[j] = next_label;
          stack.push_back(static_cast<int>(j));
        }
      }
      ++next_label;
    }
  }
  // The components each door reaches.
  std::vector<std::vector<int>> reach(doors.size());
  for (std::size_t d = 0; d < doors.size(); ++d) {
    const spott_map::Segment& opening = doors[d]->opening;
    const spott_map::Box near =
        spott_map::Box{opening.a.cwiseMin(opening.b), opening.a.cwiseMax(opening.b)}.Inflated(
            params.door_depth_m + res);
    const int x0 = std::max(0, static_cast<int>(std::floor((near.min.x() - box.min.x()) / res)));
    const int x1 =
        std::min(w - 1, static_cast<int>(std::floor((near.max.x() - box.min.x()) / res)));
    const int y0 = std::max(0, static_cast<int>(std::floor((near.min.y() - box.min.y()) / res)));
    const int y1 =
        std::min(h - 1, static_cast<int>(std::floor((near.max.y() - box.min.y()) / res)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const int l = label[static_cast<std::size_t>(y) * w + x];
        if (l < 0) continue;
        if (spott_map::DistancePointSegment(raster.CellCentre(x, y), opening) >
            params.door_depth_m) {
          continue;
        }
        reach[d].push_back(l);
      }
    }
    std::sort(reach[d].begin(), reach[d].end());
    reach[d].erase(std::unique(reach[d].begin(), reach[d].end()), reach[d].end());
    out.door_reachable[d] = !reach[d].empty();
  }
  out.origin = box.min;
  out.resolution = res;
  out.width = w;
  out.height = h;
  out.labels = std::move(label);
  out.door_components = reach;
  for (std::size_t a = 0; a < doors.size(); ++a) {
    for (std::size_t b = a + 1; b < doors.size(); ++b) {
      std::vector<int> common;
      std::set_intersection(reach[a].begin(), reach[a].end(), reach[b].begin(), reach[b].end(),
                            std::back_inserter(common));
      if (common.empty()) out.blocked.emplace_back(static_cast<int>(a), static_cast<int>(b));
    }
  }
  return out;
}

std::vector<int> ComponentsNear(const PassageAnalysis& a, const Vec2& p, double radius) {
  std::vector<int> out;
  if (a.width == 0 || !p.allFinite()) return out;
  const auto label_at = [&](int x, int y) {
    return a.labels[static_cast<std::size_t>(y) * a.width + x];
  };
  const int cx = static_cast<int>(std::floor((p.x() - a.origin.x()) / a.resolution));
  const int cy = static_cast<int>(std::floor((p.y() - a.origin.y()) / a.resolution));
  if (cx >= 0 && cy >= 0 && cx < a.width && cy < a.height && label_at(cx, cy) >= 0) {
    return {label_at(cx, cy)};
  }
  const int r = static_cast<int>(std::ceil(radius / a.resolution));
  for (int y = std::max(0, cy - r); y <= std::min(a.height - 1, cy + r); ++y) {
    for (int x = std::max(0, cx - r); x <= std::min(a.width - 1, cx + r); ++x) {
      const int l = label_at(x, y);
      if (l < 0) continue;
      const Vec2 c = a.origin + Vec2((x + 0.5) * a.resolution, (y + 0.5) * a.resolution);
      if ((c - p).norm() <= radius) out.push_back(l);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> DoorsReachedFrom(const PassageAnalysis& a, const std::vector<int>& components) {
  std::vector<int> doors;
  for (std::size_t d = 0; d < a.door_components.size(); ++d) {
    std::vector<int> common;
    std::set_intersection(a.door_components[d].begin(), a.door_components[d].end(),
                          components.begin(), components.end(), std::back_inserter(common));
    if (!common.empty()) doors.push_back(static_cast<int>(d));
  }
  return doors;
}

}  // namespace spott_global_planner

namespace spott_global_planner {

std::optional<std::vector<int>> PassageMonitor::DoorsReachedFrom(int room, const Vec2& p) const {
  const auto it = kept_.find(room);
  if (it == kept_.end()) return std::nullopt;
  std::vector<int> doors;
  const auto& kept = it->second;
  for (int d : spott_global_planner::DoorsReachedFrom(kept.analysis,
                                                      ComponentsNear(kept.analysis, p, Radius()))) {
    doors.push_back(kept.doors[static_cast<std::size_t>(d)]);
  }
  return doors;
}

bool PassageMonitor::SameSide(int room, const Vec2& p, const Vec2& q) const {
  const auto it = kept_.find(room);
  if (it == kept_.end()) return true;
  const auto a = ComponentsNear(it->second.analysis, p, Radius());
  const auto b = ComponentsNear(it->second.analysis, q, Radius());
  std::vector<int> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  return !common.empty();
}

PassageMonitor::PassageMonitor(const PassageParameters& params) : params_(params) {
  const auto violations = ValidateParameters(params);
  if (!violations.empty()) {
    std::string text = "invalid passage parameters:";
    for (const auto& s : violations) text += " " + s + ";";
    throw std::invalid_argument(text);
  }
}

std::vector<int> PassageMonitor::Update(PlanningGraph& graph,
                                        const std::vector<spott_map::MapFeature>& features) {
  std::vector<int> changed;
  const int rooms = graph.room_count();
  if (static_cast<int>(signature_.size()) != rooms) signature_.assign(rooms, std::string("\x01"));
  std::vector<spott_map::Box> feature_boxes;
  feature_boxes.reserve(features.size());
  for (const auto& f : features) feature_boxes.push_back(f.Bounds().Inflated(params_.padding_m));
  for (int r = 0; r < rooms; ++r) {
    const spott_map::Room& room = graph.room(r);
    const std::vector<const spott_map::Door*> doors = graph.source().DoorsOf(room.id);
    if (doors.size() < 2) continue;
    const spott_map::Box box = spott_map::BoundingBox(room.polygon);
    std::vector<const spott_map::MapFeature*> meeting;
    std::ostringstream sig;
    sig.precision(17);
    for (const spott_map::Door* d : doors) {
      sig << d->id << ':' << d->opening.a.transpose() << ' ' << d->opening.b.transpose() << ';';
    }
    for (std::size_t i = 0; i < features.size(); ++i) {
      if (!feature_boxes[i].Intersects(box)) continue;
      const auto& f = features[i];
      meeting.push_back(&f);
      const spott_map::Box b = f.Bounds();
      sig << f.id << ':' << static_cast<int>(f.type) << ' ' << b.min.transpose() << ' '
          << b.max.transpose() << ' ' << f.pose.yaw << ' ' << f.size_x << ' ' << f.size_y << ';';
    }
    std::string s = sig.str();
    if (s == signature_[r]) continue;
    signature_[r] = std::move(s);
    PassageAnalysis analysis = AnalysePassages(room, doors, meeting, params_);
    std::vector<std::pair<int, int>> pairs;
    std::vector<int> door_indices;
    for (const spott_map::Door* d : doors) door_indices.push_back(*graph.FindDoor(d->id));
    for (const auto& [a, b] : analysis.blocked) {
      pairs.emplace_back(door_indices[static_cast<std::size_t>(a)],
                         door_indices[static_cast<std::size_t>(b)]);
    }
    // Only the nodes with blocked passages keep their raster (for the robot's and goal's side).
    if (analysis.blocked.empty()) {
      kept_.erase(r);
    } else {
      kept_[r] = Kept{std::move(door_indices), std::move(analysis)};
    }
    const auto before = graph.BlockedPassagesOf(r);
    graph.SetBlockedPassages(r, pairs);
    if (!(graph.BlockedPassagesOf(r) == before)) changed.push_back(r);
  }
  return changed;
}

}  // namespace spott_global_planner
