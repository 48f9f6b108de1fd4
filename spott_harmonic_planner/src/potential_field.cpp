#include "spott_harmonic_planner/potential_field.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "kernels.h"
#include "mg_kernels.h"
#include "thin_direct.h"

namespace spott_harmonic_planner {

namespace {
constexpr double kSqrt2 = 1.4142135623730951;
// In the relative norm the solver hands over to line relaxation once its absolute residual is
// at round-off of the O(1) values near the goal.
constexpr double kPolishBelowAbsoluteResidual = 1e-13;
// ... and the multigrid solvers start a tail stage early from this absolute residual when the
// relative one is far above the tolerance.
constexpr double kEarlyTailBelowAbsoluteResidual = 1e-10;
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
}  // namespace

std::vector<std::string> ValidateFieldOptions(const FieldOptions& o) {
  std::vector<std::string> v = ValidateSolverOptions(o.solver);
  if (o.norm == ResidualNorm::kAbsolute) {
    // Every solver can bring max |r| below any tolerance while cells far down a corridor (or
    // deep in a nook) still hold their initial p <= 0: "converged" over a field without a path
    // from there (measured on every corridor from 20:1, and on rectangles with SOR).
    v.push_back(std::string("residual_norm absolute is refused with solver ") +
                ToString(o.solver.kind) +
                ": it reports converged while cells far from the goal still hold p <= 0 (no "
                "path from there); use relative");
  }
  if (!(o.tolerance > 0.0 && o.tolerance < 1.0)) {
    std::ostringstream s;
    s << "tolerance must be in (0, 1) (got " << o.tolerance << ")";
    v.push_back(s.str());
  }
  if (!(o.start_fraction >= 0.0 && o.start_fraction <= 1.0)) {
    std::ostringstream s;
    s << "start_fraction must be in [0, 1] (got " << o.start_fraction << ")";
    v.push_back(s.str());
  }
  if (!(o.heuristic_decay_per_cell > 0.0 && o.heuristic_decay_per_cell <= 10.0)) {
    std::ostringstream s;
    s << "heuristic_decay_per_cell must be in (0, 10] (got " << o.heuristic_decay_per_cell << ")";
    v.push_back(s.str());
  }
  return v;
}

PotentialField::PotentialField(const FieldOptions& options) : options_(options) {
  const auto violations = ValidateFieldOptions(options);
  if (!violations.empty()) {
    std::string text = "invalid potential field options:";
    for (const auto& s : violations) text += " " + s + ";";
    throw std::invalid_argument(text);
  }
  solver_ = MakeSolver(options.solver);
  thin_ = std::make_unique<internal::ThinRegionSolver>();
}

PotentialField::~PotentialField() = default;
PotentialField::PotentialField(PotentialField&&) noexcept = default;
PotentialField& PotentialField::operator=(PotentialField&&) noexcept = default;

void PotentialField::SetOccupancy(const spott_map::OccupancyRaster& raster) {
  if (raster.width() < 3 || raster.height() < 3) {
    throw std::invalid_argument("PotentialField: the window needs at least 3 x 3 cells");
  }
  const bool same_geometry = raster.width() == width_ && raster.height() == height_ &&
                             raster.resolution() == resolution_ && raster.origin() == origin_;
  const bool same_size =
      raster.width() == width_ && raster.height() == height_ && raster.resolution() == resolution_;
  const Vec2 old_origin = origin_;
  if (!same_geometry) start_ = kNoCell;  // its cell index means another place now
  width_ = raster.width();
  height_ = raster.height();
  resolution_ = raster.resolution();
  origin_ = raster.origin();
  const std::size_t n = static_cast<std::size_t>(width_) * height_;
  // Blocked cells: the raster's obstacles and padding, and the window's border ring. One read
  // pass finds whether anything changed (a map update outside the window changes nothing
  // here: everything is kept); one write pass sets the blocked cells and the cell kinds.
  const auto* cells = reinterpret_cast<const std::uint8_t*>(raster.cells().data());
  if (same_geometry && blocked_.size() == n &&
      !internal::kernels::BlockedDiffers(cells, blocked_.data(), width_, height_)) {
    return;  // nothing changed: keep all
  }
  if (!same_size) {
    // A new window size: every per-cell array is (re)allocated once here, never per plan.
    blocked_.assign(n, 1);
    p_.assign(n, 0.0);
    kind_.assign(n, FieldCell::kObstacle);
    mask_.free.assign(n, 0);
    free_runs_.clear();
    previous_goals_.clear();
    goal_cells_.clear();
    ext_m_.clear();
    ext_e_.clear();
  }
  if (!same_geometry && same_size && ShiftWarm(old_origin)) {
    // The window moved by whole cells: the values move with it (a warm start).
  } else if (!same_geometry) {
    // Another window: the old values mean nothing here (cold); keep the arrays.
    for (const FreeRun& run : free_runs_) {
      std::fill(p_.begin() + Index(run.x0, run.y), p_.begin() + Index(run.x1, run.y), 0.0);
    }
    for (std::size_t i : goal_cells_) p_[i] = 0.0;
    goal_cells_.clear();
    goal_on_border_ = false;
    report_ = IterationReport{};
  }
  static_assert(
      static_cast<int>(FieldCell::kObstacle) == 1 && static_cast<int>(FieldCell::kUnreachable) == 3,
      "kinds 1 and 3 from blocked");
  internal::kernels::SetBlocked(cells, blocked_.data(),
                                reinterpret_cast<std::uint8_t*>(kind_.data()), width_, height_);
  // Goal cells on a border segment stay goals (they are border cells by construction); a goal
  // point is dropped when its cell became blocked.
  std::size_t kept = 0;
  for (std::size_t i : goal_cells_) {
    if (goal_on_border_ || !blocked_[i]) {
      goal_cells_[kept++] = i;
    } else {
      p_[i] = 0.0;
    }
  }
  goal_cells_.resize(kept);
  RebuildMask(/*kinds_fresh=*/true);
  clearance_ready_ = false;  // computed when first asked for (steering), not on every map update
}

bool PotentialField::ShiftWarm(const Vec2& old_origin) {
  // A shift by whole cells, less than half the window: (dx, dy) old cells per new cell.
  const Vec2 d = (origin_ - old_origin) / resolution_;
  const int dx = static_cast<int>(std::lround(d.x())), dy = static_cast<int>(std::lround(d.y()));
  if (std::abs(d.x() - dx) > 1e-6 || std::abs(d.y() - dy) > 1e-6) return false;
  if (std::abs(dx) >= width_ / 2 || std::abs(dy) >= height_ / 2) return false;
  if (report_.sweeps == 0 || goal_on_border_) return false;  // nothing worth keeping
  // new (x, y) = old (x + dx, y + dy).
  shift_scratch_.assign(p_.size(), 0.0);
  for (int y = std::max(0, -dy); y < std::min(height_, height_ - dy); ++y) {
    const int x0 = std::max(0, -dx), x1 = std::min(width_, width_ - dx);
    std::copy(p_.begin() + Index(x0 + dx, y + dy), p_.begin() + Index(x1 + dx, y + dy),
              shift_scratch_.begin() + Index(x0, y));
  }
  p_.swap(shift_scratch_);
  // Cells that moved onto the new border ring hold the high value (p = 0).
  std::fill(p_.begin(), p_.begin() + width_, 0.0);
  std::fill(p_.end() - width_, p_.end(), 0.0);
  for (int y = 1; y < height_ - 1; ++y) p_[Index(0, y)] = p_[Index(width_ - 1, y)] = 0.0;
  // The previous mask's cells, moved too (RebuildMask resets the ones no longer free); the
  // solver mask itself is cleared where it was.
  for (const FreeRun& run : free_runs_) {
    std::fill(mask_.free.begin() + Index(run.x0, run.y), mask_.free.begin() + Index(run.x1, run.y),
              0);
  }
  std::size_t kept = 0;
  for (const FreeRun& run : free_runs_) {
    const int y = run.y - dy, x0 = std::max(1, run.x0 - dx), x1 = std::min(width_ - 1, run.x1 - dx);
    if (y < 1 || y >= height_ - 1 || x0 >= x1) continue;
    free_runs_[kept++] = {y, x0, x1};
  }
  free_runs_.resize(kept);
  const auto move = [&](std::vector<std::size_t>& cells) {
    std::size_t k = 0;
    for (std::size_t i : cells) {
      const int x = static_cast<int>(i % width_) - dx, y = static_cast<int>(i / width_) - dy;
      if (x < 1 || y < 1 || x >= width_ - 1 || y >= height_ - 1) continue;
      cells[k++] = Index(x, y);
    }
    cells.resize(k);
  };
  move(goal_cells_);
  move(previous_goals_);
  report_.converged = false;
  return true;
}

void PotentialField::RebuildMask(bool kinds_fresh) {
  // Cells of the previous mask: back to obstacle / unreachable (kind_ is fresh from blocked_
  // after a map update); O(previous unknowns), not O(window).
  previous_runs_.swap(free_runs_);
  free_runs_.clear();
  for (const FreeRun& run : previous_runs_) {
    const std::size_t b = Index(0, run.y);
    std::fill(mask_.free.begin() + b + run.x0, mask_.free.begin() + b + run.x1, 0);
    if (!kinds_fresh) {
      std::fill(kind_.begin() + b + run.x0, kind_.begin() + b + run.x1, FieldCell::kUnreachable);
    }
  }
  if (!kinds_fresh) {
    for (std::size_t i : previous_goals_) {
      kind_[i] = blocked_[i] ? FieldCell::kObstacle : FieldCell::kUnreachable;
    }
  }
  for (std::size_t i : previous_goals_) {
    if (std::find(goal_cells_.begin(), goal_cells_.end(), i) == goal_cells_.end()) p_[i] = 0.0;
  }
  for (std::size_t i : goal_cells_) {
    kind_[i] = FieldCell::kGoal;
    p_[i] = 1.0;
  }
  previous_goals_ = goal_cells_;
  goal_count_ = static_cast<int>(goal_cells_.size());
  // Free cells the stencil connects to the goal (4-neighbours for the 5-point stencil, 8 for
  // the 9-point one), by a scan-line fill that records each row's runs. The others have the
  // exact solution p = 0 (all their boundary is an obstacle): they are fixed there instead of
  // being left to the solver's round-off.
  const bool eight = options_.solver.stencil == Stencil::kNinePoint;
  auto* kind = kind_.data();
  const auto unreached = [kind](std::size_t i) { return kind[i] == FieldCell::kUnreachable; };
  fill_stack_.clear();
  for (std::size_t g : goal_cells_) {
    const int x = static_cast<int>(g % width_), y = static_cast<int>(g / width_);
    for (int k = 0; k < (eight ? 8 : 4); ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) continue;
      if (unreached(Index(nx, ny))) fill_stack_.push_back({ny, nx, nx + 1});
    }
  }
  // Eight kind bytes at a time (the scans below dominate a map update in open space).
  constexpr std::uint64_t kOnes = 0x0101010101010101ull;
  constexpr std::uint64_t kAllUnreached = 3 * kOnes;
  const auto word = [kind](std::size_t i) {
    std::uint64_t w;
    std::memcpy(&w, kind + i, 8);
    return w;
  };
  // First x in [x, to) that is not unreached / that is unreached.
  const auto skip_unreached = [&](std::size_t b, int x, int to) {
    while (x + 8 <= to && word(b + x) == kAllUnreached) x += 8;
    while (x < to && unreached(b + x)) ++x;
    return x;
  };
  const auto find_unreached = [&](std::size_t b, int x, int to) {
    while (x + 8 <= to) {
      const std::uint64_t v = word(b + x) ^ kAllUnreached;  // a zero byte where unreached
      if ((v - kOnes) & ~v & (kOnes << 7)) break;
      x += 8;
    }
    while (x < to && !unreached(b + x)) ++x;
    return x;
  };
  while (!fill_stack_.empty()) {
    const FreeRun seed = fill_stack_.back();
    fill_stack_.pop_back();
    const std::size_t base = Index(0, seed.y);
    if (!unreached(base + seed.x0)) continue;
    int l = seed.x0;
    while (unreached(base + l - 1)) --l;  // the ring is blocked: no bounds checks needed
    const int r = skip_unreached(base, seed.x0 + 1, width_ - 1);
    std::fill(kind + base + l, kind + base + r, FieldCell::kFree);
    free_runs_.push_back({seed.y, l, r});
    const int from = eight ? l - 1 : l, to = eight ? r + 1 : r;  // neighbours in rows y -+ 1
    for (int dy : {-1, 1}) {
      const int y = seed.y + dy;
      const std::size_t b = Index(0, y);
      for (int x = find_unreached(b, from, to); x < to; x = find_unreached(b, x, to)) {
        fill_stack_.push_back({y, x, x + 1});
        x = skip_unreached(b, x, to);
      }
    }
  }
  std::sort(free_runs_.begin(), free_runs_.end(), [](const FreeRun& a, const FreeRun& b) {
    return a.y != b.y ? a.y < b.y : a.x0 < b.x0;
  });
  mask_.width = width_;
  mask_.height = height_;
  for (const FreeRun& run : free_runs_) {
    const std::size_t b = Index(0, run.y);
    std::fill(mask_.free.begin() + b + run.x0, mask_.free.begin() + b + run.x1, 1);
  }
  // p = 0 where the previous mask had an unknown that is now fixed (kept where it stays free:
  // the warm start).
  static_assert(static_cast<int>(FieldCell::kFree) == 0 && static_cast<int>(FieldCell::kGoal) == 2,
                "free and goal: the kinds with bit 0 clear");
  const auto* kind_bytes = reinterpret_cast<const std::uint8_t*>(kind);
  for (const FreeRun& run : previous_runs_) {
    const std::size_t b = Index(0, run.y);
    double* __restrict pr = p_.data() + b;
    const std::uint8_t* __restrict kr = kind_bytes + b;
    for (int x = run.x0; x < run.x1; ++x) pr[x] = (kr[x] & 1) ? 0.0 : pr[x];
  }
  solver_ready_ = false;
  polish_ready_ = false;
  polishing_ = false;
  tail_active_ = false;
  last_relative_ = std::numeric_limits<double>::infinity();
  direct_ = false;
  direct_solved_ = false;
  extended_ = false;
  report_.converged = false;  // the equations changed: iterate before trusting the field
}

