#include "spott_tr_plus/controller/sonar_scan.h"

#include <cmath>

#include "spott_map/geometry.h"
#include "violation.h"

namespace spott_tr_plus::controller {

std::vector<std::string> ValidateParameters(const SonarScanParameters& p) {
  std::vector<std::string> v;
  if (!(std::isfinite(p.period_s) && p.period_s >= 0))
    v.push_back(Violation("period_s", ">= 0", p.period_s));
  if (p.steps < 2 || p.steps > 64) v.push_back(Violation("steps", "in [2, 64]", p.steps));
  if (!(p.step_rad > 0 && p.step_rad <= M_PI / 4))
    v.push_back(Violation("step_rad", "in (0, pi/4]", p.step_rad));
  if (!(p.settle_rad > 0 && p.settle_rad < p.step_rad / 2))
    v.push_back(Violation("settle_rad", "in (0, step_rad / 2)", p.settle_rad));
  if (!(std::isfinite(p.step_timeout_s) && p.step_timeout_s > 0))
    v.push_back(Violation("step_timeout_s", "> 0", p.step_timeout_s));
  return v;
}

double SonarScan::TurretAngle(const std::vector<double>& axes) const {
  // Every transducer turns with the turret: their mean offset from home (noise-free here, but
  // a ring with fewer mounts than at home is not comparable).
  if (axes.empty() || axes.size() != home_.size()) return 0.0;
  double sum = 0;
  for (std::size_t i = 0; i < axes.size(); ++i)
    sum += spott_map::NormalizeAngle(axes[i] - home_[i]);
  return sum / static_cast<double>(axes.size());
}

std::optional<double> SonarScan::Ask(double target, double now) {
  target_ = target;
  asked_at_ = now;
  return target;
}

std::optional<double> SonarScan::Ring(const std::vector<double>& axes, bool wanted, double now) {
  std::optional<double> ask;
  switch (state_) {
    case State::kHoming: {
      // The turret's start angle is unknown: asked home once, it is there when two rings
      // agree (a turning turret moves 4.5 degrees between the Nomad's 10 Hz rings).
      if (asked_at_ < -1e299) ask = Ask(0.0, now);
      bool still = !last_.empty() && last_.size() == axes.size();
      for (std::size_t i = 0; still && i < axes.size(); ++i)
        still = std::abs(spott_map::NormalizeAngle(axes[i] - last_[i])) <= p_.settle_rad;
      if (still) {
        home_ = axes;
        state_ = State::kIdle;
        last_end_ = now;
      }
      break;
    }
    case State::kIdle:
      if (available_ && wanted && p_.period_s > 0 && now - last_end_ >= p_.period_s &&
          axes.size() == home_.size()) {
        state_ = State::kStepping;  // this ring, read at home, is the scan's first
        step_ = 1;
        ask = Ask(p_.step_rad, now);
      }
      break;
    case State::kStepping:
      if (std::abs(TurretAngle(axes) - target_) <= p_.settle_rad) {
        if (++step_ < p_.steps) {
          ask = Ask(step_ * p_.step_rad, now);
        } else {
          state_ = State::kReturning;
          ask = Ask(0.0, now);
        }
      } else if (now - asked_at_ > p_.step_timeout_s) {
        available_ = false;  // the turret does not turn
        state_ = State::kReturning;
        ask = Ask(0.0, now);
      }
      break;
    case State::kReturning:
      if (std::abs(TurretAngle(axes)) <= p_.settle_rad || now - asked_at_ > p_.step_timeout_s) {
        if (available_) ++scans_;
        state_ = State::kIdle;
        last_end_ = now;
      }
      break;
  }
  last_ = axes;
  return ask;
}

}  // namespace spott_tr_plus::controller
