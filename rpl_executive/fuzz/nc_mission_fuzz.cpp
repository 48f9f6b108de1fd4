// Fuzzes the Noreils-Chatila mission parser, checker and executive with arbitrary text.
// Besides crashes and sanitizer reports it checks that every diagnostic is located inside the
// text, and that a file that parses prints to text that parses back to the same text. A file
// that checks clean is started and run for a few steps on modules that end every long
// operator on the next step, with sensor data that fires zone, sonar and battery conditions.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/checker.h"
#include "rpl_executive/noreils_chatila/executive.h"
#include "rpl_executive/noreils_chatila/mission_parser.h"

namespace nc = rpl_executive::noreils_chatila;

namespace {

class QuickModules : public nc::RobotModules {
 public:
  nc::OperatorReply Send(nc::OperatorHandle handle, const nc::OperatorCommand& command,
                         double) override {
    nc::OperatorReply reply;
    const std::string name = nc::OperatorName(command);
    if (name == "smooth-move" || name == "wall-following" || name == "obstacle-avoidance" ||
        name == "avoid-obstacle") {
      running.push_back(handle);
      reply.status = nc::OperatorStatus::kRunning;
    }
    return reply;
  }
  void Halt(nc::OperatorHandle, double) override {}
  std::vector<nc::OperatorHandle> running;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 8192) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const nc::ParseResult r = nc::ParseMissionText(text, "fuzz.nc");
  int lines = 1;
  for (char c : text) lines += c == '\n';
  for (const nc::Diagnostic& d : r.diagnostics) {
    if (d.where.line < 1 || d.where.line > lines || d.where.column < 1) std::abort();
  }
  if (!r.ok()) return 0;
  const std::string printed = r.file.ToText();
  const nc::ParseResult again = nc::ParseMissionText(printed, "again.nc");
  if (!again.ok() || again.file.ToText() != printed) std::abort();
  const std::vector<nc::Diagnostic> checked = nc::CheckMissionFile(r.file);
  if (nc::HasErrors(checked)) return 0;

  QuickModules modules;
  nc::Executive executive(nc::ExecutiveParameters(), nc::SurveillanceParameters(),
                          nc::SonarRing::Circular(16, 0.4, 0.26, 4.0), &modules);
  executive.SetRobotState("motors", nc::Value::Symbol("ON"));
  double t = 0.0;
  executive.SetOSurveillances(r.file, t);
  executive.OnPose(nc::PoseDatum{nc::Pose2{0.0, 0.0, 0.0}}, t);
  executive.StartMission(r.file, t);
  for (int i = 0; i < 20; ++i) {
    t += 0.1;
    const double x = 0.1 * i;
    executive.OnPose(nc::PoseDatum{nc::Pose2{x, 0.01 * i, 0.1 * i}}, t);
    nc::SonarScan scan;
    scan.ranges_m.assign(16, 0.2 + 0.05 * (i % 7));
    executive.OnSonar(scan, t);
    executive.OnBattery(nc::BatteryDatum{100.0 - 5.0 * i}, t);
    if (i % 3 == 2 && !modules.running.empty()) {
      const nc::OperatorHandle h = modules.running.back();
      modules.running.pop_back();
      nc::OperatorReply reply;
      reply.status = i % 2 ? nc::OperatorStatus::kCompleted : nc::OperatorStatus::kInterrupted;
      executive.OnOperatorReport(h, reply, t);
    }
    executive.Step(t);
  }
  return 0;
}
