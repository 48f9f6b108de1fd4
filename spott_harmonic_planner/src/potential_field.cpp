#include "spott_harmonic_planner/potential_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>
#include <stdexcept>

#include "kernels.h"

namespace spott_harmonic_planner {

namespace {
constexpr double kSqrt2 = 1.4142135623730951;
// Multigrid hands over to line relaxation (relative norm) once its absolute residual is at
// round-off of the O(1) values near the goal.
constexpr double kPolishBelowAbsoluteResidual = 1e-13;
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
}  // namespace

std::vector<std::string> ValidateFieldOptions(const FieldOptions& o) {
  std::vector<std::string> v = ValidateSolverOptions(o.solver);
  if (!(o.tolerance > 0.0 && o.tolerance < 1.0)) {
    std::ostringstream s;
    s << "tolerance must be in (0, 1) (got " << o.tolerance << ")";
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
}

void PotentialField::SetOccupancy(const spott_map::OccupancyRaster& raster) {
  if (raster.width() < 3 || raster.height() < 3) {
    throw std::invalid_argument("PotentialField: the window needs at least 3 x 3 cells");
  }
  const bool same_geometry = raster.width() == width_ && raster.height() == height_ &&
                             raster.resolution() == resolution_ && raster.origin() == origin_;
  width_ = raster.width();
  height_ = raster.height();
  resolution_ = raster.resolution();
  origin_ = raster.origin();
  blocked_.assign(static_cast<std::size_t>(width_) * height_, 0);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const bool border = x == 0 || y == 0 || x == width_ - 1 || y == height_ - 1;
      blocked_[Index(x, y)] = border || raster.Blocked(x, y) ? 1 : 0;
    }
  }
  if (!same_geometry) {
    p_.assign(blocked_.size(), 0.0);
    kind_.assign(blocked_.size(), FieldCell::kFree);
    goal_cells_.clear();
    goal_on_border_ = false;
    report_ = IterationReport{};
  }
  // Goal cells on a border segment stay goals (they are border cells by construction); a goal
  // point is dropped when its cell became blocked.
  std::vector<std::size_t> kept;
  for (std::size_t i : goal_cells_) {
    if (goal_on_border_ || !blocked_[i]) kept.push_back(i);
  }
  goal_cells_ = kept;
  RebuildMask();
  ComputeClearance();
}

void PotentialField::RebuildMask() {
  for (std::size_t i = 0; i < blocked_.size(); ++i) {
    kind_[i] = blocked_[i] ? FieldCell::kObstacle : FieldCell::kUnreachable;
  }
  for (std::size_t i : goal_cells_) kind_[i] = FieldCell::kGoal;
  goal_count_ = static_cast<int>(goal_cells_.size());
  // Free cells the stencil connects to the goal (4-neighbours for the 5-point stencil, 8 for
  // the 9-point one). The others have the exact solution p = 0 (all their boundary is an
  // obstacle): they are fixed there instead of being left to the solver's round-off.
  const int links = options_.solver.stencil == Stencil::kFivePoint ? 4 : 8;
  std::vector<std::size_t> stack(goal_cells_.begin(), goal_cells_.end());
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    const int x = static_cast<int>(i % width_);
    const int y = static_cast<int>(i / width_);
    for (int k = 0; k < links; ++k) {
      const int nx = x + kDx[k];
      const int ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) continue;
      const std::size_t j = Index(nx, ny);
      if (kind_[j] != FieldCell::kUnreachable) continue;
      kind_[j] = FieldCell::kFree;
      stack.push_back(j);
    }
  }
  mask_.width = width_;
  mask_.height = height_;
  mask_.free.assign(kind_.size(), 0);
  for (std::size_t i = 0; i < kind_.size(); ++i) {
    mask_.free[i] = kind_[i] == FieldCell::kFree ? 1 : 0;
    if (kind_[i] == FieldCell::kObstacle || kind_[i] == FieldCell::kUnreachable) p_[i] = 0.0;
    if (kind_[i] == FieldCell::kGoal) p_[i] = 1.0;
  }
  solver_ready_ = false;
  polish_ready_ = false;
  report_.converged = false;  // the equations changed: iterate before trusting the field
}

