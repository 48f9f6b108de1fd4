// markov_localization_eval: the figures of issue 7's "Benchmarks and evaluation" on robot_sim's
// core (no ROS). A B21 with its 24 sonars (laser off, as in Beetz et al. section 2.3), seeded,
// one motion + sensor update per sonar ring (robot_sim's 10 Hz). Scenarios:
//   tracking   follow a route through bonn_department from a known start
//   global     N runs each of random wandering, wall following and active localization from a
//              uniform belief, started at random in bonn_department's symmetric corridor
//   fig2       the paper's Fig. 2 run: position 1 facing south-west, localize, enter room A
//   symmetric  a perfectly symmetric world (eval/worlds/symmetric_corridor.yaml)
//   kidnap     localized and tracking, then kidnapped by a 70-degree rotation
// Usage: markov_localization_eval SCENARIO [options]
//   --runs N (20)  --seed S (1; run i uses seed S + i - 1)  --time-limit S (simulated s)
//   --resolution M, --heading-bins K (tracking 0.15 / 180, else 0.25 / 72)
//   --sigma-hit M (max(0.15, resolution))  --critical-angle RAD (0.35, the node's sonar value)
//   --calibrate (fit the sensor model's mixture to simulated rings first)
//   --full-update (eq. (2) instead of the selective eq. (4))  --lost-detector on|off (on)
//   --clearance M (state clearance; default the B21's radius)  --behaviours wander,wall,active
//   --kidnap-deg D (70)  --kidnap-shift M (0)  --settle S (30)  --on-lost uniform|keep
//   --world FILE  --picture OUT.png (fig2: the first multi-modal belief after 10 m)
//   --verbose (each active choice on stderr)  --trace (each go-to step)
// Prints markdown tables; the header lines give the settings and the load average.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "eval_harness.h"

namespace ml = markov_localization;
namespace ev = markov_localization::eval;
using ml::Pose2;
using ml::Vec2;
using robot_sim::Twist2;

namespace {

constexpr double kDeg = M_PI / 180.0;

struct Options {
  std::string scenario;
  int runs = 20;
  std::uint64_t seed = 1;
  double resolution_m = -1;  // per-scenario default when not given
  int heading_bins = -1;
  double sigma_hit_m = -1;
  double time_limit_s = -1;
  std::vector<std::string> behaviours{"wander", "wall", "active"};
  double kidnap_deg = 70.0;
  double kidnap_shift_m = 0.0;
  double settle_s = 30.0;
  std::string world;
  bool verbose = false;
  bool calibrate = false;
  bool full_update = false;
  double clearance_m = -1;
  bool on_lost_uniform = true;
  double critical_angle_rad = 0.35;
  bool lost_detector = true;
  std::string picture;
};

std::string LoadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

int Usage(const char* argv0) {
  std::cerr << "usage: " << argv0
            << " tracking|global|fig2|symmetric|kidnap [--runs N] [--seed S] [--resolution M]"
               " [--heading-bins K] [--sigma-hit M] [--time-limit S]"
               " [--behaviours wander,wall,active] [--kidnap-deg D] [--kidnap-shift M]"
               " [--settle S] [--world FILE] [--calibrate] [--full-update] [--clearance M] "
               "[--on-lost uniform|keep] [--critical-angle RAD] [--lost-detector on|off] "
               "[--picture OUT.png] [--verbose]\n";
  return 2;
}

/// Per-run bookkeeping of what the issue asks for.
struct Record {
  double success_time = -1;  ///< First time certain and right (s), -1 never.
  double wrong_time = 0;     ///< Time certain but > 0.5 m or 15 deg off (s).
  double certain_time = 0;   ///< Time certainty > threshold (s).
  double max_certainty = 0;
  double update_ms_sum = 0;
  double update_ms_max = 0;
  int updates = 0;
  void Add(const ev::Episode& e) {
    const auto& s = e.status();
    const double dt = e.tick_seconds();
    if (e.ConfidentlyWrong()) wrong_time += dt;
    if (s.certainty > e.models().settings.certain) certain_time += dt;
    max_certainty = std::max(max_certainty, s.certainty);
    if (success_time < 0 && e.Success()) success_time = s.time;
    update_ms_sum += s.update_ms;
    update_ms_max = std::max(update_ms_max, s.update_ms);
    ++updates;
  }
  double mean_ms() const { return updates ? update_ms_sum / updates : 0.0; }
};

/// A random pose in the hallways of `world` (uniform over their bounding boxes, 0.45 m inside),
/// that is a state of the map and where the robot fits.
Pose2 RandomHallwayPose(const ev::Models& m, ev::Rng& rng) {
  std::vector<const spott_map::Room*> halls;
  for (const auto& r : m.world.rooms)
    if (r.kind == spott_map::RoomKind::kHallway) halls.push_back(&r);
  std::uniform_int_distribution<std::size_t> pick(0, halls.size() - 1);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const auto& poly = halls[pick(rng)]->polygon;
    Vec2 lo = poly[0], hi = poly[0];
    for (const auto& p : poly) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    std::uniform_real_distribution<double> ux(lo.x() + 0.45, hi.x() - 0.45);
    std::uniform_real_distribution<double> uy(lo.y() + 0.45, hi.y() - 0.45);
    const Pose2 p{ux(rng), uy(rng), yaw(rng)};
    if (m.map.IsStateAt(p.Position())) return p;
  }
  throw std::runtime_error("no free hallway pose");
}

