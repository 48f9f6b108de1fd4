#include "spott_launch/leg_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>

#include "spott_map/geometry.h"
#include "spott_map/map_database.h"
#include "spott_map/map_feature.h"
#include "spott_tr_plus/task_command.h"

namespace spott_launch {

void LegMetrics::Reset(double t) {
  leg_start_ = t;
  leg_end_ = std::numeric_limits<double>::infinity();
  path_length_m_ = 0.0;
  min_wall_distance_m_ = std::numeric_limits<double>::infinity();
  bumper_hits_ = body_contacts_ = estimates_ = lost_reports_ = 0;
  lost_ = pressed_ = touching_ = false;
  lost_onsets_s_.clear();
  contact_onsets_s_.clear();
  sum_position_error_m_ = max_position_error_m_ = 0.0;
  sum_heading_error_rad_ = max_heading_error_rad_ = 0.0;
  pending_.clear();
}

void LegMetrics::OnTruth(double t, double x, double y, double yaw) {
  if (t > leg_end_) return;
  const spott_map::Vec2 p(x, y);
  const bool in_leg = t >= leg_start_;
  if (have_pose_ && in_leg) path_length_m_ += (p - position_).norm();
  position_ = p;
  yaw_ = yaw;
  have_pose_ = true;
  // The last kTruthHistoryS of ground truth: a status computed on a loaded machine can come
  // seconds (simulated) after its reading, and must still meet the truth of its stamp, or the
  // live run and its bag pair it differently.
  if (!history_.empty() && t < history_.back().t) history_.clear();
  history_.push_back(Sample{t, p, yaw});
  while (history_.size() > 2 && t - history_.front().t > kTruthHistoryS) history_.pop_front();
  if (in_leg)
    min_wall_distance_m_ = std::min(min_wall_distance_m_, DistanceToNearestSolid(*world_, p));
  Evaluate(false);
}

void LegMetrics::OnStatus(double t, double estimate_x, double estimate_y, double estimate_yaw,
                          bool lost) {
  if (t < leg_start_ || t > leg_end_) return;
  pending_.push_back(Status{t, estimate_x, estimate_y, estimate_yaw, lost});
  Evaluate(false);
}

void LegMetrics::Evaluate(bool all) {
  while (!pending_.empty() && have_pose_ && (all || history_.back().t >= pending_.front().t)) {
    const Status& s = pending_.front();
    // The truth at the status' stamp, interpolated between the samples around it: a sample
    // dropped by the live subscriber or by the recorder then hardly changes the pairing.
    spott_map::Vec2 truth = history_.front().position;
    double truth_yaw = history_.front().yaw;
    const Sample* after = nullptr;
    for (auto it = history_.rbegin(); it != history_.rend(); ++it) {
      if (it->t > s.t) {
        after = &*it;
        continue;
      }
      truth = it->position;
      truth_yaw = it->yaw;
      if (after != nullptr && after->t > it->t) {
        const double f = (s.t - it->t) / (after->t - it->t);
        truth = truth + f * (after->position - truth);
        truth_yaw += f * spott_map::NormalizeAngle(after->yaw - truth_yaw);
      }
      break;
    }
    const double e = (spott_map::Vec2(s.x, s.y) - truth).norm();
    const double h = std::abs(spott_map::NormalizeAngle(s.yaw - truth_yaw));
    ++estimates_;
    lost_reports_ += s.lost ? 1 : 0;
    if (s.lost && !lost_) lost_onsets_s_.push_back(s.t);
    lost_ = s.lost;
    sum_position_error_m_ += e;
    sum_heading_error_rad_ += h;
    max_position_error_m_ = std::max(max_position_error_m_, e);
    max_heading_error_rad_ = std::max(max_heading_error_rad_, h);
    pending_.pop_front();
  }
}

void LegMetrics::OnBumper(double t, bool any_pressed) {
  if (t < leg_start_ || t > leg_end_) return;
  bumper_hits_ += any_pressed ? 1 : 0;
  if (any_pressed && !pressed_ && !touching_) contact_onsets_s_.push_back(t);
  pressed_ = any_pressed;
}

void LegMetrics::OnBodyContact(double t, bool touching) {
  if (t < leg_start_ || t > leg_end_) return;
  body_contacts_ += touching ? 1 : 0;
  // A contact begins when the bumper or the body (a robot without a bumper, a bumper that
  // dropped out) first says so.
  if (touching && !touching_ && !pressed_) contact_onsets_s_.push_back(t);
  touching_ = touching;
}

void LegMetrics::Measure(const spott_map::Vec2& target, NavigationLeg& leg) {
  Evaluate(true);
  leg.path_length_m = path_length_m_;
  leg.final_error_m = (position_ - target).norm();
  leg.final_position = position_;
  leg.min_wall_distance_m = min_wall_distance_m_;
  leg.bumper_hits = bumper_hits_;
  leg.body_contacts = body_contacts_;
  leg.estimates = estimates_;
  leg.lost_reports = lost_reports_;
  leg.lost_onsets_s = lost_onsets_s_;
  leg.contact_onsets_s = contact_onsets_s_;
  if (estimates_ > 0) {
    leg.mean_position_error_m = sum_position_error_m_ / estimates_;
    leg.mean_heading_error_rad = sum_heading_error_rad_ / estimates_;
    leg.max_position_error_m = max_position_error_m_;
    leg.max_heading_error_rad = max_heading_error_rad_;
  }
}

double DistanceToNearestSolid(const spott_map::World& world, const spott_map::Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const spott_map::Wall& wall : world.walls) {  // boxes with flat ends, as simulated
    best = std::min(
        best, spott_map::MakeSegment(wall.id, wall.segment, "wall", wall.thickness).DistanceTo(p));
  }
  for (const spott_map::WorldObject& object : world.objects) {
    const spott_map::Polygon footprint = object.Footprint();
    const double d =
        spott_map::PointInPolygon(p, footprint) ? 0.0 : spott_map::DistanceToBoundary(p, footprint);
    best = std::min(best, d);
  }
  return best;
}

