#include "robot_sim/range_sensors.h"

#include <algorithm>
#include <cmath>

#include "spott_map/geometry.h"

namespace robot_sim {

namespace {

constexpr double kEps = 1e-4;  // Offset of a reflected ray's start off the surface (m).

Eigen::Vector3d Heading(double yaw, double elevation) {
  const double c = std::cos(elevation);
  return {c * std::cos(yaw), c * std::sin(yaw), std::sin(elevation)};
}

// Incidence angle between a ray and a surface normal, in the horizontal plane (rad).
double Incidence(const Eigen::Vector3d& dir, const Eigen::Vector3d& normal) {
  Eigen::Vector3d n(normal.x(), normal.y(), 0.0);
  if (n.norm() < 1e-9) return 0.0;
  n.normalize();
  return std::acos(std::clamp(-dir.dot(n), -1.0, 1.0));
}

using spott_map::NormalizeAngle;

double Noisy(double range, const RangeRingSpec& ring, double unit_normal) {
  return range + unit_normal * (ring.noise_stddev + ring.noise_per_metre * range);
}

}  // namespace

TransducerPose PlaceMount(const Mount& mount, const spott_map::Pose2& robot, double turret_yaw) {
  const double a = robot.yaw + turret_yaw;
  const double c = std::cos(a), s = std::sin(a);
  TransducerPose t;
  t.origin = {robot.x + c * mount.x - s * mount.y, robot.y + s * mount.x + c * mount.y, mount.z};
  t.yaw = NormalizeAngle(a + mount.yaw);
  return t;
}

namespace {

// The echo one ray of a transducer's cone returns (m), or max_range.
double EchoOfRay(const SimWorld& world, const RangeRingSpec& ring, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& dir, const btCollisionObject* self,
                 std::vector<ScatterPoint>* scatter) {
  const auto hit = world.CastRay(origin, origin + dir * ring.max_range, self);
  if (!hit) return ring.max_range;
  if (std::abs(hit->normal.z()) > 0.7) {
    // A solid's top met by a tilted ray: at grazing incidence the pulse glances off, upward or
    // to the floor (not followed); it scatters back only within the critical angle.
    const double incidence = std::acos(std::clamp(std::abs(dir.dot(hit->normal)), 0.0, 1.0));
    if (incidence > ring.critical_angle) return ring.max_range;
    if (scatter) scatter->push_back({hit->point, hit->distance});
    return hit->distance;
  }
  if (Incidence(dir, hit->normal) <= ring.critical_angle) {
    if (scatter) scatter->push_back({hit->point, hit->distance});
    return hit->distance;
  }
  // Specular: follow the reflected pulse to a second surface; if that one scatters, the echo
  // comes back the same way (a multipath reading of the whole path).
  const double left = ring.max_range - hit->distance;
  if (left <= 0) return ring.max_range;
  Eigen::Vector3d n(hit->normal.x(), hit->normal.y(), 0.0);
  n.normalize();
  const Eigen::Vector3d reflected = dir - 2 * dir.dot(n) * n;
  const Eigen::Vector3d start = hit->point + reflected * kEps;
  const auto second = world.CastRay(start, start + reflected * left, self);
  if (!second || Incidence(reflected, second->normal) > ring.critical_angle) return ring.max_range;
  const double path = hit->distance + second->distance;
  if (scatter) scatter->push_back({second->point, path});
  return std::min(path, ring.max_range);
}

}  // namespace

double EchoRange(const SimWorld& world, const RangeRingSpec& ring, const TransducerPose& t,
                 const btCollisionObject* self, std::vector<ScatterPoint>* scatter) {
  double best = ring.max_range;
  const double half = ring.field_of_view / 2;
  for (int row = 0; row < ring.vertical_rays; ++row) {
    // A circular cone: rows across its height, each as wide as the cone is at that elevation.
    const double elevation = -half + (row + 0.5) * ring.field_of_view / ring.vertical_rays;
    const double width = std::sqrt(std::max(half * half - elevation * elevation, 0.0));
    for (int k = 0; k < ring.rays; ++k) {
      const double offset = ring.rays == 1 ? 0.0 : -width + k * 2 * width / (ring.rays - 1);
      best = std::min(best, EchoOfRay(world, ring, t.origin, Heading(t.yaw + offset, elevation),
                                      self, scatter));
    }
  }
  return best;
}

std::vector<double> SenseRangeRing(const SimWorld& world, const RangeRingSpec& ring,
                                   const std::vector<TransducerPose>& poses,
                                   const btCollisionObject* self, Rng& rng) {
  const int n = static_cast<int>(poses.size());
  const int groups = std::clamp(ring.fire_groups, 1, std::max(n, 1));
  std::vector<double> clean(n, ring.max_range);
  std::vector<std::vector<ScatterPoint>> scatter(n);
  for (int i = 0; i < n; ++i) clean[i] = EchoRange(world, ring, poses[i], self, &scatter[i]);
  // Crosstalk: transducer i hears j's pulse scattered at P when P lies in i's cone and i sees P.
  std::vector<double> heard = clean;
  if (groups < n) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if (j == i || j % groups != i % groups) continue;
        for (const ScatterPoint& p : scatter[j]) {
          const Eigen::Vector3d back = p.point - poses[i].origin;
          const double back_m = back.norm();
          const double range = (p.path_m + back_m) / 2;
          if (range >= heard[i]) continue;
          const double bearing = std::atan2(back.y(), back.x());
          if (std::abs(NormalizeAngle(bearing - poses[i].yaw)) > ring.field_of_view / 2) continue;
          const auto blocked = world.CastRay(poses[i].origin, p.point - back / back_m * 0.01, self);
          if (blocked) continue;
          heard[i] = range;
        }
      }
    }
  }
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> out(n);
  for (int i = 0; i < n; ++i) {
    const double z = unit(rng);  // drawn for every transducer: a stable random stream
    if (heard[i] >= ring.max_range) {
      out[i] = ring.max_range;
    } else {
      out[i] = std::clamp(Noisy(heard[i], ring, z), ring.min_range, ring.max_range);
    }
  }
  return out;
}