bool PotentialField::SetGoalPoint(const Vec2& p) {
  const auto c = CellOf(p);
  if (!c || blocked_[Index(c->first, c->second)]) return false;
  const std::size_t cell = Index(c->first, c->second);
  // The same goal again (a re-placed goal after a map update): the mask is already its own.
  if (!goal_on_border_ && goal_cells_.size() == 1 && goal_cells_[0] == cell) return true;
  for (std::size_t i : goal_cells_) p_[i] = 0.0;
  goal_cells_ = {cell};
  goal_on_border_ = false;
  RebuildMask(false);
  return true;
}

bool PotentialField::SetGoalSegment(const spott_map::Segment& s, double half_width_m) {
  std::vector<std::size_t> cells;
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const bool border = x == 0 || y == 0 || x == width_ - 1 || y == height_ - 1;
      const bool corner = (x == 0 || x == width_ - 1) && (y == 0 || y == height_ - 1);
      if (!border || corner) continue;
      if (spott_map::DistancePointSegment(CellCentre(x, y), s) > half_width_m) continue;
      // A border cell whose inner neighbour is blocked leads nowhere: a wall crossing the border.
      const int ix = std::clamp(x, 1, width_ - 2);
      const int iy = std::clamp(y, 1, height_ - 2);
      if (blocked_[Index(ix, iy)]) continue;
      cells.push_back(Index(x, y));
    }
  }
  if (cells.empty()) return false;
  if (goal_on_border_ && cells == goal_cells_) return true;  // the same goal again
  for (std::size_t i : goal_cells_) p_[i] = 0.0;
  goal_cells_ = cells;
  goal_on_border_ = true;
  RebuildMask(false);
  return true;
}

