#include "spott_global_planner/window_tracker.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spott_global_planner {

using spott_map::Box;
using spott_map::Vec2;

namespace {

std::string Violation(const char* name, const std::string& rule, double value) {
  std::ostringstream out;
  out << name << " must be " << rule << " (got " << value << ")";
  return out.str();
}

}  // namespace

std::vector<std::string> ValidateParameters(const WindowParameters& p) {
  std::vector<std::string> v;
  const auto positive = [&v](const char* name, double value) {
    if (!(std::isfinite(value) && value > 0.0)) v.push_back(Violation(name, "> 0", value));
  };
  positive("window_size_m", p.window_size_m);
  positive("resolution_m", p.resolution_m);
  positive("max_window_size_m", p.max_window_size_m);
  if (!(std::isfinite(p.recentre_margin_m) && p.recentre_margin_m >= 0.0)) {
    v.push_back(Violation("recentre_margin_m", ">= 0", p.recentre_margin_m));
  }
  if (v.empty()) {
    if (p.resolution_m > p.window_size_m) {
      v.push_back(Violation("resolution_m", "<= window_size_m", p.resolution_m));
    }
    if (p.recentre_margin_m >= 0.5 * p.window_size_m) {
      v.push_back(Violation("recentre_margin_m", "< window_size_m / 2", p.recentre_margin_m));
    }
    if (p.max_window_size_m < p.window_size_m) {
      v.push_back(Violation("max_window_size_m", ">= window_size_m", p.max_window_size_m));
    }
    // WindowAround counts the cells in an int; the local planner takes at most 8192 across
    // (spott_map::LocalMapParameters).
    if (p.max_window_size_m / p.resolution_m > 8192.5) {
      v.push_back(Violation("max_window_size_m", "at most 8192 cells of resolution_m across",
                            p.max_window_size_m));
    }
  }
  return v;
}

Box WindowAround(const Vec2& centre, double size_m, double resolution_m) {
  const int cells = std::max(1, static_cast<int>(std::lround(size_m / resolution_m)));
  return spott_map::LatticeWindow(centre, cells, resolution_m);
}

double SideToHold(const Vec2& centre, const spott_map::Polygon& polygon, double resolution_m) {
  double half = 0.0;
  for (const Vec2& v : polygon) half = std::max(half, (v - centre).cwiseAbs().maxCoeff());
  // One extra cell on each side absorbs the snapping of the corner to the lattice.
  return (std::ceil(2.0 * half / resolution_m) + 2.0) * resolution_m;
}

WindowTracker::WindowTracker(const WindowParameters& params) : params_(params) {
  const auto violations = ValidateParameters(params);
  if (!violations.empty()) {
    std::string text = "invalid window parameters:";
    for (const auto& s : violations) text += " " + s + ";";
    throw std::invalid_argument(text);
  }
}

bool WindowTracker::Update(const Vec2& robot, const spott_map::Polygon* node) {
  double side = params_.window_size_m;
  if (params_.fit_node && node != nullptr && !node->empty()) {
    side = std::clamp(SideToHold(robot, *node, params_.resolution_m), params_.window_size_m,
                      params_.max_window_size_m);
  }
  bool move = !placed_;
  if (placed_) {
    const Box inner = window_.Inflated(-params_.recentre_margin_m);
    move = !inner.Contains(robot);
    // fit_node: a node that no longer fits (the robot walked into a bigger one) re-sizes.
    if (params_.fit_node && node != nullptr && !node->empty()) {
      const Box b = spott_map::BoundingBox(*node);
      const double current = (window_.max - window_.min).x();
      const bool holds = window_.Contains(b.min) && window_.Contains(b.max);
      if (!holds && current < params_.max_window_size_m) move = true;
    }
  }
  if (!move) return false;
  const Box next = WindowAround(robot, side, params_.resolution_m);
  const bool changed =
      !placed_ || (next.min - window_.min).norm() > 1e-9 || (next.max - window_.max).norm() > 1e-9;
  window_ = next;
  placed_ = true;
  return changed;
}

}  // namespace spott_global_planner
