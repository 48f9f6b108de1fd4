// The harmonic potential of SPOTT's local planner (III.D.1) over the padded local occupancy
// window: obstacles (already padded by robot radius plus the largest localization error,
// footnote 15, by spott_map::OccupancyRaster) and every window border cell hold the high
// Dirichlet value, the goal (a point inside the window, or the projected border segment of
// Fig. 14) the low one; the free cells satisfy the discrete Laplace equation.
//
// Complement storage (the long-corridor fix, see README "Long corridors"): the field stores
// p = 1 - u, the probability that a random walk from a cell reaches the goal before an obstacle
// (u is the paper's potential: obstacles 1, goal 0). In a corridor p decays like
// exp(-pi d / w), so u = 1 - p rounds to exactly 1 once p < 2^-53 (about 11.7 widths in
// double, 5 in float), and neighbours become indistinguishable (the paper's footnote 16).
// Stored as p, the same values keep their relative precision down to 1e-308 (about 225
// widths). Steepest descent of u is steepest ascent of p; every accessor that says
// "potential" returns u.
//
// Not thread-safe. Coordinates: metres in the frame of the raster (map); cell (ix, iy) as in
// spott_map::OccupancyRaster.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "spott_harmonic_planner/solver.h"
#include "spott_map/geometry.h"
#include "spott_map/occupancy_raster.h"

namespace spott_harmonic_planner {

using spott_map::Vec2;

namespace internal {
class ThinRegionSolver;
}

enum class ResidualNorm {
  /// max |r_i|: refused by ValidateFieldOptions with every solver (it reports converged while
  /// far cells still hold p <= 0); kept so that a configuration naming it is refused by name.
  kAbsolute,
  kRelative,  ///< max |r_i| / p_i: every cell resolved to its own magnitude (long corridors).
};

struct FieldOptions {
  SolverOptions solver;
  /// Convergence: residual norm below this, in (0, 1). 1e-4 keeps the steepest-descent path
  /// within 0.03 cells of the exactly solved field's on every benchmark grid (README).
  double tolerance = 1e-4;
  ResidualNorm norm = ResidualNorm::kRelative;  ///< The node's default too.
  /// Decay per cell of the heuristic initial guess exp(-k d), d = wavefront distance (cells);
  /// > 0. pi / 15: the decay of a harmonic function in a corridor 15 cells wide.
  double heuristic_decay_per_cell = 0.2;
  /// With a start (SetStart, the robot): the field is resolved where descent from the start can
  /// go, the cells with p >= start_fraction * p(start) (relative residual below the tolerance,
  /// and a strictly higher neighbour in each); the others only need an absolute residual below
  /// tolerance * start_fraction * p(start). In [0, 1]; 0 (or no start): every cell relative.
  double start_fraction = 0.1;
};

std::vector<std::string> ValidateFieldOptions(const FieldOptions& options);

struct IterationReport {
  int sweeps = 0;  ///< Iterations (sweeps / line passes / V-cycles) since the last cold start.
  double residual = 0.0;  ///< In the chosen norm, after the last iteration.
  /// residual < tolerance, and where that is judged (every cell, or those above the start's
  /// focus) every cell has a strictly higher 4-neighbour: discrete descent reaches the goal.
  bool converged = false;
};

/// Cell kinds of the Dirichlet problem.
enum class FieldCell : std::uint8_t {
  kFree = 0,         ///< An unknown of the Laplace equation, connected to the goal.
  kObstacle = 1,     ///< Padded obstacle or window border: u = 1 (p = 0).
  kGoal = 2,         ///< u = 0 (p = 1).
  kUnreachable = 3,  ///< Free but cut off from the goal: the exact solution is u = 1 (p = 0).
};

class PotentialField {
 public:
  /// Throws std::invalid_argument on invalid options.
  explicit PotentialField(const FieldOptions& options);
  ~PotentialField();
  PotentialField(PotentialField&&) noexcept;
  PotentialField& operator=(PotentialField&&) noexcept;

