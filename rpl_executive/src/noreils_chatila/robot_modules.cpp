#include "rpl_executive/noreils_chatila/robot_modules.h"

#include <cstdio>

namespace rpl_executive::noreils_chatila {

namespace {

struct NameVisitor {
  std::string operator()(const SmoothMoveCommand&) const { return "smooth-move"; }
  std::string operator()(const WallFollowingCommand&) const { return "wall-following"; }
  std::string operator()(const ObstacleAvoidanceCommand&) const { return "obstacle-avoidance"; }
  std::string operator()(const AvoidObstacleCommand&) const { return "avoid-obstacle"; }
  std::string operator()(const SetSpeedCommand&) const { return "set-speed"; }
  std::string operator()(const StopCommand&) const { return "stop"; }
  std::string operator()(const ReadAllUsDataCommand&) const { return "read-all-us-data"; }
  std::string operator()(const ReadPosCommand&) const { return "read-pos"; }
  std::string operator()(const DrawCommand&) const { return "draw"; }
};

struct ModuleVisitor {
  std::string operator()(const SmoothMoveCommand&) const { return "PILOT"; }
  std::string operator()(const WallFollowingCommand&) const { return "WALL-FOLLOWING"; }
  std::string operator()(const ObstacleAvoidanceCommand&) const { return "OBSTACLE-AVOIDANCE"; }
  std::string operator()(const AvoidObstacleCommand&) const { return "OBSTACLE-AVOIDANCE"; }
  std::string operator()(const SetSpeedCommand&) const { return "PILOT"; }
  std::string operator()(const StopCommand&) const { return "PILOT"; }
  std::string operator()(const ReadAllUsDataCommand&) const { return "US"; }
  std::string operator()(const ReadPosCommand&) const { return "ODOMETER"; }
  std::string operator()(const DrawCommand&) const { return "GRAPHICS"; }
};

std::string Format(const char* format, double a) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, format, a);
  return buffer;
}

struct DescribeVisitor {
  std::string operator()(const SmoothMoveCommand& c) const {
    std::string out = std::string(c.resume ? "smooth-move (resumed) " : "smooth-move ") +
                      std::to_string(c.path_m.size()) + " point(s)";
    if (!c.path_m.empty()) {
      out += Format(" to (%.2f", c.path_m.back().x) + Format(", %.2f) m", c.path_m.back().y);
    }
    if (c.final_yaw_rad) out += Format(", heading %.3f rad", *c.final_yaw_rad);
    return out;
  }
  std::string operator()(const WallFollowingCommand& c) const {
    return std::string("wall-following ") + (c.side == WallSide::kRight ? "right" : "left") +
           Format(" side at %.2f m", c.distance_m);
  }
  std::string operator()(const ObstacleAvoidanceCommand&) const { return "obstacle-avoidance"; }
  std::string operator()(const AvoidObstacleCommand&) const { return "avoid-obstacle"; }
  std::string operator()(const SetSpeedCommand& c) const {
    return Format("set-speed %.2f m/s", c.speed_mps);
  }
  std::string operator()(const StopCommand&) const { return "stop"; }
  std::string operator()(const ReadAllUsDataCommand&) const { return "read-all-us-data"; }
  std::string operator()(const ReadPosCommand&) const { return "read-pos"; }
  std::string operator()(const DrawCommand& c) const {
    std::string out = "draw";
    for (size_t i = 0; i < c.formats.size(); ++i) out += " %" + c.formats[i];
    return out;
  }
};

}  // namespace

std::string OperatorName(const OperatorCommand& command) {
  return std::visit(NameVisitor{}, command);
}

std::string ModuleName(const OperatorCommand& command) {
  return std::visit(ModuleVisitor{}, command);
}

std::string Describe(const OperatorCommand& command) {
  return std::visit(DescribeVisitor{}, command);
}

const char* StatusName(OperatorStatus status) {
  switch (status) {
    case OperatorStatus::kRunning:
      return "running";
    case OperatorStatus::kCompleted:
      return "completed";
    case OperatorStatus::kInterrupted:
      return "interrupted";
    case OperatorStatus::kFailed:
      return "failed";
  }
  return "?";
}

}  // namespace rpl_executive::noreils_chatila
