#include "markov_localization/markov_grid.h"

#include "update_kernels.h"
#include "worker_pool.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace markov_localization {

namespace {
// task(0), ..., task(count - 1) on the pool's threads when there is one.
void ForEach(WorkerPool* pool, int count, const std::function<void(int)>& task) {
  if (pool && count > 1) {
    pool->Run(count, task);
  } else {
    for (int i = 0; i < count; ++i) task(i);
  }
}

// Parts are handed to the threads in this many chunks (whoever is free takes the next), when
// at least kMinParallelParts are active; a few parts (tracking) are not worth a thread switch.
constexpr int kChunks = 8;
constexpr int kMinParallelParts = 16;
}  // namespace

std::vector<std::string> ValidateParameters(const MarkovGridParameters& p) {
  std::vector<std::string> errors;
  if (!(p.angular_resolution_rad > 0.0)) {
    errors.push_back("angular_resolution_rad must be > 0");
  } else {
    const double n = 2.0 * M_PI / p.angular_resolution_rad;
    if (std::abs(n - std::round(n)) > 1e-6 || n < 4 || n > 3600)
      errors.push_back("angular_resolution_rad must divide 2 pi into 4..3600 bins");
  }
  if (!(p.threshold_fraction > 0.0 && p.threshold_fraction < 1.0))
    errors.push_back("threshold_fraction must be in (0, 1)");
  if (!(p.floor_fraction >= 0.0 && p.floor_fraction < p.threshold_fraction))
    errors.push_back("floor_fraction must be in [0, threshold_fraction)");
  const auto& m = p.motion;
  if (!(m.sigma_xy_per_m >= 0.0)) errors.push_back("motion.sigma_xy_per_m must be >= 0");
  if (!(m.sigma_xy_per_rad >= 0.0)) errors.push_back("motion.sigma_xy_per_rad must be >= 0");
  if (!(m.sigma_theta_per_m >= 0.0)) errors.push_back("motion.sigma_theta_per_m must be >= 0");
  if (!(m.sigma_theta_per_rad >= 0.0)) errors.push_back("motion.sigma_theta_per_rad must be >= 0");
  for (const auto& e : ValidateParameters(p.lost)) errors.push_back("lost." + e);
  if (!(p.distance_filter_probability > 0.5 && p.distance_filter_probability <= 1.0))
    errors.push_back("distance_filter_probability must be in (0.5, 1]");
  if (!(p.distance_filter_sigmas >= 0.0)) errors.push_back("distance_filter_sigmas must be >= 0");
  if (p.distance_filter_max_parts < 1) errors.push_back("distance_filter_max_parts must be >= 1");
  if (!(p.distance_filter_max_fraction >= 0.0 && p.distance_filter_max_fraction <= 1.0))
    errors.push_back("distance_filter_max_fraction must be in [0, 1]");
  if (!(p.distance_filter_confirm_ratio >= 0.0 && p.distance_filter_confirm_ratio < 1.0))
    errors.push_back("distance_filter_confirm_ratio must be in [0, 1)");
  const bool threshold_valid = p.threshold_fraction > 0.0 && p.threshold_fraction < 1.0;
  if (p.lost.enabled && p.selective_update && threshold_valid &&
      !(p.lost.relocalization_mass > p.threshold_fraction))
    errors.push_back("lost.relocalization_mass must exceed threshold_fraction");
  return errors;
}

Motion MotionBetween(const Pose2& from, const Pose2& to) {
  const double c = std::cos(from.yaw), s = std::sin(from.yaw);
  const double wx = to.x - from.x, wy = to.y - from.y;
  return Motion{c * wx + s * wy, -s * wx + c * wy, spott_map::NormalizeAngle(to.yaw - from.yaw)};
}

MarkovGrid::MarkovGrid(const MapModel& map, const SensorModel& sensor,
                       const MarkovGridParameters& params)
    : map_(map), sensor_(sensor), params_(params), detector_(params.lost) {
  auto errors = ValidateParameters(params);
  if (errors.empty()) {
    nt_ = static_cast<int>(std::lround(2.0 * M_PI / params.angular_resolution_rad));
    if (sensor.num_headings() != nt_)
      errors.push_back("the sensor model was built for " + std::to_string(sensor.num_headings()) +
                       " headings, the grid has " + std::to_string(nt_));
  }
  if (!errors.empty()) {
    std::ostringstream out;
    for (std::size_t i = 0; i < errors.size(); ++i) out << (i ? "; " : "") << errors[i];
    throw std::invalid_argument(out.str());
  }
  threshold_ = params.threshold_fraction / static_cast<double>(NumStates());
  floor_ = static_cast<float>(params.floor_fraction / static_cast<double>(NumStates()));
  belief_.assign(LayerSize() * nt_, 0.0f);
  if (WorkerThreadsEnabled()) pool_ = std::make_shared<WorkerPool>();
  scratch_.assign((pool_ ? 2 : 1) * 6 * LayerSize(), 0.0f);
  evaluated_.assign(belief_.size(), 0);
  active_.assign(nt_, 1);
  alpha_.assign(nt_, 1.0);
  stored_sum_.assign(nt_, 0.0);
  moved_x_m_.assign(nt_, 0.0);
  moved_y_m_.assign(nt_, 0.0);
  moved_var_m2_.assign(nt_, 0.0);
  spans_ = kernels::StateSpans(map_.state_mask(), 16);
  SetUniform();
}

