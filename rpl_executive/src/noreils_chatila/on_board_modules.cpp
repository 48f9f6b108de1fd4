#include "rpl_executive/noreils_chatila/on_board_modules.h"

#include <cmath>
#include <stdexcept>

#include "rpl_executive/noreils_chatila/vocabulary.h"

namespace rpl_executive::noreils_chatila {

std::vector<std::string> ValidateParameters(const OnBoardParameters& p) {
  std::vector<std::string> v;
  for (const std::string& s : ValidateParameters(p.pilot)) v.push_back("pilot." + s);
  for (const std::string& s : ValidateParameters(p.wall_following)) {
    v.push_back("wall_following." + s);
  }
  for (const std::string& s : ValidateParameters(p.obstacle_avoidance)) {
    v.push_back("obstacle_avoidance." + s);
  }
  for (const std::string& s : ValidateParameters(p.sonar)) v.push_back("sonar." + s);
  return v;
}

namespace {

double Round(double x, double unit) { return std::round(x / unit * 10.0) / 10.0; }

}  // namespace

Value SonarToValue(const SonarScan& scan, const SonarRing& ring) {
  std::vector<Value> echoes;
  for (size_t i = 0; i < scan.ranges_m.size(); ++i) {
    if (!ring.IsEcho(scan.ranges_m[i])) continue;
    echoes.push_back(
        Value::List({Value::Number(static_cast<double>(i + 1)),
                     Value::Number(Round(scan.ranges_m[i], kMetresPerMissionLength))}));
  }
  return Value::List(std::move(echoes));
}

Value PoseToValue(const Pose2& pose) {
  double tenths = Round(WrapAngle(pose.yaw), kRadiansPerMissionAngle);
  if (tenths < 0) tenths += 3600.0;
  return Value::List({Value::Number(Round(pose.x, kMetresPerMissionLength)),
                      Value::Number(Round(pose.y, kMetresPerMissionLength)),
                      Value::Number(tenths)});
}

OnBoardModules::OnBoardModules(const OnBoardParameters& parameters, const SonarRing& ring)
    : parameters_(parameters),
      ring_(ring),
      pilot_(parameters.pilot),
      wall_following_(parameters.wall_following, ring, parameters.sonar),
      avoidance_(parameters.obstacle_avoidance, ring),
      avoid_obstacle_(parameters.obstacle_avoidance, ring) {
  const std::vector<std::string> errors = ValidateParameters(parameters);
  if (!errors.empty()) {
    std::string all;
    for (const std::string& e : errors) all += e + "; ";
    throw std::invalid_argument("OnBoardModules: " + all);
  }
}

void OnBoardModules::Report(OperatorHandle handle, OperatorStatus status,
                            const std::string& message) {
  OperatorReply reply;
  reply.status = status;
  reply.message = message;
  reports_.emplace_back(handle, reply);
}

// The wheels' holder stops; its operator ends with `status`.
void OnBoardModules::Release(OperatorStatus status, const std::string& message) {
  if (holder_ == Holder::kNone) return;
  pilot_.Stop();
  wall_following_.Halt();
  avoidance_.Halt();
  if (status != OperatorStatus::kRunning) Report(handle_, status, message);
  holder_ = Holder::kNone;
  handle_ = 0;
  process_output_ = ProcessOutput();
}

OperatorReply OnBoardModules::Send(OperatorHandle handle, const OperatorCommand& command,
                                   double /*now*/) {
  OperatorReply reply;
  if (const auto* move = std::get_if<SmoothMoveCommand>(&command)) {
    if (!pose_) {
      reply.status = OperatorStatus::kFailed;
      reply.message = "the pilot has no position yet";
      return reply;
    }
    Release(OperatorStatus::kInterrupted, "another movement took the wheels");
    if (!(move->resume && pilot_.Resume(pose_->pose))) {
      pilot_.Start(pose_->pose, move->path_m, move->final_yaw_rad);
    }
    holder_ = Holder::kPilot;
    handle_ = handle;
    reply.status = OperatorStatus::kRunning;
    return reply;
  }
  if (const auto* wall = std::get_if<WallFollowingCommand>(&command)) {
    Release(OperatorStatus::kInterrupted, "another movement took the wheels");
    wall_following_.Activate(wall->side, wall->distance_m);
    holder_ = Holder::kWallFollowing;
    handle_ = handle;
    reply.status = OperatorStatus::kRunning;
    return reply;
  }
  if (std::holds_alternative<AvoidObstacleCommand>(command) ||
      std::holds_alternative<ObstacleAvoidanceCommand>(command)) {
    Release(OperatorStatus::kInterrupted, "another movement took the wheels");
    elementary_task_ = std::holds_alternative<AvoidObstacleCommand>(command);
    if (elementary_task_) {
      avoid_obstacle_.Start(pilot_.RemainingVertices());
    } else {
      avoidance_.Activate();
    }
    holder_ = Holder::kAvoidance;
    handle_ = handle;
    reply.status = OperatorStatus::kRunning;
    return reply;
  }
  if (const auto* speed = std::get_if<SetSpeedCommand>(&command)) {
    pilot_.SetSpeed(speed->speed_mps);
    return reply;
  }
  if (std::holds_alternative<StopCommand>(command)) {
    Release(OperatorStatus::kInterrupted, "stopped");
    return reply;
  }
  if (std::holds_alternative<ReadAllUsDataCommand>(command)) {
    if (!sonar_ || !pose_) {
      reply.status = OperatorStatus::kFailed;
      reply.message = "no ultrasonic data yet";
      return reply;
    }
    reply.results.emplace_back("r-us-data", SonarToValue(*sonar_, ring_));
    reply.results.emplace_back("r-position", PoseToValue(pose_->pose));
    return reply;
  }
  if (std::holds_alternative<ReadPosCommand>(command)) {
    if (!pose_) {
      reply.status = OperatorStatus::kFailed;
      reply.message = "no position yet";
      return reply;
    }
    reply.results.emplace_back("r-position", PoseToValue(pose_->pose));
    return reply;
  }
  if (const auto* draw = std::get_if<DrawCommand>(&command)) {
    drawings_.push_back(*draw);
    return reply;
  }
  reply.status = OperatorStatus::kFailed;
  reply.message = "no module for " + OperatorName(command);
  return reply;
}

void OnBoardModules::OnMissionStart(double /*now*/) { pilot_.ResetSpeed(); }

void OnBoardModules::Halt(OperatorHandle handle, double /*now*/) {
  if (handle != handle_ || holder_ == Holder::kNone) return;
  Release(OperatorStatus::kRunning, "");  // halted by the executive: no report
}

void OnBoardModules::OnPose(const PoseDatum& pose) { pose_ = pose; }

void OnBoardModules::OnSonar(const SonarScan& scan) {
  sonar_ = scan;
  if (holder_ == Holder::kWallFollowing) {
    process_output_ = wall_following_.Update(scan, pilot_.speed_mps());
    if (process_output_.failed) {
      Release(OperatorStatus::kFailed, "wall-following: repeatedly insufficient data (no wall)");
    }
  } else if (holder_ == Holder::kAvoidance && elementary_task_) {
    if (!pose_) return;
    const AvoidObstacleTask::Step step =
        avoid_obstacle_.Update(pose_->pose, scan, pilot_.speed_mps());
    process_output_.command = step.command;
    if (step.status == AvoidObstacleTask::Status::kCompleted) {
      Release(OperatorStatus::kCompleted, step.message);
    } else if (step.status == AvoidObstacleTask::Status::kFailed) {
      Release(OperatorStatus::kFailed, "avoid-obstacle: " + step.message);
    }
  } else if (holder_ == Holder::kAvoidance) {
    process_output_ = avoidance_.Update(scan, pilot_.speed_mps());
    if (process_output_.failed) {
      Release(OperatorStatus::kFailed, "obstacle-avoidance: repeatedly insufficient data");
    }
  }
}

VelocityCommand OnBoardModules::Update(double /*now*/) {
  switch (holder_) {
    case Holder::kNone:
      return VelocityCommand{};
    case Holder::kPilot: {
      if (!pose_) return VelocityCommand{};
      const VelocityCommand cmd = pilot_.Update(pose_->pose);
      if (pilot_.state() == Pilot::State::kDone) {
        const OperatorHandle h = handle_;
        holder_ = Holder::kNone;
        handle_ = 0;
        Report(h, OperatorStatus::kCompleted, "");
        return VelocityCommand{};
      }
      return cmd;
    }
    case Holder::kWallFollowing:
    case Holder::kAvoidance:
      return process_output_.command;
  }
  return VelocityCommand{};
}

std::vector<std::pair<OperatorHandle, OperatorReply>> OnBoardModules::TakeReports() {
  std::vector<std::pair<OperatorHandle, OperatorReply>> out;
  std::swap(out, reports_);
  return out;
}

std::vector<DrawCommand> OnBoardModules::TakeDrawings() {
  std::vector<DrawCommand> out;
  std::swap(out, drawings_);
  return out;
}

std::string OnBoardModules::wheels_holder() const {
  switch (holder_) {
    case Holder::kNone:
      return "";
    case Holder::kPilot:
      return "smooth-move";
    case Holder::kWallFollowing:
      return "wall-following";
    case Holder::kAvoidance:
      return elementary_task_ ? "avoid-obstacle" : "obstacle-avoidance";
  }
  return "";
}

}  // namespace rpl_executive::noreils_chatila
