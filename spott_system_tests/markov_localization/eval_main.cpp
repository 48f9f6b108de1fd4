// markov_localization_eval: the figures of issue 7's "Benchmarks and evaluation" on robot_sim's
// core (no ROS). A B21 with its 24 sonars (laser off, as in Beetz et al. section 2.3), seeded,
// one motion + sensor update per sonar ring (robot_sim's 10 Hz). Scenarios:
//   tracking   follow a route through bonn_department from a known start
//   global     N runs each of random wandering, wall following and active localization from a
//              uniform belief, started at random in bonn_department's symmetric corridor
//   fig2       the paper's Fig. 2 run: position 1 facing south-west, localize, enter room A
//   symmetric  a perfectly symmetric world (spott_worlds/eval_worlds/symmetric_corridor.yaml)
//   kidnap     localized and tracking, then kidnapped by a 70-degree rotation
// Usage: markov_localization_eval SCENARIO [options]
//   --runs N (20)  --seed S (1; run i uses seed S + i - 1)  --time-limit S (simulated s)
//   --resolution M, --heading-bins K (tracking 0.15 / 180, else 0.25 / 72)
//   --sigma-hit M (max(0.15, resolution))  --critical-angle RAD (0.35, the node's sonar value)
//   --calibrate (fit the sensor model's mixture to simulated rings first)
//   --full-update (eq. (2) instead of the selective eq. (4))  --lost-detector on|off (on)
//   --clearance M (state clearance; default the B21's radius)  --behaviours wander,wall,active
//   --kidnap-deg D (70)  --kidnap-shift M (0)  --settle S (30)  --on-lost uniform|keep
//   --route lab (tracking in cim_office: across the laboratory, past its unmapped partition,
//   crate and drum, to the meeting room and back: the B-12 demo's third task)
//   --judge-short-beams (a detection needs no check without the unexpectedly short beams, as
//   before 2026-12-05)  --short-beams-min-others N (3)
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

#include "amcl_peer.h"
#include "eval_harness.h"
#include "markov_localization/occupancy_map.h"
#include "markov_localization/pose_refinement.h"
#include "spott_map/local_map.h"
#include "spott_map/map_database.h"
#include "spott_map/world_loader.h"

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
  std::string route;  // tracking: "" (the world's) or lab (cim_office)
  bool verbose = false;
  bool calibrate = false;
  bool full_update = false;
  double clearance_m = -1;
  bool on_lost_uniform = true;
  double critical_angle_rad = 0.35;
  bool lost_detector = true;
  std::string picture;
  std::string robot = "b21";
  std::string sensors = "sonar";  // sonar, laser or both
  int laser_beams = 30;
  double laser_max_range_m = 25.0;
  double laser_bin_m = 0.1;
  double laser_sigma_m = 0.15;
  double laser_exponent = 1.0;
  double motion_xy_per_m = -1;  // MotionModelParameters::sigma_xy_per_m (core default 0.1)
  double refine_cells = -1;     // PoseRefinementParameters::max_offset_cells (0: off)
  double update_min_d_m = -1;   // the node's default (MotionGateParameters) when not given
  double update_min_a_deg = -1;
  double standing_interval_s = -1;
  std::string map_file;
  int subdivision = 5;
  std::string peer;  // "" or amcl
  std::string out;   // export-map: the YAML to write
  double export_resolution_m = 0.05;
  ml::LostDetectorParameters lost;
  double distance_filter_max_fraction = -1;   // < 0: the core's default
  double distance_filter_confirm_ratio = -1;  // < 0: the core's default
};

std::string LoadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

