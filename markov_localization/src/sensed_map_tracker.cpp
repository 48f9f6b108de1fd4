#include "markov_localization/sensed_map_tracker.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "markov_localization/validation.h"
#include "spott_map/pose_algebra.h"

namespace markov_localization {

using spott_map::Pose2;
using spott_map::Vec2;

namespace {

// The rigid motion that turns the map by `yaw` about `pivot`, then shifts it by `shift`.
Pose2 TurnAbout(const Vec2& pivot, double yaw, const Vec2& shift) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {pivot.x() + shift.x() - (c * pivot.x() - s * pivot.y()),
          pivot.y() + shift.y() - (s * pivot.x() + c * pivot.y()), yaw};
}

}  // namespace

std::vector<std::string> ValidateParameters(const SensedMapTrackerParameters& p) {
  std::vector<std::string> e;
  const auto positive = [&](double v, const char* name) {
    if (!(v > 0.0 && std::isfinite(v))) e.push_back(std::string(name) + " must be > 0");
  };
  const auto non_negative = [&](double v, const char* name) {
    if (!(v >= 0.0 && std::isfinite(v))) e.push_back(std::string(name) + " must be >= 0");
  };
  positive(p.period_s, "period_s");
  positive(p.window_s, "window_s");
  positive(p.max_range_m, "max_range_m");
  non_negative(p.min_segment_length_m, "min_segment_length_m");
  non_negative(p.extend_m, "extend_m");
  if (!(p.max_incidence_rad >= 0.0 && p.max_incidence_rad < M_PI / 2))
    e.push_back("max_incidence_rad must be in [0, pi/2)");
  positive(p.gate_m, "gate_m");
  positive(p.huber_m, "huber_m");
  if (!(p.iterations >= 1 && p.iterations <= 100)) e.push_back("iterations must be in [1, 100]");
  if (!(p.min_echoes >= 3)) e.push_back("min_echoes must be >= 3");
  positive(p.min_information, "min_information");
  positive(p.max_correction_m, "max_correction_m");
  positive(p.max_correction_rad, "max_correction_rad");
  for (const std::string& w : ValidateParameters(p.wall_lattice)) e.push_back("wall_lattice/" + w);
  return e;
}

SensedMapTracker::SensedMapTracker(const SensedMapTrackerParameters& p, const Pose2& map_to_odom)
    : p_((ThrowIfInvalid(ValidateParameters(p)), p)),
      map_to_odom_(map_to_odom),
      lattice_(p.wall_lattice) {}

void SensedMapTracker::SetSegments(const std::vector<spott_map::Segment>& segments) {
  walls_.clear();
  for (const spott_map::Segment& s : segments) {
    const double length = s.Length();
    if (!(length >= p_.min_segment_length_m) || !std::isfinite(length) || length <= 0.0) continue;
    const Vec2 u = (s.b - s.a) / length;
    walls_.push_back({s.a, u, Vec2(-u.y(), u.x()), length});
  }
}

void SensedMapTracker::AddRing(double time_s, const Pose2& odom_base,
                               const std::vector<Pose2>& mounts, const std::vector<double>& ranges,
                               double min_range_m, double max_range_m, double field_of_view_rad) {
  const std::size_t n = std::min(mounts.size(), ranges.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double r = ranges[i];
    if (!std::isfinite(r) || r <= min_range_m + 1e-3 || r >= max_range_m - 1e-3) continue;
    if (r > p_.max_range_m) continue;
    const Pose2 t = spott_map::Compose(odom_base, mounts[i]);
    echoes_.push_back({time_s, {t.Position(), t.yaw, r, 0.5 * field_of_view_rad}});
  }
  // Keep the window's echoes only (a clock that went back starts over).
  while (!echoes_.empty() &&
         (echoes_.front().time_s < time_s - p_.window_s || echoes_.front().time_s > time_s)) {
    echoes_.pop_front();
  }
}

void SensedMapTracker::Reset(const Pose2& map_to_odom, double now_s) {
  map_to_odom_ = map_to_odom;
  echoes_.clear();
  lattice_.Clear();
  last_fix_s_ = now_s;
  last_lattice_s_ = now_s;
}

WallLatticeCorrection SensedMapTracker::TurnToLattice(double now_s, const Pose2& odom_base_now) {
  last_lattice_s_ = now_s;
  WallLatticeCorrection c = lattice_.Estimate(now_s, map_to_odom_.yaw);
  if (!c.ok) return c;
  if (std::abs(c.dyaw) > p_.max_correction_rad) {
    c.why = "the correction is larger than max_correction_rad";
    return c;
  }
  const Vec2 robot = spott_map::Compose(map_to_odom_, odom_base_now).Position();
  map_to_odom_ = spott_map::Compose(TurnAbout(robot, c.dyaw, Vec2::Zero()), map_to_odom_);
  c.applied = true;
  return c;
}

