#include "amcl_peer.h"

#include "markov_localization/sticky_estimate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <tuple>
#include <unordered_map>

namespace markov_localization {
namespace eval {

namespace {
double AngleDiff(double a, double b) { return spott_map::NormalizeAngle(a - b); }

struct BinKey {
  int x, y, t;
  bool operator==(const BinKey& o) const { return x == o.x && y == o.y && t == o.t; }
};
struct BinHash {
  std::size_t operator()(const BinKey& k) const {
    return (static_cast<std::size_t>(k.x) * 73856093u) ^
           (static_cast<std::size_t>(k.y) * 19349663u) ^
           (static_cast<std::size_t>(k.t) * 83492791u);
  }
};
}  // namespace

AmclPeer::AmclPeer(const MapModel& map, const SensorModelParameters* laser,
                   const SensorModelParameters* sonar, const AmclParameters& params,
                   std::uint64_t seed)
    : map_(map), laser_(laser), sonar_(sonar), params_(params), rng_(seed * 2654435761u + 7) {
  // The likelihood field: brushfire from every obstacle cell of the map's fine raster, exact
  // Euclidean distance to the nearest obstacle cell centre, capped at max_occ_dist (AMCL's
  // map_update_cspace).
  fres_ = map.resolution() / map.subdivision();
  fw_ = map.width() * map.subdivision();
  fh_ = map.height() * map.subdivision();
  const float cap = static_cast<float>(params.max_occ_dist_m);
  dist_.assign(static_cast<std::size_t>(fw_) * fh_, cap);
  std::vector<int> src(dist_.size(), -1);
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int fy = 0; fy < fh_; ++fy)
    for (int fx = 0; fx < fw_; ++fx) {
      const Vec2 c = map.origin() + Vec2((fx + 0.5) * fres_, (fy + 0.5) * fres_);
      if (!map.FineOccupiedAt(c)) continue;
      const int i = fy * fw_ + fx;
      dist_[i] = 0.0f;
      src[i] = i;
      queue.push({0.0f, i});
    }
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > dist_[i]) continue;
    const int x = i % fw_, y = i / fw_;
    const int sx = src[i] % fw_, sy = src[i] / fw_;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= fw_ || ny >= fh_) continue;
        const int j = ny * fw_ + nx;
        const float nd = static_cast<float>(fres_ * std::hypot(nx - sx, ny - sy));
        if (nd < dist_[j] && nd <= cap) {
          dist_[j] = nd;
          src[j] = src[i];
          queue.push({nd, j});
        }
      }
  }
}

double AmclPeer::Distance(double x, double y) const {
  const int fx = static_cast<int>(std::floor((x - map_.origin().x()) / fres_));
  const int fy = static_cast<int>(std::floor((y - map_.origin().y()) / fres_));
  if (fx < 0 || fy < 0 || fx >= fw_ || fy >= fh_) return params_.max_occ_dist_m;
  return dist_[static_cast<std::size_t>(fy) * fw_ + fx];
}

void AmclPeer::SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad) {
  std::normal_distribution<double> nxy(0.0, sigma_xy_m), nt(0.0, sigma_theta_rad);
  particles_.clear();
  const int n = params_.max_particles;
  for (int i = 0; i < n; ++i)
    particles_.push_back(Particle{pose.x + nxy(rng_), pose.y + nxy(rng_),
                                  spott_map::NormalizeAngle(pose.yaw + nt(rng_)), 1.0 / n});
  has_update_odom_ = false;
  updates_ = 0;
  estimate_ = pose;
  estimate_odom_ = Pose2{};
}