// export-map: the world's CAD map (walls, closed doors) as map_server writes it.
int ExportMap(const Options& o) {
  if (o.world.empty() || o.out.empty()) {
    std::cerr << "export-map needs --world FILE and --out MAP.yaml\n";
    return 2;
  }
  auto loaded = spott_map::LoadWorldFile(o.world);
  if (!loaded.ok()) {
    std::cerr << spott_map::FormatErrors(loaded.errors) << "\n";
    return 1;
  }
  const spott_map::World& w = *loaded.world;
  const double res = o.export_resolution_m;
  const spott_map::Box b = w.Bounds().Inflated(0.5);
  spott_map::OccupancyRaster raster(
      Vec2(std::floor(b.min.x() / res) * res, std::floor(b.min.y() / res) * res),
      static_cast<int>(std::ceil((b.max.x() - b.min.x()) / res)) + 1,
      static_cast<int>(std::ceil((b.max.y() - b.min.y()) / res)) + 1, res);
  spott_map::RasterizeDatabase(spott_map::MapDatabase::FromWorld(w), 0.0, 0.05, raster);
  ml::OccupancyMap map;
  map.origin = raster.origin();
  map.resolution_m = res;
  map.width = raster.width();
  map.height = raster.height();
  map.data.resize(static_cast<std::size_t>(map.width) * map.height);
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      const bool obstacle = raster.at(i, j) == spott_map::Cell::kObstacle;
      const bool inside = w.RoomContaining(raster.CellCentre(i, j)) != nullptr;
      map.data[static_cast<std::size_t>(j) * map.width + i] = obstacle ? 100 : inside ? 0 : -1;
    }
  std::string name = o.out.substr(o.out.find_last_of('/') + 1);
  name = name.substr(0, name.rfind('.')) + ".pgm";
  std::string error;
  if (!ml::WriteMapServerMap(map, o.out, name, &error)) {
    std::cerr << error << "\n";
    return 1;
  }
  std::printf("wrote %s and %s: %d x %d cells of %.3f m, origin (%.3f, %.3f)\n", o.out.c_str(),
              name.c_str(), map.width, map.height, res, map.origin.x(), map.origin.y());
  return 0;
}