int MarkovGrid::HeadingBin(double yaw) const {
  int k = static_cast<int>(std::lround(yaw / angular_resolution())) % nt_;
  return k < 0 ? k + nt_ : k;
}

int MarkovGrid::ActiveParts() const {
  int n = 0;
  for (auto a : active_) n += a;
  return n;
}

void MarkovGrid::SetUniform() {
  const float p = static_cast<float>(1.0 / static_cast<double>(NumStates()));
  for (int j = 0; j < nt_; ++j) {
    float* data = LayerData(j);
    for (std::size_t c = 0; c < LayerSize(); ++c) data[c] = map_.state_mask()[c] ? p : 0.0f;
    active_[j] = 1;
    alpha_[j] = 1.0;
  }
  rotation_ = 0;
  rotation_residual_ = 0.0;
  detector_.Reset();
  lost_ = false;
  lost_reason_.clear();
}

void MarkovGrid::SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad) {
  sigma_xy_m = std::max(sigma_xy_m, 0.1 * map_.resolution());
  sigma_theta_rad = std::max(sigma_theta_rad, 0.1 * angular_resolution());
  detector_.Reset();
  lost_ = false;
  lost_reason_.clear();
  rotation_ = 0;
  rotation_residual_ = 0.0;
  double total = 0.0;
  for (int k = 0; k < nt_; ++k) {
    const double dth = spott_map::NormalizeAngle(Heading(k) - pose.yaw);
    const double wt = std::exp(-0.5 * dth * dth / (sigma_theta_rad * sigma_theta_rad));
    float* data = LayerData(k);
    for (int iy = 0; iy < ny(); ++iy) {
      for (int ix = 0; ix < nx(); ++ix) {
        const std::size_t c = map_.Index(ix, iy);
        if (!map_.state_mask()[c]) {
          data[c] = 0.0f;
          continue;
        }
        const Vec2 d = map_.CellCentre(ix, iy) - pose.Position();
        const double w = wt * std::exp(-0.5 * d.squaredNorm() / (sigma_xy_m * sigma_xy_m));
        data[c] = static_cast<float>(w);
        total += w;
      }
    }
    active_[k] = 1;
    alpha_[k] = 1.0;
  }
  if (!(total > 0.0)) {
    SetUniform();
    return;
  }
  for (float& v : belief_) v = static_cast<float>(v / total);
}

void MarkovGrid::SetBelief(const std::vector<float>& dense) {
  if (dense.size() != belief_.size())
    throw std::invalid_argument("SetBelief: " + std::to_string(dense.size()) + " values for " +
                                std::to_string(belief_.size()) + " cells");
  rotation_ = 0;
  rotation_residual_ = 0.0;
  double total = 0.0;
  const auto& mask = map_.state_mask();
  for (int k = 0; k < nt_; ++k) {
    float* data = LayerData(k);
    const float* src = dense.data() + static_cast<std::size_t>(k) * LayerSize();
    for (std::size_t c = 0; c < LayerSize(); ++c) {
      const float v = mask[c] && std::isfinite(src[c]) && src[c] > 0.0f ? src[c] : 0.0f;
      data[c] = v;
      total += v;
    }
    active_[k] = 1;
    alpha_[k] = 1.0;
    moved_x_m_[k] = moved_y_m_[k] = moved_var_m2_[k] = 0.0;
  }
  if (!(total > 0.0)) {
    ResetUniform("the new belief holds no probability on any state");
    return;
  }
  for (float& v : belief_) v = static_cast<float>(v / total);
}

double MarkovGrid::LayerSum(int j) const { return kernels::Sum(LayerData(j), LayerSize()); }

void MarkovGrid::ShiftLayer(int j, double sx, double sy, double var_cells, float* scratch,
                            float* out) {
  float* data = LayerData(j);
  float* buf = scratch ? scratch : scratch_.data();
  const double flx = std::floor(sx), fly = std::floor(sy);
  const int ox = static_cast<int>(flx), oy = static_cast<int>(fly);
  const float fx = static_cast<float>(sx - flx), fy = static_cast<float>(sy - fly);
  const float w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
  const int w = nx(), h = ny();
  kernels::ShiftBilinear(data, buf, w, h, ox, oy, w00, w10, w01, w11);
  // The bilinear split already spreads the mass by fx(1-fx) (resp. fy(1-fy)) cells^2: only the
  // rest of the motion noise is added, by repeated 3-tap kernels [k, 1-2k, k] (variance 2k
  // each, k <= 0.25) approximating a Gaussian; mass leaving the grid is dropped.
  std::vector<float> line;
  const double var_x = var_cells - fx * (1 - fx), var_y = var_cells - fy * (1 - fy);
  if (var_x > 1e-6) {
    const int passes = static_cast<int>(std::ceil(var_x / 0.5));
    kernels::BlurX(buf, w, h, passes, static_cast<float>(var_x / passes / 2.0), line);
  }
  if (var_y > 1e-6) {
    const int passes = static_cast<int>(std::ceil(var_y / 0.5));
    kernels::BlurY(buf, w, h, passes, static_cast<float>(var_y / passes / 2.0), line);
  }
  // Mass pushed into obstacles is removed.
  kernels::MaskedCopy(out ? out : data, buf, map_.state_mask().data(), LayerSize());
}

