#include "spott_harmonic_planner/local_planner.h"

#include "spott_harmonic_planner/border_exploration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace spott_harmonic_planner {

std::vector<std::string> ValidateParameters(const PlannerParameters& p) {
  std::vector<std::string> v;
  for (const auto& s : spott_map::ValidateParameters(p.window)) v.push_back("window/" + s);
  for (const auto& s : ValidateFieldOptions(p.field)) v.push_back("solver/" + s);
  for (const auto& s : ValidateSteeringParameters(p.steering)) v.push_back("steering/" + s);
  if (p.sweeps_per_cycle < 1 || p.sweeps_per_cycle > 10000) {
    v.push_back("solver/sweeps_per_cycle must be in [1, 10000] (got " +
                std::to_string(p.sweeps_per_cycle) + ")");
  }
  if (!(p.goal_tolerance_m > 0.0)) {
    std::ostringstream s;
    s << "navigate/goal_tolerance_m must be > 0 m (got " << p.goal_tolerance_m << ")";
    v.push_back(s.str());
  }
  if (!(p.border_goal_half_width_m > 0.0)) {
    std::ostringstream s;
    s << "navigate/border_goal_half_width_m must be > 0 m (got " << p.border_goal_half_width_m
      << ")";
    v.push_back(s.str());
  }
  return v;
}

std::optional<spott_map::Segment> BorderGoalSegment(const Vec2& robot, const Vec2& goal,
                                                    const spott_map::Box& w, double half_width_m) {
  if (w.Contains(goal) || !w.Contains(robot)) return std::nullopt;
  const Vec2 d = goal - robot;
  // Smallest t in (0, 1] at which robot + t d meets a side.
  double t = std::numeric_limits<double>::infinity();
  int side = -1;  // 0: x = min, 1: x = max, 2: y = min, 3: y = max
  if (d.x() < 0) {
    const double s = (w.min.x() - robot.x()) / d.x();
    if (s < t) {
      t = s;
      side = 0;
    }
  }
  if (d.x() > 0) {
    const double s = (w.max.x() - robot.x()) / d.x();
    if (s < t) {
      t = s;
      side = 1;
    }
  }
  if (d.y() < 0) {
    const double s = (w.min.y() - robot.y()) / d.y();
    if (s < t) {
      t = s;
      side = 2;
    }
  }
  if (d.y() > 0) {
    const double s = (w.max.y() - robot.y()) / d.y();
    if (s < t) {
      t = s;
      side = 3;
    }
  }
  if (side < 0) return std::nullopt;
  const Vec2 hit = robot + t * d;
  if (side <= 1) {
    const double x = side == 0 ? w.min.x() : w.max.x();
    return spott_map::Segment{Vec2(x, std::max(w.min.y(), hit.y() - half_width_m)),
                              Vec2(x, std::min(w.max.y(), hit.y() + half_width_m))};
  }
  const double y = side == 2 ? w.min.y() : w.max.y();
  return spott_map::Segment{Vec2(std::max(w.min.x(), hit.x() - half_width_m), y),
                            Vec2(std::min(w.max.x(), hit.x() + half_width_m), y)};
}

namespace {
// Both ends on one side of the box, within tol (the global planner's segment may lie on the
// border cells' centres, half a cell inside).
bool OnBorder(const spott_map::Segment& s, const spott_map::Box& b, double tol) {
  const auto on_x = [&](double x) {
    return std::abs(s.a.x() - x) <= tol && std::abs(s.b.x() - x) <= tol;
  };
  const auto on_y = [&](double y) {
    return std::abs(s.a.y() - y) <= tol && std::abs(s.b.y() - y) <= tol;
  };
  return on_x(b.min.x()) || on_x(b.max.x()) || on_y(b.min.y()) || on_y(b.max.y());
}

// `s` (on a side of an earlier window) moved onto the side of `b` it faces from `robot`, its
// extent along that side kept and clipped to `b`; none when nothing of it is left.
std::optional<spott_map::Segment> OnSameSide(const spott_map::Segment& s, const Vec2& robot,
                                             const spott_map::Box& b) {
  const Vec2 mid = s.Midpoint();
  if (std::abs(s.a.x() - s.b.x()) <= std::abs(s.a.y() - s.b.y())) {  // on an east or west side
    const double x = mid.x() > robot.x() ? b.max.x() : b.min.x();
    const double y0 = std::max(std::min(s.a.y(), s.b.y()), b.min.y());
    const double y1 = std::min(std::max(s.a.y(), s.b.y()), b.max.y());
    if (y0 > y1) return std::nullopt;
    return spott_map::Segment{Vec2(x, y0), Vec2(x, y1)};
  }
  const double y = mid.y() > robot.y() ? b.max.y() : b.min.y();
  const double x0 = std::max(std::min(s.a.x(), s.b.x()), b.min.x());
  const double x1 = std::min(std::max(s.a.x(), s.b.x()), b.max.x());
  if (x0 > x1) return std::nullopt;
  return spott_map::Segment{Vec2(x0, y), Vec2(x1, y)};
}

PlannerParameters Checked(const PlannerParameters& p) {
  const auto v = ValidateParameters(p);
  if (!v.empty()) {
    std::string text = "invalid planner parameters:";
    for (const auto& s : v) text += " " + s + ";";
    throw std::invalid_argument(text);
  }
  return p;
}
}  // namespace