void AmclPeer::Motion(const Pose2& from, const Pose2& to) {
  // AMCL's ODOM_MODEL_DIFF (Probabilistic Robotics table 5.6).
  const double dx = to.x - from.x, dy = to.y - from.y;
  const double trans = std::hypot(dx, dy);
  const double rot1 = trans < 0.01 ? 0.0 : AngleDiff(std::atan2(dy, dx), from.yaw);
  const double rot2 = AngleDiff(AngleDiff(to.yaw, from.yaw), rot1);
  const double rot1_noise =
      std::min(std::abs(AngleDiff(rot1, 0.0)), std::abs(AngleDiff(rot1, M_PI)));
  const double rot2_noise =
      std::min(std::abs(AngleDiff(rot2, 0.0)), std::abs(AngleDiff(rot2, M_PI)));
  const auto& a = params_;
  const double s_rot1 = std::sqrt(a.alpha1 * rot1_noise * rot1_noise + a.alpha2 * trans * trans);
  const double s_trans = std::sqrt(a.alpha3 * trans * trans + a.alpha4 * rot1_noise * rot1_noise +
                                   a.alpha4 * rot2_noise * rot2_noise);
  const double s_rot2 = std::sqrt(a.alpha1 * rot2_noise * rot2_noise + a.alpha2 * trans * trans);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (Particle& p : particles_) {
    const double r1 = AngleDiff(rot1, s_rot1 * n01(rng_));
    const double t = trans - s_trans * n01(rng_);
    const double r2 = AngleDiff(rot2, s_rot2 * n01(rng_));
    p.x += t * std::cos(p.yaw + r1);
    p.y += t * std::sin(p.yaw + r1);
    p.yaw = spott_map::NormalizeAngle(p.yaw + r1 + r2);
  }
}

void AmclPeer::Sense(const SensorModelParameters& beams, const std::vector<double>& ranges) {
  // AMCL's LikelihoodFieldModel.
  const double denom = 2.0 * params_.sigma_hit_m * params_.sigma_hit_m;
  const double rand = params_.z_rand / beams.max_range_m;
  double total = 0.0;
  for (Particle& p : particles_) {
    const double c = std::cos(p.yaw), s = std::sin(p.yaw);
    double w = 1.0;
    for (std::size_t b = 0; b < ranges.size(); ++b) {
      const double r = ranges[b];
      if (!std::isfinite(r) || r >= beams.max_range_m) continue;
      const Vec2 o = beams.beam_origins_m.empty() ? Vec2(0, 0) : beams.beam_origins_m[b];
      const double a = p.yaw + beams.beam_angles_rad[b];
      const double hx = p.x + c * o.x() - s * o.y() + r * std::cos(a);
      const double hy = p.y + s * o.x() + c * o.y() + r * std::sin(a);
      const double z = Distance(hx, hy);
      const double pz = params_.z_hit * std::exp(-z * z / denom) + rand;
      w += pz * pz * pz;
    }
    p.w *= w;
    total += p.w;
  }
  if (!(total > 0.0)) {
    for (Particle& p : particles_) p.w = 1.0 / particles_.size();
    return;
  }
  const double avg = total / particles_.size();
  for (Particle& p : particles_) p.w /= total;
  if (params_.recovery_alpha_slow > 0.0) {
    w_slow_ = w_slow_ == 0.0 ? avg : w_slow_ + params_.recovery_alpha_slow * (avg - w_slow_);
    w_fast_ = w_fast_ == 0.0 ? avg : w_fast_ + params_.recovery_alpha_fast * (avg - w_fast_);
  }
}

void AmclPeer::Resample() {
  // AMCL's pf_update_resample: roulette-wheel draws until the KLD bound of the occupied bins.
  std::vector<double> cumulative(particles_.size() + 1, 0.0);
  for (std::size_t i = 0; i < particles_.size(); ++i)
    cumulative[i + 1] = cumulative[i] + particles_[i].w;
  const double w_diff = w_slow_ > 0.0 ? std::max(0.0, 1.0 - w_fast_ / w_slow_) : 0.0;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Particle> next;
  std::unordered_map<BinKey, int, BinHash> bins;
  auto limit = [&](int k) {
    if (k <= 1) return params_.max_particles;
    const double b = 2.0 / (9.0 * (k - 1));
    const double x = 1.0 - b + std::sqrt(b) * params_.kld_z;
    const int n = static_cast<int>(std::ceil((k - 1) / (2.0 * params_.kld_err) * x * x * x));
    return std::clamp(n, params_.min_particles, params_.max_particles);
  };
  while (static_cast<int>(next.size()) < params_.max_particles) {
    Particle q;
    if (w_diff > 0.0 && u01(rng_) < w_diff) {
      // A random free pose (recovery).
      for (int attempt = 0; attempt < 1000; ++attempt) {
        const int ix = static_cast<int>(u01(rng_) * map_.width());
        const int iy = static_cast<int>(u01(rng_) * map_.height());
        if (!map_.IsState(ix, iy)) continue;
        const Vec2 c = map_.CellCentre(ix, iy);
        q = Particle{c.x(), c.y(), (2.0 * u01(rng_) - 1.0) * M_PI, 1.0};
        break;
      }
    } else {
      const double r = u01(rng_) * cumulative.back();
      const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), r);
      const std::size_t i = std::min<std::size_t>(
          particles_.size() - 1,
          static_cast<std::size_t>(std::max<long>(0, it - cumulative.begin() - 1)));
      q = particles_[i];
    }
    q.w = 1.0;
    next.push_back(q);
    bins[BinKey{static_cast<int>(std::floor(q.x / params_.bin_xy_m)),
                static_cast<int>(std::floor(q.y / params_.bin_xy_m)),
                static_cast<int>(std::floor(q.yaw / params_.bin_theta_rad))}] = 1;
    if (static_cast<int>(next.size()) > limit(static_cast<int>(bins.size()))) break;
  }
  for (Particle& p : next) p.w = 1.0 / next.size();
  particles_.swap(next);
  if (w_diff > 0.0) w_slow_ = w_fast_ = 0.0;
}