void MarkovGrid::MotionUpdate(const Motion& m) {
  const auto& mp = params_.motion;
  const double dist = std::hypot(m.dx, m.dy);
  const double turn = std::abs(m.dtheta);
  const double sigma_xy = mp.sigma_xy_per_m * dist + mp.sigma_xy_per_rad * turn;
  const double sigma_th = mp.sigma_theta_per_m * dist + mp.sigma_theta_per_rad * turn;
  const double res = map_.resolution();
  const double var_cells = sigma_xy * sigma_xy / (res * res);

  // Translation along each part's heading (the heading before the turn, refined by the turn
  // not yet applied to the bins).
  // With every part active and heading noise to add, each shift is done just before the
  // heading noise needs the layer (one pass over the belief instead of two).
  const double var_bins = sigma_th * sigma_th / (angular_resolution() * angular_resolution());
  const bool all_active = std::find(active_.begin(), active_.end(), 0) == active_.end();
  const bool fuse_shift = all_active && var_bins > 1e-6;
  std::vector<double> shift_x(nt_), shift_y(nt_);  // cells
  auto shift = [&](int j, float* scratch, float* out) {
    ShiftLayer(j, shift_x[j], shift_y[j], var_cells, scratch, out);
  };
  for (int j = 0; j < nt_; ++j) {
    const double heading = Heading(HeadingOfLayer(j)) + rotation_residual_;
    const double wx = std::cos(heading) * m.dx - std::sin(heading) * m.dy;
    const double wy = std::sin(heading) * m.dx + std::cos(heading) * m.dy;
    if (active_[j]) {
      shift_x[j] = wx / res;
      shift_y[j] = wy / res;
      if (!fuse_shift) shift(j, nullptr, nullptr);
    } else {  // a_pi accumulates; applied when the part wakes up.
      moved_x_m_[j] += wx;
      moved_y_m_[j] += wy;
      moved_var_m2_[j] += sigma_xy * sigma_xy;
    }
  }
  // The turn moves every part to its new heading bin: a relabelling of the layers.
  rotation_residual_ += m.dtheta;
  const long r = std::lround(rotation_residual_ / angular_resolution());
  rotation_residual_ -= r * angular_resolution();
  rotation_ = static_cast<int>(((rotation_ + r) % nt_ + nt_) % nt_);

  // Heading noise between neighbouring parts. Mass that flows into an inactive part is stored
  // there in its own scale (P / alpha_pi); inactive parts (all cells below theta) send none.
  std::vector<double> active_sums;  // sum of each active part after the heading noise
  if (var_bins > 1e-6) {
    const int passes = static_cast<int>(std::ceil(var_bins / 0.5));
    const float w = static_cast<float>(var_bins / passes / 2.0);
    // A part that would receive cells above theta from an active neighbour is no longer
    // "all below theta": it rejoins the update (with its stored movement) before the mass
    // arrives, so that the sensor update sees it.
    if (params_.selective_update) {
      // Only the maxima of active parts next to an inactive one matter (taken before any wakes).
      const std::vector<std::uint8_t> was_active = active_;
      std::vector<float> layer_max(nt_, -1.0f);
      auto max_of = [&](int q) {
        if (!was_active[q]) return 0.0f;
        if (layer_max[q] < 0.0f) layer_max[q] = kernels::Max(LayerData(q), LayerSize());
        return layer_max[q];
      };
      const double inflow = std::min(1.0, var_bins / 2.0);
      for (int q = 0; q < nt_; ++q) {
        if (was_active[q]) continue;
        const double m = std::max(max_of((q + nt_ - 1) % nt_), max_of((q + 1) % nt_));
        if (inflow * m > threshold_) WakeLayer(q);
      }
    }
    // Each pass: new_j = (1 - 2w) old_j + w old_{j-1} + w old_{j+1} over the active parts, in
    // place in ascending j: old_{j+1} is still in place, old_{j-1} is kept in a buffer (a few
    // layers instead of a copy of all of them). Buffers of segment h: scratch_ layers 6h (the
    // shift's target), 6h + 1 to 6h + 5.
    const float c0 = 1.0f - 2.0f * w;
    const std::size_t size = LayerSize();
    auto buffer = [&](int h, int i) { return scratch_.data() + (6 * h + i) * size; };
    active_sums.assign(nt_, 0.0);
    if (all_active) {
      // Every part active: the layers are cut into segments, one per thread. Phase 1 puts the
      // old (in the first pass: just shifted) values of each segment's first and last layer in
      // buffers 1 and 2; phase 2 runs each segment in ascending j, the old values of layer
      // j + 1 made (shifted or copied) into buffers 3-5 in turn, the neighbour segments' edges
      // read from their buffers; the result is written over layer j.
      const int segments = pool_ ? 2 : 1;
      auto begin = [&](int h) { return h * nt_ / segments; };
      for (int p = 0; p < passes; ++p) {
        const bool shift_now = fuse_shift && p == 0;
        auto old_of = [&](int h, int j, float* out) {
          if (shift_now)
            shift(j, buffer(h, 0), out);
          else
            std::copy(LayerData(j), LayerData(j) + size, out);
          return out;
        };
        ForEach(pool_.get(), segments, [&](int h) {
          const int a = begin(h), b = begin(h + 1);  // b - a >= 2 (nt_ >= 4)
          old_of(h, a, buffer(h, 1));
          old_of(h, b - 1, buffer(h, 2));
        });
        ForEach(pool_.get(), segments, [&](int h) {
          const int a = begin(h), b = begin(h + 1);
          const float* prev_old = buffer((h + segments - 1) % segments, 2);
          const float* cur_old = buffer(h, 1);
          for (int j = a; j < b; ++j) {
            const float* next_old = j + 1 == b       ? buffer((h + 1) % segments, 1)
                                    : j + 1 == b - 1 ? buffer(h, 2)
                                                     : old_of(h, j + 1, buffer(h, 3 + (j + 1) % 3));
            active_sums[j] =
                kernels::HeadingBlend(LayerData(j), cur_old, prev_old, next_old, c0, w, size);
            prev_old = cur_old;
            cur_old = next_old;
          }
        });
      }
    } else {
      float* first = buffer(0, 1);
      for (int p = 0; p < passes; ++p) {
        if (active_[0]) std::copy(LayerData(0), LayerData(0) + size, first);
        const float* prev_old = active_[nt_ - 1] ? LayerData(nt_ - 1) : nullptr;
        float* spare = buffer(0, 3);
        float* spare2 = buffer(0, 4);
        for (int j = 0; j < nt_; ++j) {
          if (!active_[j]) {
            prev_old = nullptr;
            continue;
          }
          const float* cur_old = first;
          if (j > 0) {
            std::copy(LayerData(j), LayerData(j) + size, spare);
            cur_old = spare;
            std::swap(spare, spare2);
          }
          const float* next_old = j + 1 < nt_ ? (active_[j + 1] ? LayerData(j + 1) : nullptr)
                                              : (active_[0] ? first : nullptr);
          active_sums[j] =
              kernels::HeadingBlend(LayerData(j), cur_old, prev_old, next_old, c0, w, size);
          // Mass that flows into an inactive part is stored there in its own scale.
          const int nb[2] = {(j + nt_ - 1) % nt_, (j + 1) % nt_};
          for (int q : nb) {
            if (active_[q]) continue;
            float* dst = LayerData(q);
            if (alpha_[q] < 1e-20) MaterializeLayer(q);  // keeps w / alpha_pi in float range
            const float scale = static_cast<float>(w / alpha_[q]);
            double added = 0.0;
            for (std::size_t c = 0; c < size; ++c) {
              dst[c] += scale * cur_old[c];
              added += scale * cur_old[c];
            }
            stored_sum_[q] += added;
          }
          prev_old = cur_old;
        }
      }
    }
  }
  Normalize(active_sums.empty() ? nullptr : active_sums.data());
}