bool PotentialField::SetStart(const Vec2& p) {
  const auto c = CellOf(p);
  start_ = c && !blocked_[Index(c->first, c->second)] ? Index(c->first, c->second) : kNoCell;
  // Converged for a start with a higher p is converged for this one only if its focus is not
  // wider (a lower floor asks more).
  if (report_.converged && Floor() < converged_floor_) report_.converged = false;
  return start_ != kNoCell;
}

void PotentialField::ClearStart() {
  start_ = kNoCell;
  if (report_.converged && converged_floor_ > 0.0) report_.converged = false;
}

double PotentialField::Floor() const {
  if (start_ == kNoCell || extended_) return 0.0;
  const FieldCell k = kind_[start_];
  if (k != FieldCell::kFree && k != FieldCell::kGoal) return 0.0;
  return std::max(0.0, options_.start_fraction * p_[start_]);
}

void PotentialField::Judge(double residual, const std::size_t* deficit) {
  report_.residual = residual;
  report_.converged = residual < options_.tolerance;
  if (report_.converged && !extended_) {
    // The residual says nothing about the order of neighbouring values where they are almost
    // equal: check that descent cannot stop on the way (one pass over the unknowns, or counted
    // in the pass that computed `residual`).
    const double floor = Floor();
    const std::size_t stuck =
        deficit ? *deficit
                : internal::kernels::AscentDeficit(
                      p_.data(), width_, reinterpret_cast<const internal::Run*>(free_runs_.data()),
                      free_runs_.size(), floor);
    report_.converged = stuck == 0;
    converged_floor_ = floor;
  }
}

void PotentialField::EnsureSetup() {
  if (solver_ready_) return;
  // The default solver solves thin regions (corridors) exactly: relative accuracy down to any
  // magnitude, in O(cells), where an iteration's error would have to fall below each cell's
  // exponentially small value.
  direct_ = options_.solver.kind == SolverKind::kMultigridCg && goal_count_ > 0 &&
            thin_->Analyze(width_, height_, kind_, goal_cells_, options_.solver.stencil);
  direct_solved_ = false;
  if (!direct_) solver_->Setup(mask_);
  solver_ready_ = true;
}

bool PotentialField::DirectSolve() {
  if (direct_solved_) return true;
  if (ext_m_.size() != p_.size()) {
    ext_m_.assign(p_.size(), 0.0);
    ext_e_.assign(p_.size(), 0);
  }
  thin_->Solve(ext_m_, ext_e_);
  int lowest = 0;
  for (const FreeRun& run : free_runs_) {
    const std::size_t b = Index(0, run.y);
    for (int x = run.x0; x < run.x1; ++x) lowest = std::min(lowest, ext_e_[b + x]);
  }
  for (const FreeRun& run : free_runs_) {
    const std::size_t b = Index(0, run.y);
    for (int x = run.x0; x < run.x1; ++x) p_[b + x] = std::ldexp(ext_m_[b + x], ext_e_[b + x]);
  }
  // Below about 2^-1000 double loses digits, then the value: keep mantissa and exponent.
  extended_ = lowest < -1000;
  direct_solved_ = true;
  return true;
}

