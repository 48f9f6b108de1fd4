// Bumper contacts the local planner remembers as obstacles (until SPOTT's TR+ controller, which
// owns the sensed map, records them for every copy): a pressed segment marks the point where
// the robot's body touched something the map lacks, so the next descent goes around it.
#pragma once

#include <vector>

#include "spott_map/map_feature.h"

namespace spott_harmonic_planner {

class ContactMemory {
 public:
  /// Contacts are kept `memory_s` seconds (> 0) as discs of diameter `size_m` (> 0).
  ContactMemory(double memory_s, double size_m) : memory_s_(memory_s), size_m_(size_m) {}

  /// The contact point on the body: `robot` (map) plus `radius_m` along `angle_rad` (base frame)
  /// turned by the robot's heading. A contact within size_m of a kept one renews it.
  void Add(const spott_map::Pose2& robot, double radius_m, double angle_rad, double now_s);
  /// Forgets contacts older than memory_s; true when one was forgotten.
  bool Expire(double now_s);
  /// The kept contacts as sensed ellipse features labelled "contact".
  std::vector<spott_map::MapFeature> Features() const;
  std::size_t size() const { return contacts_.size(); }

 private:
  struct Kept {
    spott_map::Vec2 point;
    double time_s;
    int id;
  };
  double memory_s_, size_m_;
  std::vector<Kept> contacts_;
  int next_id_ = 0;
};

}  // namespace spott_harmonic_planner