void MarkovGrid::Normalize() { Normalize(nullptr); }

void MarkovGrid::Normalize(const double* active_sums) {
  double total = 0.0;
  for (int j = 0; j < nt_; ++j) {
    if (active_[j])
      total += active_sums ? active_sums[j] : LayerSum(j);
    else
      total += stored_sum_[j] * alpha_[j];
  }
  if (!(total > 0.0) || !std::isfinite(total)) {  // nothing is known any more: say so
    ResetUniform(!(total > 0.0) ? "every state was ruled out (the motion moved all mass into "
                                  "obstacles)"
                                : "the belief's sum is not finite");
    return;
  }
  const float inv = static_cast<float>(1.0 / total);
  std::vector<int> active_layers;
  for (int j = 0; j < nt_; ++j) {
    if (active_[j])
      active_layers.push_back(j);
    else
      alpha_[j] /= total;
  }
  const int n = static_cast<int>(active_layers.size());
  ForEach(pool_.get(), n >= kMinParallelParts ? kChunks : 1, [&](int t) {
    const int chunks = n >= kMinParallelParts ? kChunks : 1;
    for (int i = t * n / chunks; i < (t + 1) * n / chunks; ++i)
      kernels::Scale(LayerData(active_layers[i]), LayerSize(), inv);
  });
}

bool MarkovGrid::ReportCertainty(double certainty, double threshold) {
  if (detector_.OnCertainty(certainty, threshold)) {
    MixUniform(params_.lost.relocalization_mass);
    lost_ = true;
    lost_reason_ = detector_.reason();
  }
  return lost_;
}

void MarkovGrid::MixUniform(double mass) {
  mass = std::clamp(mass, 0.0, 1.0);
  const float keep = static_cast<float>(1.0 - mass);
  const float add = static_cast<float>(mass / static_cast<double>(NumStates()));
  const auto& mask = map_.state_mask();
  for (int j = 0; j < nt_; ++j) {
    if (!active_[j]) WakeLayer(j);
    float* data = LayerData(j);
    for (std::size_t c = 0; c < LayerSize(); ++c) data[c] = mask[c] ? keep * data[c] + add : 0.0f;
  }
  Normalize();
}

