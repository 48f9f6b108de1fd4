// Helpers of the Noreils-Chatila core tests: missions from text, scripted modules, sonar
// scans, and a small world of wall segments that simulates the ultrasonic belt.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rpl_executive/noreils_chatila/executive.h"
#include "rpl_executive/noreils_chatila/mission_parser.h"
#include "rpl_executive/noreils_chatila/robot_modules.h"
#include "rpl_executive/noreils_chatila/sensor_data.h"

namespace rpl_executive::noreils_chatila::testing {

inline std::string MissionPath(const std::string& name) {
  return std::string(PACKAGE_DIR) + "/missions/" + name;
}

/// Parses `text`, failing the test on any diagnostic.
inline MissionFile Parse(const std::string& text, const std::string& file = "test.nc") {
  ParseResult r = ParseMissionText(text, file);
  EXPECT_TRUE(r.diagnostics.empty()) << FormatDiagnostics(r.diagnostics);
  return r.file;
}

inline MissionFile ParseFile(const std::string& name) {
  ParseResult r = ParseMissionFile(MissionPath(name));
  EXPECT_TRUE(r.diagnostics.empty()) << FormatDiagnostics(r.diagnostics);
  return r.file;
}

/// HILARE's belt: 16 sensors on a 0.4 m circle, sensor 1 forward (robot_sim/urdf/hilare.urdf),
/// half opening 0.26 rad, 4 m range.
inline SonarRing HilareRing() { return SonarRing::Circular(16, 0.4, 0.26, 4.0); }

/// A scan with no echo but the given (sensor id, range) pairs.
inline SonarScan Scan(std::vector<std::pair<int, double>> echoes = {}) {
  SonarScan s;
  s.ranges_m.assign(16, std::numeric_limits<double>::infinity());
  for (const auto& [id, r] : echoes) s.ranges_m[id - 1] = r;
  return s;
}

inline PoseDatum At(double x, double y, double yaw = 0.0) { return PoseDatum{Pose2{x, y, yaw}}; }

/// Modules that record what they receive. Long operators run until the test reports on them;
/// stop interrupts the running movement and reports it on the next Deliver (Fig. 5, 7).
class ScriptedModules : public RobotModules {
 public:
  struct Sent {
    OperatorHandle handle;
    std::string name;
    OperatorCommand command;
  };

  OperatorReply Send(OperatorHandle handle, const OperatorCommand& command, double) override {
    sent.push_back(Sent{handle, OperatorName(command), command});
    OperatorReply reply;
    const std::string name = OperatorName(command);
    if (name == "smooth-move" || name == "wall-following" || name == "obstacle-avoidance" ||
        name == "avoid-obstacle") {
      if (fail_next_long) {
        fail_next_long = false;
        reply.status = OperatorStatus::kFailed;
        reply.message = "scripted failure";
        return reply;
      }
      if (running != 0) pending.emplace_back(running, Reply(OperatorStatus::kInterrupted));
      running = handle;
      reply.status = OperatorStatus::kRunning;
      return reply;
    }
    if (name == "stop") {
      if (running != 0 && report_interruptions) {
        pending.emplace_back(running, Reply(OperatorStatus::kInterrupted));
      }
      running = 0;
    }
    if (name == "read-all-us-data") {
      reply.results.emplace_back(
          "r-us-data", Value::List({Value::List({Value::Number(1), Value::Number(120)})}));
      reply.results.emplace_back(
          "r-position", Value::List({Value::Number(200), Value::Number(520), Value::Number(0)}));
    }
    return reply;
  }
  void Halt(OperatorHandle handle, double) override {
    halted.push_back(handle);
    if (handle == running) running = 0;
  }

  static OperatorReply Reply(OperatorStatus status, std::string message = "") {
    OperatorReply r;
    r.status = status;
    r.message = std::move(message);
    return r;
  }
  /// Delivers the queued reports to the executive.
  void Deliver(Executive* e, double now) {
    auto reports = std::move(pending);
    pending.clear();
    for (const auto& [h, r] : reports) e->OnOperatorReport(h, r, now);
  }
  /// The running long operator ends with `status`.
  void Finish(Executive* e, double now, OperatorStatus status = OperatorStatus::kCompleted) {
    const OperatorHandle h = running;
    running = 0;
    e->OnOperatorReport(h, Reply(status, status == OperatorStatus::kFailed ? "scripted" : ""), now);
  }
  std::vector<std::string> Names() const {
    std::vector<std::string> out;
    for (const Sent& s : sent) out.push_back(s.name);
    return out;
  }
  int Count(const std::string& name) const {
    int n = 0;
    for (const Sent& s : sent) n += s.name == name;
    return n;
  }

  std::vector<Sent> sent;
  std::vector<OperatorHandle> halted;
  std::vector<std::pair<OperatorHandle, OperatorReply>> pending;
  OperatorHandle running = 0;
  bool report_interruptions = true;
  bool fail_next_long = false;
};

struct Segment {
  Point2 a, b;
};

/// A sonar belt in a world of segments: each sensor reads the nearest point of a segment inside
/// its beam (ray casting over 15 rays across the opening), a ray whose incidence on the surface
/// is beyond `critical_angle_rad` returning nothing (specular reflection), as robot_sim's sonar.
inline SonarScan SimulateSonar(const std::vector<Segment>& world, const Pose2& pose,
                               const SonarRing& ring, double critical_angle_rad = 0.35) {
  SonarScan scan;
  for (const SonarMount& m : ring.mounts) {
    const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
    const Point2 o{pose.x + c * m.x_m - s * m.y_m, pose.y + s * m.x_m + c * m.y_m};
    double best = std::numeric_limits<double>::infinity();
    const int rays = 15;
    for (int k = 0; k < rays; ++k) {
      const double a = pose.yaw + m.yaw_rad - ring.half_field_of_view_rad +
                       2.0 * ring.half_field_of_view_rad * k / (rays - 1);
      const Point2 d{std::cos(a), std::sin(a)};
      for (const Segment& w : world) {
        const Point2 e{w.b.x - w.a.x, w.b.y - w.a.y};
        const double den = d.x * e.y - d.y * e.x;
        if (std::fabs(den) < 1e-12) continue;
        const double t = ((w.a.x - o.x) * e.y - (w.a.y - o.y) * e.x) / den;
        const double u = ((w.a.x - o.x) * d.y - (w.a.y - o.y) * d.x) / den;
        if (t <= 0.0 || u < 0.0 || u > 1.0) continue;
        const double len = std::hypot(e.x, e.y);
        const double incidence = std::acos(std::fabs(d.x * e.y - d.y * e.x) / len);
        if (incidence > critical_angle_rad) continue;
        best = std::min(best, t);
      }
    }
    scan.ranges_m.push_back(best < ring.max_range_m ? best
                                                    : std::numeric_limits<double>::infinity());
  }
  return scan;
}

/// hilare_room's inner faces (spott_worlds/worlds/hilare_room.yaml: an 8 x 9 m room, walls 0.15 m
/// thick, so faces 0.075 m inside the polygon).
inline std::vector<Segment> HilareRoomWalls() {
  const double f = 0.075;
  return {Segment{{f, f}, {8 - f, f}}, Segment{{8 - f, f}, {8 - f, 9 - f}},
          Segment{{8 - f, 9 - f}, {f, 9 - f}}, Segment{{f, 9 - f}, {f, f}}};
}

}  // namespace rpl_executive::noreils_chatila::testing
