#include "spott_map/map_database.h"

#include <algorithm>

namespace spott_map {

MapDatabase MapDatabase::FromWorld(const World& world) {
  MapDatabase db;
  for (MapFeature& f : CadFeatures(world)) db.AddFeature(std::move(f));
  db.graph_ = RoomDoorGraph(world);
  return db;
}

const MapFeature* MapDatabase::FindFeature(const std::string& id) const {
  for (const MapFeature& f : features_) {
    if (f.id == id) return &f;
  }
  return nullptr;
}

std::vector<const MapFeature*> MapDatabase::FeaturesIn(const Box& box) const {
  std::vector<const MapFeature*> result;
  for (const MapFeature& f : features_) {
    if (f.Bounds().Intersects(box)) result.push_back(&f);
  }
  return result;
}

bool MapDatabase::AddFeature(MapFeature feature) {
  if (feature.id.empty() || FindFeature(feature.id)) return false;
  features_.push_back(std::move(feature));
  ++revision_;
  return true;
}

MapDatabase::AddResult MapDatabase::AddSensedFeature(MapFeature feature, double tolerance_m,
                                                     MatchAgainst against) {
  for (MapFeature& existing : features_) {
    if (against == MatchAgainst::kCad && existing.source != FeatureSource::kCad) continue;
    if (!IsSameFeature(existing, feature, tolerance_m)) continue;
    if (!feature.label.empty() && feature.label != existing.label) {
      existing.label = feature.label;
      ++revision_;
      return AddResult{AddResult::Outcome::kRelabelled, existing.id};
    }
    return AddResult{AddResult::Outcome::kAlreadyPresent, existing.id};
  }
  feature.source = FeatureSource::kSensed;
  if (feature.id.empty() || FindFeature(feature.id)) {
    do {
      feature.id = "sensed_" + std::to_string(next_sensed_id_++);
    } while (FindFeature(feature.id));
  }
  const std::string id = feature.id;
  features_.push_back(std::move(feature));
  ++revision_;
  return AddResult{AddResult::Outcome::kAdded, id};
}

bool MapDatabase::RemoveFeature(const std::string& id) {
  auto it = std::find_if(features_.begin(), features_.end(),
                         [&id](const MapFeature& f) { return f.id == id; });
  if (it == features_.end()) return false;
  features_.erase(it);
  ++revision_;
  return true;
}

bool MapDatabase::Relabel(const std::string& id, const std::string& label) {
  for (MapFeature& f : features_) {
    if (f.id != id) continue;
    if (f.label != label) {
      f.label = label;
      ++revision_;
    }
    return true;
  }
  return false;
}

bool MapDatabase::SetDoorState(const std::string& door_id, DoorState state) {
  const Door* door = graph_.FindDoor(door_id);
  if (!door) return false;
  const DoorState before = door->state;
  if (!graph_.SetDoorState(door_id, state)) return false;
  if (before != state) ++revision_;
  return true;
}

void MapDatabase::SetGraph(RoomDoorGraph graph) {
  graph_ = std::move(graph);
  ++revision_;
}

}  // namespace spott_map
