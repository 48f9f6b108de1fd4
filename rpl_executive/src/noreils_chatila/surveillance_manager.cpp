#include "rpl_executive/noreils_chatila/surveillance_manager.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace rpl_executive::noreils_chatila {

std::vector<std::string> ValidateParameters(const SurveillanceParameters& p) {
  std::vector<std::string> v;
  if (!(p.part_validity_s > 0.0)) v.push_back("part_validity_s: must be above 0");
  if (!(p.laser_front_half_angle_rad > 0.0 && p.laser_front_half_angle_rad <= kPi)) {
    v.push_back("laser_front_half_angle_rad: must be in (0, pi]");
  }
  for (const std::string& s : ValidateParameters(p.sonar)) v.push_back("sonar." + s);
  return v;
}

SurveillanceManager::SurveillanceManager(const SurveillanceParameters& parameters,
                                         const SonarRing& ring, RobotModules* modules,
                                         MessageLog* log,
                                         std::function<OperatorHandle()> next_handle)
    : parameters_(parameters),
      ring_(ring),
      modules_(modules),
      log_(log),
      next_handle_(std::move(next_handle)) {}

int SurveillanceManager::CountCrossings(const CompiledCondition& c) {
  if (c.op == CompiledCondition::Op::kAtom) {
    return std::holds_alternative<StraightLineCondition>(c.atom) ? 1 : 0;
  }
  int n = 0;
  for (const CompiledCondition& child : c.children) n += CountCrossings(child);
  return n;
}

SurveillanceManager::Formula SurveillanceManager::Split(const CompiledCondition& c,
                                                        Record* record) {
  Formula f;
  const std::vector<SensorKind> sensors = SensorsOf(c);
  if (sensors.size() == 1) {
    Part part;
    part.sensor = sensors[0];
    part.condition = c;
    part.crossing_side.resize(CountCrossings(c));
    f.op = CompiledCondition::Op::kAtom;
    f.part = static_cast<int>(record->parts.size());
    record->parts.push_back(std::move(part));
    return f;
  }
  f.op = c.op;
  for (const CompiledCondition& child : c.children) f.children.push_back(Split(child, record));
  return f;
}

SurveillanceManager::Record* SurveillanceManager::Find(MonitorId id) {
  auto it = std::lower_bound(records_.begin(), records_.end(), id,
                             [](const Record& r, MonitorId i) { return r.id < i; });
  return it != records_.end() && it->id == id ? &*it : nullptr;
}

const SurveillanceManager::Record* SurveillanceManager::Find(MonitorId id) const {
  return const_cast<SurveillanceManager*>(this)->Find(id);
}

MonitorId SurveillanceManager::Register(MonitorRequest request, double now) {
  Record r;
  r.id = next_id_++;
  r.request = std::move(request);
  r.formula = Split(r.request.condition, &r);
  log_->Add(now, Message::Kind::kMonitorId, "SM", "EM", r.id, r.request.label);
  records_.push_back(std::move(r));
  return records_.back().id;
}

void SurveillanceManager::Activate(MonitorId id, double now, Activation mode) {
  Record* r = Find(id);
  if (r == nullptr || r->active) return;
  r->active = true;
  r->must_see_false = mode == Activation::kAfterFalse;
  const bool evaluate_at_once = mode == Activation::kAtOnce;
  for (Part& part : r->parts) {
    part.evaluated = false;
    for (auto& side : part.crossing_side) side.reset();
    if (log_->enabled()) {
      log_->Add(now, Message::Kind::kCondition, "SM", SsmName(part.sensor), id,
                part.condition.text);
    }
  }
  // Every part starts from its sensor's latest datum: crossings need a first side, and with
  // `evaluate_at_once` the formula is evaluated now.
  bool any_true = false;
  for (Part& part : r->parts) {
    const int s = static_cast<int>(part.sensor);
    const bool have = (part.sensor == SensorKind::kSonar && sonar_) ||
                      (part.sensor == SensorKind::kPose && pose_) ||
                      (part.sensor == SensorKind::kLaser && laser_) ||
                      (part.sensor == SensorKind::kBattery && battery_);
    if (!have || now - stamp_[s] > parameters_.part_validity_s) continue;
    const bool value = EvaluatePart(&part, now, !evaluate_at_once);
    if (evaluate_at_once) {
      part.value = value;
      part.evaluated = true;
      part.stamp = stamp_[s];
      any_true |= value;
      if (value && log_->enabled()) {
        log_->Add(now, Message::Kind::kConditionTrue, SsmName(part.sensor), "SM", id,
                  part.condition.text);
      }
    }
  }
  if (evaluate_at_once && any_true && EvaluateFormula(r->formula, *r, now) == Truth::kTrue) {
    Fire({r}, now);
  }
}

bool SurveillanceManager::Remove(MonitorId id) {
  auto it = std::lower_bound(records_.begin(), records_.end(), id,
                             [](const Record& r, MonitorId i) { return r.id < i; });
  if (it == records_.end() || it->id != id) return false;
  records_.erase(it);
  return true;
}