void MarkovGrid::MaterializeLayer(int j) {
  // Stored values times alpha_pi are the probabilities; write them out (tiny ones become 0).
  float* data = LayerData(j);
  for (std::size_t c = 0; c < LayerSize(); ++c)
    data[c] = static_cast<float>(static_cast<double>(data[c]) * alpha_[j]);
  alpha_[j] = 1.0;
  stored_sum_[j] = LayerSum(j);
}

void MarkovGrid::WakeLayer(int j) {
  float* data = LayerData(j);
  kernels::Scale(data, LayerSize(), static_cast<float>(alpha_[j]));
  const double res = map_.resolution();
  ShiftLayer(j, moved_x_m_[j] / res, moved_y_m_[j] / res, moved_var_m2_[j] / (res * res));
  active_[j] = 1;
  alpha_[j] = 1.0;
  moved_x_m_[j] = moved_y_m_[j] = moved_var_m2_[j] = 0.0;
}

SensorUpdateStats MarkovGrid::SensorUpdate(const std::vector<double>& ranges_m) {
  return SensorUpdateWith({SensorReading{&sensor_, &ranges_m}});
}

namespace {
// The smallest value the product of one group's normalized columns may bring the largest
// updated cell to: far above FLT_MIN (1.2e-38), so that neither the cells nor 1 / their sum
// (the normalizing factor, a float) leave the float range.
constexpr double kMinGroupProduct = 1e-30;
}  // namespace

