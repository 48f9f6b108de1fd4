#include "eval_harness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>

#include <ctime>

#include "spott_map/world_loader.h"

namespace markov_localization {
namespace eval {

double Elapsed(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

Vec2 Compose(const Pose2& pose, const Vec2& rel) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return Vec2(pose.x + c * rel.x() - s * rel.y(), pose.y + s * rel.x() + c * rel.y());
}

Vec2 MapToOdom(const Pose2& estimate, const Pose2& odom, const Vec2& p) {
  // Relative to the robot in the map, then placed relative to the robot in odom.
  const double c = std::cos(estimate.yaw), s = std::sin(estimate.yaw);
  const Vec2 d = p - estimate.Position();
  const Vec2 rel(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  return Compose(odom, rel);
}

double ProcessCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

std::unique_ptr<Models> Models::Load(const std::string& world_file, const Settings& settings) {
  const auto start = std::chrono::steady_clock::now();
  auto loaded = spott_map::LoadWorldFile(world_file);
  if (!loaded.ok()) throw std::runtime_error(spott_map::FormatErrors(loaded.errors));
  const std::string rdir = settings.robot_dir;
  auto robot = robot_sim::LoadRobotSpec(rdir + "/config/robots/" + settings.robot_name + ".yaml",
                                        rdir + "/urdf/" + settings.robot_name + ".urdf");
  if (!robot.ok()) throw std::runtime_error(spott_map::FormatErrors(robot.errors));

  MapModelParameters mp;
  mp.resolution_m = settings.resolution_m;
  mp.ray_cast_subdivision = settings.ray_cast_subdivision;  // as the node
  mp.state_clearance_m =
      settings.state_clearance_m >= 0 ? settings.state_clearance_m : robot.spec->radius_m;
  std::shared_ptr<const MapModel> map;
  if (settings.map_file.empty()) {
    map = std::make_shared<const MapModel>(MapModel::FromWorld(*loaded.world, mp));
  } else {
    const MapFileResult file = LoadMapServerMap(settings.map_file);
    if (!file.ok()) throw std::runtime_error(spott_map::FormatErrors(file.errors));
    map = std::make_shared<const MapModel>(MapModel::FromOccupancy(*file.map, mp));
  }
  auto m = std::make_unique<Models>(std::move(map));
  m->settings = settings;
  m->settings.state_clearance_m = mp.state_clearance_m;
  m->world = *loaded.world;
  m->robot = *robot.spec;
  if (!settings.use_laser) m->robot.laser.reset();  // sonars only, as in the paper
  if (settings.use_laser && !m->robot.laser)
    throw std::runtime_error("robot " + settings.robot_name + " has no laser");
  m->ring = m->robot.FindRing("sonar");
  if (!m->ring) throw std::runtime_error(settings.robot_name + " has no ring 'sonar'");

  // The node's construction from the ring (markov_localization_node.cpp): beam axes and mean
  // offset from the mounts, max range from the ring, the cone from its field of view,
  // specular beyond 0.35 rad.
  double offset = 0.0;
  for (const auto& mount : m->ring->mounts) {
    m->sensor_params.beam_angles_rad.push_back(mount.yaw);
    m->sensor_params.beam_origins_m.push_back(Vec2(mount.x, mount.y));
    offset += std::hypot(mount.x, mount.y);
  }
  m->sensor_params.sensor_offset_m = offset / m->ring->mounts.size();
  m->sensor_params.max_range_m = m->ring->max_range;
  m->sensor_params.beam_width_rad = m->ring->field_of_view;
  m->sensor_params.critical_angle_rad = settings.critical_angle_rad;
  m->sensor_params.sigma_hit_m = settings.sigma_hit_m;
  std::vector<SensorModelParameters> sensors;
  if (settings.use_sonar) {
    m->sonar_sensor = static_cast<int>(sensors.size());
    sensors.push_back(m->sensor_params);
  }
  if (settings.use_laser) {
    // The node's laser model: AMCL's beam subsampling, beams from the laser's mount.
    const auto& l = *m->robot.laser;
    const int n = l.beams;
    const int max_beams = std::max(2, settings.laser_max_beams);
    const int step = std::max(1, (n - 1) / (max_beams - 1));
    const double inc = (l.angle_max - l.angle_min) / (n - 1);
    auto& lp = m->laser_params;
    for (int i = 0; i < n; i += step) {
      m->laser_beams.push_back(i);
      lp.beam_angles_rad.push_back(l.mount.yaw + l.angle_min + i * inc);
      lp.beam_origins_m.push_back(Vec2(l.mount.x, l.mount.y));
    }
    lp.sensor_offset_m = 0.0;
    lp.max_range_m = std::min(settings.laser_max_range_m, l.max_range);
    lp.range_bin_m = settings.laser_range_bin_m;
    lp.sigma_hit_m = settings.laser_sigma_hit_m;
    lp.likelihood_exponent = settings.laser_exponent;
    lp.beam_width_rad = 0.0;
    lp.critical_angle_rad = M_PI / 2;
    m->laser_sensor = static_cast<int>(sensors.size());
    sensors.push_back(lp);
  }
  if (sensors.empty()) throw std::runtime_error("no sensor to localize on");
  m->loc_models = LocalizationModels::Build(m->map_ptr, sensors, settings.heading_bins);
  m->sensor = m->loc_models->sensors[0].get();
  if (settings.calibrate) {
    if (!settings.use_sonar) throw std::runtime_error("--calibrate fits the sonar model");
    m->sensor_params = CalibrateSensorModel(*m, settings.calibration_poses,
                                            settings.calibration_seed, &m->calibration_report);
    sensors[m->sonar_sensor] = m->sensor_params;
    m->loc_models = LocalizationModels::Build(m->map_ptr, sensors, settings.heading_bins);
    m->sensor = m->loc_models->sensors[0].get();
  }
  m->grid_params.angular_resolution_rad = 2.0 * M_PI / settings.heading_bins;
  m->grid_params.selective_update = settings.selective_update;
  m->grid_params.lost = settings.lost;
  m->grid_params.lost.enabled = settings.lost_detector;
  if (settings.distance_filter_max_fraction >= 0)
    m->grid_params.distance_filter_max_fraction = settings.distance_filter_max_fraction;
  if (settings.distance_filter_confirm_ratio >= 0)
    m->grid_params.distance_filter_confirm_ratio = settings.distance_filter_confirm_ratio;
  if (settings.motion_xy_per_m >= 0)
    m->grid_params.motion.sigma_xy_per_m = settings.motion_xy_per_m;
  m->certainty.threshold = settings.certain;
  m->loc_params.grid = m->grid_params;
  m->loc_params.gate = settings.gate;
  m->loc_params.certainty = m->certainty;
  m->loc_params.modes = m->modes;
  m->loc_params.sticky.match_rad = 30.0 * M_PI / 180.0;  // the node's estimate/match_deg
  if (settings.refine_cells == 0) m->loc_params.refine.enabled = false;
  if (settings.refine_cells > 0) m->loc_params.refine.max_offset_cells = settings.refine_cells;
  m->active = std::make_unique<ActiveLocalizer>(m->map, *m->sensor, ActiveLocalizationParameters{});
  m->build_seconds = Elapsed(start);
  return m;
}

namespace {

// The model's components for expected bin e, as in SensorModel's table: each normalized over
// the bins. c[0] hit, c[1] short, c[2] max, c[3] rand.
std::vector<std::array<double, 4>> Components(int num_bins, double bw, double sigma, double lambda,
                                              int e) {
  const int max_bin = num_bins - 1;
  std::vector<std::array<double, 4>> c(num_bins);
  double hit_sum = 0, short_sum = 0;
  const double expected_m = e * bw;
  for (int z = 0; z < num_bins; ++z) {
    const double lo = z == 0 ? -1e9 : (z - 0.5) * bw;
    const double hi = z == max_bin ? 1e9 : (z + 0.5) * bw;
    auto cdf = [&](double x) {
      return 0.5 * std::erfc(-(x - expected_m) / (sigma * std::sqrt(2.0)));
    };
    c[z][0] = cdf(hi) - cdf(lo);
    hit_sum += c[z][0];
    c[z][1] = 0;
    if (z < e) {
      const double a = std::max(0.0, lo), b = std::min(hi, expected_m);
      c[z][1] = std::exp(-lambda * a) - std::exp(-lambda * b);
      short_sum += c[z][1];
    }
    c[z][2] = z == max_bin ? 1.0 : 0.0;
    c[z][3] = 1.0 / num_bins;
  }
  for (int z = 0; z < num_bins; ++z) {
    c[z][0] = hit_sum > 0 ? c[z][0] / hit_sum : 0.0;
    if (short_sum > 0)
      c[z][1] /= short_sum;
    else
      c[z][1] = z == e ? 1.0 : 0.0;
  }
  return c;
}

}  // namespace

SensorModelParameters CalibrateSensorModel(const Models& m, int poses, std::uint64_t seed,
                                           std::string* report) {
  const SensorModel& model = *m.sensor;
  const int nb = model.num_bins();
  // Counts of (expected bin, reading bin).
  std::vector<double> counts(static_cast<std::size_t>(nb) * nb, 0.0);
  std::vector<std::pair<int, int>> cells;
  for (int iy = 0; iy < m.map.height(); ++iy)
    for (int ix = 0; ix < m.map.width(); ++ix)
      if (m.map.IsState(ix, iy)) cells.emplace_back(ix, iy);
  Rng rng(seed);
  robot_sim::SimWorldParameters wp;
  wp.octomap_resolution_m = 0.2;
  auto world = std::make_unique<robot_sim::SimWorld>(wp);
  world->Build(m.world);
  robot_sim::Simulator sim(std::move(world));
  std::uniform_int_distribution<std::size_t> pick(0, cells.size() - 1);
  std::uniform_real_distribution<double> u(-0.5, 0.5), yaw(-M_PI, M_PI);
  std::optional<int> robot;
  const double res = m.map.resolution();
  const double bin_rad = 2.0 * M_PI / model.num_headings();
  int used = 0;
  for (int attempt = 0; used < poses && attempt < 50 * poses; ++attempt) {
    const auto [ix, iy] = cells[pick(rng)];
    const Vec2 c = m.map.CellCentre(ix, iy);
    const Pose2 pose{c.x() + u(rng) * res, c.y() + u(rng) * res, yaw(rng)};
    std::string error;
    if (!robot) {
      robot = sim.AddRobot(m.robot, pose, robot_sim::OdometryErrorModel{}, &error);
      if (!robot) continue;
    } else if (!sim.Kidnap(*robot, pose, /*relative=*/false, &error)) {
      continue;
    }
    const auto ranges = sim.SenseRing(*robot, *m.ring, rng);
    const int k = static_cast<int>(std::lround(pose.yaw / bin_rad));
    const std::size_t cell = m.map.Index(ix, iy);
    for (int b = 0; b < model.num_beams(); ++b) {
      const int dir = ((k + model.beam_offset(b)) % model.num_headings() + model.num_headings()) %
                      model.num_headings();
      counts[static_cast<std::size_t>(model.ExpectedBin(dir, cell)) * nb +
             model.RangeBin(ranges[b])] += 1.0;
    }
    ++used;
  }
  const SensorModelParameters defaults = m.sensor_params;
  const double lambda = defaults.lambda_short_per_m;
  auto loglik = [&](double sigma, const std::array<double, 4>& w) {
    double ll = 0, n = 0;
    for (int e = 0; e < nb; ++e) {
      const auto c = Components(nb, defaults.range_bin_m, sigma, lambda, e);
      for (int z = 0; z < nb; ++z) {
        const double k = counts[static_cast<std::size_t>(e) * nb + z];
        if (k == 0) continue;
        double p = 0;
        for (int j = 0; j < 4; ++j) p += w[j] * c[z][j];
        ll += k * std::log(std::max(p, 1e-300));
        n += k;
      }
    }
    return ll / std::max(n, 1.0);
  };
  double best_ll = -1e300, best_sigma = defaults.sigma_hit_m;
  std::array<double, 4> best_w{defaults.z_hit, defaults.z_short, defaults.z_max, defaults.z_rand};
  for (double sigma = 0.1; sigma <= 0.6001; sigma += 0.05) {
    std::vector<std::vector<std::array<double, 4>>> comp;
    for (int e = 0; e < nb; ++e)
      comp.push_back(Components(nb, defaults.range_bin_m, sigma, lambda, e));
    std::array<double, 4> w{0.25, 0.25, 0.25, 0.25};
    for (int it = 0; it < 200; ++it) {  // EM on the mixture weights
      std::array<double, 4> acc{0, 0, 0, 0};
      double n = 0;
      for (int e = 0; e < nb; ++e)
        for (int z = 0; z < nb; ++z) {
          const double k = counts[static_cast<std::size_t>(e) * nb + z];
          if (k == 0) continue;
          double p = 0;
          for (int j = 0; j < 4; ++j) p += w[j] * comp[e][z][j];
          if (!(p > 0)) continue;
          for (int j = 0; j < 4; ++j) acc[j] += k * w[j] * comp[e][z][j] / p;
          n += k;
        }
      for (int j = 0; j < 4; ++j) w[j] = acc[j] / n;
    }
    const double ll = loglik(sigma, w);
    if (ll > best_ll) best_ll = ll, best_sigma = sigma, best_w = w;
  }
  SensorModelParameters out = defaults;
  out.sigma_hit_m = best_sigma;
  // Keep every weight positive and the sum exactly 1 (ValidateParameters).
  for (double& w : best_w) w = std::max(w, 1e-3);
  const double sum = best_w[0] + best_w[1] + best_w[2] + best_w[3];
  out.z_hit = best_w[0] / sum;
  out.z_short = best_w[1] / sum;
  out.z_max = best_w[2] / sum;
  out.z_rand = 1.0 - out.z_hit - out.z_short - out.z_max;
  if (report) {
    double max_frac = 0, total = 0, expect_echo = 0, max_when_echo = 0;
    for (int e = 0; e < nb; ++e)
      for (int z = 0; z < nb; ++z) {
        const double k = counts[static_cast<std::size_t>(e) * nb + z];
        total += k;
        if (z == nb - 1) max_frac += k;
        if (e < nb - 1) {
          expect_echo += k;
          if (z == nb - 1) max_when_echo += k;
        }
      }
    char buf[512];
    std::snprintf(
        buf, sizeof buf,
        "sensor model fitted to %d simulated rings (%.0f readings; %.0f%% no echo, %.0f%% "
        "no echo where the map predicts one): sigma_hit %.2f m, z_hit %.3f, z_short "
        "%.3f, z_max %.3f, z_rand %.3f; log-likelihood per reading %.3f (core defaults "
        "with sigma_hit %.2f m: %.3f)",
        used, total, 100 * max_frac / std::max(total, 1.0),
        100 * max_when_echo / std::max(expect_echo, 1.0), out.sigma_hit_m, out.z_hit, out.z_short,
        out.z_max, out.z_rand,
        loglik(out.sigma_hit_m, {out.z_hit, out.z_short, out.z_max, out.z_rand}),
        defaults.sigma_hit_m,
        loglik(defaults.sigma_hit_m,
               {defaults.z_hit, defaults.z_short, defaults.z_max, defaults.z_rand}));
    *report = buf;
  }
  return out;
}

std::string Models::RoomAt(const Vec2& p) const {
  for (const auto& r : world.rooms)
    if (spott_map::PointInPolygon(p, r.polygon)) return r.id;
  return "outside";
}

Episode::Episode(const Models& models, const Pose2& start, std::uint64_t seed, bool known_start)
    : models_(models), rng_(seed) {
  robot_sim::SimWorldParameters wp;
  wp.octomap_resolution_m = 0.2;  // the OctoMap is not used by the sonar model; builds faster
  auto world = std::make_unique<robot_sim::SimWorld>(wp);
  world->Build(models.world);
  sim_ = std::make_unique<robot_sim::Simulator>(std::move(world));
  robot_sim::OdometryErrorModel odo;  // robot_sim's config/robot_sim.yaml defaults
  odo.linear_noise = 0.01;
  odo.angular_noise = 0.01;
  odo.angular_noise_per_m = 0.005;
  std::string error;
  const auto r = sim_->AddRobot(models.robot, start, odo, &error);
  if (!r) throw std::runtime_error("start blocked: " + error);
  robot_ = *r;
  localizer_ = std::make_unique<Localizer>(models.loc_models, models.loc_params);
  if (known_start) localizer_->SetGaussian(start, 0.1, 3.0 * M_PI / 180.0);
  ranges_.assign(models.ring->mounts.size(), models.ring->max_range);
  status_.truth = start;
}

void Episode::SetPeer(std::unique_ptr<PeerFilter> peer) { peer_ = std::move(peer); }

const Status& Episode::Tick(const Twist2& cmd) {
  const Settings& s = models_.settings;
  std::string error;
  if (!sim_->SetCommand(robot_, cmd, &error)) throw std::runtime_error("command: " + error);
  const int steps = std::max(1, static_cast<int>(std::lround(s.physics_hz / s.sonar_hz)));
  stalled_ = false;
  bumper_.clear();
  for (int i = 0; i < steps; ++i) {
    const Pose2 before = truth();
    sim_->Step(1.0 / s.physics_hz, rng_);
    distance_ += (truth().Position() - before.Position()).norm();
    stalled_ = stalled_ || sim_->Stalled(robot_);
    const std::vector<bool> pressed = sim_->Bumper(robot_);
    bumper_.resize(pressed.size(), false);
    for (std::size_t k = 0; k < pressed.size(); ++k) bumper_[k] = bumper_[k] || pressed[k];
  }
  ranges_ = sim_->SenseRing(robot_, *models_.ring, rng_);
  if (models_.laser_sensor >= 0) {
    const std::vector<double> full = sim_->SenseLaser(robot_, rng_);
    laser_.clear();
    for (int i : models_.laser_beams) laser_.push_back(full.at(i));
  }
  const double now = sim_->time();
  // The node's pipeline: each reading to the Localizer (motion gate, updates, lost handling).
  const double c0 = ProcessCpuSeconds();
  status_.updated = false;
  status_.lost_detector = false;
  status_.lost_reason.clear();
  auto feed = [&](int sensor, const std::vector<double>& z) {
    if (sensor < 0) return;
    const LocalizerStep step = localizer_->OnReading(sensor, z, odom(), now);
    if (!step.updated) return;
    status_.updated = true;
    status_.states_evaluated = step.stats.states_evaluated;
    status_.groups = step.stats.groups;
    if (step.lost) {
      status_.lost_detector = true;
      status_.lost_reason = step.lost_reason;
    }
  };
  feed(models_.sonar_sensor, ranges_);
  feed(models_.laser_sensor, laser_);
  const double c1 = ProcessCpuSeconds();
  status_.update_ms = 1e3 * (c1 - c0);
  cpu_ms_ += status_.update_ms;
  if (peer_) {
    if (models_.sonar_sensor >= 0) peer_->OnReading(false, ranges_, odom(), now);
    if (models_.laser_sensor >= 0) peer_->OnReading(true, laser_, odom(), now);
    peer_cpu_ms_ += 1e3 * (ProcessCpuSeconds() - c1);
  }
  status_.time = now;
  const auto& c = localizer_->summary().certainty;
  status_.certainty = c.certainty;
  // What the node publishes: the estimate through map -> odom, fixed between updates.
  status_.estimate = localizer_->has_estimate() ? localizer_->Estimate(odom()) : c.estimate;
  status_.truth = truth();
  status_.pos_error = (status_.estimate.Position() - truth().Position()).norm();
  status_.yaw_error = std::abs(spott_map::NormalizeAngle(status_.estimate.yaw - truth().yaw));
  return status_;
}

bool Episode::Success() const {
  const Settings& s = models_.settings;
  return status_.certainty > s.certain && status_.pos_error < s.success_pos_m &&
         status_.yaw_error < s.success_rad;
}

bool Episode::ConfidentlyWrong() const {
  const Settings& s = models_.settings;
  return status_.certainty > s.certain &&
         (status_.pos_error > s.wrong_pos_m || status_.yaw_error > s.wrong_rad);
}

std::vector<Mode> Episode::Modes() const {
  return ExtractModes(BeliefSnapshot::Of(localizer_->grid()), models_.modes);
}

double MinRange(const Models& m, const std::vector<double>& ranges, double from, double to) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double a = spott_map::NormalizeAngle(m.ring->mounts[i].yaw);
    if (a >= from - 1e-6 && a <= to + 1e-6 && std::isfinite(ranges[i]))
      best = std::min(best, ranges[i]);
  }
  return best;
}

bool verbose_trace = false;

namespace {

constexpr double kDeg = M_PI / 180.0;

// Front clearance: the three sonars ahead (0, +-15 degrees) and the two beside them.
double Front(Episode& e) { return MinRange(e.models(), e.ranges(), -31 * kDeg, 31 * kDeg); }

}  // namespace

bool Escape::Step(Episode& e, Twist2* cmd) {
  if (phase_ == 0 && e.stalled()) {
    // Direction of the contact in the robot frame: mean of the pressed bumper segments.
    double cx = 0.0, cy = 0.0;
    const auto& bumper = e.bumper();
    for (std::size_t k = 0; k < bumper.size(); ++k)
      if (bumper[k]) {
        const double a = 2.0 * M_PI * k / bumper.size();
        cx += std::cos(a), cy += std::sin(a);
      }
    double contact = 0.0;
    if (std::hypot(cx, cy) > 1e-6) {
      contact = std::atan2(cy, cx);
    } else {
      std::size_t nearest = 0;
      for (std::size_t i = 1; i < e.ranges().size(); ++i)
        if (e.ranges()[i] < e.ranges()[nearest]) nearest = i;
      contact = e.models().ring->mounts[nearest].yaw;
    }
    target_yaw_ = e.odom().yaw + contact + M_PI;
    phase_ = 1;
  }
  if (phase_ == 1) {
    const double err = spott_map::NormalizeAngle(target_yaw_ - e.odom().yaw);
    if (std::abs(err) > 0.25) {
      *cmd = {0.0, std::copysign(1.0, err)};
      return true;
    }
    phase_ = 2;
    until_ = e.time() + 0.8;
  }
  if (phase_ == 2) {
    if (e.time() < until_ && !e.stalled()) {
      *cmd = {0.2, 0.0};
      return true;
    }
    phase_ = 0;
  }
  return false;
}

Twist2 RandomWander::Command(Episode& e) {
  const double dt = e.tick_seconds();
  const double v = e.models().settings.speed_mps;
  Twist2 esc;
  if (e.stalled()) turn_left_ = 0.0;
  if (escape_.Step(e, &esc)) return esc;
  if (turn_left_ != 0.0) {
    const double w = std::copysign(1.0, turn_left_);
    turn_left_ -= w * dt;
    if (turn_left_ * w <= 0.0) turn_left_ = 0.0;
    if (turn_left_ == 0.0 && Front(e) < 0.9) turn_left_ = w * 0.5;  // keep turning until free
    return {0.0, w};
  }
  if (Front(e) < 0.6) {
    const double left = MinRange(e.models(), e.ranges(), 30 * kDeg, 120 * kDeg);
    const double right = MinRange(e.models(), e.ranges(), -120 * kDeg, -30 * kDeg);
    std::uniform_real_distribution<double> angle(60 * kDeg, 180 * kDeg);
    turn_left_ = (left >= right ? 1.0 : -1.0) * angle(e.rng());
    return {0.0, 0.0};
  }
  return {v, 0.0};
}

Twist2 WallFollow::Command(Episode& e) {
  const double dt = e.tick_seconds();
  const double v = 0.8 * e.models().settings.speed_mps;
  const double side = right_ ? -1.0 : 1.0;  // + = left
  (void)dt;
  Twist2 esc;
  if (escape_.Step(e, &esc)) return esc;
  const double front = Front(e);
  if (front < 0.7) return {0.0, -side * 0.8};  // turn away from the wall side
  const double wall = right_ ? MinRange(e.models(), e.ranges(), -106 * kDeg, -44 * kDeg)
                             : MinRange(e.models(), e.ranges(), 44 * kDeg, 106 * kDeg);
  if (wall > 1.6) return {0.6 * v, side * 0.5};  // wall lost: curve towards its side
  const double err = wall - 0.6;
  const double w = std::clamp(side * 1.5 * err, -0.8, 0.8);
  return {v * (front < 1.2 ? 0.5 : 1.0), w};
}

void GoTo::Set(std::vector<Vec2> odom_waypoints, double now, double timeout_s) {
  wp_ = std::move(odom_waypoints);
  next_ = 0;
  deadline_ = now + timeout_s;
  done_ = wp_.empty();
  timed_out_ = false;
  escape_ = Escape();
  stalls_ = 0;
}

Twist2 GoTo::Command(Episode& e) {
  if (done_) return {};
  if (e.time() > deadline_ || stalls_ > 8) {
    done_ = timed_out_ = true;
    return {};
  }
  if (e.stalled()) ++stalls_;
  Twist2 esc;
  if (escape_.Step(e, &esc)) return esc;
  const Pose2& o = e.odom();
  while (next_ + 1 < wp_.size() && (wp_[next_] - o.Position()).norm() < 0.4) ++next_;
  const Vec2 d = wp_[next_] - o.Position();
  if (next_ + 1 == wp_.size() && d.norm() < 0.25) {
    done_ = true;
    return {};
  }
  const double err = spott_map::NormalizeAngle(std::atan2(d.y(), d.x()) - o.yaw);
  if (std::abs(err) > 0.5) return {0.0, std::clamp(2.0 * err, -1.0, 1.0)};
  double v = std::min(e.models().settings.speed_mps, 0.3 + d.norm());
  double w = std::clamp(1.5 * err, -1.0, 1.0);
  // Obstacle avoidance: slow down near something ahead, and steer away from the nearer side.
  const double front = MinRange(e.models(), e.ranges(), -16 * kDeg, 16 * kDeg);
  if (verbose_trace) {
    std::fprintf(stderr,
                 "      go-to t %.1f truth (%.2f, %.2f, %.0f) wp %zu/%zu front %.2f err %.2f\n",
                 e.time(), e.truth().x, e.truth().y, e.truth().yaw * 180 / M_PI, next_, wp_.size(),
                 front, err);
  }
  if (front < 0.25) {
    v = 0.0;
    const double left = MinRange(e.models(), e.ranges(), 30 * kDeg, 100 * kDeg);
    const double right = MinRange(e.models(), e.ranges(), -100 * kDeg, -30 * kDeg);
    w = left >= right ? 0.6 : -0.6;
  } else if (front < 0.8) {
    v *= (front - 0.25) / 0.55;
    v = std::max(v, 0.1);
  }
  if (v > 0.0) {  // keep off the walls beside the robot
    const double left = MinRange(e.models(), e.ranges(), 40 * kDeg, 95 * kDeg);
    const double right = MinRange(e.models(), e.ranges(), -95 * kDeg, -40 * kDeg);
    if (left < 0.25 && left < right) w -= 2.0 * (0.25 - left) + 0.2;
    if (right < 0.25 && right < left) w += 2.0 * (0.25 - right) + 0.2;
    w = std::clamp(w, -1.0, 1.0);
  }
  return {v, w};
}

Twist2 ActiveDriver::Command(Episode& e) {
  if (e.time() < fallback_until_) return fallback_.Command(e);
  if (!goto_.done()) {
    const Twist2 cmd = goto_.Command(e);
    if (verbose && goto_.done())
      std::fprintf(stderr, "    t %.1f go-to %s at truth (%.2f, %.2f), certainty %.2f\n", e.time(),
                   goto_.timed_out() ? "gave up" : "arrived", e.truth().x, e.truth().y,
                   e.status().certainty);
    if (!goto_.done()) return cmd;
  }
  // Choose a*: the belief's modes, eqs. (6)-(9).
  const auto t0 = std::chrono::steady_clock::now();
  const auto modes = e.Modes();
  const ActiveChoice choice = e.models().active->Choose(modes);
  choose_ms_ += 1e3 * Elapsed(t0);
  ++choices_;
  if (!choice.found || choice.path.size() < 2 || std::hypot(choice.ax, choice.ay) < 0.3) {
    fallback_until_ = e.time() + 3.0;  // nothing worth going to: wander a little
    return fallback_.Command(e);
  }
  targets_true_.push_back(Compose(e.truth(), Vec2(choice.ax, choice.ay)));
  if (verbose)
    std::fprintf(stderr,
                 "    t %.1f choice %d: %zu modes, a* (%.2f ahead, %.2f left) -> %s (%.2f, %.2f) "
                 "E[H] %.2f v %.2f path %zu\n",
                 e.time(), choices_, modes.size(), choice.ax, choice.ay,
                 e.models().RoomAt(targets_true_.back()).c_str(), targets_true_.back().x(),
                 targets_true_.back().y(), choice.expected_entropy, choice.cost,
                 choice.path.size());
  std::vector<Vec2> wp;
  for (const Vec2& p : choice.path) wp.push_back(Compose(e.odom(), p));
  goto_.Set(std::move(wp), e.time(), 60.0);
  return goto_.Command(e);
}

}  // namespace eval
}  // namespace markov_localization