LocalPlanner::LocalPlanner(const PlannerParameters& params)
    : params_(Checked(params)), window_(params.window), field_(params.field) {}

void LocalPlanner::SetMap(const spott_map::MapDatabase& db) {
  db_ = db;
  map_dirty_ = true;
}

void LocalPlanner::SetGoal(const Vec2& goal, double snap_radius_m) {
  goal_ = goal;
  goal_snap_radius_m_ = std::isfinite(snap_radius_m) ? std::max(0.0, snap_radius_m) : 0.0;
  border_goal_.reset();
  goal_dirty_ = true;
  goal_moved_ = true;
}

void LocalPlanner::SetBorderGoal(const spott_map::Segment& segment) {
  border_goal_ = segment;
  goal_dirty_ = true;
  goal_moved_ = true;
}

void LocalPlanner::ClearBorderGoal() {
  if (!border_goal_) return;
  border_goal_.reset();
  goal_dirty_ = true;
  goal_moved_ = true;
}

void LocalPlanner::ClearGoal() {
  goal_.reset();
  border_goal_.reset();
  goal_dirty_ = true;
  goal_moved_ = true;
}

void LocalPlanner::CorrectPose(const spott_map::Pose2& estimate) { pose_ = estimate; }

void LocalPlanner::Odometry(const spott_map::Pose2& odom) {
  if (last_odom_) {
    // The increment in the previous odometry pose's own frame, applied to the estimate.
    const double c = std::cos(last_odom_->yaw), s = std::sin(last_odom_->yaw);
    const double dx = odom.x - last_odom_->x, dy = odom.y - last_odom_->y;
    const double fx = c * dx + s * dy, fy = -s * dx + c * dy;
    const double ce = std::cos(pose_.yaw), se = std::sin(pose_.yaw);
    pose_.x += ce * fx - se * fy;
    pose_.y += se * fx + ce * fy;
    pose_.yaw = WrapAngle(pose_.yaw + odom.yaw - last_odom_->yaw);
  }
  last_odom_ = odom;
}

void LocalPlanner::PlaceGoal() {
  status_.problem.clear();
  status_.has_goal = false;
  status_.border_widened = false;
  status_.exploring = false;
  status_.goal_snapped_m = 0.0;
  if (!goal_) return;
  const spott_map::Box b = window_.bounds();
  // Inside the window's inner part (the border ring holds the high value), decided by the
  // goal's cell: a goal on the inner part's edge lies in a border cell.
  const double r = window_.raster().resolution();
  const auto cell = window_.raster().CellOf(*goal_);
  const bool inner = cell && cell->first >= 1 && cell->second >= 1 &&
                     cell->first <= window_.raster().width() - 2 &&
                     cell->second <= window_.raster().height() - 2;
  bool ok;
  if ((inner || b.Contains(*goal_)) && !border_goal_) {
    // A goal in the border ring is aimed at from the inner cell next to it (at most a cell
    // away); the window re-centres before the robot gets there.
    const Vec2 aim = inner ? *goal_
                           : goal_->cwiseMax(b.min + Vec2(1.5 * r, 1.5 * r))
                                 .cwiseMin(b.max - Vec2(1.5 * r, 1.5 * r));
    ok = field_.SetGoalPoint(aim);
    // A goal in the padding (beside a door's jamb, the controller's goal region fitted with
    // another margin) is aimed at through the nearest free cell within the goal's tolerance.
    if (!ok && inner && goal_snap_radius_m_ > 0.0) {
      if (const auto free = NearestFreeCell(aim, goal_snap_radius_m_)) {
        ok = field_.SetGoalPoint(*free);
        if (ok) status_.goal_snapped_m = (*free - aim).norm();
      }
    }
    if (!ok) {
      status_.problem = "the goal lies in a padded obstacle";
      if (goal_snap_radius_m_ > 0.0) {
        std::ostringstream s;
        s << " (no free cell within " << goal_snap_radius_m_ << " m)";
        status_.problem += s.str();
      }
    }
  } else {
    std::optional<spott_map::Segment> seg = border_goal_;
    // The global planner's segment lay on the window's border when it came; after a re-centre
    // it lies inside until the projection onto the new window arrives (a cycle or two). Until
    // then the goal is that segment carried to the same side of the new window (a corridor's
    // cross-section stays one): the robot does not stop for it.
    if (seg && !OnBorder(*seg, b, r)) {
      seg = OnSameSide(*seg, pose_.Position(), b);
    } else if (!seg) {
      seg = BorderGoalSegment(pose_.Position(), *goal_, b, params_.border_goal_half_width_m);
    }
    // A border goal whose own cells are all blocked (a door projected at an angle onto a wall
    // crossing the border, the window shifted by a localization error) widens step by step to
    // the free border cells nearest it, up to border_goal_half_width_m.
    ok = false;
    for (double half = 0.75 * r; seg && !ok; half *= 2.0) {
      ok = field_.SetGoalSegment(*seg, std::min(half, params_.border_goal_half_width_m));
      status_.border_widened = half > 0.75 * r;
      if (half >= params_.border_goal_half_width_m) break;
    }
    if (!ok) status_.problem = "the projected border goal is blocked";
  }
  // A new goal starts cold (full multigrid); the same point goal in a re-centred window keeps
  // the values the window shift moved along (warm start).
  if (ok && (goal_moved_ || field_.goal_on_border() || field_.report().sweeps == 0)) {
    field_.ColdStart();
  }
  goal_moved_ = false;
  status_.has_goal = ok;
}