void AmclPeer::ComputeEstimate() {
  // Clusters of adjacent occupied bins (AMCL's kd-tree clustering); the heaviest one's mean.
  std::unordered_map<BinKey, std::vector<std::size_t>, BinHash> bins;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Particle& p = particles_[i];
    bins[BinKey{static_cast<int>(std::floor(p.x / params_.bin_xy_m)),
                static_cast<int>(std::floor(p.y / params_.bin_xy_m)),
                static_cast<int>(std::floor(p.yaw / params_.bin_theta_rad))}]
        .push_back(i);
  }
  std::unordered_map<BinKey, int, BinHash> cluster;
  int clusters = 0;
  double best_w = -1.0;
  Pose2 best = estimate_;
  for (const auto& [key, members] : bins) {
    if (cluster.count(key)) continue;
    const int id = clusters++;
    std::vector<BinKey> stack{key};
    cluster[key] = id;
    double w = 0.0, sx = 0.0, sy = 0.0, ss = 0.0, sc = 0.0;
    while (!stack.empty()) {
      const BinKey k = stack.back();
      stack.pop_back();
      for (std::size_t i : bins[k]) {
        const Particle& p = particles_[i];
        w += p.w, sx += p.w * p.x, sy += p.w * p.y;
        ss += p.w * std::sin(p.yaw), sc += p.w * std::cos(p.yaw);
      }
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dt = -1; dt <= 1; ++dt) {
            const BinKey n{k.x + dx, k.y + dy, k.t + dt};
            if (!bins.count(n) || cluster.count(n)) continue;
            cluster[n] = id;
            stack.push_back(n);
          }
    }
    if (w > best_w) {
      best_w = w;
      best = Pose2{sx / w, sy / w, std::atan2(ss, sc)};
    }
  }
  estimate_ = best;
}

void AmclPeer::OnReading(bool laser, const std::vector<double>& ranges, const Pose2& odom,
                         double now_s) {
  (void)now_s;
  static thread_local std::vector<double> sonar_ranges;
  if (!laser && laser_) {  // with a laser, the sonar ring joins the laser's updates
    sonar_ranges = ranges;
    pending_sonar_ = sonar_ != nullptr;
    return;
  }
  if (particles_.empty()) return;
  bool update = !has_update_odom_;
  if (has_update_odom_) {
    const double dx = odom.x - update_odom_.x, dy = odom.y - update_odom_.y;
    update = std::hypot(dx, dy) >= params_.update_min_d_m ||
             std::abs(AngleDiff(odom.yaw, update_odom_.yaw)) >= params_.update_min_a_rad;
  }
  if (!update) return;
  if (has_update_odom_) Motion(update_odom_, odom);
  update_odom_ = odom;
  has_update_odom_ = true;
  Sense(laser ? *laser_ : *sonar_, ranges);
  if (laser && pending_sonar_) Sense(*sonar_, sonar_ranges);
  pending_sonar_ = false;
  if (++updates_ % params_.resample_interval == 0) Resample();
  ComputeEstimate();
  estimate_odom_ = odom;
}

Pose2 AmclPeer::Estimate(const Pose2& odom) const {
  // map -> odom fixed between updates, as AMCL publishes it.
  return markov_localization::Compose(MapToOdom(estimate_, estimate_odom_), odom);
}

}  // namespace eval
}  // namespace markov_localization
