// The TR+ controller on the robot without ROS (issue 16's figures), the shipped navigation
// program (programs/spott_navigation.tr) on cim_office's CAD map:
//  - BM_ControllerCycle: one cycle while `go in room(lab)` drives the robot along the west
//    hallway: the pose, odometry and localization, a 16-sonar ring cast on the CAD map (the
//    sensor mapper's input), Advance at the interpreter's wake times, Tick. What the node
//    spends per sensor message on the running program; the paper's SPOTT ran its TR+ cycle
//    in about 25 us per condition (SPOTT III-E), i.e. a few ms per cycle of this program.
//  - BM_BumperToReflexCommand: from Bumper(pressed) to the reflex's first velocity command
//    (the controller's share of the sensor-to-/cmd_vel latency; the node adds one ROS hop and
//    the arbiter's take_wheels call).
// Counters: per_cycle_us / median_us / p99_us; sonar_features: features the mapper added.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "spott_map/map_database.h"
#include "spott_map/world_loader.h"
#include "spott_tr_plus/controller/navigation_controller.h"
#include "spott_tr_plus/parser.h"

namespace spott_tr_plus::controller {
namespace {

constexpr double kNomadRadius = 0.2285;  // m (Nomad 200 URDF)
constexpr double kSonarMaxRange = 6.5;   // m (Polaroid 6500 ranging module)

// The velocity commands by source; nothing else is needed to drive the fake robot.
struct BenchIo : ControllerIo {
  std::vector<NavigateGoal> navigates;
  Velocity last_reflex;
  int reflex_commands = 0;
  void SendNavigate(const NavigateGoal& g) override { navigates.push_back(g); }
  void CancelNavigate() override {}
  void TakeWheels(const std::string&) override {}
  void ReleaseWheels(const std::string&) override {}
  void Drive(const std::string& source, const Velocity& v) override {
    if (source == "reflex") {
      last_reflex = v;
      ++reflex_commands;
    }
  }
  void SendMapUpdate(const MapChange&) override {}
  void SetPtuPattern(const std::string&) override {}
  void PointTurret(double) override {}
  void PublishTaskFeedback(const TaskFeedback&) override {}
  bool StartActiveLocalize(double) override { return false; }
  void CancelActiveLocalize() override {}
  void TaskFinished(const TaskResult&) override {}
};

// The nearest wall face along a ray (walls as centre lines, faces half a thickness off).
double CastOnWalls(const spott_map::World& world, const spott_map::Vec2& from, double angle) {
  const spott_map::Vec2 d(std::cos(angle), std::sin(angle));
  double best = kSonarMaxRange;
  for (const spott_map::Wall& w : world.walls) {
    const spott_map::Vec2 e = w.segment.b - w.segment.a;
    const double denom = d.x() * e.y() - d.y() * e.x();
    if (std::abs(denom) < 1e-12) continue;
    const spott_map::Vec2 f = w.segment.a - from;
    const double t = (f.x() * e.y() - f.y() * e.x()) / denom;  // along the ray
    const double u = (f.x() * d.y() - f.y() * d.x()) / denom;  // along the wall
    if (t <= 0.0 || u < 0.0 || u > 1.0) continue;
    const double cos_incidence = std::abs(denom) / e.norm();
    best = std::min(best, t - 0.5 * w.thickness / std::max(cos_incidence, 0.1));
  }
  return std::max(best, 0.0);
}

class Rig {
 public:
  Rig() {
    auto loaded = spott_map::LoadWorldFile(WORLDS_DIR "/cim_office.yaml");
    if (!loaded.ok()) throw std::runtime_error(spott_map::FormatErrors(loaded.errors));
    world_ = *loaded.world;
    const ParseResult parsed = ParseProgramFile(PROGRAMS_DIR "/spott_navigation.tr");
    if (!parsed.ok()) throw std::runtime_error(FormatDiagnostics(parsed.diagnostics));
    ControllerParameters params;
    params.robot_radius_m = kNomadRadius;
    std::vector<Diagnostic> d;
    controller_ = NavigationController::Create(parsed.program, params, &io_, &d);
    if (!controller_) throw std::runtime_error(FormatDiagnostics(d));
    const spott_map::MapDatabase db = spott_map::MapDatabase::FromWorld(world_);
    controller_->Start(0.0);
    controller_->SetGraph(db.graph(), 0.0);
    controller_->SetFeatures(db.features(), 0.0);
    controller_->SetPlaces(world_.places);
    for (int i = 0; i < 16; ++i) {  // the Nomad's ring: 16 transducers, 22.5 degrees apart
      const double a = i * 2.0 * M_PI / 16.0;
      ring_.mounts.push_back(Pose2{kNomadRadius * std::cos(a), kNomadRadius * std::sin(a), a});
    }
    ring_.min_range_m = 0.15;
    ring_.max_range_m = kSonarMaxRange;
    ring_.field_of_view_rad = 25.0 * M_PI / 180.0;
    ring_.ranges.assign(16, kSonarMaxRange);
    At(1.2, 8.25, 0.0, 0.0);
  }

