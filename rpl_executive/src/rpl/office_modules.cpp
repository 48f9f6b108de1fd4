#include "rpl_executive/rpl/office_modules.h"

#include <cmath>
#include <cstdio>

#include "rpl_executive/rpl/office_robot.h"

namespace rpl_executive {
namespace rpl {
namespace office {

namespace {

std::string Format(const char* format, double a, double b) {
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), format, a, b);
  return buffer;
}

}  // namespace

const char* GoalOutcomeName(GoalOutcome outcome) {
  switch (outcome) {
    case GoalOutcome::kSucceeded:
      return "succeeded";
    case GoalOutcome::kUnreachable:
      return "unreachable";
    case GoalOutcome::kPreempted:
      return "preempted";
    case GoalOutcome::kFailed:
      return "failed";
  }
  return "?";
}

std::vector<std::string> ValidateParameters(const NavigationModuleParameters& p) {
  std::vector<std::string> e = ValidateParameters(p.plan);
  if (!(p.goal_tolerance_m > 0 && p.goal_tolerance_m <= 5))
    e.push_back("goal_tolerance_m: must be in (0, 5] m");
  if (!(p.target_tolerance_m > 0 && p.target_tolerance_m <= 5))
    e.push_back("target_tolerance_m: must be in (0, 5] m");
  return e;
}

std::vector<std::string> ValidateParameters(const ActiveLocalizationParameters& p) {
  std::vector<std::string> e;
  if (!(p.certainty_threshold > 0 && p.certainty_threshold < 1))
    e.push_back("certainty_threshold: must be in (0, 1)");
  if (!(p.timeout_s >= 0 && p.timeout_s <= 1e5)) e.push_back("timeout_s: must be in [0, 1e5] s");
  return e;
}

// ---- NAVIGATION -------------------------------------------------------------------------------

NavigationModule::NavigationModule(Executive* executive, NavigateClient* client,
                                   TravelModeSwitch* travel,
                                   const NavigationModuleParameters& parameters)
    : executive_(executive), client_(client), travel_(travel), params_(parameters) {}

ModuleSpec NavigationModule::Spec() const { return NavigationSpec(); }

void NavigationModule::SetMap(const BuildingMap& map) {
  map_ = map;
  has_map_ = true;
}

void NavigationModule::Activate(ActivationId id, const std::vector<Value>& args, double now_s) {
  clear_after_step_ = false;
  auto refuse = [&](const std::string& why) {
    note_ = why;
    executive_->ReportFailure(id, why);
    clear_after_step_ = true;  // a count left by an earlier plan goes to 0 after the report
  };
  const Value& dest = args.empty() ? Value() : args[0];
  if (!dest.IsList() || dest.items().size() != 2 || !dest.items()[0].IsNumber() ||
      !dest.items()[1].IsNumber() || !std::isfinite(dest.items()[0].number()) ||
      !std::isfinite(dest.items()[1].number())) {
    refuse("the destination must be (X Y) in m (map frame), got " + dest.ToString());
    return;
  }
  destination_ = {dest.items()[0].number(), dest.items()[1].number()};
  if (!has_map_) {
    refuse("no building map yet (world_server's room_door_graph)");
    return;
  }
  if (!pose_) {
    refuse("no position estimate yet (localization_status)");
    return;
  }
  std::string error;
  std::optional<NavigationPlan> plan =
      PlanNavigation(map_, *pose_, destination_, params_.plan, &error);
  if (!plan) {
    refuse("unreachable: " + error);
    return;
  }
  plan_ = std::move(plan);
  ++plans_generated_;
  id_ = id;
  remaining_ = plan_->targets;
  PublishFluents(now_s);
  SetMode(TravelModeAt(plan_->regions, *pose_), "", now_s);
  SendNext(now_s);
}

void NavigationModule::Deactivate(ActivationId id, double now_s) {
  if (id != id_ || id_ == 0) return;
  client_->CancelGoal(now_s);
  id_ = 0;
  remaining_.clear();  // "delete all target points"
  clear_after_step_ = false;
  note_ = "deactivated: target points deleted";
  PublishFluents(now_s);
  SetMode(TravelMode::kNone, "", now_s);
}

void NavigationModule::SendNext(double now_s) {
  const Point& target = remaining_.front();
  const bool last = remaining_.size() == 1;
  const std::size_t index = plan_->targets.size() - remaining_.size() + 1;
  note_ = "target " + std::to_string(index) + " of " + std::to_string(plan_->targets.size()) +
          Format(" (%.2f, %.2f)", target.x_m, target.y_m);
  client_->SendGoal(target, last ? params_.goal_tolerance_m : params_.target_tolerance_m, now_s);
}

void NavigationModule::OnGoalDone(GoalOutcome outcome, const std::string& reason, double now_s) {
  if (id_ == 0) return;
  if (outcome == GoalOutcome::kSucceeded) {
    remaining_.erase(remaining_.begin());
    if (!remaining_.empty()) {
      PublishFluents(now_s);
      SendNext(now_s);
      return;
    }
    const ActivationId id = id_;
    id_ = 0;
    clear_after_step_ = true;
    SetMode(TravelMode::kNone, "", now_s);
    // Navigate judged its success on the same estimate; allow for one estimate of lag.
    const double off =
        pose_ ? std::hypot(pose_->x_m - destination_.x_m, pose_->y_m - destination_.y_m) : 0.0;
    if (off > params_.goal_tolerance_m + 0.1) {
      note_ = Format("Navigate succeeded but the estimate is %.2f m from the destination (%.2f m",
                     off, params_.goal_tolerance_m) +
              " asked)";
      executive_->ReportFailure(id, note_);
      return;
    }
    note_ = "reached the destination";
    executive_->ReportSuccess(id, Value::Symbol(":ARRIVED"));
    return;
  }
  const ActivationId id = id_;
  id_ = 0;
  clear_after_step_ = true;
  SetMode(TravelMode::kNone, "", now_s);
  note_ = std::string(GoalOutcomeName(outcome)) + (reason.empty() ? "" : ": " + reason);
  executive_->ReportFailure(id, note_);
}

bool NavigationModule::AfterStep(double now_s) {
  if (!clear_after_step_ || id_ != 0) return false;
  clear_after_step_ = false;
  const bool changed = !remaining_.empty() ||
                       executive_->GetFluent(kNrOfNavGoals) != Value::Number(0) ||
                       executive_->GetFluent(kNavigationActive).Truthy();
  remaining_.clear();
  PublishFluents(now_s);
  return changed;
}

void NavigationModule::OnPose(const Point& position, double now_s) {
  pose_ = position;
  if (id_ == 0 || !plan_) return;
  // Outside every region of the plan (a short way off the path) the last mode holds.
  std::string region;
  TravelMode mode = TravelMode::kNone;
  for (const TravelRegion& r : plan_->regions) {
    if (!InsidePolygon(r.polygon, position)) continue;
    if (r.mode == TravelMode::kDoorway || mode == TravelMode::kNone) {
      mode = r.mode;
      region = r.id;
    }
    if (mode == TravelMode::kDoorway) break;
  }
  if (mode != TravelMode::kNone) SetMode(mode, region, now_s);
}

void NavigationModule::SetMode(TravelMode mode, const std::string& region, double now_s) {
  if (mode == mode_) return;
  mode_ = mode;
  mode_region_ = region;
  if (travel_) travel_->SetTravelMode(mode, region, now_s);
}

void NavigationModule::PublishFluents(double now_s) {
  executive_->SetFluent(kNrOfNavGoals, Value::Number(static_cast<double>(remaining_.size())),
                        now_s);
  executive_->SetFluent(kNavigationActive, Value::Boolean(id_ != 0), now_s);
}

// ---- ACTIVE-LOCALIZATION ----------------------------------------------------------------------

ActiveLocalizationModule::ActiveLocalizationModule(Executive* executive,
                                                   ActiveLocalizeClient* client,
                                                   const ActiveLocalizationParameters& parameters)
    : executive_(executive), client_(client), params_(parameters) {}

ModuleSpec ActiveLocalizationModule::Spec() const { return ActiveLocalizationSpec(); }

void ActiveLocalizationModule::Activate(ActivationId id, const std::vector<Value>&, double now_s) {
  id_ = id;
  ++activations_;
  client_->Start(params_.uniform_start, params_.certainty_threshold, params_.timeout_s, now_s);
}

void ActiveLocalizationModule::Deactivate(ActivationId id, double now_s) {
  if (id != id_ || id_ == 0) return;
  id_ = 0;
  client_->Cancel(now_s);
}

void ActiveLocalizationModule::OnDone(bool success, const std::string& reason, double) {
  if (id_ == 0) return;
  const ActivationId id = id_;
  id_ = 0;
  if (success) {
    executive_->ReportSuccess(id, Value::True());
  } else {
    executive_->ReportFailure(id, reason.empty() ? "ActiveLocalize gave up" : reason);
  }
}

// ---- POSITION-TRACKING ------------------------------------------------------------------------

PositionTrackingModule::PositionTrackingModule(Executive* executive, double status_timeout_s)
    : executive_(executive), status_timeout_s_(status_timeout_s) {}

ModuleSpec PositionTrackingModule::Spec() const { return PositionTrackingSpec(); }

void PositionTrackingModule::Activate(ActivationId id, const std::vector<Value>&, double now_s) {
  if (!last_status_s_ || now_s - *last_status_s_ > status_timeout_s_) {
    executive_->ReportFailure(
        id, last_status_s_ ? Format("no localization status for %.1f s (%.1f s allowed)",
                                    now_s - *last_status_s_, status_timeout_s_)
                           : "no localization status yet: is markov_localization running?");
    return;
  }
  id_ = id;
}

void PositionTrackingModule::Deactivate(ActivationId id, double) {
  if (id == id_) id_ = 0;
}

void PositionTrackingModule::OnStatus(double now_s) { last_status_s_ = now_s; }

void PositionTrackingModule::OnTime(double now_s) {
  if (id_ == 0 || !last_status_s_ || now_s - *last_status_s_ <= status_timeout_s_) return;
  const ActivationId id = id_;
  id_ = 0;
  executive_->ReportFailure(id, Format("no localization status for %.1f s (%.1f s allowed)",
                                       now_s - *last_status_s_, status_timeout_s_));
}

}  // namespace office
}  // namespace rpl
}  // namespace rpl_executive
