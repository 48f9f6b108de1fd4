#include "spott_harmonic_planner/contact_memory.h"

#include <algorithm>
#include <cmath>

namespace spott_harmonic_planner {

void ContactMemory::Add(const spott_map::Pose2& robot, double radius_m, double angle_rad,
                        double now_s) {
  const double a = robot.yaw + angle_rad;
  // Half the disc beyond the body's surface: the obstacle touched it from outside.
  const double r = radius_m + size_m_ / 2.0;
  const spott_map::Vec2 p(robot.x + r * std::cos(a), robot.y + r * std::sin(a));
  for (Kept& k : contacts_) {
    if ((k.point - p).norm() < size_m_) {
      k.time_s = now_s;
      return;
    }
  }
  contacts_.push_back({p, now_s, next_id_++});
}

bool ContactMemory::Expire(double now_s) {
  const std::size_t before = contacts_.size();
  contacts_.erase(std::remove_if(contacts_.begin(), contacts_.end(),
                                 [&](const Kept& k) { return now_s - k.time_s > memory_s_; }),
                  contacts_.end());
  return contacts_.size() != before;
}

std::vector<spott_map::MapFeature> ContactMemory::Features() const {
  std::vector<spott_map::MapFeature> out;
  for (const Kept& k : contacts_) {
    spott_map::MapFeature f;
    f.id = "contact_" + std::to_string(k.id);
    f.type = spott_map::FeatureType::kEllipse;
    f.source = spott_map::FeatureSource::kSensed;
    f.label = "contact";
    f.pose = spott_map::Pose2{k.point.x(), k.point.y(), 0.0};
    f.size_x = f.size_y = size_m_;
    out.push_back(f);
  }
  return out;
}

}  // namespace spott_harmonic_planner
