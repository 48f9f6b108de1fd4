// The world map of SPOTT section III.A: vector primitives with labels and attributes, the
// abstract room/door graph, the robot's pose and the current task. Sensed features enter only
// when they are not already there; a sensed feature that is already there may relabel it. There
// is no geometric fusion (the paper leaves it out).
//
// Not thread-safe: one owner (the controller node) changes it; copies follow its updates.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "spott_map/map_feature.h"
#include "spott_map/room_door_graph.h"
#include "spott_map/world.h"

namespace spott_map {

class MapDatabase {
 public:
  MapDatabase() = default;

  /// The a priori map of a world: its CAD walls labelled "wall" and its room/door graph.
  /// Objects are not added: they are not in the CAD map.
  static MapDatabase FromWorld(const World& world);

  const std::vector<MapFeature>& features() const { return features_; }
  const MapFeature* FindFeature(const std::string& id) const;
  /// Features whose bounds meet `box`.
  std::vector<const MapFeature*> FeaturesIn(const Box& box) const;

  /// Adds a feature as given (a priori data). False when its id is empty or taken.
  bool AddFeature(MapFeature feature);

  struct AddResult {
    enum class Outcome {
      kAdded,           ///< New: stored under `id`.
      kAlreadyPresent,  ///< Matched feature `id`; nothing changed.
      kRelabelled,      ///< Matched feature `id`, whose label became the sensed one.
    };
    Outcome outcome = Outcome::kAdded;
    std::string id;
  };
  /// Which features a sensed one is matched against.
  enum class MatchAgainst { kAll, kCad };
  /// Adds a sensed feature unless one already there (of those `against` names) matches it
  /// within `tolerance_m` (IsSameFeature). A match with a different, non-empty label relabels
  /// the existing feature. An empty id is replaced by "sensed_<n>".
  AddResult AddSensedFeature(MapFeature feature, double tolerance_m,
                             MatchAgainst against = MatchAgainst::kAll);

  bool RemoveFeature(const std::string& id);
  bool Relabel(const std::string& id, const std::string& label);

  const RoomDoorGraph& graph() const { return graph_; }
  /// False for an unknown door, or for closing an opening.
  bool SetDoorState(const std::string& door_id, DoorState state);
  void SetGraph(RoomDoorGraph graph);

  const std::optional<Pose2>& robot_pose() const { return robot_pose_; }
  void SetRobotPose(const Pose2& pose) { robot_pose_ = pose; }
  const std::string& task() const { return task_; }
  void SetTask(const std::string& task) { task_ = task; }

  /// Increases on every change of features or door states (windows re-cut when it moves).
  std::uint64_t revision() const { return revision_; }

 private:
  std::vector<MapFeature> features_;
  RoomDoorGraph graph_;
  std::optional<Pose2> robot_pose_;
  std::string task_;
  std::uint64_t revision_ = 0;
  std::uint64_t next_sensed_id_ = 0;
};

}  // namespace spott_map