void PrintHeader(const Options& o, const ev::Models& m, const std::string& world_file) {
  std::printf("# markov_localization_eval %s: world %s, B21 sonars only (%zu beams, max %.1f m)\n",
              o.scenario.c_str(), world_file.c_str(), m.ring->mounts.size(), m.ring->max_range);
  std::printf("# sonar model: cone %.2f rad, critical angle %.2f rad; lost detector %s\n",
              m.sensor_params.beam_width_rad, m.sensor_params.critical_angle_rad,
              m.grid_params.lost.enabled ? "on (core defaults)" : "off");
  std::printf(
      "# grid %.2f m x %.1f deg (%zu states; state clearance %.3f m), sigma_hit %.2f m, %s, "
      "speed %.2f m/s, 1 update per ring at %.0f Hz; models built in %.1f s\n",
      m.settings.resolution_m, 360.0 / m.settings.heading_bins,
      m.map.NumStateCells() * static_cast<std::size_t>(m.settings.heading_bins),
      m.settings.state_clearance_m, m.sensor_params.sigma_hit_m,
      m.settings.selective_update ? "selective update eq. (4)" : "full update eq. (2)",
      m.settings.speed_mps, m.settings.sonar_hz, m.build_seconds);
  if (!m.calibration_report.empty())
    std::printf("# %s\n", m.calibration_report.c_str());
  else
    std::printf(
        "# sensor model: the core's defaults (z_hit %.2f, z_short %.2f, z_max %.2f, "
        "z_rand %.2f) with sigma_hit above\n",
        m.sensor_params.z_hit, m.sensor_params.z_short, m.sensor_params.z_max,
        m.sensor_params.z_rand);
  std::printf("# seed %llu, load average at start: %s\n", static_cast<unsigned long long>(o.seed),
              LoadAverage().c_str());
}