bool PotentialField::SetGoalPoint(const Vec2& p) {
  const auto c = CellOf(p);
  if (!c || blocked_[Index(c->first, c->second)]) return false;
  for (std::size_t i : goal_cells_) p_[i] = 0.0;
  goal_cells_ = {Index(c->first, c->second)};
  goal_on_border_ = false;
  RebuildMask();
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
  for (std::size_t i : goal_cells_) p_[i] = 0.0;
  goal_cells_ = cells;
  goal_on_border_ = true;
  RebuildMask();
  return true;
}

void PotentialField::ColdStart() {
  // 8-connected wavefront (Dijkstra, no corner cutting) from the goal through free cells.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> d(kind_.size(), inf);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  for (std::size_t i : goal_cells_) {
    d[i] = 0.0;
    open.push({0.0, i});
  }
  while (!open.empty()) {
    const auto [di, i] = open.top();
    open.pop();
    if (di > d[i]) continue;
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
      const double nd = di + (k < 4 ? 1.0 : kSqrt2);
      if (nd < d[j]) {
        d[j] = nd;
        open.push({nd, j});
      }
    }
  }
  for (std::size_t i = 0; i < kind_.size(); ++i) {
    if (kind_[i] == FieldCell::kFree) {
      p_[i] = std::isfinite(d[i]) ? std::exp(-options_.heuristic_decay_per_cell * d[i]) : 0.0;
    }
  }
  report_ = IterationReport{};
  report_.residual = Residual();
  report_.converged = report_.residual < options_.tolerance;
}

double PotentialField::Residual() const {
  if (width_ == 0) return 0.0;
  if (options_.norm == ResidualNorm::kAbsolute) {
    return kernels::Residual(options_.solver.stencil, width_, height_, p_.data(), nullptr,
                             mask_.free.data(), nullptr);
  }
  std::vector<double> r(p_.size(), 0.0);
  kernels::Residual(options_.solver.stencil, width_, height_, p_.data(), nullptr, mask_.free.data(),
                    r.data());
  double worst = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (r[i] == 0.0) continue;
    worst = std::max(
        worst, p_[i] > 0.0 ? std::abs(r[i]) / p_[i] : std::numeric_limits<double>::infinity());
  }
  return worst;
}

IterationReport PotentialField::Iterate(int sweeps) {
  if (width_ == 0 || goal_count_ == 0) {
    throw std::logic_error("PotentialField::Iterate: no window or no goal");
  }
  if (!solver_ready_) {
    solver_->Setup(mask_);
    solver_ready_ = true;
  }
  for (int s = 0; s < sweeps; ++s) {
    if (options_.norm == ResidualNorm::kAbsolute) {
      solver_->Iterate(p_.data());
      continue;
    }
    // Relative accuracy needs p >= 0 everywhere (the exact p is). A multigrid coarse correction
    // is accurate in absolute terms only: it brings the field to round-off of its largest
    // values, after which line relaxation (local, positive weights) resolves the small tails.
    IterativeSolver* solver = solver_.get();
    if (solver_->kind() == SolverKind::kMultigrid &&
        kernels::Residual(options_.solver.stencil, width_, height_, p_.data(), nullptr,
                          mask_.free.data(), nullptr) < kPolishBelowAbsoluteResidual) {
      if (!polish_) {
        SolverOptions o = options_.solver;
        o.kind = SolverKind::kAdi;
        o.omega = 0.0;
        polish_ = MakeSolver(o);
      }
      if (!polish_ready_) {
        polish_->Setup(mask_);
        polish_ready_ = true;
      }
      solver = polish_.get();
    }
    solver->Iterate(p_.data());
    for (std::size_t i = 0; i < p_.size(); ++i) p_[i] = std::max(p_[i], 0.0);
  }
  report_.sweeps += sweeps;
  report_.residual = Residual();
  report_.converged = report_.residual < options_.tolerance;
  return report_;
}