  void At(double x, double y, double yaw, double v) {
    pose_ = Pose2{x, y, yaw};
    controller_->SetPose(pose_, now_);
    controller_->SetOdometry(pose_, v, 0.0, now_);
    controller_->SetLocalization(true, now_);
  }

  // One 10 Hz cycle: the robot 4 cm further east along the hallway (back to the west end at
  // x = 9 m, before the lab's door), its sonar ring, the interpreter's wakes and a tick.
  void Cycle() {
    now_ += 0.1;
    double x = pose_.x + 0.04;
    if (x > 9.0) x = 1.2;
    At(x, 8.25, 0.0, 0.4);
    for (std::size_t i = 0; i < ring_.mounts.size(); ++i) {
      const Pose2& m = ring_.mounts[i];
      const spott_map::Vec2 at(pose_.x + m.x, pose_.y + m.y);
      ring_.ranges[i] = std::max(CastOnWalls(world_, at, pose_.yaw + m.yaw), ring_.min_range_m);
    }
    controller_->Sonar(ring_, now_);
    while (controller_->NextWakeTime() <= now_) controller_->Advance(now_);
    controller_->Tick(now_);
  }

  NavigationController& controller() { return *controller_; }
  BenchIo& io() { return io_; }
  double& now() { return now_; }
  const Pose2& pose() const { return pose_; }

 private:
  spott_map::World world_;
  BenchIo io_;
  std::unique_ptr<NavigationController> controller_;
  RangeRing ring_;
  Pose2 pose_;
  double now_ = 0.0;
};

double Percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * v.size()))];
}

void BM_ControllerCycle(benchmark::State& state) {
  Rig rig;
  if (!rig.controller().StartTask(1, "go in room(lab)", rig.now()).accepted) {
    state.SkipWithError("the task was refused");
    return;
  }
  for (int i = 0; i < 20; ++i) rig.Cycle();  // stopped, interpreted, Navigate sent
  if (rig.io().navigates.empty()) {
    state.SkipWithError("no Navigate goal: the task did not start");
    return;
  }
  std::vector<double> samples;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    rig.Cycle();
    samples.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
  }
  state.counters["median_us"] = Percentile(samples, 0.5);
  state.counters["p99_us"] = Percentile(samples, 0.99);
  state.counters["sonar_features"] = static_cast<double>(rig.controller().added_features().size());
  state.counters["task_running"] = rig.controller().has_task() ? 1 : 0;
}

void BM_BumperToReflexCommand(benchmark::State& state) {
  Rig rig;
  rig.At(5.0, 8.25, 0.0, 0.0);
  std::vector<double> samples;
  for (auto _ : state) {
    const int before = rig.io().reflex_commands;
    const auto t0 = std::chrono::steady_clock::now();
    rig.controller().Bumper({0.0}, rig.now());  // the front segment pressed
    const auto t1 = std::chrono::steady_clock::now();
    state.PauseTiming();
    if (rig.io().reflex_commands == before || rig.io().last_reflex.linear_mps >= 0.0) {
      state.SkipWithError("the reflex did not back away on the bumper");
      return;
    }
    samples.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    // Let the reflex finish (the robot backs 0.3 m away from the contact), then come back.
    rig.controller().Bumper({}, rig.now());
    Pose2 p = rig.pose();
    for (int i = 0; i < 200 && rig.controller().State().frames.size() > 0; ++i) {
      rig.now() += 0.05;
      const Velocity v = rig.io().last_reflex;
      p.x += v.linear_mps * std::cos(p.yaw) * 0.05;
      p.yaw += v.angular_rps * 0.05;
      rig.At(p.x, p.y, p.yaw, v.linear_mps);
      while (rig.controller().NextWakeTime() <= rig.now()) rig.controller().Advance(rig.now());
      rig.controller().Tick(rig.now());
      if (i > 10 && v.linear_mps == 0.0 && v.angular_rps == 0.0) break;
    }
    rig.now() += 1.0;
    rig.At(5.0, 8.25, 0.0, 0.0);
    rig.controller().Tick(rig.now());
    state.ResumeTiming();
  }
  state.counters["median_us"] = Percentile(samples, 0.5);
  state.counters["p99_us"] = Percentile(samples, 0.99);
}

BENCHMARK(BM_ControllerCycle)->Iterations(3000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BumperToReflexCommand)->Iterations(300)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace spott_tr_plus::controller

BENCHMARK_MAIN();
