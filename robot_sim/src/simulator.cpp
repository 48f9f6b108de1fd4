#include "robot_sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spott_map/geometry.h"

namespace robot_sim {

namespace {

using spott_map::NormalizeAngle;

// Bisection steps when a move collides: the contact is found to 1/2^10 of a step.
constexpr int kContactBisections = 10;

}  // namespace

Simulator::Simulator(std::unique_ptr<SimWorld> world) : world_(std::move(world)) {}

std::optional<int> Simulator::AddRobot(const RobotSpec& spec, const spott_map::Pose2& start,
                                       const OdometryErrorModel& odometry, std::string* error) {
  const std::string solid =
      world_->SolidAt(start.x, start.y, spec.radius_m, spec.height_m, nullptr);
  if (!solid.empty()) {
    if (error)
      *error = "start pose (" + std::to_string(start.x) + ", " + std::to_string(start.y) +
               ") is inside '" + solid + "'";
    return std::nullopt;
  }
  Robot r;
  r.spec = spec;
  r.pose = start;
  r.odometry = Odometry(odometry);
  r.body = world_->AddRobotBody(spec.name + "_" + std::to_string(robots_.size()), spec.radius_m,
                                spec.height_m);
  world_->MoveRobotBody(r.body, start.x, start.y, start.yaw);
  r.odometry.Reset({0.0, 0.0, 0.0});
  if (spec.bumper) r.bumper.assign(spec.bumper->segments, false);
  r.heads.assign(spec.profilers.size(), {0.0, 0.0});
  robots_.push_back(std::move(r));
  return static_cast<int>(robots_.size()) - 1;
}

bool Simulator::SetCommand(int robot, const Twist2& cmd, std::string* error) {
  Robot& r = robots_.at(robot);
  if (!CommandIsSane(cmd, r.spec.drive)) {
    r.command = {};
    if (error) {
      *error = "refused velocity command (v=" + std::to_string(cmd.v) +
               " m/s, w=" + std::to_string(cmd.w) +
               " rad/s): not finite or over 10x the limits of " + r.spec.name + "; stopping";
    }
    return false;
  }
  r.command = cmd;
  return true;
}

bool Simulator::Collides(const Robot& r, double x, double y) const {
  return world_->CylinderCollides(x, y, r.spec.radius_m, r.spec.height_m, r.body);
}

bool Simulator::Overlapped(int robot, double margin_m) const {
  const Robot& r = robots_.at(robot);
  return world_->CylinderCollides(r.pose.x, r.pose.y, r.spec.radius_m + margin_m, r.spec.height_m,
                                  r.body);
}

void Simulator::Step(double dt, Rng& rng) {
  for (Robot& r : robots_) {
    const double turret_step = r.spec.drive.max_turret_rps * dt;
    r.turret_yaw =
        NormalizeAngle(r.turret_yaw + std::clamp(NormalizeAngle(r.turret_target - r.turret_yaw),
                                                 -turret_step, turret_step));
    r.twist = LimitVelocity(r.twist, r.command, r.spec.drive, dt);
    spott_map::Pose2 next = Integrate(r.pose, r.twist, dt);
    r.stalled = false;
    if ((next.x != r.pose.x || next.y != r.pose.y) && Collides(r, next.x, next.y)) {
      // Cut the step at the contact: the largest collision-free fraction of it.
      double lo = 0.0, hi = 1.0;
      for (int i = 0; i < kContactBisections; ++i) {
        const double mid = (lo + hi) / 2;
        const spott_map::Pose2 p = Integrate(r.pose, r.twist, dt * mid);
        (Collides(r, p.x, p.y) ? hi : lo) = mid;
      }
      next = Integrate(r.pose, r.twist, dt * lo);
      next.yaw = NormalizeAngle(r.pose.yaw + r.twist.w * dt);  // a cylinder turns freely
      r.twist.v = 0.0;  // pushing against the obstacle: the motors stall
      r.stalled = true;
    }
    // What the wheels turned: the distance along the heading and the rotation.
    const double dx = next.x - r.pose.x, dy = next.y - r.pose.y;
    const double mid_yaw = r.pose.yaw + NormalizeAngle(next.yaw - r.pose.yaw) / 2;
    const double distance = dx * std::cos(mid_yaw) + dy * std::sin(mid_yaw);
    const double rotation = NormalizeAngle(next.yaw - r.pose.yaw);
    const bool slipping = time_ < r.slip_until;
    r.odometry.Update(distance, rotation, rng, slipping ? r.slip_linear : 1.0,
                      slipping ? r.slip_angular : 1.0);
    r.odometry.set_twist({distance / dt, rotation / dt});
    r.pose = next;
    world_->MoveRobotBody(r.body, r.pose.x, r.pose.y, r.pose.yaw);
  }
  // Bumpers after every robot has moved (robots press each other's bumpers too).
  for (Robot& r : robots_) {
    if (!r.spec.bumper) continue;
    std::vector<double> angles = world_->ContactAngles(
        r.pose.x, r.pose.y, r.spec.radius_m, r.spec.height_m, r.spec.bumper->travel_m, r.body);
    for (double& a : angles) a = NormalizeAngle(a - r.pose.yaw);
    r.bumper = BumperSegments(*r.spec.bumper, angles);
  }
  time_ += dt;
}

const SensorFault* Simulator::ActiveFault(Robot& r, const std::string& key) {
  auto it = r.faults.find(key);
  if (it == r.faults.end()) return nullptr;
  if (time_ >= it->second.until) {
    r.faults.erase(it);
    return nullptr;
  }
  return &it->second;
}

void Simulator::ApplyFaults(Robot& r, const std::string& name, double min_range, double max_range,
                            std::vector<double>& values, Rng& rng) {
  std::vector<double>& last = r.last[name];
  if (last.size() != values.size()) last = values;
  std::normal_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const SensorFault* f = ActiveFault(r, name + "/" + std::to_string(i + 1));
    if (!f) f = ActiveFault(r, name);
    if (!f) continue;
    switch (f->kind) {
      case FaultKind::kDropout:
        values[i] = std::numeric_limits<double>::quiet_NaN();
        break;
      case FaultKind::kStuck:
        values[i] = last[i];
        break;
      case FaultKind::kNoise:
        if (std::isfinite(values[i]))
          values[i] = std::clamp(values[i] + unit(rng) * f->noise_stddev, min_range, max_range);
        break;
    }
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isnan(values[i])) last[i] = values[i];
  }
}

