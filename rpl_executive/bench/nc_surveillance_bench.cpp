// The surveillance manager's cost per datum with 100 active monitors (issue 18), per sensor
// kind, against a peer that has no sensor surveillance managers: it evaluates every monitor's
// whole formula on the latest data whenever any datum arrives (the design the paper's per-sensor
// SSMs avoid, section 4.1.2). No monitor fires: this is the steady state of a mission.
//
//   ./spott bench rpl_executive_bench_nc_surveillance
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/mission_parser.h"
#include "rpl_executive/noreils_chatila/surveillance_manager.h"
#include "rpl_executive/noreils_chatila/vocabulary.h"

namespace nc = rpl_executive::noreils_chatila;

namespace {

class NoModules : public nc::RobotModules {
 public:
  nc::OperatorReply Send(nc::OperatorHandle, const nc::OperatorCommand&, double) override {
    return nc::OperatorReply();
  }
  void Halt(nc::OperatorHandle, double) override {}
};

nc::CompiledCondition Compile(const std::string& text) {
  const nc::ParseResult r =
      nc::ParseMissionText("(OSURV: MNTR " + text + " => ((stop)))", "bench.nc");
  const nc::Resolver none = [](const std::string&) { return nc::Lookup(); };
  return nc::DecodeCondition(r.file.o_surveillances.at(0).condition, none, 16).value;
}

// 100 monitors of a kind, none of which fires on the data below.
std::vector<nc::CompiledCondition> Monitors(const std::string& kind) {
  std::vector<nc::CompiledCondition> out;
  for (int i = 0; i < 100; ++i) {
    const std::string k =
        kind == "mixed" ? std::vector<std::string>{"zone", "threshold", "perception", "and"}[i % 4]
                        : kind;
    const int a = 1 + i % 16, b = 1 + (i + 1) % 16;
    const std::string x = std::to_string(1000 + 10 * i);
    if (k == "zone") {
      out.push_back(Compile("(S_zone IN ((" + x + " 0)(" + x + " 100)(" +
                            std::to_string(1050 + 10 * i) + " 100)(" +
                            std::to_string(1050 + 10 * i) + " 0)))"));
    } else if (k == "threshold") {
      out.push_back(Compile("(S_us-threshold ((" + std::to_string(a) + " 20)(" + std::to_string(b) +
                            " 25)(" + std::to_string(1 + (i + 2) % 16) + " 25)(" +
                            std::to_string(1 + (i + 3) % 16) + " 20)))"));
    } else if (k == "perception") {
      out.push_back(Compile("(S_us-perception line (" + std::to_string(300 + i) + " " +
                            std::to_string(10 * i) + "))"));
    } else {  // a formula over two sensors
      out.push_back(Compile("(AND (S_us-threshold ((" + std::to_string(a) + " 20))) (S_zone IN ((" +
                            x + " 0)(" + x + " 100)(" + std::to_string(1050 + 10 * i) +
                            " 100))))"));
    }
  }
  return out;
}

// A scan of a room: echoes of two walls on eight sensors, nothing within 25 cm.
nc::SonarScan RoomScan(const nc::SonarRing& ring) {
  nc::SonarScan s;
  s.ranges_m.assign(16, 1e9);
  for (int i : {15, 0, 1}) {
    s.ranges_m[i] = nc::PredictedRange(ring.mounts[i], ring.half_field_of_view_rad, 1.2, 0.0);
  }
  for (int i : {3, 4, 5}) {
    s.ranges_m[i] = nc::PredictedRange(ring.mounts[i], ring.half_field_of_view_rad, 0.9, 1.5708);
  }
  s.ranges_m[9] = 2.0;
  s.ranges_m[12] = 1.5;
  return s;
}

struct Fixture {
  explicit Fixture(const std::string& kind)
      : ring(nc::SonarRing::Circular(16, 0.4, 0.26, 4.0)),
        log(0),
        sm(nc::SurveillanceParameters(), ring, &modules, &log, [this] { return ++handle; }),
        conditions(Monitors(kind)),
        scan(RoomScan(ring)) {
    double t = 0.0;
    sm.OnPose(nc::PoseDatum{nc::Pose2{0.5, 0.5, 0.0}}, t);
    sm.OnSonar(scan, t);
    for (const auto& c : conditions) {
      nc::MonitorRequest r;
      r.condition = c;
      r.reflex = {nc::StopCommand{}};
      sm.Activate(sm.Register(r, t), t, nc::SurveillanceManager::Activation::kNextDatum);
    }
  }
  nc::SonarRing ring;
  NoModules modules;
  nc::MessageLog log;
  nc::OperatorHandle handle = 0;
  nc::SurveillanceManager sm;
  std::vector<nc::CompiledCondition> conditions;
  nc::SonarScan scan;
};

const char* kKinds[] = {"zone", "threshold", "perception", "and", "mixed"};

// Ours: the datum goes to its sensor's SSM, which evaluates only its parts.
void BM_SurveillanceManager_Sonar(benchmark::State& state) {
  Fixture f(kKinds[state.range(0)]);
  const double t = 0.0;  // all parts stay fresh: every formula is evaluated in full
  for (auto _ : state) f.sm.OnSonar(f.scan, t);
  if (f.sm.active_count() != 100) state.SkipWithError("a monitor fired");
  state.SetLabel(std::string(kKinds[state.range(0)]) + ", 100 monitors, per sonar datum");
}

void BM_SurveillanceManager_Pose(benchmark::State& state) {
  Fixture f(kKinds[state.range(0)]);
  const double t = 0.0;
  int i = 0;
  for (auto _ : state) f.sm.OnPose(nc::PoseDatum{nc::Pose2{0.5, 0.5 + 1e-6 * (++i % 2), 0.0}}, t);
  if (f.sm.active_count() != 100) state.SkipWithError("a monitor fired");
  state.SetLabel(std::string(kKinds[state.range(0)]) + ", 100 monitors, per pose datum");
}

// Peer: every monitor's whole formula on the latest data at every datum.
void BM_NaiveEvaluateAll_Sonar(benchmark::State& state) {
  Fixture f(kKinds[state.range(0)]);
  nc::SurveillanceManager latest(nc::SurveillanceParameters(), f.ring, &f.modules, &f.log,
                                 [] { return nc::OperatorHandle(1); });
  latest.OnPose(nc::PoseDatum{nc::Pose2{0.5, 0.5, 0.0}}, 0.0);
  const double t = 0.0;
  int fired = 0;
  for (auto _ : state) {
    latest.OnSonar(f.scan, t);  // stores the datum (it has no monitors); lines once per scan
    for (const auto& c : f.conditions) fired += latest.EvaluateOnLatest(c, t).value_or(false);
  }
  if (fired != 0) state.SkipWithError("a monitor fired");
  state.SetLabel(std::string(kKinds[state.range(0)]) + ", 100 monitors, per sonar datum");
}

// The sonar interpretation alone (once per scan, whatever the number of perception monitors).
void BM_InterpretLines(benchmark::State& state) {
  const nc::SonarRing ring = nc::SonarRing::Circular(16, 0.4, 0.26, 4.0);
  const nc::SonarScan scan = RoomScan(ring);
  size_t lines = 0;
  for (auto _ : state) {
    lines += nc::InterpretLines(scan, ring, nc::SonarInterpretationParameters()).size();
  }
  benchmark::DoNotOptimize(lines);
  state.SetLabel("16 sonars, 8 echoes, 2 lines");
}

BENCHMARK(BM_SurveillanceManager_Sonar)->DenseRange(0, 4);
BENCHMARK(BM_NaiveEvaluateAll_Sonar)->DenseRange(0, 4);
BENCHMARK(BM_SurveillanceManager_Pose)->DenseRange(0, 4);
BENCHMARK(BM_InterpretLines);

}  // namespace

BENCHMARK_MAIN();