void PotentialField::ColdStart() {
  polishing_ = false;
  tail_active_ = false;
  last_relative_ = std::numeric_limits<double>::infinity();
  if (width_ > 0 && goal_count_ > 0) {
    EnsureSetup();
    if (direct_) {
      DirectSolve();
      report_ = IterationReport{};
      report_.sweeps = 1;  // the exact solve counts as one iteration
      Judge(Residual());
      return;
    }
    if (solver_->InitialGuess(p_.data())) {
      // Negative values are left to the iteration (clamping would restart conjugate gradients).
      solver_->Restart();
      NotJudged();
      return;
    }
  }
  // 8-connected wavefront from the goal through free cells (no corner cutting), with the
  // integer chamfer weights 5 (straight) and 7 (diagonal) so that a bucket queue (Dial's
  // algorithm) runs it in O(cells): d / 5 approximates the octile distance in cells.
  constexpr int kStraight = 5, kDiagonal = 7;
  constexpr std::uint32_t kUnseen = std::numeric_limits<std::uint32_t>::max();
  wave_.assign(kind_.size(), kUnseen);
  std::vector<std::vector<std::uint32_t>> buckets(kDiagonal + 1);
  for (std::size_t i : goal_cells_) {
    wave_[i] = 0;
    buckets[0].push_back(static_cast<std::uint32_t>(i));
  }
  std::size_t pending = goal_cells_.size();
  for (std::uint32_t dist = 0; pending > 0; ++dist) {
    auto& bucket = buckets[dist % buckets.size()];
    for (std::size_t q = 0; q < bucket.size(); ++q) {
      const std::uint32_t i = bucket[q];
      --pending;
      if (wave_[i] != dist) continue;  // a stale entry: reached sooner since
      const int x = static_cast<int>(i % width_);
      const int y = static_cast<int>(i / width_);
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kDx[k];
        const int ny = y + kDy[k];
        if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) continue;
        const std::size_t j = Index(nx, ny);
        if (kind_[j] != FieldCell::kFree) continue;
        if (k >= 4 && (kind_[Index(nx, y)] == FieldCell::kObstacle ||
                       kind_[Index(x, ny)] == FieldCell::kObstacle)) {
          continue;
        }
        const std::uint32_t nd = dist + (k < 4 ? kStraight : kDiagonal);
        if (nd < wave_[j]) {
          wave_[j] = nd;
          buckets[nd % buckets.size()].push_back(static_cast<std::uint32_t>(j));
          ++pending;
        }
      }
    }
    bucket.clear();
  }
  // p = exp(-k d): one exp per distinct distance step, multiplied up.
  const double step = std::exp(-options_.heuristic_decay_per_cell / kStraight);
  std::vector<double>& table = exp_table_;
  for (std::size_t i = 0; i < kind_.size(); ++i) {
    if (kind_[i] != FieldCell::kFree) continue;
    if (wave_[i] == kUnseen) {
      p_[i] = 0.0;
      continue;
    }
    while (table.size() <= wave_[i]) table.push_back(table.empty() ? 1.0 : table.back() * step);
    p_[i] = table[wave_[i]];
  }
  table.clear();
  solver_->Restart();
  NotJudged();
}

void PotentialField::NotJudged() {
  // The first iteration computes the residual anyway (a pass of its own here would cost as much
  // as a smoothing sweep).
  report_ = IterationReport{};
  report_.residual = std::numeric_limits<double>::infinity();
}

PotentialField::Norms PotentialField::ResidualNorms(bool with_deficit) const {
  Norms norms;
  if (width_ == 0) return norms;
  const bool five = options_.solver.stencil == Stencil::kFivePoint;
  const double inf = std::numeric_limits<double>::infinity();
  if (extended_) {
    // Each cell against its neighbours scaled to its own exponent.
    for (const FreeRun& run : free_runs_) {
      for (int x = run.x0; x < run.x1; ++x) {
        const std::size_t i = Index(x, run.y);
        const int e = ext_e_[i];
        const auto v = [&](std::size_t j) { return Scaled(j, e); };
        const std::size_t w = static_cast<std::size_t>(width_);
        const double m =
            five ? 0.25 * ((v(i - 1) + v(i + 1)) + (v(i - w) + v(i + w)))
                 : 0.2 * ((v(i - 1) + v(i + 1)) + (v(i - w) + v(i + w))) +
                       0.05 * ((v(i - w - 1) + v(i - w + 1)) + (v(i + w - 1) + v(i + w + 1)));
        const double here = ext_m_[i];
        const double r = std::abs(m - here);
        norms.absolute = std::max(norms.absolute, std::ldexp(r, e));
        norms.relative = std::max(norms.relative, here > 0.0 ? r / here : (r > 0.0 ? inf : 0.0));
      }
    }
    return norms;
  }
  static_assert(sizeof(FreeRun) == sizeof(internal::Run), "same run layout");
  const auto k = internal::kernels::ResidualNorms(
      p_.data(), width_, reinterpret_cast<const internal::Run*>(free_runs_.data()),
      free_runs_.size(), !five, Floor(), with_deficit);
  norms.absolute = k.absolute;
  norms.relative = k.relative;
  norms.deficit = k.deficit;
  norms.has_deficit = with_deficit;
  return norms;
}

double PotentialField::Residual() const {
  const Norms n = ResidualNorms();
  return options_.norm == ResidualNorm::kAbsolute ? n.absolute : n.relative;
}

bool PotentialField::ClampNegatives() {
  bool clamped = false;
  for (const FreeRun& run : free_runs_) {
    double* row = p_.data() + Index(0, run.y);
    for (int x = run.x0; x < run.x1; ++x) {
      if (row[x] < 0.0) {
        row[x] = 0.0;
        clamped = true;
      }
    }
  }
  return clamped;
}