std::vector<double> Simulator::SenseRing(int robot, const RangeRingSpec& ring, Rng& rng) {
  Robot& r = robots_.at(robot);
  std::vector<TransducerPose> poses;
  poses.reserve(ring.mounts.size());
  for (const Mount& m : ring.mounts) poses.push_back(PlaceMount(m, r.pose, r.turret_yaw));
  std::vector<double> ranges = SenseRangeRing(*world_, ring, poses, r.body, rng);
  ApplyFaults(r, ring.name, ring.min_range, ring.max_range, ranges, rng);
  return ranges;
}

std::vector<double> Simulator::SenseLaser(int robot, Rng& rng) {
  Robot& r = robots_.at(robot);
  if (!r.spec.laser) return {};
  const LaserSpec& laser = *r.spec.laser;
  std::vector<double> ranges =
      robot_sim::SenseLaser(*world_, laser, PlaceMount(laser.mount, r.pose, 0.0), r.body, rng);
  ApplyFaults(r, laser.name, laser.min_range, laser.max_range, ranges, rng);
  return ranges;
}

std::vector<double> Simulator::SenseProfile(int robot, int index, bool horizontal, Rng& rng,
                                            std::vector<double>* angles) {
  Robot& r = robots_.at(robot);
  const ProfilerSpec& p = r.spec.profilers.at(index);
  // The heads ride on the turret; pan turns the head about its own vertical axis.
  TransducerPose head = PlaceMount(p.mount, r.pose, r.turret_yaw);
  head.yaw = NormalizeAngle(head.yaw + r.heads[index].first);
  std::vector<double> ranges = robot_sim::SenseProfile(*world_, p, head, r.heads[index].second,
                                                       horizontal, r.body, rng, angles);
  ApplyFaults(r, p.name, p.min_range, p.max_range, ranges, rng);
  return ranges;
}

bool Simulator::PointHead(int robot, int index, double pan, double tilt) {
  Robot& r = robots_.at(robot);
  if (index < 0 || index >= static_cast<int>(r.heads.size()) || !std::isfinite(pan) ||
      !std::isfinite(tilt) || std::abs(tilt) > M_PI / 2) {
    return false;
  }
  r.heads[index] = {NormalizeAngle(pan), tilt};
  return true;
}

std::vector<bool> Simulator::Bumper(int robot) {
  Robot& r = robots_.at(robot);
  std::vector<bool> pressed = r.bumper;
  for (std::size_t i = 0; i < pressed.size(); ++i) {
    const SensorFault* f = ActiveFault(r, "bumper/" + std::to_string(i + 1));
    if (!f) f = ActiveFault(r, "bumper");
    if (f && f->kind == FaultKind::kDropout) pressed[i] = false;
  }
  return pressed;
}

std::vector<double> Simulator::BodyContacts(int robot) const {
  const Robot& r = robots_.at(robot);
  std::vector<double> angles = world_->ContactAngles(r.pose.x, r.pose.y, r.spec.radius_m,
                                                     r.spec.height_m, kBodyTouchM, r.body);
  for (double& a : angles) a = NormalizeAngle(a - r.pose.yaw);
  return angles;
}