IterationReport PotentialField::Solve(int max_sweeps) {
  if (report_.converged && report_.sweeps > 0) return report_;
  for (int s = 0; s < max_sweeps; ++s) {
    Iterate(1);
    if (report_.converged) break;
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

namespace {
struct Bilinear {
  int x0, y0;
  double fx, fy;
};
}  // namespace

double PotentialField::InterpolatedGoalProbability(const Vec2& p) const {
  if (!CellOf(p)) return 0.0;
  const double gx = std::clamp((p.x() - origin_.x()) / resolution_ - 0.5, 0.0, width_ - 1.0);
  const double gy = std::clamp((p.y() - origin_.y()) / resolution_ - 0.5, 0.0, height_ - 1.0);
  const int x0 = std::min(static_cast<int>(gx), width_ - 2);
  const int y0 = std::min(static_cast<int>(gy), height_ - 2);
  const double fx = gx - x0;
  const double fy = gy - y0;
  const double p00 = p_[Index(x0, y0)], p10 = p_[Index(x0 + 1, y0)];
  const double p01 = p_[Index(x0, y0 + 1)], p11 = p_[Index(x0 + 1, y0 + 1)];
  return (1 - fy) * ((1 - fx) * p00 + fx * p10) + fy * ((1 - fx) * p01 + fx * p11);
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
  // Gradient of p (ascent of p = descent of u): central differences at the four surrounding
  // cell centres, interpolated bilinearly. (The gradient of the bilinear interpolant itself
  // jumps at cell centres and makes paths zig-zag along a corridor's centre line.) The common
  // factor 1 / (2 resolution) does not change the direction.
  const auto gradient = [this](int x, int y) {
    const int xm = std::max(x - 1, 0), xp = std::min(x + 1, width_ - 1);
    const int ym = std::max(y - 1, 0), yp = std::min(y + 1, height_ - 1);
    return Vec2(p_[Index(xp, y)] - p_[Index(xm, y)], p_[Index(x, yp)] - p_[Index(x, ym)]);
  };
  const Vec2 g = (1 - fy) * ((1 - fx) * gradient(x0, y0) + fx * gradient(x0 + 1, y0)) +
                 fy * ((1 - fx) * gradient(x0, y0 + 1) + fx * gradient(x0 + 1, y0 + 1));
  const double dx = g.x(), dy = g.y();
  const double n = std::hypot(dx, dy);  // hypot: no underflow for p ~ 1e-300 in corridors
  if (!(n > 0.0)) return std::nullopt;
  return Vec2(dx / n, dy / n);
}

std::optional<std::pair<int, int>> PotentialField::BestNeighbour(int x, int y) const {
  std::optional<std::pair<int, int>> best;
  double best_p = p_[Index(x, y)];
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
    if (p_[Index(nx, ny)] > best_p) {
      best_p = p_[Index(nx, ny)];
      best = std::make_pair(nx, ny);
    }
  }
  return best;
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
  Vec2 pos = start;
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
    // Every step must raise the interpolated p strictly: the path cannot cycle.
    const double here = InterpolatedGoalProbability(pos);
    Vec2 next;
    bool continuous = false;
    if (const auto d1 = DescentDirection(pos)) {
      const auto d2 = DescentDirection(pos + 0.5 * h * *d1);
      next = pos + h * (d2 ? *d2 : *d1);
      const auto nc = CellOf(next);
      continuous = nc && kind_[Index(nc->first, nc->second)] != FieldCell::kObstacle &&
                   InterpolatedGoalProbability(next) > here;
    }
    if (!continuous) {
      // Flat or misleading interpolant (saddles, passages one or two cells wide): discrete
      // steepest descent over cells until above the current value. For a harmonic field some
      // 4-neighbour is strictly better (mean-value property), so this ends at the goal at worst.
      std::pair<int, int> cell = *c;
      bool found = false;
      for (int hop = 0; hop < width_ + height_; ++hop) {
        const auto best = BestNeighbour(cell.first, cell.second);
        if (!best) break;
        cell = *best;
        if (p_[Index(cell.first, cell.second)] > here) {
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

void PotentialField::ComputeClearance() {
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
  // Centre-to-centre distance minus half a cell: the distance to the blocked cell's square.
  return std::max(0.0, (clearance_cells_[Index(c->first, c->second)] - 0.5) * resolution_);
}

}  // namespace spott_harmonic_planner