bool SurveillanceManager::IsActive(MonitorId id) const {
  const Record* r = Find(id);
  return r != nullptr && r->active;
}

size_t SurveillanceManager::active_count() const {
  size_t n = 0;
  for (const Record& r : records_) n += r.active;
  return n;
}

std::vector<std::string> SurveillanceManager::ActiveLabels() const {
  std::vector<std::string> out;
  for (const Record& r : records_) {
    if (r.active) out.push_back(std::to_string(r.id) + ": " + r.request.label);
  }
  return out;
}

const std::vector<SonarLine>& SurveillanceManager::latest_lines() {
  if (!lines_valid_) {
    lines_ = sonar_ ? InterpretLines(*sonar_, ring_, parameters_.sonar) : std::vector<SonarLine>();
    lines_valid_ = true;
  }
  return lines_;
}

bool SurveillanceManager::EvaluateAtom(const CompiledCondition& c, Part* part, int* crossing,
                                       bool latest_only) {
  switch (c.op) {
    case CompiledCondition::Op::kAnd: {
      bool all = true;
      for (const auto& child : c.children) all &= EvaluateAtom(child, part, crossing, latest_only);
      return all;  // every child is evaluated: crossings keep their sides
    }
    case CompiledCondition::Op::kOr: {
      bool any = false;
      for (const auto& child : c.children) any |= EvaluateAtom(child, part, crossing, latest_only);
      return any;
    }
    case CompiledCondition::Op::kNot:
      return !EvaluateAtom(c.children[0], part, crossing, latest_only);
    case CompiledCondition::Op::kAtom:
      break;
  }
  if (const auto* zone = std::get_if<ZoneCondition>(&c.atom)) {
    if (!pose_) return false;
    const Point2 p{pose_->pose.x, pose_->pose.y};
    return PointInPolygon(p, zone->polygon_m) == zone->inside;
  }
  if (const auto* line = std::get_if<StraightLineCondition>(&c.atom)) {
    const int k = (*crossing)++;
    if (!pose_ || part == nullptr) return false;
    const double d = SignedDistanceToLine(Point2{pose_->pose.x, pose_->pose.y}, line->origin_m,
                                          line->direction_rad);
    std::optional<double>& side = part->crossing_side[k];
    const bool crossed = !latest_only && side.has_value() &&
                         ((*side < 0.0 && d >= 0.0) || (*side > 0.0 && d <= 0.0));
    side = d;
    return crossed;
  }
  if (const auto* us = std::get_if<UsThresholdCondition>(&c.atom)) {
    if (!sonar_) return false;
    for (const auto& [id, threshold] : us->thresholds_m) {
      const size_t i = static_cast<size_t>(id - 1);
      if (i < sonar_->ranges_m.size() && ring_.IsEcho(sonar_->ranges_m[i]) &&
          sonar_->ranges_m[i] < threshold) {
        return true;
      }
    }
    return false;
  }
  if (const auto* perception = std::get_if<UsPerceptionCondition>(&c.atom)) {
    if (!sonar_) return false;
    return PerceivesLine(latest_lines(), perception->rho_m, perception->theta_rad,
                         parameters_.sonar);
  }
  if (const auto* b = std::get_if<BatteryCondition>(&c.atom)) {
    if (!battery_) return false;
    return b->below ? battery_->level_percent < b->level_percent
                    : battery_->level_percent > b->level_percent;
  }
  if (const auto* l = std::get_if<LaserThresholdCondition>(&c.atom)) {
    if (!laser_) return false;
    for (size_t i = 0; i < laser_->ranges_m.size(); ++i) {
      const double r = laser_->ranges_m[i];
      const double a = laser_->angle_min_rad + laser_->angle_increment_rad * i;
      if (std::isfinite(r) && r < laser_->max_range_m && r < l->distance_m &&
          std::fabs(WrapAngle(a)) <= parameters_.laser_front_half_angle_rad) {
        return true;
      }
    }
    return false;
  }
  return false;
}

bool SurveillanceManager::EvaluatePart(Part* part, double /*now*/, bool latest_only) {
  int crossing = 0;
  return EvaluateAtom(part->condition, part, &crossing, latest_only);
}

SurveillanceManager::Truth SurveillanceManager::EvaluateFormula(const Formula& f, const Record& r,
                                                                double now) const {
  switch (f.op) {
    case CompiledCondition::Op::kAtom: {
      const Part& p = r.parts[f.part];
      if (!p.evaluated || now - p.stamp > parameters_.part_validity_s) return Truth::kUnknown;
      return p.value ? Truth::kTrue : Truth::kFalse;
    }
    case CompiledCondition::Op::kNot: {
      const Truth t = EvaluateFormula(f.children[0], r, now);
      return t == Truth::kUnknown ? t : t == Truth::kTrue ? Truth::kFalse : Truth::kTrue;
    }
    case CompiledCondition::Op::kAnd: {
      Truth out = Truth::kTrue;
      for (const Formula& c : f.children) {
        const Truth t = EvaluateFormula(c, r, now);
        if (t == Truth::kFalse) return Truth::kFalse;
        if (t == Truth::kUnknown) out = Truth::kUnknown;
      }
      return out;
    }
    case CompiledCondition::Op::kOr: {
      Truth out = Truth::kFalse;
      for (const Formula& c : f.children) {
        const Truth t = EvaluateFormula(c, r, now);
        if (t == Truth::kTrue) return Truth::kTrue;
        if (t == Truth::kUnknown) out = Truth::kUnknown;
      }
      return out;
    }
  }
  return Truth::kUnknown;
}