  /// Loads the window: blocked cells of `raster` (obstacle or padding) and its border ring become
  /// obstacles. Keeps the current values where the window geometry is unchanged (warm start
  /// after a map update) and moves them with a window shifted by whole cells (less than half the
  /// window, point goal: the re-centred window); otherwise the field is cold. The goal is kept
  /// when it is still valid (a border goal is dropped by a shift).
  void SetOccupancy(const spott_map::OccupancyRaster& raster);

  /// Goal at the cell holding `p`. False (goal unchanged) when `p` is outside the window or in
  /// a blocked cell.
  bool SetGoalPoint(const Vec2& p);
  /// Goal on the window border: every border cell within `half_width_m` of the segment (the
  /// thick line of Fig. 14). False when no border cell qualifies.
  bool SetGoalSegment(const spott_map::Segment& s, double half_width_m);
  bool HasGoal() const { return goal_count_ > 0; }

  /// The start of the plan (the robot's position): convergence is judged where descent from it
  /// can go (FieldOptions::start_fraction), as navfn's propagation stops at the start. False (no
  /// start: the whole field is judged) outside the window or in a blocked cell. A start whose
  /// p is lower than the one the field was converged for makes the field not converged.
  bool SetStart(const Vec2& p);
  void ClearStart();
  bool HasStart() const { return start_ != kNoCell; }
  bool goal_on_border() const { return goal_on_border_; }

  /// Anytime initial guess (III.D.1). The multigrid solvers: full multigrid (about one V-cycle
  /// of work), and with multigrid_cg a thin free region (a corridor) is solved exactly here. SOR
  /// and ADI: p = exp(-k d) with d the 8-connected wavefront distance (chamfer 5/7, in cells)
  /// from the goal through free cells; 0 where the goal cannot be reached (which is exact).
  /// Resets the sweep count; the residual is judged from the first iteration on (report():
  /// infinite, not converged; the exact solve of a thin region is judged at once).
  void ColdStart();
  /// `sweeps` more iterations (warm). Returns the state after them. With the relative norm,
  /// once the solver stalls at round-off the cells below the resolved scale are solved in
  /// stages of their own (multigrid solvers) or by line Gauss-Seidel (SOR, ADI); each counts.
  /// `converged` is reported only after the true residual met the tolerance.
  IterationReport Iterate(int sweeps);
  /// Iterates until converged or `max_sweeps` more iterations were spent.
  IterationReport Solve(int max_sweeps);
  IterationReport report() const { return report_; }
  /// The residual in the field's norm: max |r_i| / max(p_i, start_fraction * p(start)).
  double Residual() const;

  // --- Geometry and values.
  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const Vec2& origin() const { return origin_; }
  FieldCell cell(int ix, int iy) const { return kind_[Index(ix, iy)]; }
  /// p (complement storage): 1 at the goal, 0 at obstacles.
  double GoalProbability(int ix, int iy) const { return p_[Index(ix, iy)]; }
  /// u = 1 - p: the paper's potential (obstacles 1, goal 0), rounded as double stores it.
  double Potential(int ix, int iy) const { return 1.0 - p_[Index(ix, iy)]; }
  /// ln p, also where p is below double's range (values() and GoalProbability() hold 0 there:
  /// corridors beyond about 280 widths, solved exactly with a binary exponent per level);
  /// -infinity where p = 0.
  double LogGoalProbability(int ix, int iy) const;
  /// True when some cell's p lies below double's range (see LogGoalProbability).
  bool extended_range() const { return extended_; }
  const std::vector<double>& values() const { return p_; }
  const std::vector<FieldCell>& cells() const { return kind_; }
  std::optional<std::pair<int, int>> CellOf(const Vec2& p) const;
  Vec2 CellCentre(int ix, int iy) const;