IterationReport PotentialField::Iterate(int sweeps) {
  if (width_ == 0 || goal_count_ == 0) {
    throw std::logic_error("PotentialField::Iterate: no window or no goal");
  }
  const bool warm = !solver_ready_;  // the equations changed since the last iteration
  EnsureSetup();
  if (warm && !direct_ && !tail_active_ && !polishing_ && solver_->CorrectionGuess(p_.data())) {
    // The kept values plus a full-multigrid correction for the change: the iteration then starts
    // with the change's own error reduced like a cold start's.
    solver_->Restart();
  }
  if (direct_) {
    const bool fresh = !direct_solved_;
    DirectSolve();
    if (fresh) report_.sweeps += 1;
    Judge(Residual());
    return report_;
  }
  const bool relative = options_.norm == ResidualNorm::kRelative;
  const bool multigrid = options_.solver.kind == SolverKind::kMultigrid ||
                         options_.solver.kind == SolverKind::kMultigridCg;
  Norms norms;
  bool tracked = false;
  for (int s = 0; s < sweeps; ++s) {
    if (tail_active_) {
      // A tail stage: the cells below the scale the main solve resolved, solved on their own,
      // scaled to O(1), with the resolved cells as Dirichlet values.
      norms = IterateTail();
      tracked = false;
      continue;
    }
    // Relative accuracy needs p >= 0 everywhere (the exact p is). The configured solver is
    // accurate in absolute terms: it brings the field to round-off of its largest values. Then
    // the multigrid solvers solve the tails (cells too small for that round-off) in stages, each
    // scaled to O(1) (StartTail); SOR and ADI go on with line Gauss-Seidel without
    // over-relaxation (all weights positive, Thomas algorithm on an M-matrix: no cancellation),
    // which resolves the tails, each to its own magnitude, slowly.
    if (polishing_) {
      if (!polish_) {
        SolverOptions o = options_.solver;
        o.kind = SolverKind::kAdi;
        o.omega = 1.0;  // over-relaxation would overshoot tiny values below zero
        polish_ = MakeSolver(o);
      }
      if (!polish_ready_) {
        polish_->Setup(mask_);
        polish_ready_ = true;
      }
      polish_->Iterate(p_.data());
    } else {
      solver_->SetRelativeFloor(Floor());
      solver_->Iterate(p_.data());
    }
    if (relative && polishing_ && ClampNegatives())
      solver_->Restart();  // its state no longer matches
    tracked = !polishing_ && solver_->LastResidual(&norms.absolute, &norms.relative);
    if (!tracked) norms = ResidualNorms();
    // Hand over when the solver stalls at round-off (its absolute residual at the O(1) values'
    // last bits and the relative one no longer halving per iteration).
    if (relative && !polishing_ && norms.absolute < kPolishBelowAbsoluteResidual &&
        !(norms.relative < options_.tolerance) && !(norms.relative < 0.5 * last_relative_)) {
      if (!(multigrid && StartTail(norms.absolute, 1.0))) polishing_ = true;
    } else if (relative && multigrid && norms.absolute < kEarlyTailBelowAbsoluteResidual &&
               !(norms.relative < 100.0 * options_.tolerance)) {
      // Far from converged relative to the cells' values while the absolute residual is
      // small: a deep tail (a room behind a narrow door); solve it on its own now rather than
      // iterate the whole window down to round-off first.
      StartTail(norms.absolute, 1.0);
    }
    last_relative_ = norms.relative;
  }
  report_.sweeps += sweeps;
  const double residual = sweeps > 0 ? (relative ? norms.relative : norms.absolute) : Residual();
  if (residual < options_.tolerance && tracked) {
    // The solver's residual is recursive (updated, not recomputed): confirm with the true one.
    const Norms n = ResidualNorms(/*with_deficit=*/true);
    const double confirmed = relative ? n.relative : n.absolute;
    if (!(confirmed < options_.tolerance)) solver_->Restart();
    Judge(confirmed, n.has_deficit ? &n.deficit : nullptr);
  } else {
    Judge(residual);
  }
  return report_;
}

bool PotentialField::StartTail(double resolved_absolute, double scale) {
  // Cells with p >= tau are resolved to a tenth of the tolerance by an absolute accuracy of
  // `resolved_absolute` (in units of `scale`); the others form the tail.
  const double tau = scale * std::max(resolved_absolute, 1e-16) * 10.0 / options_.tolerance;
  // A stage is worth it only well below the scale above it (a tight tolerance leaves no room:
  // the polish then resolves what is left).
  if (!(tau > 0.0) || tau >= 1e-3 * scale) return false;
  if (tail_mask_.free.size() != p_.size()) {
    tail_mask_.free.assign(p_.size(), 0);
    tail_u_.assign(p_.size(), 0.0);
    tail_runs_.clear();
  }
  for (const FreeRun& run : tail_runs_) {
    std::fill(tail_mask_.free.begin() + Index(run.x0, run.y),
              tail_mask_.free.begin() + Index(run.x1, run.y), 0);
  }
  previous_tail_runs_.swap(tail_runs_);
  tail_runs_.clear();
  tail_mask_.width = width_;
  tail_mask_.height = height_;
  std::size_t cells = 0;
  for (const FreeRun& run : free_runs_) {
    const std::size_t b = Index(0, run.y);
    for (int x = run.x0; x < run.x1;) {
      if (!(p_[b + x] < tau)) {
        ++x;
        continue;
      }
      const int x0 = x;
      while (x < run.x1 && p_[b + x] < tau) ++x;
      tail_runs_.push_back({run.y, x0, x});
      std::fill(tail_mask_.free.begin() + b + x0, tail_mask_.free.begin() + b + x, 1);
      cells += static_cast<std::size_t>(x - x0);
    }
  }
  // A tail is solved on its own only while it is a part of the region above it (the whole
  // field is better served by the solver that already runs on it).
  std::size_t above = 0;
  for (const FreeRun& run : scale == 1.0 ? free_runs_ : previous_tail_runs_) {
    above += static_cast<std::size_t>(run.x1 - run.x0);
  }
  if (cells == 0 || 2 * cells > above) {
    for (const FreeRun& run : tail_runs_) {
      std::fill(tail_mask_.free.begin() + Index(run.x0, run.y),
                tail_mask_.free.begin() + Index(run.x1, run.y), 0);
    }
    tail_runs_.swap(previous_tail_runs_);
    return false;
  }
  // The scaled field: p / tau everywhere (the Dirichlet values of the stage).
  const double inv = 1.0 / tau;
  for (std::size_t i = 0; i < p_.size(); ++i) tail_u_[i] = p_[i] * inv;
  if (!tail_solver_) tail_solver_ = MakeSolver(options_.solver);
  tail_solver_->Setup(tail_mask_);
  tail_solver_->InitialGuess(tail_u_.data());
  tail_scale_ = tau;
  tail_active_ = true;
  tail_last_relative_ = std::numeric_limits<double>::infinity();
  return true;
}

