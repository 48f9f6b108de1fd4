// The local planner's window b_pf as the global planner models it: a square centred (to the
// nearest cell of the global lattice) on the robot, moved when the robot comes within the
// re-centre margin of its border (III.D.1 step f), the same rule as spott_map::LocalMap. When
// the local planner reports its own window the node uses that instead.
//
// The paper's remedy for cases 1 and 2 of Fig. 14 ("make the size of the potential field such
// that the node is completely within the potential field's spatial extent") is the option
// fit_node: the side grows, up to max_window_size_m, until the robot's node lies inside.
#pragma once

#include <string>
#include <vector>

#include "spott_map/geometry.h"

namespace spott_global_planner {

struct WindowParameters {
  double window_size_m = 7.0;      ///< Side of the square window (m), > 0 (paper: 35 x 35 cells).
  double resolution_m = 0.2;       ///< Cell side of the local planner's grid (m), > 0.
  double recentre_margin_m = 1.0;  ///< Re-centre this close to the border (m), [0, size / 2).
  bool fit_node = false;           ///< Grow the window to hold the robot's whole node.
  /// Largest side fit_node may give (m), >= window_size_m and at most 8192 cells of resolution_m
  /// (the local planner's limit).
  double max_window_size_m = 30.0;
};

/// Every violated constraint, naming its parameter ("window_size_m must be > 0 (got -1)").
std::vector<std::string> ValidateParameters(const WindowParameters& p);

/// The square of side `size_m` (rounded to whole cells) centred on `centre`, snapped to the
/// lattice of `resolution_m` by spott_map::LatticeWindow, as the local map is.
spott_map::Box WindowAround(const spott_map::Vec2& centre, double size_m, double resolution_m);

/// The smallest side, a whole number of cells, of a window centred on `centre` that holds
/// `polygon` (m).
double SideToHold(const spott_map::Vec2& centre, const spott_map::Polygon& polygon,
                  double resolution_m);

class WindowTracker {
 public:
  /// Throws std::invalid_argument listing every violation.
  explicit WindowTracker(const WindowParameters& params);

  /// Places the window for the robot at `robot` in node `node` (null when it is in none).
  /// Returns true when the window moved or changed size.
  bool Update(const spott_map::Vec2& robot, const spott_map::Polygon* node);
  /// Forces a re-centre at the next Update.
  void Reset() { placed_ = false; }
  bool placed() const { return placed_; }
  const spott_map::Box& window() const { return window_; }
  const WindowParameters& parameters() const { return params_; }

 private:
  WindowParameters params_;
  spott_map::Box window_;
  bool placed_ = false;
};

}  // namespace spott_global_planner