  /// Steepest-descent direction of u (unit vector, map frame) at a continuous position, from
  /// the gradient of the bilinear interpolant of p between the four nearest cell centres.
  /// nullopt outside the window, in a blocked cell, or where the field is flat (p = 0: the goal
  /// is unreachable from there, or the field is not yet initialized).
  std::optional<Vec2> DescentDirection(const Vec2& p) const;
  /// The cheap heuristic potential of the paper's anytime scheme ([46], Khatib): attraction to
  /// the nearest goal cell plus repulsion 1/d^2 from the blocked cells within `influence_cells`
  /// of `p`. Answers at once, before any sweep, from the loaded window and goal; it can have local
  /// minima (which is why the harmonic field replaces it). nullopt outside the window or with no
  /// goal.
  std::optional<Vec2> HeuristicDirection(const Vec2& p, int influence_cells = 3) const;
  /// Bilinear interpolation of p at a continuous position (0 outside).
  double InterpolatedGoalProbability(const Vec2& p) const;

  struct Path {
    std::vector<Vec2> points;  ///< From the start to the goal (or to where it stopped).
    bool reached_goal = false;
    bool entered_obstacle = false;
    double length_m = 0.0;
  };
  /// Integrates steepest descent from `start` with steps of `step_cells` cells (midpoint rule);
  /// where the interpolated gradient vanishes it steps to the best 8-neighbour cell.
  Path DescendPath(const Vec2& start, double step_cells = 0.5, int max_steps = 0) const;

  /// The 8-neighbour with the largest p, if larger than the cell's own (no obstacles, no
  /// diagonal step past an obstacle corner): one step of discrete steepest descent.
  std::optional<std::pair<int, int>> BestNeighbour(int ix, int iy) const;

  /// Not thread-safe even though const: the distance transform is computed on first use.
  /// Distance (m) from `p` to the nearest obstacle cell's square (border ring included).
  double Clearance(const Vec2& p) const;

 private:
  std::size_t Index(int ix, int iy) const {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(ix);
  }
  static constexpr std::size_t kNoCell = static_cast<std::size_t>(-1);
  void RebuildMask(bool kinds_fresh);
  // start_fraction * p(start), or 0 without a start.
  double Floor() const;
  // Marks the field converged when `residual` meets the tolerance and every cell above the
  // floor has a strictly higher neighbour (discrete descent from the start reaches the goal).
  void Judge(double residual, const std::size_t* deficit = nullptr);
  // After a cold start: no iteration yet, residual infinite (not computed), not converged.
  void NotJudged();
  bool ShiftWarm(const Vec2& old_origin);
  void ComputeClearance() const;
  void EnsureSetup();
  struct Norms {
    double absolute = 0.0;
    double relative = 0.0;
    std::size_t deficit = 0;  // cells where ascent stops (AscentDeficit), when has_deficit
    bool has_deficit = false;
  };
  Norms ResidualNorms(bool with_deficit = false) const;
  bool ClampNegatives();
  bool DirectSolve();
  // Extended range: p_i = ScaledGoalProbability(i, ref) * 2^ref.
  // The binary exponent of a cell's value; obstacles (p = 0) have none (kNoExponent), so that
  // they never set the scale of a neighbourhood.
  static constexpr int kNoExponent = -(1 << 29);
  int Exponent(std::size_t i) const {
    if (!extended_) return 0;
    if (kind_[i] == FieldCell::kFree) return ext_e_[i];
    return p_[i] > 0.0 ? 0 : kNoExponent;
  }
  int ScaleOf(int a, int b, int c, int d) const {
    const int e = std::max(std::max(a, b), std::max(c, d));
    return e == kNoExponent ? 0 : e;
  }
  double Scaled(std::size_t i, int ref) const {
    if (!extended_) return ref == 0 ? p_[i] : std::ldexp(p_[i], -ref);
    return kind_[i] == FieldCell::kFree ? std::ldexp(ext_m_[i], ext_e_[i] - ref)
                                        : std::ldexp(p_[i], -ref);
  }
  // Bilinear interpolation of p at `p`, as value * 2^ref (ref: the largest exponent of the four
  // cells).
  double InterpolatedScaled(const Vec2& p, int* ref) const;
  bool SegmentClear(const Vec2& a, const Vec2& b) const;
  bool StartTail(double resolved_absolute, double scale);
  Norms IterateTail();