std::vector<double> SenseLaser(const SimWorld& world, const LaserSpec& laser,
                               const TransducerPose& pose, const btCollisionObject* self,
                               Rng& rng) {
  std::vector<double> ranges(laser.beams);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double step = (laser.angle_max - laser.angle_min) / (laser.beams - 1);
  for (int b = 0; b < laser.beams; ++b) {
    const Eigen::Vector3d dir = Heading(pose.yaw + laser.angle_min + b * step, 0.0);
    const double z = noise(rng);
    const auto hit = world.CastRay(pose.origin, pose.origin + dir * laser.max_range, self);
    if (!hit) {
      ranges[b] = std::numeric_limits<double>::infinity();
      continue;
    }
    ranges[b] =
        std::clamp(hit->distance + z * laser.noise_stddev, laser.min_range, laser.max_range);
  }
  return ranges;
}

std::vector<double> SenseProfile(const SimWorld& world, const ProfilerSpec& profiler,
                                 const TransducerPose& head, double tilt, bool horizontal,
                                 const btCollisionObject* self, Rng& rng,
                                 std::vector<double>* angles) {
  std::vector<double> ranges(profiler.samples);
  if (angles) angles->resize(profiler.samples);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double step = profiler.field_of_view / (profiler.samples - 1);
  for (int k = 0; k < profiler.samples; ++k) {
    const double a = -profiler.field_of_view / 2 + k * step;
    if (angles) (*angles)[k] = a;
    // Direction in the head frame, then pitched by the tilt and turned by the heading.
    const double yaw = head.yaw + (horizontal ? a : 0.0);
    const double pitch = tilt + (horizontal ? 0.0 : a);
    const Eigen::Vector3d dir(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                              -std::sin(pitch));
    const double z = noise(rng);
    double range = profiler.max_range;
    if (const auto hit = world.CastRay(head.origin, head.origin + dir * profiler.max_range, self)) {
      range = hit->distance;
    }
    if (dir.z() < -1e-12) range = std::min(range, -head.origin.z() / dir.z());  // the floor
    ranges[k] = range >= profiler.max_range ? profiler.max_range
                                            : std::clamp(range + z * profiler.noise_stddev,
                                                         profiler.min_range, profiler.max_range);
  }
  return ranges;
}

std::vector<bool> BumperSegments(const BumperSpec& bumper, const std::vector<double>& angles) {
  std::vector<bool> pressed(bumper.segments, false);
  const double width = 2 * M_PI / bumper.segments;
  for (double a : angles) {
    double u = std::fmod(a + width / 2, 2 * M_PI);
    if (u < 0) u += 2 * M_PI;
    const int s = std::min(static_cast<int>(u / width), bumper.segments - 1);
    pressed[s] = true;
  }
  return pressed;
}

}  // namespace robot_sim