std::string Fmt(double v, const char* f = "%.1f") {
  if (v < 0) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// ---------------------------------------------------------------------------------------------
// tracking
int Tracking(const Options& o, const ev::Models& m) {
  // The route (map frame): corridor east -> room B -> corridor -> room A -> corridor west.
  const std::vector<Vec2> route = {{17.5, 10.0}, {17.5, 8.2},  {17.5, 5.0},  {17.5, 8.2},
                                   {17.5, 10.0}, {12.5, 10.0}, {12.5, 11.8}, {14.0, 13.5},
                                   {12.5, 11.8}, {12.5, 10.0}, {3.0, 10.0}};
  const Pose2 start{24.0, 10.0, M_PI};
  std::printf(
      "| run | seed | route | distance (m) | time (s) | mean / max pos error (cm) | "
      "mean / max heading error (deg) | min certainty | update mean / max (ms) | "
      "confidently wrong (s) | lost detector fired |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> all_pos, all_yaw, all_ms;
  for (int run = 0; run < o.runs; ++run) {
    const std::uint64_t seed = o.seed + run;
    ev::Episode e(m, start, seed, /*known_start=*/true);
    ev::GoTo go;
    Record rec;
    double sum_pos = 0, max_pos = 0, sum_yaw = 0, max_yaw = 0, min_cert = 1;
    int alarms = 0;
    std::size_t leg = 0;
    bool started = false;
    while (e.time() < o.time_limit_s && leg < route.size()) {
      if (!started || go.done()) {
        if (started) ++leg;
        if (leg >= route.size()) break;
        // Steered on the ground truth: the route is the experiment, not the localization's.
        go.Set({ev::MapToOdom(e.truth(), e.odom(), route[leg])}, e.time(), 120.0);
        started = true;
      }
      e.Tick(go.Command(e));
      rec.Add(e);
      const auto& s = e.status();
      sum_pos += s.pos_error, max_pos = std::max(max_pos, s.pos_error);
      sum_yaw += s.yaw_error, max_yaw = std::max(max_yaw, s.yaw_error);
      min_cert = std::min(min_cert, s.certainty);
      if (s.lost_detector) ++alarms;
      all_pos.push_back(s.pos_error), all_yaw.push_back(s.yaw_error);
      all_ms.push_back(s.update_ms);
    }
    const int n = std::max(1, rec.updates);
    std::printf(
        "| %d | %llu | %s | %.1f | %.1f | %.1f / %.1f | %.2f / %.2f | %.2f | %.1f / %.1f | "
        "%.1f | %d |\n",
        run + 1, static_cast<unsigned long long>(seed),
        leg >= route.size() ? "completed" : "not completed", e.distance(), e.time(),
        100 * sum_pos / n, 100 * max_pos, sum_yaw / n / kDeg, max_yaw / kDeg, min_cert,
        rec.mean_ms(), rec.update_ms_max, rec.wrong_time, alarms);
    std::fflush(stdout);
  }
  auto mean = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
  };
  std::sort(all_ms.begin(), all_ms.end());
  std::printf(
      "\nall runs: mean position error %.1f cm, mean heading error %.2f deg, update mean "
      "%.1f ms, median %.1f ms, 99th percentile %.1f ms (budget at 10 Hz: 100 ms)\n",
      100 * mean(all_pos), mean(all_yaw) / kDeg, mean(all_ms),
      all_ms.empty() ? 0.0 : all_ms[all_ms.size() / 2],
      all_ms.empty() ? 0.0 : all_ms[all_ms.size() * 99 / 100]);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// global
struct GlobalResult {
  bool success = false;
  double time = -1;
  double wrong = 0;
  double distance = 0;
  double final_certainty = 0;
  double final_error = 0;
  double mean_ms = 0;
  int choices = 0;
  std::string rooms;
  double wall_s = 0;
};

// Appends room ids of successive targets, dropping repeats.
std::string RoomsOf(const ev::Models& m, const std::vector<Vec2>& targets) {
  std::string out, last;
  for (const auto& t : targets) {
    const std::string r = m.RoomAt(t);
    if (r == last) continue;
    out += (out.empty() ? "" : ">") + r;
    last = r;
  }
  return out.empty() ? "-" : out;
}

GlobalResult GlobalRun(const Options& o, const ev::Models& m, const Pose2& start,
                       std::uint64_t seed, const std::string& behaviour) {
  const auto t0 = std::chrono::steady_clock::now();
  ev::Episode e(m, start, seed, /*known_start=*/false);
  ev::RandomWander wander;
  ev::WallFollow wall(seed % 2 == 0);
  ev::ActiveDriver active;
  active.verbose = o.verbose;
  Record rec;
  double random_motion_m = 10.0;  // active: about ten metres of random motion first (paper)
  while (e.time() < o.time_limit_s) {
    ev::Behaviour* b = &wander;
    if (behaviour == "wall") b = &wall;
    if (behaviour == "active" && e.distance() >= random_motion_m) b = &active;
    e.Tick(b->Command(e));
    rec.Add(e);
    if (o.verbose && static_cast<int>(std::lround(e.time() * 10)) % 100 == 0)
      std::fprintf(stderr, "  t %.0f s cert %.2f err %.2f m %.0f deg modes? dist %.1f\n", e.time(),
                   e.status().certainty, e.status().pos_error, e.status().yaw_error / kDeg,
                   e.distance());
    if (rec.success_time >= 0) break;
  }
  GlobalResult r;
  r.success = rec.success_time >= 0;
  r.time = rec.success_time;
  r.wrong = rec.wrong_time;
  r.distance = e.distance();
  r.final_certainty = e.status().certainty;
  r.final_error = e.status().pos_error;
  r.mean_ms = rec.mean_ms();
  r.choices = active.choices();
  r.rooms = behaviour == "active" ? RoomsOf(m, active.targets_true()) : "-";
  r.wall_s = ev::Elapsed(t0);
  return r;
}

int Global(const Options& o, const ev::Models& m) {
  std::printf(
      "| behaviour | run | seed | start (x, y, deg) | success | time to it (s) | "
      "distance (m) | confidently wrong (s) | final certainty | final error (m) | "
      "choices of a* | rooms of a* (true frame) | update mean (ms) | wall (s) |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::map<std::string, std::vector<GlobalResult>> all;
  for (int run = 0; run < o.runs; ++run) {
    const std::uint64_t seed = o.seed + run;
    ev::Rng rng(seed * 7919 + 17);
    const Pose2 start = RandomHallwayPose(m, rng);
    for (const auto& behaviour : o.behaviours) {
      const GlobalResult r = GlobalRun(o, m, start, seed, behaviour);
      all[behaviour].push_back(r);
      std::printf(
          "| %s | %d | %llu | (%.2f, %.2f, %.0f) | %s | %s | %.1f | %.1f | %.2f | %.2f | "
          "%d | %s | %.1f | %.0f |\n",
          behaviour.c_str(), run + 1, static_cast<unsigned long long>(seed), start.x, start.y,
          start.yaw / kDeg, r.success ? "yes" : "no", Fmt(r.time).c_str(), r.distance, r.wrong,
          r.final_certainty, r.final_error, r.choices, r.rooms.c_str(), r.mean_ms, r.wall_s);
      std::fflush(stdout);
    }
  }
  std::printf(
      "\n| behaviour | success | time to success: median / max (s) | runs confidently "
      "wrong | total time confidently wrong (s) |\n|---|---|---|---|---|\n");
  for (const auto& behaviour : o.behaviours) {
    const auto& v = all[behaviour];
    std::vector<double> times;
    int wrong_runs = 0;
    double wrong = 0;
    for (const auto& r : v) {
      if (r.success) times.push_back(r.time);
      if (r.wrong > 0) ++wrong_runs;
      wrong += r.wrong;
    }
    std::sort(times.begin(), times.end());
    std::printf("| %s | %zu / %zu | %s / %s | %d | %.1f |\n", behaviour.c_str(), times.size(),
                v.size(), times.empty() ? "-" : Fmt(times[times.size() / 2]).c_str(),
                times.empty() ? "-" : Fmt(times.back()).c_str(), wrong_runs, wrong);
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------
// fig2
int Fig2(const Options& o, const ev::Models& m) {
  const spott_map::Place* p1 = m.world.FindPlace("position_1");
  const spott_map::Place* target = m.world.FindPlace("room_a_target");
  if (!p1 || !target) {
    std::cerr << "world has no position_1 / room_a_target place\n";
    return 1;
  }
  std::printf(
      "# start: place position_1 (%.2f, %.2f, %.0f deg: facing south-west), then room A "
      "via place room_a_target (%.1f, %.1f)\n",
      p1->pose.x, p1->pose.y, p1->pose.yaw / kDeg, target->pose.x, target->pose.y);
  std::printf(
      "| run | seed | modes after 10 m | certainty after 10 m | time to certain and "
      "right (s) | rooms of a* (true frame) | choices | reached room A | total time (s) "
      "| distance (m) | confidently wrong (s) | wall (s) |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  bool pictured = false;
  for (int run = 0; run < o.runs; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint64_t seed = o.seed + run;
    ev::Episode e(m, p1->pose, seed, /*known_start=*/false);
    ev::RandomWander wander;
    ev::ActiveDriver active;
    active.verbose = o.verbose;
    ev::GoTo to_a;
    Record rec;
    int modes_10m = -1;
    double cert_10m = -1;
    bool heading_to_a = false, reached = false;
    double certain_at = -1;
    while (e.time() < o.time_limit_s) {
      Twist2 cmd;
      if (e.distance() < 10.0) {
        cmd = wander.Command(e);
      } else if (!heading_to_a) {
        cmd = active.Command(e);
      } else {
        cmd = to_a.Command(e);
        if (to_a.done()) {
          reached = !to_a.timed_out() && m.RoomAt(e.truth().Position()) == "room_a";
          break;
        }
      }
      e.Tick(cmd);
      rec.Add(e);
      if (modes_10m < 0 && e.distance() >= 10.0) {  // the paper's position 2: Fig. 3's belief
        const auto modes = e.Modes();
        modes_10m = static_cast<int>(modes.size());
        cert_10m = e.status().certainty;
        if (!o.picture.empty() && !pictured && modes.size() >= 2) {  // a multi-modal belief
          pictured = true;
          const auto b = ml::BeliefSnapshot::Of(e.grid());
          if (!ev::WriteBeliefPicture(m.map, b, e.truth(), modes, o.picture))
            std::cerr << "cannot write " << o.picture << "\n";
          std::printf(
              "# picture of run %d's belief after 10 m: %s (truth (%.2f, %.2f, %.0f deg), "
              "entropy %.2f nats of %.2f); modes:",
              run + 1, o.picture.c_str(), e.truth().x, e.truth().y, e.truth().yaw / kDeg,
              ml::Entropy(b), std::log(static_cast<double>(b.num_states)));
          for (const auto& md : modes)
            std::printf(" (%.2f, %.2f, %.0f deg) %.3f;", md.mean.x, md.mean.y, md.mean.yaw / kDeg,
                        md.mass);
          std::printf("\n");
        }
      }
      // The robot decides by its certainty alone; the harness scores against the truth.
      if (!heading_to_a && e.distance() >= 10.0 && e.status().certainty > m.settings.certain) {
        heading_to_a = true;
        certain_at = e.time();
        const auto& est = e.status().estimate;
        // A plain go-to, no planner: the door of room A is a waypoint.
        std::vector<Vec2> wp;
        for (const Vec2& p : {Vec2(12.5, 10.0), Vec2(12.5, 11.8), target->pose.Position()})
          wp.push_back(ev::MapToOdom(est, e.odom(), p));
        to_a.Set(wp, e.time(), 120.0);
      }
    }
    std::printf(
        "| %d | %llu | %d | %.2f | %s (certain at %s) | %s | %d | %s | %.1f | %.1f | "
        "%.1f | %.0f |\n",
        run + 1, static_cast<unsigned long long>(seed), modes_10m, cert_10m,
        Fmt(rec.success_time).c_str(), Fmt(certain_at).c_str(),
        RoomsOf(m, active.targets_true()).c_str(), active.choices(), reached ? "yes" : "no",
        e.time(), e.distance(), rec.wrong_time, ev::Elapsed(t0));
    std::fflush(stdout);
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------
// symmetric
int Symmetric(const Options& o, const ev::Models& m) {
  std::printf(
      "| run | seed | start (x, y, deg) | time (s) | distance (m) | max certainty | time "
      "certain (s) | confidently wrong (s) | final modes | final certainty |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  int violations = 0;
  double wrong_total = 0;
  for (int run = 0; run < o.runs; ++run) {
    const std::uint64_t seed = o.seed + run;
    ev::Rng rng(seed * 7919 + 17);
    const Pose2 start = RandomHallwayPose(m, rng);
    ev::Episode e(m, start, seed, /*known_start=*/false);
    ev::RandomWander wander;
    Record rec;
    while (e.time() < o.time_limit_s) {
      e.Tick(wander.Command(e));
      rec.Add(e);
    }
    if (rec.max_certainty > m.settings.certain) ++violations;
    wrong_total += rec.wrong_time;
    std::printf(
        "| %d | %llu | (%.2f, %.2f, %.0f) | %.0f | %.1f | %.3f | %.1f | %.1f | %zu | "
        "%.3f |\n",
        run + 1, static_cast<unsigned long long>(seed), start.x, start.y, start.yaw / kDeg,
        e.time(), e.distance(), rec.max_certainty, rec.certain_time, rec.wrong_time,
        e.Modes().size(), e.status().certainty);
    std::fflush(stdout);
  }
  std::printf("\nruns with certainty > %.1f: %d of %d; total time confidently wrong %.1f s\n",
              m.settings.certain, violations, o.runs, wrong_total);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// kidnap
int Kidnap(const Options& o, const ev::Models& m) {
  std::printf(
      "# kidnap: %.0f deg clockwise rotation in place%s after %.0f s of tracking "
      "(random wandering from a known start in the corridor); lost = %s; once lost: %s; "
      "%0.f s allowed after the kidnap\n",
      o.kidnap_deg,
      o.kidnap_shift_m != 0 ? (" and " + Fmt(o.kidnap_shift_m, "%.2f") + " m ahead").c_str() : "",
      o.settle_s, "MarkovGrid::lost() (the lost detector, with the certainty reported)",
      o.on_lost_uniform ? "uniform belief, ~10 m random motion, then active localization"
                        : "active localization on the belief as it is",
      o.time_limit_s);
  std::printf(
      "| run | seed | start (x, y, deg) | tracking before | certainty < 0.8 after (s) "
      "| detector lost after (s) | relocalized after (s) | confidently wrong after "
      "kidnap (s) | certainty < 0.8 before the kidnap (s) | final certainty | final "
      "error (m, deg) | wall (s) |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int recovered = 0;
  for (int run = 0; run < o.runs; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint64_t seed = o.seed + run;
    ev::Rng rng(seed * 7919 + 17);
    const Pose2 start = RandomHallwayPose(m, rng);
    ev::Episode e(m, start, seed, /*known_start=*/true);
    ev::RandomWander wander;
    ev::ActiveDriver active;
    active.verbose = o.verbose;
    double unsure_before = 0;  // time below the threshold while still tracking (false alarms)
    while (e.time() < o.settle_s) {
      e.Tick(wander.Command(e));
      if (e.status().certainty < m.settings.certain) unsure_before += e.tick_seconds();
    }
    const bool tracking = e.Success();
    std::string error;
    const Pose2 jump{o.kidnap_shift_m, 0.0, -o.kidnap_deg * kDeg};
    if (!e.sim().Kidnap(e.robot(), jump, /*relative=*/true, &error)) {
      std::printf("| %d | %llu | kidnap refused: %s |\n", run + 1,
                  static_cast<unsigned long long>(seed), error.c_str());
      continue;
    }
    const double tk = e.time();
    double below = -1, lost = -1, reloc = -1, wrong = 0;
    double relocalize_from_m = -1;  // odometry distance when relocalization started
    while (e.time() < tk + o.time_limit_s) {
      // Once lost: the relocalization (uniform belief, about ten metres of random
      // motion, then active localization), or (--on-lost keep) active localization on the
      // belief as it is.
      const bool relocalizing = relocalize_from_m >= 0;
      const bool random_phase =
          !relocalizing || (o.on_lost_uniform && e.distance() - relocalize_from_m < 10.0);
      e.Tick(random_phase ? wander.Command(e) : active.Command(e));
      const auto& s = e.status();
      if (e.ConfidentlyWrong()) wrong += e.tick_seconds();
      if (below < 0 && s.certainty < m.settings.certain) below = e.time() - tk;
      if (lost < 0 && s.lost_detector) lost = e.time() - tk;
      if (!relocalizing && lost >= 0) {
        relocalize_from_m = e.distance();
        if (o.on_lost_uniform) e.grid().SetUniform();
        continue;
      }
      if ((below >= 0 || lost >= 0) && e.Success()) {
        reloc = e.time() - tk;
        break;
      }
    }
    if (reloc >= 0) ++recovered;
    std::printf(
        "| %d | %llu | (%.2f, %.2f, %.0f) | %s | %s | %s | %s | %.1f | %.1f | %.2f | "
        "%.2f, %.0f | %.0f |\n",
        run + 1, static_cast<unsigned long long>(seed), start.x, start.y, start.yaw / kDeg,
        tracking ? "yes" : "no", Fmt(below).c_str(), Fmt(lost).c_str(), Fmt(reloc).c_str(), wrong,
        unsure_before, e.status().certainty, e.status().pos_error, e.status().yaw_error / kDeg,
        ev::Elapsed(t0));
    std::fflush(stdout);
  }
  std::printf("\nrecovered (certain and right again) in %d of %d runs\n", recovered, o.runs);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return Usage(argv[0]);
  Options o;
  o.scenario = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    try {
      if (a == "--runs")
        o.runs = std::stoi(next());
      else if (a == "--seed")
        o.seed = std::stoull(next());
      else if (a == "--resolution")
        o.resolution_m = std::stod(next());
      else if (a == "--heading-bins")
        o.heading_bins = std::stoi(next());
      else if (a == "--sigma-hit")
        o.sigma_hit_m = std::stod(next());
      else if (a == "--time-limit")
        o.time_limit_s = std::stod(next());
      else if (a == "--kidnap-deg")
        o.kidnap_deg = std::stod(next());
      else if (a == "--kidnap-shift")
        o.kidnap_shift_m = std::stod(next());
      else if (a == "--settle")
        o.settle_s = std::stod(next());
      else if (a == "--world")
        o.world = next();
      else if (a == "--picture")
        o.picture = next();
      else if (a == "--verbose")
        o.verbose = true;
      else if (a == "--trace")
        o.verbose = ev::verbose_trace = true;
      else if (a == "--calibrate")
        o.calibrate = true;
      else if (a == "--full-update")
        o.full_update = true;
      else if (a == "--clearance")
        o.clearance_m = std::stod(next());
      else if (a == "--critical-angle")
        o.critical_angle_rad = std::stod(next());
      else if (a == "--lost-detector") {
        const std::string v = next();
        if (v != "on" && v != "off") {
          std::cerr << "--lost-detector must be on or off\n";
          return 2;
        }
        o.lost_detector = v == "on";
      } else if (a == "--on-lost") {
        const std::string v = next();
        if (v != "uniform" && v != "keep") {
          std::cerr << "--on-lost must be uniform or keep\n";
          return 2;
        }
        o.on_lost_uniform = v == "uniform";
      } else if (a == "--behaviours") {
        o.behaviours.clear();
        std::stringstream ss(next());
        std::string b;
        while (std::getline(ss, b, ',')) {
          if (b != "wander" && b != "wall" && b != "active") {
            std::cerr << "--behaviours: unknown behaviour '" << b << "'\n";
            return 2;
          }
          o.behaviours.push_back(b);
        }
      } else {
        std::cerr << "unknown option " << a << "\n";
        return Usage(argv[0]);
      }
    } catch (const std::exception&) {
      std::cerr << "bad value for " << a << "\n";
      return 2;
    }
  }
  const bool tracking = o.scenario == "tracking";
  if (o.scenario != "tracking" && o.scenario != "global" && o.scenario != "fig2" &&
      o.scenario != "symmetric" && o.scenario != "kidnap")
    return Usage(argv[0]);
  if (o.resolution_m < 0) o.resolution_m = tracking ? 0.15 : 0.25;
  if (o.heading_bins < 0) o.heading_bins = tracking ? 180 : 72;
  if (o.sigma_hit_m < 0) o.sigma_hit_m = std::max(0.15, o.resolution_m);
  if (o.time_limit_s < 0)
    o.time_limit_s = tracking                    ? 600
                     : o.scenario == "symmetric" ? 120
                     : o.scenario == "kidnap"    ? 240
                                                 : 480;
  if (o.world.empty())
    o.world = o.scenario == "symmetric" ? std::string(EVAL_WORLDS_DIR) + "/symmetric_corridor.yaml"
                                        : std::string(WORLDS_DIR) + "/bonn_department.yaml";
  if (o.runs < 1 || !(o.resolution_m > 0) || o.heading_bins < 4) {
    std::cerr << "--runs must be >= 1, --resolution > 0, --heading-bins >= 4\n";
    return 2;
  }
  ev::Settings s;
  s.resolution_m = o.resolution_m;
  s.heading_bins = o.heading_bins;
  s.sigma_hit_m = o.sigma_hit_m;
  s.robot_dir = ROBOT_SIM_DIR;
  s.calibrate = o.calibrate;
  s.selective_update = !o.full_update;
  s.state_clearance_m = o.clearance_m;
  s.critical_angle_rad = o.critical_angle_rad;
  s.lost_detector = o.lost_detector;
  const auto start = std::chrono::steady_clock::now();
  try {
    const auto models = ev::Models::Load(o.world, s);
    PrintHeader(o, *models, o.world);
    int rc = 0;
    if (o.scenario == "tracking") rc = Tracking(o, *models);
    if (o.scenario == "global") rc = Global(o, *models);
    if (o.scenario == "fig2") rc = Fig2(o, *models);
    if (o.scenario == "symmetric") rc = Symmetric(o, *models);
    if (o.scenario == "kidnap") rc = Kidnap(o, *models);
    std::printf("# wall time %.0f s; load average at end: %s\n", ev::Elapsed(start),
                LoadAverage().c_str());
    return rc;
  } catch (const std::exception& e) {
    std::cerr << "markov_localization_eval: " << e.what() << "\n";
    return 1;
  }
}