PotentialField::Norms PotentialField::IterateTail() {
  const double floor = Floor() / tail_scale_;  // the start's focus in the stage's units
  tail_solver_->SetRelativeFloor(floor);
  tail_solver_->Iterate(tail_u_.data());
  Norms tail;
  if (!tail_solver_->LastResidual(&tail.absolute, &tail.relative)) {
    const auto k = internal::kernels::ResidualNorms(
        tail_u_.data(), width_, reinterpret_cast<const internal::Run*>(tail_runs_.data()),
        tail_runs_.size(), options_.solver.stencil == Stencil::kNinePoint, floor);
    tail.absolute = k.absolute;
    tail.relative = k.relative;
  }
  for (const FreeRun& run : tail_runs_) {
    const std::size_t b = Index(0, run.y);
    for (int x = run.x0; x < run.x1; ++x) p_[b + x] = tail_u_[b + x] * tail_scale_;
  }
  if (tail.relative < options_.tolerance) {
    tail_active_ = false;
    return ResidualNorms();  // the whole field, resolved part and tail
  }
  const bool stalls =
      tail.absolute < kPolishBelowAbsoluteResidual && !(tail.relative < 0.5 * tail_last_relative_);
  const bool deep = tail.absolute < kEarlyTailBelowAbsoluteResidual &&
                    !(tail.relative < 100.0 * options_.tolerance);
  if (stalls || deep) {
    // This stage stalls at round-off of its own scale, or has a deep tail of its own: the next
    // stage below it.
    const double scale = tail_scale_;
    tail_active_ = false;
    if (!StartTail(tail.absolute, scale)) {
      if (stalls) {
        polishing_ = true;  // round-off here and nothing below: the line relaxation
      } else {
        tail_active_ = true;  // no deeper stage: go on with this one
      }
    }
  }
  tail_last_relative_ = tail.relative;
  Norms n;
  n.absolute = tail.absolute * tail_scale_;
  n.relative = tail.relative;
  return n;
}

IterationReport PotentialField::Solve(int max_sweeps) {
  if (report_.converged && report_.sweeps > 0) return report_;
  // The residual costs about one sweep: SOR and ADI check it every fourth sweep.
  const int check =
      solver_->kind() == SolverKind::kMultigrid || solver_->kind() == SolverKind::kMultigridCg ? 1
                                                                                               : 4;
  for (int s = 0; s < max_sweeps && !report_.converged; s += check) {
    Iterate(std::min(check, max_sweeps - s));
  }
  return report_;
}

std::optional<std::pair<int, int>> PotentialField::CellOf(const Vec2& p) const {
  const double gx = (p.x() - origin_.x()) / resolution_;
  const double gy = (p.y() - origin_.y()) / resolution_;
  if (!(gx >= 0.0 && gy >= 0.0 && gx < width_ && gy < height_)) return std::nullopt;
  return std::make_pair(static_cast<int>(gx), static_cast<int>(gy));
}

Vec2 PotentialField::CellCentre(int ix, int iy) const {
  return origin_ + resolution_ * Vec2(ix + 0.5, iy + 0.5);
}

double PotentialField::LogGoalProbability(int ix, int iy) const {
  const std::size_t i = Index(ix, iy);
  const double v = extended_ && kind_[i] == FieldCell::kFree ? ext_m_[i] : p_[i];
  if (!(v > 0.0)) return -std::numeric_limits<double>::infinity();
  return std::log(v) + Exponent(i) * M_LN2;
}

double PotentialField::InterpolatedScaled(const Vec2& p, int* ref) const {
  *ref = 0;
  if (!CellOf(p)) return 0.0;
  const double gx = std::clamp((p.x() - origin_.x()) / resolution_ - 0.5, 0.0, width_ - 1.0);
  const double gy = std::clamp((p.y() - origin_.y()) / resolution_ - 0.5, 0.0, height_ - 1.0);
  const int x0 = std::min(static_cast<int>(gx), width_ - 2);
  const int y0 = std::min(static_cast<int>(gy), height_ - 2);
  const double fx = gx - x0;
  const double fy = gy - y0;
  const std::size_t i00 = Index(x0, y0), i10 = Index(x0 + 1, y0);
  const std::size_t i01 = Index(x0, y0 + 1), i11 = Index(x0 + 1, y0 + 1);
  if (extended_) {
    *ref = ScaleOf(Exponent(i00), Exponent(i10), Exponent(i01), Exponent(i11));
  }
  const int e = *ref;
  const double p00 = Scaled(i00, e), p10 = Scaled(i10, e);
  const double p01 = Scaled(i01, e), p11 = Scaled(i11, e);
  return (1 - fy) * ((1 - fx) * p00 + fx * p10) + fy * ((1 - fx) * p01 + fx * p11);
}

double PotentialField::InterpolatedGoalProbability(const Vec2& p) const {
  int ref = 0;
  const double v = InterpolatedScaled(p, &ref);
  return ref == 0 ? v : std::ldexp(v, ref);
}

