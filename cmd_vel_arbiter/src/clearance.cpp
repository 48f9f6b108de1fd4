#include "cmd_vel_arbiter/clearance.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cmd_vel_arbiter {

namespace {
constexpr double kAtMinimumM = 1e-4;  // a float32 reading of the minimum, within rounding

// An echo at (px, py) in the robot's frame bounds the gap ahead or behind when it lies in the
// corridor the round body sweeps: along x from the body's outline to the echo.
void AddEcho(double px, double py, double radius, double half_width, SpeedBounds& b) {
  if (std::abs(py) >= half_width) return;
  const double body = std::sqrt(std::max(0.0, radius * radius - py * py));
  if (px > 0.0) b.forward_gap_m = std::min(b.forward_gap_m, std::max(0.0, px - body));
  if (px < 0.0) b.backward_gap_m = std::min(b.backward_gap_m, std::max(0.0, -px - body));
}
}  // namespace

std::vector<std::string> ValidateParameters(const ClearanceParameters& p) {
  std::vector<std::string> v;
  const auto in = [&](const char* name, double x, double lo, double hi, bool open_lo) {
    if (!(std::isfinite(x) && (open_lo ? x > lo : x >= lo) && x <= hi)) {
      std::ostringstream m;
      m << "clearance/" << name << " must be in " << (open_lo ? "(" : "[") << lo << ", " << hi
        << "], got " << x;
      v.push_back(m.str());
    }
  };
  in("deceleration_mps2", p.deceleration_mps2, 0.0, 100.0, true);
  in("latency_s", p.latency_s, 0.0, 5.0, false);
  in("stop_margin_m", p.stop_margin_m, 0.0, 2.0, false);
  in("corridor_margin_m", p.corridor_margin_m, 0.0, 1.0, false);
  in("footprint_radius_m", p.footprint_radius_m, 0.0, 10.0, false);
  return v;
}

double StoppingSpeed(double gap_m, const ClearanceParameters& p) {
  if (!std::isfinite(gap_m)) return std::numeric_limits<double>::infinity();
  const double d = gap_m - p.stop_margin_m;
  if (d <= 0.0) return 0.0;
  // v T + v^2 / (2 a) = d  =>  v = -a T + sqrt((a T)^2 + 2 a d)
  const double a = p.deceleration_mps2, aT = a * p.latency_s;
  return -aT + std::sqrt(aT * aT + 2.0 * a * d);
}

SpeedBounds BoundsFromRing(const std::vector<Transducer>& transducers, double field_of_view_rad,
                           double min_range_m, double max_range_m,
                           const std::vector<double>& ranges_m, const ClearanceParameters& p) {
  SpeedBounds b;
  double radius = p.footprint_radius_m;
  if (radius <= 0.0) {
    for (const Transducer& t : transducers) radius = std::max(radius, std::hypot(t.x, t.y));
  }
  const double half_width = radius + p.corridor_margin_m;
  const double half_fov = std::isfinite(field_of_view_rad) ? 0.5 * field_of_view_rad : 0.0;
  const std::size_t n = std::min(transducers.size(), ranges_m.size());
  for (std::size_t i = 0; i < n; ++i) {
    double r = ranges_m[i];
    const Transducer& t = transducers[i];
    // At the minimum (a driver clamps what lies closer to it; robot_sim does) or -Inf (REP 117:
    // too close to measure): from a transducer looking along the motion, the echo may be at its
    // face (read as 0.15 m, a B-12 pushed its front against an unmapped crate at 0.23 m/s for
    // 240 s); from one looking aside it stays at the minimum (applied to every transducer, a
    // Nomad, blind to 0.43 m, stood by a doorway's jambs).
    if (p.min_range_at_face &&
        (r == -std::numeric_limits<double>::infinity() ||
         (r >= min_range_m - kAtMinimumM && r <= min_range_m + kAtMinimumM))) {
      const double ahead = std::abs(std::remainder(t.yaw, 2.0 * M_PI));
      r = ahead <= half_fov || M_PI - ahead <= half_fov ? 0.0 : min_range_m;
    } else if (!std::isfinite(r) || r < min_range_m || r >= max_range_m) {
      continue;
    }
    // The echo lies somewhere on the arc: its ends and middle stand for it.
    for (const double off : {-half_fov, 0.0, half_fov}) {
      AddEcho(t.x + r * std::cos(t.yaw + off), t.y + r * std::sin(t.yaw + off), radius, half_width,
              b);
    }
  }
  b.forward_mps = StoppingSpeed(b.forward_gap_m, p);
  b.backward_mps = StoppingSpeed(b.backward_gap_m, p);
  return b;
}

SpeedBounds BoundsFromScan(const ScanGeometry& scan, const std::vector<double>& ranges_m,
                           double radius_m, const ClearanceParameters& p) {
  SpeedBounds b;
  const double radius = p.footprint_radius_m > 0.0 ? p.footprint_radius_m : radius_m;
  const double half_width = radius + p.corridor_margin_m;
  const Transducer& m = scan.mount;
  for (std::size_t i = 0; i < ranges_m.size(); ++i) {
    const double r = ranges_m[i];
    if (!std::isfinite(r) || r < scan.range_min_m || r >= scan.range_max_m) continue;
    const double a = m.yaw + scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
    AddEcho(m.x + r * std::cos(a), m.y + r * std::sin(a), radius, half_width, b);
  }
  b.forward_mps = StoppingSpeed(b.forward_gap_m, p);
  b.backward_mps = StoppingSpeed(b.backward_gap_m, p);
  return b;
}

RingBoundsSet::RingBoundsSet(std::size_t rings, double max_age_s)
    : rings_(rings), max_age_s_(max_age_s) {}

void RingBoundsSet::Set(std::size_t ring, const SpeedBounds& bounds, double now_s) {
  if (ring >= rings_.size()) return;
  rings_[ring] = Entry{bounds, now_s, true};
}

SpeedBounds RingBoundsSet::Tightest(double now_s, std::vector<std::size_t>* went_silent) {
  SpeedBounds t;
  for (std::size_t i = 0; i < rings_.size(); ++i) {
    Entry& e = rings_[i];
    if (!e.fresh) continue;
    if (now_s - e.time_s > max_age_s_) {
      e.fresh = false;
      if (went_silent) went_silent->push_back(i);
      continue;
    }
    t.forward_mps = std::min(t.forward_mps, e.bounds.forward_mps);
    t.backward_mps = std::min(t.backward_mps, e.bounds.backward_mps);
    t.forward_gap_m = std::min(t.forward_gap_m, e.bounds.forward_gap_m);
    t.backward_gap_m = std::min(t.backward_gap_m, e.bounds.backward_gap_m);
  }
  return t;
}

}  // namespace cmd_vel_arbiter