SensorUpdateStats MarkovGrid::SensorUpdateWith(const std::vector<SensorReading>& readings) {
  // Every beam of every reading: its model, row offset and the reading's range bin.
  struct Beam {
    const SensorModel* model;
    int b;
    int offset;  // heading bins from the state's heading to the beam's direction
    int z;
    bool dropped;  // NaN: the sensor dropped out; the beam says nothing
    bool judged;   // counted in the lost detector's surprise
  };
  std::vector<Beam> beams;
  for (const SensorReading& r : readings) {
    if (!r.sensor || !r.ranges_m)
      throw std::invalid_argument("SensorUpdate: a reading without sensor model or ranges");
    const SensorModel& s = *r.sensor;
    if (s.num_headings() != nt_ || s.num_cells() != LayerSize())
      throw std::invalid_argument("SensorUpdate: a sensor model built for another map or grid");
    const int nb = s.num_beams();
    if (static_cast<int>(r.ranges_m->size()) != nb)
      throw std::invalid_argument("SensorUpdate: " + std::to_string(r.ranges_m->size()) +
                                  " readings for a sensor model of " + std::to_string(nb) +
                                  " beams");
    if (!std::isfinite(r.turn_rad))
      throw std::invalid_argument("SensorUpdate: a reading turned by a non-finite angle");
    const long turn = std::lround(std::remainder(r.turn_rad, 2.0 * M_PI) / angular_resolution());
    for (int b = 0; b < nb; ++b) {
      const double range = (*r.ranges_m)[b];
      const int offset = static_cast<int>(((s.beam_offset(b) + turn) % nt_ + nt_) % nt_);
      beams.push_back(Beam{&s, b, offset, s.BeamBin(b, range), std::isnan(range), r.judged});
    }
  }
  SensorUpdateStats stats;
  stats.beam_used.assign(beams.size(), 1);
  // The most likely state before the update, found once when the surprise or the distance
  // filter's confirmation needs it.
  const bool position_known = ActiveParts() <= params_.distance_filter_max_parts;
  int best_j = -1;
  std::size_t best_c = 0;
  bool best_found = false;
  auto find_best = [&] {
    if (best_found) return;
    best_found = true;
    float best = -1.0f;
    for (int j = 0; j < nt_; ++j) {
      if (!active_[j]) continue;
      const float* data = LayerData(j);
      for (std::size_t sp = 0; sp + 1 < spans_.size(); sp += 2)
        for (std::uint32_t c = spans_[sp]; c < spans_[sp + 1]; ++c)
          if (data[c] > best) best = data[c], best_j = j, best_c = c;
    }
  };
  // The mean surprise per judged beam (LostDetectorParameters::surprise) of the beams `use`
  // keeps, at the least surprising of the most likely state and its 26 neighbours: the cells
  // and heading bins quantize the pose, and in a doorway the cell next to the true one sees the
  // jambs differently (a single-scan "collapse" at every door at 10 cm otherwise). NaN when no
  // beam is judged.
  auto surprise_of = [&](const std::vector<std::uint8_t>& use) {
    double surprise = std::numeric_limits<double>::quiet_NaN();
    find_best();
    if (best_j < 0) return surprise;
    const int k0 = HeadingOfLayer(best_j);
    const int cx = static_cast<int>(best_c % static_cast<std::size_t>(nx()));
    const int cy = static_cast<int>(best_c / static_cast<std::size_t>(nx()));
    for (int dk = -1; dk <= 1; ++dk)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = cx + dx, y = cy + dy;
          if (!map_.Contains(x, y) || !map_.IsState(x, y)) continue;
          const int k = ((k0 + dk) % nt_ + nt_) % nt_;
          const std::size_t c = map_.Index(x, y);
          double sum = 0.0;
          int judged = 0;
          for (std::size_t i = 0; i < beams.size(); ++i) {
            const Beam& b = beams[i];
            if (!use[i] || b.dropped || !b.judged) continue;
            const SensorModel& s = *b.model;
            const int e = s.BeamRow(b.b, (k + b.offset) % nt_)[c];
            sum += std::log(s.Likelihood(e, b.z)) - s.ExpectedLogLikelihood(e);
            ++judged;
          }
          if (judged == 0) continue;  // no judged beam: the detector waits (NaN)
          const double mean = sum / static_cast<double>(judged);
          if (!(surprise >= mean)) surprise = mean;
        }
    return surprise;
  };
  std::vector<std::uint8_t> unexpected(beams.size(), 0);
  {
    const std::size_t left_out = DistanceFilter(
        beams.size(),
        [&](std::size_t i) {
          return BeamTables{beams[i].model, beams[i].b, beams[i].offset};
        },
        [&](std::size_t i) { return beams[i].z; }, &unexpected);
    bool leave_out = left_out <= params_.distance_filter_max_fraction * beams.size();
    if (!leave_out && left_out > 0 && params_.distance_filter_confirm_ratio > 0.0 &&
        detector_.slow() > 0.0) {
      // More unexpected short readings than a passer-by makes: an object the map lacks (a
      // partition, a crate) or a wrong belief. The other beams decide: they fit as usual only
      // where the robot is.
      std::vector<std::uint8_t> rest(beams.size());
      for (std::size_t i = 0; i < beams.size(); ++i) rest[i] = !unexpected[i];
      const double confirmed = surprise_of(rest);
      leave_out = confirmed >= std::log(params_.distance_filter_confirm_ratio * detector_.slow());
      stats.distance_filter_confirmed = leave_out;
    }
    if (leave_out)
      for (std::size_t i = 0; i < beams.size(); ++i)
        if (unexpected[i]) stats.beam_used[i] = 0;
  }
  {
    std::vector<Beam> kept;
    for (std::size_t i = 0; i < beams.size(); ++i) {
      if (beams[i].dropped) {
        stats.beam_used[i] = 0;
        ++stats.beams_dropped;
      } else if (stats.beam_used[i]) {
        kept.push_back(beams[i]);
      }
    }
    stats.beams_filtered = static_cast<int>(beams.size() - kept.size()) - stats.beams_dropped;
    // The lost detector's surprise at the most likely state before the update, of the beams
    // the update uses (see LostDetectorParameters::surprise).
    if (kept.empty()) {
      // nothing to judge: the update below returns at once
    } else if (params_.lost.surprise && position_known) {
      stats.surprise_per_beam = surprise_of(stats.beam_used);
      // The surprise without the unexpectedly short beams the update still uses (more than the
      // cap, unconfirmed), while enough other beams remain: an object the map lacks can only
      // shorten a reading (LostDetectorParameters::judge_without_short_beams).
      std::vector<std::uint8_t> expected = stats.beam_used;
      int short_beams = 0, other_beams = 0;
      for (std::size_t i = 0; i < beams.size(); ++i) {
        if (!expected[i] || !beams[i].judged) continue;  // counted as the surprise counts
        if (unexpected[i])
          expected[i] = 0, ++short_beams;
        else
          ++other_beams;
      }
      if (params_.lost.judge_without_short_beams && short_beams > 0 &&
          other_beams >= params_.lost.short_beams_min_others) {
        stats.surprise_without_short_per_beam = surprise_of(expected);
      }
    } else {
      stats.surprise_per_beam = std::numeric_limits<double>::quiet_NaN();
    }
    beams.swap(kept);
  }
  stats.beams = static_cast<int>(beams.size());
  if (beams.empty()) return stats;
  const double surprise = stats.surprise_per_beam;
  // Per beam, the column of ratios P(z_b | e) / P~(z_b) for the reading's bin z_b, divided by
  // its largest entry (so no product overflows); 1 / that largest entry is the factor of the
  // cells left out by eq. (4) instead of 1, so the normalized result is eq. (4) exactly.
  // Stored with kernels::kPermuteBins floats per beam when the table is that small (the AVX-512
  // kernel keeps a column in registers), zero-padded.
  //
  // Numerically safe for any number of beams: the beams are applied in groups, each group one
  // exact update of eq. (2) / (4) with its own normalization (the product of the groups'
  // normalized updates is the normalized product). A group holds as many beams as keep the
  // largest updated cell above kMinGroupProduct even if every beam took its column's smallest
  // entry there: after a normalization the largest updated cell is at least 0.5 / |L| (at most
  // 0.01 of the mass is set aside, eq. (4)), so the group's product of column minima must stay
  // above kMinGroupProduct * 2 |L|. A 24-sonar ring is one group in most scans.
  int bins = 0;
  for (const auto& b : beams) bins = std::max(bins, b.model->num_bins());
  const int stride = bins <= kernels::kPermuteBins ? kernels::kPermuteBins : bins;
  std::vector<float> columns(beams.size() * stride, 0.0f);
  std::vector<double> log_max(beams.size()), log_min(beams.size());
  for (std::size_t i = 0; i < beams.size(); ++i) {
    const SensorModel& s = *beams[i].model;
    const int z = beams[i].z;
    float mx = 0.0f;
    for (int e = 0; e < s.num_bins(); ++e) mx = std::max(mx, s.Ratio(e, z));
    float mn = 1.0f;
    for (int e = 0; e < s.num_bins(); ++e) {
      const float c = s.Ratio(e, z) / mx;
      columns[i * stride + e] = c;
      mn = std::min(mn, c);
    }
    log_max[i] = std::log(static_cast<double>(mx));
    log_min[i] = std::log(std::max(static_cast<double>(mn), 1e-30));
  }
  const double budget =
      std::log(kMinGroupProduct) + std::log(2.0 * static_cast<double>(NumStates()));
  double log_alpha = 0.0;  // sum over the groups of log alpha_g
  std::size_t begin = 0;
  while (begin < beams.size()) {
    std::size_t end = begin + 1;
    double sum = log_min[begin];
    while (end < beams.size() && sum + log_min[end] >= budget) sum += log_min[end++];
    double log_unlikely_factor = 0.0;
    for (std::size_t i = begin; i < end; ++i) log_unlikely_factor -= log_max[i];
    std::vector<BeamTables> group;
    for (std::size_t i = begin; i < end; ++i)
      group.push_back(BeamTables{beams[i].model, beams[i].b, beams[i].offset});
    double alpha = 0.0;
    if (!SensorGroup(columns.data() + begin * stride, stride, group, log_unlikely_factor, &stats,
                     &alpha)) {
      return stats;  // reset, with the reason in stats
    }
    log_alpha += std::log(alpha);
    ++stats.groups;
    begin = end;
  }
  stats.log_normalizer = log_alpha;
  stats.normalizer = std::exp(log_alpha);
  stats.log_likelihood_per_beam = -log_alpha / static_cast<double>(beams.size());
  bool woken = false;
  for (int j = 0; j < nt_; ++j) {
    if (!active_[j] && alpha_[j] > 1.0) {  // the rest of the belief lost against this part
      WakeLayer(j);
      ++stats.parts_woken;
      woken = true;
    }
  }
  if (woken) Normalize();
  if (params_.selective_update) {
    for (int j = 0; j < nt_; ++j) {
      if (!active_[j]) continue;
      const float mx =
          woken || layer_max_[j] < 0.0f ? kernels::Max(LayerData(j), LayerSize()) : layer_max_[j];
      if (mx < static_cast<float>(threshold_)) {
        active_[j] = 0;
        alpha_[j] = 1.0;
        stored_sum_[j] = LayerSum(j);
        moved_x_m_[j] = moved_y_m_[j] = moved_var_m2_[j] = 0.0;
      }
    }
  }
  // The detector's input: the surprise when asked for (NaN while it cannot be computed: the
  // detector then waits), else the predictive fit.
  lost_ = params_.lost.surprise ? detector_.Update(surprise, stats.surprise_without_short_per_beam)
                                : detector_.Update(stats.log_likelihood_per_beam);
  if (lost_) {
    lost_reason_ = detector_.reason();
    MixUniform(params_.lost.relocalization_mass);
    stats.lost_detected = true;
    stats.lost_reason = lost_reason_;
  }
  return stats;
}