int Usage(const char* argv0) {
  std::cerr << "usage: " << argv0
            << " tracking|global|fig2|symmetric|kidnap [--runs N] [--seed S] [--resolution M]"
               " [--heading-bins K] [--sigma-hit M] [--time-limit S]"
               " [--behaviours wander,wall,active] [--kidnap-deg D] [--kidnap-shift M]"
               " [--settle S] [--world FILE] [--calibrate] [--full-update] [--clearance M] "
               "[--on-lost uniform|keep] [--critical-angle RAD] [--lost-detector on|off] "
               "[--lost-ratio R] [--scan-lost-ratio R] [--certainty-drop-ratio R] "
               "[--judge-short-beams] [--short-beams-min-others N] "
               "[--distance-filter-max-fraction F] [--distance-filter-confirm-ratio R] [--picture "
               "OUT.png] [--verbose]\n";
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
  std::printf(
      "# markov_localization_eval %s: world %s, robot %s, localizing on %s\n", o.scenario.c_str(),
      world_file.c_str(), o.robot.c_str(),
      o.map_file.empty() ? "the world's CAD map" : ("map_server map " + o.map_file).c_str());
  if (m.sonar_sensor >= 0)
    std::printf("# sonar: %zu beams, max %.1f m\n", m.ring->mounts.size(), m.ring->max_range);
  if (m.laser_sensor >= 0)
    std::printf(
        "# laser: %zu of %d beams (AMCL's laser_max_beams %d), model max range %.1f m, bins %.2f "
        "m, sigma_hit %.2f m, single ray from the mount (%.2f, %.2f)\n",
        m.laser_beams.size(), m.robot.laser->beams, o.laser_beams, m.laser_params.max_range_m,
        m.laser_params.range_bin_m, m.laser_params.sigma_hit_m, m.robot.laser->mount.x,
        m.robot.laser->mount.y);
  std::printf(
      "# motion gate: update_min_d %.2f m, update_min_a %.1f deg, standing interval %.1f s; ray "
      "cast subdivision %d; lost detector lost_ratio %.2f scan_lost_ratio %.2f "
      "certainty_drop_ratio %.2f rates %.2f / %.3f hold %d, %s; distance "
      "filter max fraction %.2f, confirm ratio %.2f\n",
      m.settings.gate.update_min_d_m, m.settings.gate.update_min_a_rad / kDeg,
      m.settings.gate.standing_interval_s, m.settings.ray_cast_subdivision,
      m.grid_params.lost.lost_ratio, m.grid_params.lost.scan_lost_ratio,
      m.grid_params.lost.certainty_drop_ratio, m.grid_params.lost.fast_rate,
      m.grid_params.lost.slow_rate, m.grid_params.lost.hold_scans,
      m.grid_params.lost.judge_without_short_beams ? "detections checked without short beams"
                                                   : "short beams judged",
      m.grid_params.distance_filter_max_fraction, m.grid_params.distance_filter_confirm_ratio);
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

/// A tracking route: the true start and map-frame waypoints (steered on the ground truth: the
/// route is the experiment, not the localization's).
struct Route {
  Pose2 start;
  std::vector<Vec2> waypoints;
};

Route RouteOf(const std::string& world_name, const std::string& name) {
  if (world_name == "cim_office" && name == "lab")  // where "go in room(lab)" ends, then west
    return {{25.0, 10.8, 150.0 * kDeg},
            {{22.5, 12.3},
             {19.0, 12.5},
             {16.0, 13.0},
             {14.0, 15.5},
             {10.8, 17.5},
             {8.0, 18.3},
             {10.8, 17.5},
             {14.0, 15.5},
             {19.0, 15.2},
             {23.0, 15.0},
             {25.0, 11.0}}};
  if (world_name == "cim_office")  // the demo's legs: the hallway, office 106, the lab bench
    return {{1.2, 8.25, 0.0},
            {{29.2, 7.8},
             {26.0, 8.25},
             {26.0, 6.2},
             {27.5, 3.0},
             {26.0, 6.2},
             {26.0, 8.25},
             {25.0, 8.6},
             {25.0, 10.4},
             {26.0, 16.5}}};
  if (world_name == "hilare_room")  // the demo's legs: wall_follow_start, zone_exit, corridor
    return {{0.8, 5.2, 0.0}, {{6.0, 2.5}, {3.6, 3.2}, {6.5, 1.2}, {9.25, 1.2}, {9.25, 7.0}}};
  if (world_name == "crossing_corridors")  // both hallways end to end, one office
    return {{1.5, 16.0, 0.0},
            {{40.5, 16.0},
             {21.0, 16.0},
             {21.0, 30.5},
             {21.0, 7.0},
             {24.5, 7.0},
             {21.0, 7.0},
             {21.0, 1.5},
             {21.0, 16.0},
             {1.5, 16.0}}};
  // bonn_department: corridor east -> room B -> corridor -> room A -> corridor west.
  return {{24.0, 10.0, M_PI},
          {{17.5, 10.0},
           {17.5, 8.2},
           {17.5, 5.0},
           {17.5, 8.2},
           {17.5, 10.0},
           {12.5, 10.0},
           {12.5, 11.8},
           {14.0, 13.5},
           {12.5, 11.8},
           {12.5, 10.0},
           {3.0, 10.0}}};
}

/// Errors of a published estimate along a run.
struct ErrorStats {
  double sum_pos = 0, max_pos = 0, sum_yaw = 0, max_yaw = 0;
  int n = 0, over_half_m = 0, over_20cm = 0;
  void Add(const Pose2& estimate, const Pose2& truth) {
    const double p = (estimate.Position() - truth.Position()).norm();
    const double y = std::abs(spott_map::NormalizeAngle(estimate.yaw - truth.yaw));
    sum_pos += p, max_pos = std::max(max_pos, p), sum_yaw += y, max_yaw = std::max(max_yaw, y);
    over_half_m += p > 0.5, over_20cm += p > 0.2;
    ++n;
  }
  void Merge(const ErrorStats& o) {
    sum_pos += o.sum_pos, sum_yaw += o.sum_yaw, n += o.n, over_half_m += o.over_half_m;
    over_20cm += o.over_20cm, max_pos = std::max(max_pos, o.max_pos);
    max_yaw = std::max(max_yaw, o.max_yaw);
  }
  double mean_cm() const { return n ? 100 * sum_pos / n : 0.0; }
  double mean_deg() const { return n ? sum_yaw / n / kDeg : 0.0; }
};

std::unique_ptr<ev::PeerFilter> MakePeer(const Options& o, const ev::Models& m, std::uint64_t seed);

int Tracking(const Options& o, const ev::Models& m) {
  if (!o.route.empty() && !(o.route == "lab" && m.world.name == "cim_office")) {
    std::fprintf(stderr, "tracking: no route '%s' in %s (cim_office has 'lab')\n", o.route.c_str(),
                 m.world.name.c_str());
    return 2;
  }
  Route route = RouteOf(m.world.name, o.route);
  // Legs of at most 4 m: each leg is steered on odometry from the true pose at its start, and
  // over 38 m of hallway the odometry's heading drift took the robot into a wall (where no
  // state of the belief is: a misfit the localization is not to blame for).
  {
    std::vector<Vec2> dense;
    Vec2 from = route.start.Position();
    for (const Vec2& w : route.waypoints) {
      const int n = std::max(1, static_cast<int>(std::ceil((w - from).norm() / 4.0)));
      for (int i = 1; i <= n; ++i)
        dense.push_back(from + (w - from) * (static_cast<double>(i) / n));
      from = w;
    }
    route.waypoints = dense;
  }
  std::printf(
      "# route in %s from (%.2f, %.2f, %.0f deg) through %zu waypoints; errors of the published "
      "estimate (map -> odom x odometry, as the node publishes it) at every scan (%.0f Hz)\n",
      m.world.name.c_str(), route.start.x, route.start.y, route.start.yaw / kDeg,
      route.waypoints.size(), m.settings.sonar_hz);
  std::printf(
      "| run | seed | route | distance (m) | time (s) | mean / max pos error (cm) | mean / max "
      "heading error (deg) | scans > 20 cm / > 0.5 m | min certainty | updates | CPU per update "
      "(ms) | CPU per s of route (ms) | lost alarms "
      "|%s\n|---|---|---|---|---|---|---|---|---|---|---"
      "|---|---|%s\n",
      o.peer.empty() ? ""
                     : " peer mean / max (cm) | peer mean / max (deg) | peer > 0.5 m | peer "
                       "CPU per s (ms) |",
      o.peer.empty() ? "" : "---|---|---|---|");
  ErrorStats all, all_peer;
  double cpu_ms = 0, peer_cpu_ms = 0, route_s = 0;
  int updates = 0, alarms_all = 0;
  std::vector<double> update_ms;
  for (int run = 0; run < o.runs; ++run) {
    const std::uint64_t seed = o.seed + run;
    ev::Episode e(m, route.start, seed, /*known_start=*/true);
    if (!o.peer.empty()) {
      e.SetPeer(MakePeer(o, m, seed));
      e.peer()->SetGaussian(route.start, 0.1, 3.0 * kDeg);  // the grid's start (Episode)
    }
    ev::GoTo go;
    ErrorStats err, peer_err;
    double min_cert = 1;
    int alarms = 0;
    std::size_t leg = 0;
    bool started = false;
    while (e.time() < o.time_limit_s && leg < route.waypoints.size()) {
      if (!started || go.done()) {
        if (started) ++leg;
        if (leg >= route.waypoints.size()) break;
        go.Set({ev::MapToOdom(e.truth(), e.odom(), route.waypoints[leg])}, e.time(), 120.0);
        started = true;
      }
      e.Tick(go.Command(e));
      const auto& s = e.status();
      err.Add(s.estimate, e.truth());
      if (e.peer()) peer_err.Add(e.peer()->Estimate(e.odom()), e.truth());
      min_cert = std::min(min_cert, s.certainty);
      if (std::getenv("ML_TRACE") && s.updated) {
        const auto& c = e.localizer().summary().certainty;
        const Pose2& t = e.truth();
        const double ct = std::cos(t.yaw), st = std::sin(t.yaw);
        const double ex = s.estimate.x - t.x, ey = s.estimate.y - t.y;
        std::fprintf(stderr,
                     "T %.1f truth %.3f %.3f %.1f est %.3f %.3f %.1f along %+.3f across %+.3f "
                     "max %.3f %.3f %.1f cert %.2f modes %zu\n",
                     e.time(), t.x, t.y, t.yaw / kDeg, s.estimate.x, s.estimate.y,
                     s.estimate.yaw / kDeg, ct * ex + st * ey, -st * ex + ct * ey, c.maximum.x,
                     c.maximum.y, c.maximum.yaw / kDeg, c.certainty,
                     e.localizer().summary().modes.size());
      }
      if (s.lost_detector) {
        ++alarms;
        if (o.verbose)
          std::fprintf(stderr, "  run %d t %.1f lost: %s (truth %.2f %.2f, error %.2f m)\n",
                       run + 1, e.time(), s.lost_reason.c_str(), e.truth().x, e.truth().y,
                       s.pos_error);
      }
      if (s.updated) update_ms.push_back(s.update_ms);
    }
    all.Merge(err);
    all_peer.Merge(peer_err);
    cpu_ms += e.cpu_ms();
    peer_cpu_ms += e.peer_cpu_ms();
    route_s += e.time();
    updates += e.updates();
    alarms_all += alarms;
    std::printf(
        "| %d | %llu | %s | %.1f | %.1f | %.1f / %.1f | %.2f / %.2f | %d / %d | %.2f | %d | %.2f | "
        "%.1f | %d |",
        run + 1, static_cast<unsigned long long>(seed),
        leg >= route.waypoints.size() ? "completed" : "not completed", e.distance(), e.time(),
        err.mean_cm(), 100 * err.max_pos, err.mean_deg(), err.max_yaw / kDeg, err.over_20cm,
        err.over_half_m, min_cert, e.updates(), e.cpu_ms() / std::max(1, e.updates()),
        e.cpu_ms() / std::max(1e-9, e.time()), alarms);
    if (e.peer())
      std::printf(" %.1f / %.1f | %.2f / %.2f | %d | %.1f |", peer_err.mean_cm(),
                  100 * peer_err.max_pos, peer_err.mean_deg(), peer_err.max_yaw / kDeg,
                  peer_err.over_half_m, e.peer_cpu_ms() / std::max(1e-9, e.time()));
    std::printf("\n");
    std::fflush(stdout);
  }
  std::sort(update_ms.begin(), update_ms.end());
  std::printf(
      "\nall runs: mean error %.1f cm / %.2f deg, max %.1f cm / %.2f deg, %d of %d scans over "
      "0.5 m (%d over 20 cm); %d lost alarms; %d updates, CPU per update %.2f ms (median %.2f, "
      "99th percentile %.2f), CPU per second of route %.1f ms\n",
      all.mean_cm(), all.mean_deg(), 100 * all.max_pos, all.max_yaw / kDeg, all.over_half_m, all.n,
      all.over_20cm, alarms_all, updates, cpu_ms / std::max(1, updates),
      update_ms.empty() ? 0.0 : update_ms[update_ms.size() / 2],
      update_ms.empty() ? 0.0 : update_ms[update_ms.size() * 99 / 100],
      cpu_ms / std::max(1e-9, route_s));
  if (!o.peer.empty())
    std::printf(
        "peer %s: mean error %.1f cm / %.2f deg, max %.1f cm / %.2f deg, %d scans over 0.5 m; CPU "
        "per second of route %.1f ms (grid / peer CPU: %.2f)\n",
        o.peer.c_str(), all_peer.mean_cm(), all_peer.mean_deg(), 100 * all_peer.max_pos,
        all_peer.max_yaw / kDeg, all_peer.over_half_m, peer_cpu_ms / std::max(1e-9, route_s),
        cpu_ms / std::max(1e-9, peer_cpu_ms));
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
        if (o.on_lost_uniform) e.localizer().SetUniform();
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

std::unique_ptr<ev::PeerFilter> MakePeer(const Options& o, const ev::Models& m,
                                         std::uint64_t seed) {
  (void)o;
  ev::AmclParameters p;
  p.update_min_d_m = m.settings.gate.update_min_d_m;
  p.update_min_a_rad = m.settings.gate.update_min_a_rad;
  return std::make_unique<ev::AmclPeer>(m.map, m.laser_sensor >= 0 ? &m.laser_params : nullptr,
                                        m.sonar_sensor >= 0 ? &m.sensor_params : nullptr, p, seed);
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
      else if (a == "--route")
        o.route = next();
      else if (a == "--picture")
        o.picture = next();
      else if (a == "--robot")
        o.robot = next();
      else if (a == "--sensors")
        o.sensors = next();
      else if (a == "--laser-beams")
        o.laser_beams = std::stoi(next());
      else if (a == "--laser-max-range")
        o.laser_max_range_m = std::stod(next());
      else if (a == "--laser-bin")
        o.laser_bin_m = std::stod(next());
      else if (a == "--laser-sigma")
        o.laser_sigma_m = std::stod(next());
      else if (a == "--laser-exponent")
        o.laser_exponent = std::stod(next());
      else if (a == "--motion-xy-per-m")
        o.motion_xy_per_m = std::stod(next());
      else if (a == "--refine-cells")
        o.refine_cells = std::stod(next());
      else if (a == "--update-min-d")
        o.update_min_d_m = std::stod(next());
      else if (a == "--update-min-a-deg")
        o.update_min_a_deg = std::stod(next());
      else if (a == "--standing-interval")
        o.standing_interval_s = std::stod(next());
      else if (a == "--map-file")
        o.map_file = next();
      else if (a == "--subdivision")
        o.subdivision = std::stoi(next());
      else if (a == "--peer")
        o.peer = next();
      else if (a == "--out")
        o.out = next();
      else if (a == "--export-resolution")
        o.export_resolution_m = std::stod(next());
      else if (a == "--lost-ratio")
        o.lost.lost_ratio = std::stod(next());
      else if (a == "--scan-lost-ratio")
        o.lost.scan_lost_ratio = std::stod(next());
      else if (a == "--certainty-drop-ratio")
        o.lost.certainty_drop_ratio = std::stod(next());
      else if (a == "--judge-short-beams")  // the lost detector sees them
        o.lost.judge_without_short_beams = false;
      else if (a == "--short-beams-min-others")
        o.lost.short_beams_min_others = std::stoi(next());
      else if (a == "--distance-filter-max-fraction")
        o.distance_filter_max_fraction = std::stod(next());
      else if (a == "--distance-filter-confirm-ratio")
        o.distance_filter_confirm_ratio = std::stod(next());
      else if (a == "--fast-rate")
        o.lost.fast_rate = std::stod(next());
      else if (a == "--slow-rate")
        o.lost.slow_rate = std::stod(next());
      else if (a == "--hold-scans")
        o.lost.hold_scans = std::stoi(next());
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
  if (o.scenario == "export-map") return ExportMap(o);
  if (o.scenario == "probe") {
    ev::Settings s;
    s.robot_dir = ROBOT_SIM_DIR;
    s.use_laser = true;
    s.use_sonar = o.sensors != "laser";
    s.resolution_m = 0.15;
    s.heading_bins = 180;
    s.sigma_hit_m = 0.15;
    s.laser_max_range_m = o.laser_max_range_m;
    s.laser_max_beams = o.laser_beams;
    auto m = ev::Models::Load(std::string(WORLDS_DIR) + "/bonn_department.yaml", s);
    const Pose2 truth{17.494, 6.98, -M_PI / 2};
    ev::Episode e(*m, truth, 1, true);
    e.Tick({0, 0});
    std::vector<ml::SensorReading> r;
    r.push_back({m->loc_models->sensors[m->laser_sensor].get(), &e.laser()});
    for (double dx = -0.2; dx <= 0.2001; dx += 0.02) {
      std::printf(
          "dx %+.2f LL %.2f  dy %+.2f LL %.2f  dyaw %+.1f LL %.2f\n", dx,
          ml::ScanLogLikelihood(m->map, r, Pose2{truth.x + dx, truth.y, truth.yaw}, 0.33), dx,
          ml::ScanLogLikelihood(m->map, r, Pose2{truth.x, truth.y + dx, truth.yaw}, 0.33), dx * 10,
          ml::ScanLogLikelihood(m->map, r, Pose2{truth.x, truth.y, truth.yaw + dx * 10 * kDeg},
                                0.33));
    }
    for (int b = 0; b < static_cast<int>(e.laser().size()); b += 3)
      std::printf("beam %d angle %.1f z %.3f expected %.3f\n", b,
                  m->laser_params.beam_angles_rad[b] / kDeg, e.laser()[b],
                  m->loc_models->sensors[m->laser_sensor]->ExpectedRange(m->map, truth, b));
    return 0;
  }
  if (o.scenario != "tracking" && o.scenario != "global" && o.scenario != "fig2" &&
      o.scenario != "symmetric" && o.scenario != "kidnap")
    return Usage(argv[0]);
  if (o.sensors != "sonar" && o.sensors != "laser" && o.sensors != "both") {
    std::cerr << "--sensors must be sonar, laser or both\n";
    return 2;
  }
  if (!o.peer.empty() && o.peer != "amcl") {
    std::cerr << "--peer must be amcl\n";
    return 2;
  }
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
  s.robot_name = o.robot;
  s.use_sonar = o.sensors != "laser";
  s.use_laser = o.sensors != "sonar";
  s.laser_max_beams = o.laser_beams;
  s.laser_max_range_m = o.laser_max_range_m;
  s.laser_range_bin_m = o.laser_bin_m;
  s.laser_sigma_hit_m = o.laser_sigma_m;
  s.laser_exponent = o.laser_exponent;
  s.motion_xy_per_m = o.motion_xy_per_m;
  s.refine_cells = o.refine_cells;
  if (o.update_min_d_m >= 0) s.gate.update_min_d_m = o.update_min_d_m;
  if (o.update_min_a_deg >= 0) s.gate.update_min_a_rad = o.update_min_a_deg * kDeg;
  if (o.standing_interval_s >= 0) s.gate.standing_interval_s = o.standing_interval_s;
  s.map_file = o.map_file;
  s.ray_cast_subdivision = o.subdivision;
  s.lost = o.lost;
  s.distance_filter_max_fraction = o.distance_filter_max_fraction;
  s.distance_filter_confirm_ratio = o.distance_filter_confirm_ratio;
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
