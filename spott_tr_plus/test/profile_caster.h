// A range-profile caster for the recognition tests: a small scene of upright boxes and cylinders
// standing on the floor, like robot_sim's solids, seen by a QUADRIS head at the Nomad's 0.85 m
// (64 samples over 0.7 rad, 4 m range), horizontal or vertical.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "spott_tr_plus/controller/object_recognition.h"

namespace spott_tr_plus::test_scene {

using controller::ProfileSample;
using controller::Vec3;
using spott_map::Vec2;

constexpr double kHeadZ = 0.85, kField = 0.7, kMaxRange = 4.0;
constexpr int kSamples = 64;

// An upright extrusion standing on the floor: a box (sides sx, sy, turned by yaw) or a cylinder
// (diameter sx).
struct Solid {
  Vec2 centre;
  double yaw, sx, sy, height;
  bool cylinder;
};

// Entry distance along the ray o + t d into `s` (t > 0), if any.
inline std::optional<double> Hit(const Solid& s, const Vec3& o, const Vec3& d) {
  double t0 = 0.0, t1 = 1e9;
  const auto slab = [&](double oo, double dd, double lo, double hi) {
    if (std::abs(dd) < 1e-12) return oo >= lo && oo <= hi;
    double a = (lo - oo) / dd, b = (hi - oo) / dd;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    return t0 <= t1;
  };
  if (!slab(o.z(), d.z(), 0.0, s.height)) return std::nullopt;
  const Vec2 p = o.head<2>() - s.centre;
  if (s.cylinder) {
    const Vec2 dd = d.head<2>();
    const double r = s.sx / 2, a = dd.squaredNorm(), b = 2 * p.dot(dd), c = p.squaredNorm() - r * r;
    if (a < 1e-12) return c <= 0 ? std::optional<double>(t0) : std::nullopt;
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return std::nullopt;
    t0 = std::max(t0, (-b - std::sqrt(disc)) / (2 * a));
    t1 = std::min(t1, (-b + std::sqrt(disc)) / (2 * a));
  } else {
    const double c = std::cos(s.yaw), sn = std::sin(s.yaw);
    const Vec2 lp(c * p.x() + sn * p.y(), -sn * p.x() + c * p.y());
    const Vec2 ld(c * d.x() + sn * d.y(), -sn * d.x() + c * d.y());
    if (!slab(lp.x(), ld.x(), -s.sx / 2, s.sx / 2) || !slab(lp.y(), ld.y(), -s.sy / 2, s.sy / 2))
      return std::nullopt;
  }
  if (t0 > t1 || t1 <= 0) return std::nullopt;
  return t0;
}

// `tilt`: the head pitched down (rad), as robot_sim's heads.
inline std::vector<ProfileSample> Cast(const std::vector<Solid>& scene, const Vec3& o, double pan,
                                       bool vertical, double tilt = 0.0) {
  std::vector<ProfileSample> out;
  for (int i = 0; i < kSamples; ++i) {
    const double a = -kField / 2 + kField * i / (kSamples - 1);
    const double az = vertical ? pan : pan + a, el = (vertical ? a : 0.0) - tilt;
    const Vec3 d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    double t = kMaxRange;
    if (d.z() < 0) t = std::min(t, -o.z() / d.z());  // the floor
    for (const Solid& s : scene) {
      if (auto h = Hit(s, o, d)) t = std::min(t, *h);
    }
    out.push_back({o + t * d, t < kMaxRange});
  }
  return out;
}

}  // namespace spott_tr_plus::test_scene