void JudgeLeg(const std::string& refusal, const std::string& off_goal, NavigationLeg& leg) {
  leg.reached = false;
  if (!refusal.empty()) {
    leg.outcome = "not reached: " + refusal;
  } else if (!off_goal.empty()) {
    leg.outcome = "not reached: " + off_goal;
  } else if (leg.bumper_hits > 0) {
    leg.outcome = "not reached: at the goal, but after " + std::to_string(leg.bumper_hits) +
                  " bumper contacts";
  } else if (leg.body_contacts > 0) {
    leg.outcome = "not reached: at the goal, but the body touched a wall or object (" +
                  std::to_string(leg.body_contacts) + " ground-truth contact messages)";
  } else {
    leg.outcome = "reached";
    leg.reached = true;
  }
}

namespace {

// "<claim>, but the robot is <where> 0.31 m from the <goal> (tolerance 0.25 m)".
std::string OffBy(const char* claim, const char* where, const char* goal, double error_m,
                  double tolerance_m) {
  char why[240];
  std::snprintf(why, sizeof(why), "%s, but the robot is %s%.2f m from the %s (tolerance %.2f m)",
                claim, where, error_m, goal, tolerance_m);
  return why;
}

}  // namespace

std::string OffPlace(const NavigationLeg& leg, double tolerance_m) {
  if (leg.final_error_m <= tolerance_m) return "";
  return OffBy("Navigate succeeded on the estimate", "", "target", leg.final_error_m, tolerance_m);
}

void SetMissionTarget(const MissionSpec& spec, const spott_map::World& world, NavigationLeg& leg) {
  leg.mission = spec.name.text;
  leg.goal = spec.goal_place.text;
  leg.has_target = false;
  if (const spott_map::Place* place = world.FindPlace(spec.goal_place.text)) {
    leg.target = place->pose;
    leg.has_target = true;
  } else if (spec.goal_point) {
    leg.target = {spec.goal_point->x(), spec.goal_point->y(), 0.0};
    leg.has_target = true;
  }
}

std::string OffMissionGoal(const NavigationLeg& leg, double tolerance_m) {
  if (!leg.has_target || leg.final_error_m <= tolerance_m) return "";
  return OffBy("the mission went as its scenario says", "", "mission's goal", leg.final_error_m,
               tolerance_m);
}

void JudgeMissionLeg(const std::string& mismatch, double tolerance_m, NavigationLeg& leg) {
  JudgeLeg(mismatch, OffMissionGoal(leg, tolerance_m), leg);
  if (leg.reached) leg.outcome = "as the scenario says";
}

