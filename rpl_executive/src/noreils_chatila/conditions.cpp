#include "rpl_executive/noreils_chatila/conditions.h"

#include <algorithm>

namespace rpl_executive::noreils_chatila {

const char* SsmName(SensorKind sensor) {
  switch (sensor) {
    case SensorKind::kSonar:
      return "US-SSM";
    case SensorKind::kPose:
      return "POSE-SSM";
    case SensorKind::kLaser:
      return "LASER-SSM";
    case SensorKind::kBattery:
      return "BATTERY-SSM";
  }
  return "SSM";
}

SensorKind SensorOf(const AtomicCondition& atom) {
  struct Visitor {
    SensorKind operator()(const ZoneCondition&) const { return SensorKind::kPose; }
    SensorKind operator()(const UsThresholdCondition&) const { return SensorKind::kSonar; }
    SensorKind operator()(const UsPerceptionCondition&) const { return SensorKind::kSonar; }
    SensorKind operator()(const StraightLineCondition&) const { return SensorKind::kPose; }
    SensorKind operator()(const BatteryCondition&) const { return SensorKind::kBattery; }
    SensorKind operator()(const LaserThresholdCondition&) const { return SensorKind::kLaser; }
  };
  return std::visit(Visitor{}, atom);
}

namespace {

void Collect(const CompiledCondition& c, bool* seen) {
  if (c.op == CompiledCondition::Op::kAtom) {
    seen[static_cast<int>(SensorOf(c.atom))] = true;
    return;
  }
  for (const CompiledCondition& child : c.children) Collect(child, seen);
}

}  // namespace

std::vector<SensorKind> SensorsOf(const CompiledCondition& condition) {
  bool seen[kSensorKinds] = {false, false, false, false};
  Collect(condition, seen);
  std::vector<SensorKind> out;
  for (int i = 0; i < kSensorKinds; ++i) {
    if (seen[i]) out.push_back(static_cast<SensorKind>(i));
  }
  return out;
}

}  // namespace rpl_executive::noreils_chatila