template <typename TablesOf, typename BinOf>
std::size_t MarkovGrid::DistanceFilter(std::size_t n, TablesOf tables_of, BinOf bin_of,
                                       std::vector<std::uint8_t>* unexpected) const {
  if (!params_.distance_filter || ActiveParts() > params_.distance_filter_max_parts) return 0;
  // P(the reading is more than margin shorter than expected) under the belief, over the
  // states above theta (the rest hold less than 1% of the mass).
  const float theta = static_cast<float>(threshold_);
  std::vector<double> shorter(n, 0.0);
  std::vector<int> margin_bins(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SensorModel& s = *tables_of(i).model;
    margin_bins[i] = static_cast<int>(std::ceil(
        params_.distance_filter_sigmas * s.parameters().sigma_hit_m / s.parameters().range_bin_m -
        1e-9));
  }
  double mass = 0.0;
  for (int j = 0; j < nt_; ++j) {
    if (!active_[j]) continue;
    const int k = HeadingOfLayer(j);
    const float* data = LayerData(j);
    std::vector<const std::uint8_t*> rows(n);
    for (std::size_t i = 0; i < n; ++i) {
      const BeamTables t = tables_of(i);
      rows[i] = t.model->BeamRow(t.beam, (k + t.offset) % nt_);
    }
    for (std::size_t sp = 0; sp + 1 < spans_.size(); sp += 2) {
      for (std::uint32_t c = spans_[sp]; c < spans_[sp + 1]; ++c) {
        const float p = data[c];
        if (p <= theta) continue;
        mass += p;
        for (std::size_t i = 0; i < n; ++i)
          if (bin_of(i) + margin_bins[i] < rows[i][c]) shorter[i] += p;
      }
    }
  }
  if (!(mass > 0.0)) return 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (shorter[i] >= params_.distance_filter_probability * mass) (*unexpected)[i] = 1, ++count;
  return count;
}