void SurveillanceManager::OnDatum(SensorKind sensor, double now) {
  stamp_[static_cast<int>(sensor)] = now;
  std::vector<Record*> fired;
  for (Record& r : records_) {
    if (!r.active) continue;
    bool touched = false;
    bool rose = false;
    for (Part& part : r.parts) {
      if (part.sensor != sensor) continue;
      touched = true;
      const bool value = EvaluatePart(&part, now, false);
      if (value && !(part.evaluated && part.value)) rose = true;
      part.value = value;
      part.evaluated = true;
      part.stamp = now;
      if (rose && log_->enabled()) {
        log_->Add(now, Message::Kind::kConditionTrue, SsmName(sensor), "SM", r.id,
                  part.condition.text);
      }
      rose = false;
    }
    if (!touched) continue;
    const Truth t = EvaluateFormula(r.formula, r, now);
    if (r.must_see_false) {
      if (t == Truth::kFalse) r.must_see_false = false;
      continue;
    }
    if (t == Truth::kTrue) fired.push_back(&r);
  }
  if (!fired.empty()) Fire(std::move(fired), now);
}

void SurveillanceManager::Fire(std::vector<Record*> fired, double now) {
  auto key = [](const Record* r) {
    return std::make_tuple(r->request.o_surveillance ? 0 : 1, r->request.terminal ? 0 : 1,
                           r->request.is_static ? 0 : 1, r->request.rank, r->id);
  };
  std::sort(fired.begin(), fired.end(),
            [&](const Record* a, const Record* b) { return key(a) < key(b); });
  std::vector<Firing> firings;
  for (Record* r : fired) {
    r->active = false;  // fired: no longer evaluated; the executive destroys it
    Firing f;
    f.id = r->id;
    f.label = r->request.label;
    f.o_surveillance = r->request.o_surveillance;
    f.terminal = r->request.terminal;
    f.is_static = r->request.is_static;
    firings.push_back(f);
  }
  // Reflexes first, at once, in priority order (6-1), each followed by its message to the
  // executive (6-2). Records may move when the listener registers monitors: copy what is used.
  for (const Firing& f : firings) {
    Record* r = Find(f.id);
    const std::vector<OperatorCommand> reflex =
        r ? r->request.reflex : std::vector<OperatorCommand>();
    for (const OperatorCommand& command : reflex) {
      const OperatorHandle handle = next_handle_();
      log_->Add(now, Message::Kind::kReflex, "SM", ModuleName(command), f.id, Describe(command));
      const OperatorReply reply = modules_->Send(handle, command, now);
      if (reply.status == OperatorStatus::kFailed || reply.status == OperatorStatus::kRunning) {
        log_->Add(now, Message::Kind::kNote, ModuleName(command), "SM", f.id,
                  std::string("reflex ") + StatusName(reply.status) +
                      (reply.message.empty() ? "" : ": " + reply.message));
      }
    }
    log_->Add(now, Message::Kind::kFired, "SM", "EM", f.id, f.label);
    if (listener_ != nullptr) listener_->OnMonitorFired(f, now);
  }
}

void SurveillanceManager::OnSonar(const SonarScan& scan, double now) {
  sonar_ = scan;
  lines_valid_ = false;
  OnDatum(SensorKind::kSonar, now);
}

void SurveillanceManager::OnPose(const PoseDatum& pose, double now) {
  pose_ = pose;
  OnDatum(SensorKind::kPose, now);
}

void SurveillanceManager::OnLaser(const LaserScan& scan, double now) {
  laser_ = scan;
  OnDatum(SensorKind::kLaser, now);
}

void SurveillanceManager::OnBattery(const BatteryDatum& battery, double now) {
  battery_ = battery;
  OnDatum(SensorKind::kBattery, now);
}

std::optional<bool> SurveillanceManager::EvaluateOnLatest(const CompiledCondition& condition,
                                                          double now) {
  for (SensorKind s : SensorsOf(condition)) {
    const bool have = (s == SensorKind::kSonar && sonar_) || (s == SensorKind::kPose && pose_) ||
                      (s == SensorKind::kLaser && laser_) ||
                      (s == SensorKind::kBattery && battery_);
    if (!have || now - stamp_[static_cast<int>(s)] > parameters_.part_validity_s) {
      return std::nullopt;
    }
  }
  int crossing = 0;
  return EvaluateAtom(condition, nullptr, &crossing, true);
}

}  // namespace rpl_executive::noreils_chatila
