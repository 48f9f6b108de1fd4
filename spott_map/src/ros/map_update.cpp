#include "spott_map/ros/map_update.h"

#include "spott_map/ros/conversions.h"

namespace spott_map::ros_conversions {

std::vector<std::string> ApplyMapUpdate(const spott_msgs::MapUpdate& update,
                                        double feature_tolerance_m, MapDatabase& db) {
  std::vector<std::string> problems;
  // Removals first: the successor of a refined feature overlaps it and would be its duplicate.
  for (const std::string& id : update.removed) {
    if (!db.RemoveFeature(id)) problems.push_back("cannot remove unknown feature '" + id + "'");
  }
  for (const auto& msg : update.added) {
    std::string error;
    if (auto feature = FromMsg(msg, &error)) {
      // The owner's features (with ids) are mirrored: it de-duplicated them by its own rules.
      const auto against =
          msg.id.empty() ? MapDatabase::MatchAgainst::kAll : MapDatabase::MatchAgainst::kCad;
      db.AddSensedFeature(std::move(*feature), feature_tolerance_m, against);
    } else {
      problems.push_back(error);
    }
  }
  for (const auto& msg : update.relabelled) {
    if (!db.Relabel(msg.id, msg.label)) {
      problems.push_back("cannot relabel unknown feature '" + msg.id + "'");
    }
  }
  for (const auto& door : update.doors) {
    const auto state = DoorStateFromMsg(door.state);
    if (!state) {
      problems.push_back("door '" + door.door_id + "': invalid state " +
                         std::to_string(door.state));
    } else if (!db.SetDoorState(door.door_id, *state)) {
      problems.push_back("cannot set door '" + door.door_id +
                         "': unknown door, or an opening cannot be closed");
    }
  }
  return problems;
}

}  // namespace spott_map::ros_conversions