bool Simulator::Kidnap(int robot, const spott_map::Pose2& target, bool relative,
                       std::string* error) {
  Robot& r = robots_.at(robot);
  if (!std::isfinite(target.x) || !std::isfinite(target.y) || !std::isfinite(target.yaw)) {
    if (error) *error = "kidnap target is not finite";
    return false;
  }
  spott_map::Pose2 p = target;
  if (relative) {
    const double c = std::cos(r.pose.yaw), s = std::sin(r.pose.yaw);
    p = {r.pose.x + c * target.x - s * target.y, r.pose.y + s * target.x + c * target.y,
         NormalizeAngle(r.pose.yaw + target.yaw)};
  }
  p.yaw = NormalizeAngle(p.yaw);
  auto where = [&] { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; };
  if (!world_->InsideMap(p.x, p.y)) {
    if (error) *error = "kidnap target " + where() + " is outside every room of the map";
    return false;
  }
  const std::string solid = world_->SolidAt(p.x, p.y, r.spec.radius_m, r.spec.height_m, r.body);
  if (!solid.empty()) {
    if (error) *error = "kidnap target " + where() + " is inside '" + solid + "'";
    return false;
  }
  r.pose = p;
  r.twist = {};
  world_->MoveRobotBody(r.body, p.x, p.y, p.yaw);
  return true;
}

bool Simulator::KnownSensor(const Robot& r, const std::string& sensor) const {
  const auto slash = sensor.find('/');
  const std::string name = sensor.substr(0, slash);
  std::size_t count = 0;
  if (const RangeRingSpec* ring = r.spec.FindRing(name)) {
    count = ring->mounts.size();
  } else if (r.spec.laser && name == r.spec.laser->name) {
    count = static_cast<std::size_t>(r.spec.laser->beams);
  } else if (r.spec.bumper && name == "bumper") {
    count = static_cast<std::size_t>(r.spec.bumper->segments);
  } else if (auto it = std::find_if(r.spec.profilers.begin(), r.spec.profilers.end(),
                                    [&](const ProfilerSpec& p) { return p.name == name; });
             it != r.spec.profilers.end()) {
    count = static_cast<std::size_t>(it->samples);
  } else {
    return false;
  }
  if (slash == std::string::npos) return true;
  const std::string index = sensor.substr(slash + 1);
  if (index.empty() || index.size() > 6 ||
      index.find_first_not_of("0123456789") != std::string::npos) {
    return false;
  }
  const std::size_t i = std::stoul(index);
  return i >= 1 && i <= count;
}

bool Simulator::InjectFault(int robot, const std::string& sensor, const SensorFault& fault,
                            std::string* error) {
  Robot& r = robots_.at(robot);
  if (!KnownSensor(r, sensor)) {
    if (error) *error = "no sensor '" + sensor + "' on " + r.spec.name;
    return false;
  }
  if (fault.kind == FaultKind::kNoise && !(fault.noise_stddev > 0 && fault.noise_stddev < 100)) {
    if (error) *error = "noise fault needs noise_stddev in (0, 100) m";
    return false;
  }
  if (std::isnan(fault.until) || fault.until <= time_) {
    if (error) *error = "fault would end before it starts (duration must be positive)";
    return false;
  }
  r.faults[sensor] = fault;
  return true;
}

bool Simulator::ClearFault(int robot, const std::string& sensor, std::string* error) {
  Robot& r = robots_.at(robot);
  if (!KnownSensor(r, sensor)) {
    if (error) *error = "no sensor '" + sensor + "' on " + r.spec.name;
    return false;
  }
  for (auto it = r.faults.begin(); it != r.faults.end();) {
    const bool match = it->first == sensor || it->first.rfind(sensor + "/", 0) == 0;
    it = match ? r.faults.erase(it) : std::next(it);
  }
  return true;
}

bool Simulator::Slip(int robot, double linear_scale, double angular_scale, double duration,
                     std::string* error) {
  Robot& r = robots_.at(robot);
  if (!(linear_scale >= 0 && linear_scale <= 2) || !(angular_scale >= 0 && angular_scale <= 2) ||
      !(duration > 0 && duration < 1e6)) {
    if (error) *error = "slip needs scales in [0, 2] and a duration in (0, 1e6) s";
    return false;
  }
  r.slip_linear = linear_scale;
  r.slip_angular = angular_scale;
  r.slip_until = time_ + duration;
  return true;
}

bool Simulator::ReplaceWorld(const spott_map::World& world, std::string* error) {
  // Check on a scratch copy first, so that a refusal leaves the old building untouched.
  SimWorld scratch(world_->params());
  scratch.Build(world);
  for (const Robot& r : robots_) {
    const std::string solid =
        scratch.SolidAt(r.pose.x, r.pose.y, r.spec.radius_m, r.spec.height_m, nullptr);
    if (!solid.empty() || !scratch.InsideMap(r.pose.x, r.pose.y)) {
      if (error) {
        *error = "robot " + r.spec.name + " at (" + std::to_string(r.pose.x) + ", " +
                 std::to_string(r.pose.y) + ") would be " +
                 (solid.empty() ? "outside every room" : "inside '" + solid + "'") + " of world '" +
                 world.name + "'";
      }
      return false;
    }
  }
  world_->Build(world);
  return true;
}

void Simulator::SetTurretYaw(int robot, double yaw) {
  if (std::isfinite(yaw)) robots_.at(robot).turret_target = NormalizeAngle(yaw);
}

}  // namespace robot_sim