std::optional<Vec2> PotentialField::DescentDirection(const Vec2& p) const {
  const auto c = CellOf(p);
  if (!c) return std::nullopt;
  const FieldCell k = kind_[Index(c->first, c->second)];
  if (k == FieldCell::kObstacle || k == FieldCell::kUnreachable) return std::nullopt;
  const double gx = std::clamp((p.x() - origin_.x()) / resolution_ - 0.5, 0.0, width_ - 1.0);
  const double gy = std::clamp((p.y() - origin_.y()) / resolution_ - 0.5, 0.0, height_ - 1.0);
  const int x0 = std::min(static_cast<int>(gx), width_ - 2);
  const int y0 = std::min(static_cast<int>(gy), height_ - 2);
  const double fx = gx - x0;
  const double fy = gy - y0;
  // Values scaled to the largest exponent of the four surrounding cells (0 unless p lies below
  // double's range).
  int e = 0;
  if (extended_) {
    e = ScaleOf(Exponent(Index(x0, y0)), Exponent(Index(x0 + 1, y0)), Exponent(Index(x0, y0 + 1)),
                Exponent(Index(x0 + 1, y0 + 1)));
  }
  // Gradient of p (ascent of p = descent of u): central differences at the four surrounding
  // cell centres, interpolated bilinearly. (The gradient of the bilinear interpolant itself
  // jumps at cell centres and makes paths zig-zag along a corridor's centre line.) The common
  // factor 1 / (2 resolution) does not change the direction.
  const auto gradient = [this, e](int x, int y) {
    const int xm = std::max(x - 1, 0), xp = std::min(x + 1, width_ - 1);
    const int ym = std::max(y - 1, 0), yp = std::min(y + 1, height_ - 1);
    return Vec2(Scaled(Index(xp, y), e) - Scaled(Index(xm, y), e),
                Scaled(Index(x, yp), e) - Scaled(Index(x, ym), e));
  };
  const Vec2 g = (1 - fy) * ((1 - fx) * gradient(x0, y0) + fx * gradient(x0 + 1, y0)) +
                 fy * ((1 - fx) * gradient(x0, y0 + 1) + fx * gradient(x0 + 1, y0 + 1));
  // Normalised by the larger component first: no underflow of dx^2 for p ~ 1e-300.
  const double ax = std::abs(g.x()), ay = std::abs(g.y());
  const double big = std::max(ax, ay);
  if (!(big > 0.0)) return std::nullopt;
  const double dx = g.x() / big, dy = g.y() / big;
  const double n = std::sqrt(dx * dx + dy * dy);
  return Vec2(dx / n, dy / n);
}

std::optional<Vec2> PotentialField::HeuristicDirection(const Vec2& p, int influence) const {
  const auto c = CellOf(p);
  if (!c || goal_cells_.empty()) return std::nullopt;
  // Attraction: unit vector to the nearest goal cell (a point goal has one).
  Vec2 goal = CellCentre(static_cast<int>(goal_cells_[0] % width_),
                         static_cast<int>(goal_cells_[0] / width_));
  double best = (goal - p).squaredNorm();
  for (std::size_t k = 1; k < goal_cells_.size(); ++k) {
    const Vec2 g = CellCentre(static_cast<int>(goal_cells_[k] % width_),
                              static_cast<int>(goal_cells_[k] / width_));
    if ((g - p).squaredNorm() < best) {
      best = (g - p).squaredNorm();
      goal = g;
    }
  }
  Vec2 force = goal - p;
  const double dist = force.norm();
  if (dist > 0.0) force /= dist;
  // Repulsion from nearby blocked cells (the window border included), in cells.
  Vec2 push(0.0, 0.0);
  for (int dy = -influence; dy <= influence; ++dy) {
    for (int dx = -influence; dx <= influence; ++dx) {
      const int x = c->first + dx, y = c->second + dy;
      if (x < 0 || y < 0 || x >= width_ || y >= height_ || !blocked_[Index(x, y)]) continue;
      const Vec2 away = (p - CellCentre(x, y)) / resolution_;
      const double d2 = std::max(away.squaredNorm(), 0.25);
      push += away / (d2 * std::sqrt(d2));
    }
  }
  force += push / static_cast<double>(influence * influence);
  const double n = force.norm();
  if (!(n > 0.0)) return std::nullopt;
  return Vec2(force / n);
}

std::optional<std::pair<int, int>> PotentialField::BestNeighbour(int x, int y) const {
  std::optional<std::pair<int, int>> best;
  const int e = Exponent(Index(x, y));
  double best_p = Scaled(Index(x, y), e);
  for (int j = 0; j < 8; ++j) {
    const int nx = x + kDx[j];
    const int ny = y + kDy[j];
    if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) continue;
    if (kind_[Index(nx, ny)] == FieldCell::kObstacle) continue;
    // No diagonal step past an obstacle's corner.
    if (j >= 4 && (kind_[Index(nx, y)] == FieldCell::kObstacle ||
                   kind_[Index(x, ny)] == FieldCell::kObstacle)) {
      continue;
    }
    const double v = Scaled(Index(nx, ny), e);
    if (v > best_p) {
      best_p = v;
      best = std::make_pair(nx, ny);
    }
  }
  return best;
}

bool PotentialField::SegmentClear(const Vec2& a, const Vec2& b) const {
  // Every cell the segment a-b meets (Amanatides-Woo traversal in cell coordinates); where it
  // passes exactly through a cell corner both side cells count, so it cannot slip between two
  // blocked cells touching at a corner either.
  const double ax = (a.x() - origin_.x()) / resolution_, ay = (a.y() - origin_.y()) / resolution_;
  const double bx = (b.x() - origin_.x()) / resolution_, by = (b.y() - origin_.y()) / resolution_;
  int x = static_cast<int>(std::floor(ax)), y = static_cast<int>(std::floor(ay));
  const int xe = static_cast<int>(std::floor(bx)), ye = static_cast<int>(std::floor(by));
  const auto blocked = [this](int cx, int cy) {
    return cx < 0 || cy < 0 || cx >= width_ || cy >= height_ ||
           kind_[Index(cx, cy)] == FieldCell::kObstacle;
  };
  if (blocked(x, y)) return false;
  const double dx = bx - ax, dy = by - ay;
  const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const double tdx = dx != 0.0 ? std::abs(1.0 / dx) : inf;
  const double tdy = dy != 0.0 ? std::abs(1.0 / dy) : inf;
  double tx = dx != 0.0 ? ((sx > 0 ? x + 1 - ax : ax - x) * tdx) : inf;
  double ty = dy != 0.0 ? ((sy > 0 ? y + 1 - ay : ay - y) * tdy) : inf;
  for (int guard = 0; (x != xe || y != ye) && guard < 64; ++guard) {
    if (std::abs(tx - ty) < 1e-12) {
      if (blocked(x + sx, y) || blocked(x, y + sy)) return false;  // through a corner
      x += sx;
      y += sy;
      tx += tdx;
      ty += tdy;
    } else if (tx < ty) {
      x += sx;
      tx += tdx;
    } else {
      y += sy;
      ty += tdy;
    }
    if (blocked(x, y)) return false;
  }
  return true;
}