SensedMapFix SensedMapTracker::Localize(double now_s, const Pose2& odom_base_now) {
  last_fix_s_ = now_s;
  SensedMapFix fix;

  // Each echo's transducer in the map before the correction.
  std::vector<spott_map::SonarEcho> placed;
  for (const Echo& e : echoes_) {
    if (e.time_s < now_s - p_.window_s || e.time_s > now_s) continue;
    const Pose2 t =
        spott_map::Compose(map_to_odom_, Pose2{e.echo.from.x(), e.echo.from.y(), e.echo.axis});
    placed.push_back({t.Position(), t.yaw, e.echo.range, e.echo.half_cone});
  }
  fix.echoes = static_cast<int>(placed.size());
  // The heading turns about the echoes' centroid: there it is independent of the shift across a
  // wall (about the robot, at the window's end, the two mix and a corridor's heading looks weak).
  Vec2 pivot = spott_map::Compose(map_to_odom_, odom_base_now).Position();
  if (!placed.empty()) {
    Vec2 sum(0.0, 0.0);
    for (const spott_map::SonarEcho& e : placed) sum += e.from;
    pivot = sum / static_cast<double>(placed.size());
  }
  if (walls_.empty()) {
    fix.why = "no sensed segment to match";
    return fix;
  }

  // The correction: x, y, heading (rad) about the pivot.
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();
  const auto moved = [&](const spott_map::SonarEcho& e) {
    const Pose2 p = spott_map::Compose(TurnAbout(pivot, delta.z(), delta.head<2>()),
                                       Pose2{e.from.x(), e.from.y(), e.axis});
    spott_map::SonarEcho m = e;
    m.from = p.Position();
    m.axis = p.yaw;
    return m;
  };
  // The wall that explains an echo best: its predicted echo (the foot of the perpendicular in
  // the cone, else the cone's edge) reflects on the (extended) segment, with the range nearest
  // the echo's, within the gate. `n` points from the wall to the transducer; the predicted range
  // is n . (from - a) * stretch (stretch = 1 / cos of the cone's excess).
  struct Match {
    double residual, stretch;
    Vec2 n;
  };
  const auto associate = [&](const spott_map::SonarEcho& e, Match* m) {
    double best = p_.gate_m;
    bool found = false;
    for (const Wall& w : walls_) {
      const Vec2 n = w.n.dot(e.from - w.a) >= 0.0 ? w.n : Vec2(-w.n);
      const auto predicted = spott_map::PredictEcho(e, n, n.dot(w.a), p_.max_incidence_rad);
      if (!predicted) continue;
      const double along = w.u.dot(predicted->reflection - w.a);
      if (along < -p_.extend_m || along > w.length + p_.extend_m) continue;
      const double residual = e.range - predicted->range;
      if (std::abs(residual) < best) {
        best = std::abs(residual);
        *m = {residual, 1.0 / std::cos(predicted->excess), n};
        found = true;
      }
    }
    return found;
  };

  const double lever = 1.0;  // heading's information compared with a metre's
  double rms_first = -1.0;
  int matched = 0;
  int constrained = 0;
  for (int iteration = 0; iteration < p_.iterations; ++iteration) {
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();         // the weighted normal equations
    Eigen::Matrix3d geometry = Eigen::Matrix3d::Zero();  // unweighted: which directions echoes fix
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    double squares = 0.0;
    matched = 0;
    for (const spott_map::SonarEcho& e : placed) {
      const spott_map::SonarEcho now = moved(e);
      const Vec2& at = now.from;
      Match m;
      if (!associate(now, &m)) continue;
      ++matched;
      squares += m.residual * m.residual;
      const double a = std::abs(m.residual);
      const double w = a <= p_.huber_m ? 1.0 : p_.huber_m / a;
      // residual = range - stretch * n.(at - wall): d residual / d(x, y, heading), the cone's
      // excess held (its change with the heading is second order for a fix's few degrees).
      const Vec2 lever_arm = at - pivot - delta.head<2>();
      const Vec2 g_at = -m.stretch * m.n;
      const Eigen::Vector3d j(
          g_at.x(), g_at.y(),
          p_.correct_heading ? g_at.dot(Vec2(-lever_arm.y(), lever_arm.x())) / lever : 0.0);
      h += w * j * j.transpose();
      geometry += j * j.transpose();
      g -= w * j * m.residual;
    }
    const double rms = matched ? std::sqrt(squares / matched) : 0.0;
    if (rms_first < 0.0) rms_first = rms;
    fix.rms_after_m = rms;
    if (matched < p_.min_echoes) break;
    // Only the directions the echoes fix move (the heading scaled by the lever). Which ones is
    // the geometry's (unweighted: an end wall's echoes far off in the first step still count);
    // the step in them solves the weighted equations.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(geometry);
    Eigen::Matrix<double, 3, Eigen::Dynamic> basis(3, 0);
    for (int k = 0; k < 3; ++k) {
      if (!(eigen.eigenvalues()(k) >= p_.min_information)) continue;
      basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
      basis.col(basis.cols() - 1) = eigen.eigenvectors().col(k);
    }
    constrained = static_cast<int>(basis.cols());
    fix.heading_information = geometry(2, 2) * lever * lever;
    if (constrained == 0) break;
    const Eigen::MatrixXd reduced = basis.transpose() * h * basis;
    const Eigen::Vector3d step = basis * reduced.ldlt().solve(basis.transpose() * g);
    delta += Eigen::Vector3d(step.x(), step.y(), step.z() / lever);
    if (step.head<2>().norm() < 1e-4 && std::abs(step.z()) < 1e-5) break;
  }
  fix.rms_before_m = std::max(0.0, rms_first);
  fix.matched = matched;
  fix.constrained = constrained;
  fix.dx = delta.x();
  fix.dy = delta.y();
  fix.dyaw = delta.z();
  if (matched < p_.min_echoes) {
    fix.why = "too few echoes match the sensed segments (" + std::to_string(matched) + " of " +
              std::to_string(placed.size()) + ")";
    return fix;
  }
  if (constrained == 0) {
    fix.why = "the echoes fix no direction";
    return fix;
  }
  if (delta.head<2>().norm() > p_.max_correction_m || std::abs(delta.z()) > p_.max_correction_rad) {
    fix.why = "the correction is larger than max_correction_m / max_correction_rad";
    return fix;
  }
  // map -> odom moves by the correction: (R(dyaw) about the pivot, then the shift) * map -> odom.
  map_to_odom_ = spott_map::Compose(TurnAbout(pivot, delta.z(), delta.head<2>()), map_to_odom_);
  fix.applied = true;
  return fix;
}

}  // namespace markov_localization