std::string MissionMismatch(const MissionSpec& spec, const std::string& outcome,
                            const std::string& message, const std::vector<std::string>& fired) {
  const auto listed = [](const std::vector<std::string>& v) {
    std::string out;
    for (const auto& c : v) out += (out.empty() ? "" : ", ") + c;
    return "[" + out + "]";
  };
  if (outcome != spec.outcome) {
    return "the mission " + outcome + (message.empty() ? "" : " (" + message + ")") +
           ", expected " + spec.outcome;
  }
  if (spec.monitors && fired != *spec.monitors)
    return "the monitors fired " + listed(fired) + ", expected " + listed(*spec.monitors);
  // monitors_include: a subsequence of what fired.
  std::size_t next = 0;
  for (const auto& c : fired)
    if (next < spec.monitors_include.size() && c == spec.monitors_include[next]) ++next;
  if (next < spec.monitors_include.size())
    return "the monitors fired " + listed(fired) + ", expected " + listed(spec.monitors_include) +
           " among them in this order";
  if (!spec.message_contains.empty() && message.find(spec.message_contains) == std::string::npos)
    return "the executive said '" + message + "', expected it to say '" + spec.message_contains +
           "'";
  return "";
}

double NearestObjectOfKind(const spott_map::World& world, const std::string& label,
                           const spott_map::Vec2& at) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const spott_map::WorldObject& o : world.objects) {
    if (spott_map::ToString(o.kind) != label) continue;
    const spott_map::Polygon footprint = o.Footprint();
    nearest = std::min(nearest, spott_map::PointInPolygon(at, footprint)
                                    ? 0.0
                                    : spott_map::DistanceToBoundary(at, footprint));
  }
  return nearest;
}

std::string OffFoundObject(const spott_map::World& world, const NavigationLeg& leg) {
  if (leg.found_label.empty()) return "nothing was found";
  if (!leg.found_at.allFinite()) return "the object found has no place";
  const double nearest = NearestObjectOfKind(world, leg.found_label, leg.found_at);
  if (nearest <= kFoundToleranceM) return "";
  std::ostringstream why;
  why << std::fixed << std::setprecision(2) << "the controller found a " << leg.found_label
      << " at (" << leg.found_at.x() << ", " << leg.found_at.y() << "), but ";
  if (std::isfinite(nearest))
    why << "the world's nearest " << leg.found_label << " is " << nearest << " m away";
  else
    why << "the world has no " << leg.found_label;
  why << " (tolerance " << kFoundToleranceM << " m)";
  return why.str();
}

std::string OffTeleoperation(const spott_map::Pose2& start, double direction,
                             const NavigationLeg& leg) {
  const spott_map::Vec2 way(std::cos(direction), std::sin(direction));
  const double advance = (leg.final_position - start.Position()).dot(way);
  if (advance >= kTeleopAdvanceM) return "";
  std::ostringstream why;
  why << std::fixed << std::setprecision(2) << "the controller says stopped, but the robot went "
      << advance << " m the way it was sent (at least " << kTeleopAdvanceM << " m)";
  return why.str();
}

std::string OffTaskGoal(const spott_map::World& world, const std::string& command,
                        const spott_map::Pose2& start, const NavigationLeg& leg,
                        double tolerance_m) {
  // The goal regions are judged as the controller sees them (spott_tr_plus task
  // interpretation) but on the CAD map of the world file and the ground truth.
  const spott_map::MapDatabase cad = spott_map::MapDatabase::FromWorld(world);
  const spott_tr_plus::PlaceResolver resolve = spott_tr_plus::MapPlaceResolver(cad, world.places);
  bool in_region = false;
  std::string region_error;
  const auto parsed = spott_tr_plus::ParseTaskCommand(command);
  if (parsed.ok() && parsed.command->verb == spott_tr_plus::Verb::kFind)
    return OffFoundObject(world, leg);
  if (parsed.ok()) {
    const auto in =
        spott_tr_plus::InterpretTask(*parsed.command, start.x, start.y, start.yaw,
                                     spott_tr_plus::TaskInterpretationParameters{}, resolve);
    using Mode = spott_tr_plus::TaskInterpretation::Mode;
    using Bias = spott_tr_plus::DirectionBias::Kind;
    if (in.ok() && in.interpretation->mode == Mode::kTeleoperate) {
      const spott_tr_plus::DirectionBias& b = in.interpretation->bias;
      if (b.kind == Bias::kRelativeHeading)
        return OffTeleoperation(start, start.yaw + b.angle, leg);
      if (b.kind == Bias::kAbsoluteHeading) return OffTeleoperation(start, b.angle, leg);
      return "the tele-operation names no heading";
    }
    if (in.ok() && in.interpretation->goal) {
      in_region = in.interpretation->goal->Contains(leg.final_position.x(), leg.final_position.y());
    } else {
      region_error = "the command names no goal region";
    }
  }
  if (!leg.has_target || !region_error.empty())
    return region_error.empty() ? "no goal point" : region_error;
  if (in_region || leg.final_error_m <= tolerance_m) return "";
  return OffBy("the controller says reached", "outside the goal region and ", "goal point",
               leg.final_error_m, tolerance_m);
}

}  // namespace spott_launch