bool MarkovGrid::SensorGroup(const float* columns, int stride, const std::vector<BeamTables>& beams,
                             double log_unlikely_factor, SensorUpdateStats* stats,
                             double* alpha_out) {
  const int nb = static_cast<int>(beams.size());
  const double unlikely_factor = std::exp(log_unlikely_factor);
  const float theta = params_.selective_update ? static_cast<float>(threshold_) : 0.0f;
  std::vector<int> active_layers;
  for (int j = 0; j < nt_; ++j)
    if (active_[j]) active_layers.push_back(j);
  const int n = static_cast<int>(active_layers.size());
  const int chunks = n >= kMinParallelParts ? kChunks : 1;
  const std::size_t cells = LayerSize();
  // Each part's sums in its own place, added below in part order whatever thread ran it.
  std::vector<kernels::SensorLayerOut> outs(nt_);
  ForEach(pool_.get(), chunks, [&](int t) {
    std::vector<const std::uint8_t*> rows(nb);
    for (int i = t * n / chunks; i < (t + 1) * n / chunks; ++i) {
      const int j = active_layers[i];
      const int k = HeadingOfLayer(j);
      for (int b = 0; b < nb; ++b) {
        rows[b] = beams[b].model->BeamRow(beams[b].beam, (k + beams[b].offset) % nt_);
      }
      kernels::SensorLayerIn in;
      in.data = LayerData(j);
      in.flags = evaluated_.data() + static_cast<std::size_t>(j) * cells;
      in.rows = rows.data();
      in.columns = columns;
      in.beams = nb;
      in.column_stride = stride;
      in.theta = theta;
      in.spans = spans_.data();
      in.num_spans = spans_.size() / 2;
      outs[j] = kernels::SensorLayer(in);
    }
  });
  double likely_total = 0.0, unlikely_total = 0.0;
  std::size_t evaluated = 0;
  for (int j = 0; j < nt_; ++j) {
    if (!active_[j]) {
      unlikely_total += stored_sum_[j] * alpha_[j];
      continue;
    }
    evaluated += outs[j].evaluated;
    likely_total += outs[j].likely;
    unlikely_total += outs[j].unlikely;
  }
  stats->states_evaluated = std::max(stats->states_evaluated, evaluated);
  stats->active_parts = n;
  // total in the scale of the normalized columns; alpha of eq. (4) is unlikely_factor / total.
  const double total = likely_total + unlikely_factor * unlikely_total;
  if (!(total > 0.0) || !std::isfinite(total) || !(1.0 / total < 1e37)) {
    ResetUniform(!(total > 0.0) ? "every state was ruled out by the scan (likelihood sum 0)"
                                : "the scan's likelihood sum left the float range");
    stats->lost_detected = true;
    stats->lost_reason = lost_reason_;
    return false;
  }
  const double alpha = unlikely_factor / total;
  const float a_likely = static_cast<float>(1.0 / total);
  const float a_unlikely = static_cast<float>(alpha);
  layer_max_.assign(nt_, -1.0f);
  ForEach(pool_.get(), chunks, [&](int t) {
    for (int i = t * n / chunks; i < (t + 1) * n / chunks; ++i) {
      const int j = active_layers[i];
      // Which factor a cell gets depends on whether it was updated; its value before was
      // <= theta exactly when it was left out. A floor keeps every state recoverable.
      layer_max_[j] = kernels::ScaleLayer(
          LayerData(j), evaluated_.data() + static_cast<std::size_t>(j) * cells,
          map_.state_mask().data(), spans_.data(), spans_.size() / 2, a_likely, a_unlikely, floor_);
    }
  });
  for (int j : active_layers) {
    if (!std::isfinite(layer_max_[j])) {
      ResetUniform("the sensor update produced a non-finite probability");
      stats->lost_detected = true;
      stats->lost_reason = lost_reason_;
      return false;
    }
  }
  for (int j = 0; j < nt_; ++j)
    if (!active_[j]) alpha_[j] *= alpha;
  *alpha_out = alpha;
  return true;
}

void MarkovGrid::ResetUniform(const std::string& reason) {
  SetUniform();
  lost_ = true;
  lost_reason_ = reason;
  ++resets_;
}

double MarkovGrid::Probability(int ix, int iy, int k) const {
  const int j = Layer(k);
  const double v = LayerData(j)[map_.Index(ix, iy)];
  return active_[j] ? v : v * alpha_[j];
}

std::vector<float> MarkovGrid::Dense() const {
  std::vector<float> out(belief_.size());
  for (int k = 0; k < nt_; ++k) {
    const int j = Layer(k);
    const float* data = LayerData(j);
    float* dst = out.data() + static_cast<std::size_t>(k) * LayerSize();
    const float a = active_[j] ? 1.0f : static_cast<float>(alpha_[j]);
    for (std::size_t c = 0; c < LayerSize(); ++c) dst[c] = data[c] * a;
  }
  return out;
}

}  // namespace markov_localization