  FieldOptions options_;
  std::unique_ptr<IterativeSolver> solver_;
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 1.0;
  Vec2 origin_{0.0, 0.0};
  std::vector<std::uint8_t> blocked_;  // raster obstacles + border ring
  std::vector<FieldCell> kind_;
  std::vector<double> p_;
  mutable std::vector<float> clearance_cells_;
  mutable bool clearance_ready_ = false;
  std::vector<std::uint32_t> wave_;  // ColdStart's wavefront distances (chamfer 5/7)
  std::vector<double> exp_table_;    // distance transform (cells) to the nearest blocked cell
  GridMask mask_;
  bool solver_ready_ = false;
  std::unique_ptr<IterativeSolver> polish_;  // relative norm: line Gauss-Seidel at the end
  bool polish_ready_ = false;
  bool polishing_ = false;
  double last_relative_ = 0.0;  // the relative residual after the previous iteration
  struct FreeRun {
    int y, x0, x1;
  };
  std::vector<FreeRun> free_runs_;  // runs of kFree cells per row
  std::vector<FreeRun> previous_runs_, fill_stack_;
  std::vector<std::size_t> previous_goals_;
  std::vector<double> shift_scratch_;
  // Tail stages (multigrid solvers): the cells below the resolved scale, solved scaled by it.
  std::unique_ptr<IterativeSolver> tail_solver_;
  GridMask tail_mask_;
  std::vector<FreeRun> tail_runs_, previous_tail_runs_;
  std::vector<double> tail_u_;
  double tail_scale_ = 1.0;
  double tail_last_relative_ = 0.0;
  bool tail_active_ = false;
  std::unique_ptr<internal::ThinRegionSolver> thin_;  // exact solver of thin regions
  bool direct_ = false;                               // the current mask is solved by thin_
  bool direct_solved_ = false;
  bool extended_ = false;  // p below double's range somewhere: ext_m_ * 2^ext_e_
  std::vector<double> ext_m_;
  std::vector<std::int32_t> ext_e_;
  int goal_count_ = 0;
  std::size_t start_ = kNoCell;
  double converged_floor_ = 0.0;  // the floor the current convergence was judged with
  bool goal_on_border_ = false;
  std::vector<std::size_t> goal_cells_;
  IterationReport report_;
};

/// Free cells (reachable, p > 0) from which no 8-neighbour is strictly lower in `values`
/// (lower = closer to the goal): the cells where descent has nowhere to go. `values` is any
/// representation of u (or -p) over the field's grid; goal cells and obstacles are skipped.
template <typename T>
int CountFlatCells(const PotentialField& field, const std::vector<T>& values) {
  int flat = 0;
  for (int y = 1; y < field.height() - 1; ++y) {
    for (int x = 1; x < field.width() - 1; ++x) {
      if (field.cell(x, y) != FieldCell::kFree || field.GoalProbability(x, y) <= 0.0) continue;
      const T v = values[static_cast<std::size_t>(y) * field.width() + x];
      bool lower = false;
      for (int dy = -1; dy <= 1 && !lower; ++dy) {
        for (int dx = -1; dx <= 1 && !lower; ++dx) {
          if (dx == 0 && dy == 0) continue;
          if (field.cell(x + dx, y + dy) == FieldCell::kObstacle) continue;
          lower = values[static_cast<std::size_t>(y + dy) * field.width() + x + dx] < v;
        }
      }
      flat += lower ? 0 : 1;
    }
  }
  return flat;
}

}  // namespace spott_harmonic_planner