void LocalPlanner::ExploreIfCutOff() {
  // The global planner's projection follows the room/door graph: never second-guessed here.
  if (!goal_ || border_goal_) return;
  const auto c = field_.CellOf(pose_.Position());
  if (!c) return;
  const FieldCell kind = field_.cell(c->first, c->second);
  // Cut off: the robot's free cell is not connected to the goal's, or the projection's border
  // cells are all blocked. In the padding steering escapes first; a point goal inside a sensed
  // obstacle stays refused.
  const bool blocked_projection = !status_.has_goal && !window_.bounds().Contains(*goal_);
  if (kind != FieldCell::kUnreachable && !blocked_projection) return;
  const auto frontier = NearestReachableBorderCell(field_, pose_.Position(), *goal_);
  if (!frontier) return;
  const double r = window_.raster().resolution();
  if (!field_.SetGoalSegment(spott_map::Segment{*frontier, *frontier}, 0.75 * r)) return;
  field_.ColdStart();
  status_.problem.clear();
  status_.has_goal = true;
  status_.exploring = true;
}

std::optional<Vec2> LocalPlanner::NearestFreeCell(const Vec2& p, double radius_m) const {
  const auto c = field_.CellOf(p);
  if (!c) return std::nullopt;
  const int r = static_cast<int>(std::ceil(radius_m / field_.resolution()));
  std::optional<Vec2> best;
  double best_d = radius_m, best_to_robot = 0.0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int x = c->first + dx, y = c->second + dy;
      if (x < 1 || y < 1 || x > field_.width() - 2 || y > field_.height() - 2) continue;
      if (field_.cell(x, y) == FieldCell::kObstacle) continue;
      const Vec2 centre = field_.CellCentre(x, y);
      const double d = (centre - p).norm();
      const double to_robot = (centre - pose_.Position()).norm();
      // Nearest the goal; of equals, the one nearer the robot (its side of the padding).
      if (d < best_d - 1e-9 || (best && d < best_d + 1e-9 && to_robot < best_to_robot)) {
        best = centre;
        best_d = d;
        best_to_robot = to_robot;
      }
    }
  }
  return best;
}

PlannerStatus LocalPlanner::Cycle() {
  status_.recentred = false;
  if (!window_cut_ || window_.NeedsRecentre(pose_.Position())) {  // (f) then step 1, 2
    window_.Recentre(db_, pose_.Position());
    field_.SetOccupancy(window_.raster());
    window_cut_ = true;
    map_dirty_ = false;
    status_.recentred = true;
    goal_dirty_ = true;
  } else if (map_dirty_) {  // (c): same window, warm start
    window_.Refresh(db_);
    field_.SetOccupancy(window_.raster());
    map_dirty_ = false;
    if (goal_ && !field_.HasGoal()) goal_dirty_ = true;
  }
  if (goal_dirty_) {
    PlaceGoal();
    goal_dirty_ = false;
  }
  if (params_.explore_when_cut_off) ExploreIfCutOff();
  if (field_.HasGoal() && status_.has_goal) {  // (a)
    // Resolved where descent from the robot goes; a converged field is not iterated again until
    // the map, the goal or the robot's place asks for more.
    field_.SetStart(pose_.Position());
    status_.iteration = field_.Solve(params_.sweeps_per_cycle);
  }
  status_.goal_on_border = field_.goal_on_border();
  return status_;
}

SteeringCommand LocalPlanner::Steer(SpeedMode mode, std::optional<double> bias) const {
  if (!status_.has_goal) {
    SteeringCommand cmd;
    cmd.reason = goal_ ? status_.problem : "no goal";
    return cmd;
  }
  return ComputeSteering(
      field_, pose_, mode, bias,
      field_.goal_on_border() ? std::numeric_limits<double>::infinity() : DistanceToGoal(),
      params_.steering);
}

PotentialField::Path LocalPlanner::PredictedPath() const {
  if (!status_.has_goal) return {};
  return field_.DescendPath(pose_.Position());
}

double LocalPlanner::DistanceToGoal() const {
  if (!goal_) return 0.0;
  const auto path = PredictedPath();
  if (!path.reached_goal) return (*goal_ - pose_.Position()).norm();
  double d = path.length_m;
  if (!path.points.empty()) d += (*goal_ - path.points.back()).norm();
  return d;
}

bool LocalPlanner::GoalReached() const {
  return goal_ && (*goal_ - pose_.Position()).norm() <= params_.goal_tolerance_m;
}

}  // namespace spott_harmonic_planner