PotentialField::Path PotentialField::DescendPath(const Vec2& start, double step_cells,
                                                 int max_steps) const {
  Path path;
  path.points.push_back(start);
  if (max_steps <= 0) {
    max_steps = static_cast<int>(
        std::min<std::size_t>(4 * kind_.size() / step_cells + 16, std::numeric_limits<int>::max()));
  }
  const double h = step_cells * resolution_;
  // a > b for values v * 2^ref.
  const auto above = [](double va, int ra, double vb, int rb) {
    return ra == rb ? va > vb : std::ldexp(va, ra - rb) > vb;
  };
  Vec2 pos = start;
  bool have_here = false;
  double cached_here = 0.0;
  int cached_ref = 0;
  for (int step = 0; step <= max_steps; ++step) {
    const auto c = CellOf(pos);
    if (!c) break;
    const FieldCell k = kind_[Index(c->first, c->second)];
    if (k == FieldCell::kGoal) {
      path.reached_goal = true;
      break;
    }
    if (k == FieldCell::kUnreachable) break;
    if (k == FieldCell::kObstacle) {
      path.entered_obstacle = true;
      break;
    }
    if (step == max_steps) break;
    // Every step must raise the interpolated p strictly (the path cannot cycle) and its
    // segment must not cross a blocked cell, not even at a corner.
    int here_ref = 0;
    double here;
    if (have_here) {  // the previous continuous step's end
      here = cached_here;
      here_ref = cached_ref;
    } else {
      here = InterpolatedScaled(pos, &here_ref);
    }
    have_here = false;
    Vec2 next;
    bool continuous = false;
    if (const auto d1 = DescentDirection(pos)) {
      const auto d2 = DescentDirection(pos + 0.5 * h * *d1);
      next = pos + h * (d2 ? *d2 : *d1);
      const auto nc = CellOf(next);
      if (nc && kind_[Index(nc->first, nc->second)] != FieldCell::kObstacle &&
          SegmentClear(pos, next)) {
        int next_ref = 0;
        const double there = InterpolatedScaled(next, &next_ref);
        continuous = above(there, next_ref, here, here_ref);
        if (continuous) {
          have_here = true;
          cached_here = there;
          cached_ref = next_ref;
        }
      }
    }
    if (!continuous) {
      // Flat or misleading interpolant (saddles, passages one or two cells wide): discrete
      // steepest descent over cells until above the current value. For a harmonic field some
      // 4-neighbour is strictly better (mean-value property), so this ends at the goal at worst.
      std::pair<int, int> cell = *c;
      bool found = false;
      for (int hop = 0; hop < width_ + height_; ++hop) {
        // From anywhere in a cell, the segment to a neighbour's centre stays in the cells
        // BestNeighbour checked (the two side cells of a diagonal step are free).
        const auto best = BestNeighbour(cell.first, cell.second);
        if (!best) break;
        cell = *best;
        const std::size_t ci = Index(cell.first, cell.second);
        if (above(Scaled(ci, Exponent(ci)), Exponent(ci), here, here_ref)) {
          found = true;
          break;
        }
        // An intermediate cell: part of the path (each hop is one cell, never across a corner).
        const Vec2 via = CellCentre(cell.first, cell.second);
        path.length_m += (via - pos).norm();
        pos = via;
        path.points.push_back(pos);
      }
      if (!found) break;
      next = CellCentre(cell.first, cell.second);
    }
    path.length_m += (next - pos).norm();
    pos = next;
    path.points.push_back(pos);
  }
  return path;
}

void PotentialField::ComputeClearance() const {
  // Chamfer distance (1, sqrt 2) between cell centres to the nearest blocked cell.
  const float inf = std::numeric_limits<float>::infinity();
  clearance_cells_.assign(blocked_.size(), inf);
  for (std::size_t i = 0; i < blocked_.size(); ++i) {
    if (blocked_[i]) clearance_cells_[i] = 0.0f;
  }
  const float s2 = static_cast<float>(kSqrt2);
  auto relax = [&](int x, int y, int dx, int dy, float w) {
    const int nx = x + dx, ny = y + dy;
    if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) return;
    float& c = clearance_cells_[Index(x, y)];
    c = std::min(c, clearance_cells_[Index(nx, ny)] + w);
  };
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      relax(x, y, -1, 0, 1.0f);
      relax(x, y, 0, -1, 1.0f);
      relax(x, y, -1, -1, s2);
      relax(x, y, 1, -1, s2);
    }
  }
  for (int y = height_ - 1; y >= 0; --y) {
    for (int x = width_ - 1; x >= 0; --x) {
      relax(x, y, 1, 0, 1.0f);
      relax(x, y, 0, 1, 1.0f);
      relax(x, y, 1, 1, s2);
      relax(x, y, -1, 1, s2);
    }
  }
}

double PotentialField::Clearance(const Vec2& p) const {
  const auto c = CellOf(p);
  if (!c) return 0.0;
  if (!clearance_ready_) {
    ComputeClearance();
    clearance_ready_ = true;
  }
  // Bilinear between the four cell centres around p: one cell's value steps by a whole cell,
  // and the steering's bias and speed, which scale with the clearance, stepped with it (along a
  // wall the robot weaved, the turn rate reversing every ~2 s).
  const double gx = std::clamp((p.x() - origin_.x()) / resolution_ - 0.5, 0.0, width_ - 1.0);
  const double gy = std::clamp((p.y() - origin_.y()) / resolution_ - 0.5, 0.0, height_ - 1.0);
  const int x0 = std::min(static_cast<int>(gx), width_ - 2);
  const int y0 = std::min(static_cast<int>(gy), height_ - 2);
  const double tx = gx - x0, ty = gy - y0;
  const auto at = [&](int x, int y) { return static_cast<double>(clearance_cells_[Index(x, y)]); };
  double cells = 0.0;  // (a window without a blocked cell: infinite; a zero weight adds nothing)
  for (const auto& [x, y, w] :
       {std::tuple{x0, y0, (1.0 - tx) * (1.0 - ty)}, std::tuple{x0 + 1, y0, tx * (1.0 - ty)},
        std::tuple{x0, y0 + 1, (1.0 - tx) * ty}, std::tuple{x0 + 1, y0 + 1, tx * ty}}) {
    if (w > 0.0) cells += w * at(x, y);
  }
  // Centre-to-centre distance minus half a cell: the distance to the blocked cell's square.
  return std::max(0.0, (cells - 0.5) * resolution_);
}

}  // namespace spott_harmonic_planner
