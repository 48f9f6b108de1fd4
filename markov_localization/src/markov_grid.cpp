#include "markov_localization/markov_grid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace markov_localization {

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
  scratch_.assign(LayerSize(), 0.0f);
  evaluated_.assign(belief_.size(), 0);
  active_.assign(nt_, 1);
  alpha_.assign(nt_, 1.0);
  stored_sum_.assign(nt_, 0.0);
  moved_x_m_.assign(nt_, 0.0);
  moved_y_m_.assign(nt_, 0.0);
  moved_var_m2_.assign(nt_, 0.0);
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
}

void MarkovGrid::SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad) {
  sigma_xy_m = std::max(sigma_xy_m, 0.1 * map_.resolution());
  sigma_theta_rad = std::max(sigma_theta_rad, 0.1 * angular_resolution());
  detector_.Reset();
  lost_ = false;
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

double MarkovGrid::LayerSum(int j) const {
  const float* data = LayerData(j);
  double s = 0.0;
  for (std::size_t c = 0; c < LayerSize(); ++c) s += data[c];
  return s;
}

void MarkovGrid::ClearNonStates(float* data) const {
  const auto& mask = map_.state_mask();
  for (std::size_t c = 0; c < LayerSize(); ++c)
    if (!mask[c]) data[c] = 0.0f;
}

namespace {
// Repeated 3-tap kernels [w, 1-2w, w] (variance 2w each, w <= 0.25) approximate a Gaussian of
// the requested variance (cells^2) along one axis; mass leaving the grid is dropped.
void BlurAxis(float* data, int nx, int ny, double var, bool along_x, std::vector<float>& line) {
  if (!(var > 1e-6)) return;
  const int passes = static_cast<int>(std::ceil(var / 0.5));
  const float w = static_cast<float>(var / passes / 2.0);
  const float c = 1.0f - 2.0f * w;
  const int n = along_x ? nx : ny;
  const int lines = along_x ? ny : nx;
  const std::size_t stride = along_x ? 1 : static_cast<std::size_t>(nx);
  line.resize(n + 2);
  for (int l = 0; l < lines; ++l) {
    float* base = along_x ? data + static_cast<std::size_t>(l) * nx : data + l;
    bool any = false;
    for (int i = 0; i < n; ++i) {
      line[i + 1] = base[i * stride];
      any = any || line[i + 1] != 0.0f;
    }
    if (!any) continue;
    for (int p = 0; p < passes; ++p) {
      line[0] = line[n + 1] = 0.0f;
      float prev = 0.0f;
      for (int i = 1; i <= n; ++i) {
        const float cur = line[i];
        line[i] = w * (prev + line[i + 1]) + c * cur;
        prev = cur;
      }
    }
    for (int i = 0; i < n; ++i) base[i * stride] = line[i + 1];
  }
}
}  // namespace

void MarkovGrid::BlurLayerXY(float* data, double var_cells) {
  std::vector<float> line;
  BlurAxis(data, nx(), ny(), var_cells, true, line);
  BlurAxis(data, nx(), ny(), var_cells, false, line);
}

void MarkovGrid::ShiftLayer(int j, double sx, double sy, double var_cells) {
  float* data = LayerData(j);
  const double flx = std::floor(sx), fly = std::floor(sy);
  const int ox = static_cast<int>(flx), oy = static_cast<int>(fly);
  const float fx = static_cast<float>(sx - flx), fy = static_cast<float>(sy - fly);
  const float w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
  std::fill(scratch_.begin(), scratch_.end(), 0.0f);
  const int w = nx(), h = ny();
  for (int iy = 0; iy < h; ++iy) {
    const int ty = iy + oy;
    if (ty < -1 || ty >= h) continue;
    for (int ix = 0; ix < w; ++ix) {
      const float v = data[static_cast<std::size_t>(iy) * w + ix];
      if (v == 0.0f) continue;
      const int tx = ix + ox;
      if (tx < -1 || tx >= w) continue;
      if (ty >= 0) {
        float* row = &scratch_[static_cast<std::size_t>(ty) * w];
        if (tx >= 0) row[tx] += v * w00;
        if (tx + 1 < w) row[tx + 1] += v * w10;
      }
      if (ty + 1 < h) {
        float* row = &scratch_[static_cast<std::size_t>(ty + 1) * w];
        if (tx >= 0) row[tx] += v * w01;
        if (tx + 1 < w) row[tx + 1] += v * w11;
      }
    }
  }
  std::memcpy(data, scratch_.data(), scratch_.size() * sizeof(float));
  // The bilinear split already spreads the mass by fx(1-fx) (resp. fy(1-fy)) cells^2: only the
  // rest of the motion noise is added.
  std::vector<float> line;
  BlurAxis(data, w, h, var_cells - fx * (1 - fx), true, line);
  BlurAxis(data, w, h, var_cells - fy * (1 - fy), false, line);
  ClearNonStates(data);
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
  for (int j = 0; j < nt_; ++j) {
    const double heading = Heading(HeadingOfLayer(j)) + rotation_residual_;
    const double wx = std::cos(heading) * m.dx - std::sin(heading) * m.dy;
    const double wy = std::sin(heading) * m.dx + std::cos(heading) * m.dy;
    if (active_[j]) {
      ShiftLayer(j, wx / res, wy / res, var_cells);
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
  const double var_bins = sigma_th * sigma_th / (angular_resolution() * angular_resolution());
  if (var_bins > 1e-6) {
    const int passes = static_cast<int>(std::ceil(var_bins / 0.5));
    const float w = static_cast<float>(var_bins / passes / 2.0);
    // A part that would receive cells above theta from an active neighbour is no longer
    // "all below theta": it rejoins the update (with its stored movement) before the mass
    // arrives, so that the sensor update sees it.
    if (params_.selective_update) {
      std::vector<float> layer_max(nt_, 0.0f);
      for (int j = 0; j < nt_; ++j)
        if (active_[j]) layer_max[j] = *std::max_element(LayerData(j), LayerData(j) + LayerSize());
      const double inflow = std::min(1.0, var_bins / 2.0);
      for (int q = 0; q < nt_; ++q) {
        if (active_[q]) continue;
        const double m = std::max(layer_max[(q + nt_ - 1) % nt_], layer_max[(q + 1) % nt_]);
        if (inflow * m > threshold_) WakeLayer(q);
      }
    }
    std::vector<std::vector<float>> old(nt_);
    for (int p = 0; p < passes; ++p) {
      for (int j = 0; j < nt_; ++j) {
        if (active_[j])
          old[j].assign(LayerData(j), LayerData(j) + LayerSize());
        else
          old[j].clear();
      }
      for (int j = 0; j < nt_; ++j) {
        if (!active_[j]) continue;
        float* data = LayerData(j);
        const int nb[2] = {(j + nt_ - 1) % nt_, (j + 1) % nt_};
        for (std::size_t c = 0; c < LayerSize(); ++c) data[c] = (1.0f - 2.0f * w) * old[j][c];
        for (int q : nb) {
          if (active_[q]) {
            for (std::size_t c = 0; c < LayerSize(); ++c) data[c] += w * old[q][c];
          } else {
            float* dst = LayerData(q);
            if (alpha_[q] < 1e-20) MaterializeLayer(q);  // keeps w / alpha_pi in float range
            const float scale = static_cast<float>(w / alpha_[q]);
            double added = 0.0;
            for (std::size_t c = 0; c < LayerSize(); ++c) {
              dst[c] += scale * old[j][c];
              added += scale * old[j][c];
            }
            stored_sum_[q] += added;
          }
        }
      }
    }
  }
  Normalize();
}

void MarkovGrid::Normalize() {
  double total = 0.0;
  for (int j = 0; j < nt_; ++j) total += active_[j] ? LayerSum(j) : stored_sum_[j] * alpha_[j];
  if (!(total > 0.0)) {  // every state ruled out: nothing is known any more.
    SetUniform();
    return;
  }
  const float inv = static_cast<float>(1.0 / total);
  for (int j = 0; j < nt_; ++j) {
    if (active_[j]) {
      float* data = LayerData(j);
      for (std::size_t c = 0; c < LayerSize(); ++c) data[c] *= inv;
    } else {
      alpha_[j] /= total;
    }
  }
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
  const float a = static_cast<float>(alpha_[j]);
  for (std::size_t c = 0; c < LayerSize(); ++c) data[c] *= a;
  const double res = map_.resolution();
  ShiftLayer(j, moved_x_m_[j] / res, moved_y_m_[j] / res, moved_var_m2_[j] / (res * res));
  active_[j] = 1;
  alpha_[j] = 1.0;
  moved_x_m_[j] = moved_y_m_[j] = moved_var_m2_[j] = 0.0;
}

SensorUpdateStats MarkovGrid::SensorUpdate(const std::vector<double>& ranges_m) {
  const int nb = sensor_.num_beams();
  if (static_cast<int>(ranges_m.size()) != nb)
    throw std::invalid_argument("SensorUpdate: " + std::to_string(ranges_m.size()) +
                                " readings for a sensor model of " + std::to_string(nb) + " beams");
  SensorUpdateStats stats;
  const int bins = sensor_.num_bins();
  // Per beam, the column of ratios P(z_b | e) / P~(z_b) for the reading's bin z_b, divided by
  // its largest entry so that the product over 24 beams cannot overflow a float; the common
  // factor `unlikely_factor` (prod_b 1 / max_e ratio) is what the cells left out by eq. (4)
  // are multiplied by instead of 1, so the normalized result is eq. (4) exactly.
  std::vector<float> columns(static_cast<std::size_t>(nb) * bins);
  double log_unlikely_factor = 0.0;
  for (int b = 0; b < nb; ++b) {
    const int z = sensor_.RangeBin(ranges_m[b]);
    float mx = 0.0f;
    for (int e = 0; e < bins; ++e) mx = std::max(mx, sensor_.Ratio(e, z));
    for (int e = 0; e < bins; ++e) columns[b * bins + e] = sensor_.Ratio(e, z) / mx;
    log_unlikely_factor -= std::log(static_cast<double>(mx));
  }
  const double unlikely_factor = std::exp(log_unlikely_factor);
  const float theta = params_.selective_update ? static_cast<float>(threshold_) : 0.0f;
  std::vector<const std::uint8_t*> rows(nb);
  double likely_total = 0.0, unlikely_total = 0.0;
  for (int j = 0; j < nt_; ++j) {
    if (!active_[j]) {
      unlikely_total += stored_sum_[j] * alpha_[j];
      continue;
    }
    ++stats.active_parts;
    const int k = HeadingOfLayer(j);
    for (int b = 0; b < nb; ++b) rows[b] = sensor_.ExpectedRow((k + sensor_.beam_offset(b)) % nt_);
    float* data = LayerData(j);
    std::uint8_t* flags = evaluated_.data() + static_cast<std::size_t>(j) * LayerSize();
    double likely = 0.0, unlikely = 0.0;
    std::size_t evaluated = 0;
    for (std::size_t c = 0; c < LayerSize(); ++c) {
      const float p = data[c];
      // Eq. (4): cells at or below theta keep P(l) (their factor P~(s)/P~(s) = 1).
      if (p <= theta) {
        unlikely += p;
        flags[c] = 0;
        continue;
      }
      flags[c] = 1;
      float l = 1.0f;
      for (int b = 0; b < nb; ++b) l *= columns[b * bins + rows[b][c]];
      const float v = p * l;
      data[c] = v;
      likely += v;
      ++evaluated;
    }
    stats.states_evaluated += evaluated;
    likely_total += likely;
    unlikely_total += unlikely;
  }
  // total in the scale of the normalized columns; alpha of eq. (4) is unlikely_factor / total.
  const double total = likely_total + unlikely_factor * unlikely_total;
  if (!(total > 0.0) || !std::isfinite(total)) {
    SetUniform();
    return stats;
  }
  const double alpha = unlikely_factor / total;
  stats.normalizer = alpha;
  stats.log_likelihood_per_beam = -std::log(alpha) / nb;
  const float a_likely = static_cast<float>(1.0 / total);
  const float a_unlikely = static_cast<float>(alpha);
  const auto& mask = map_.state_mask();
  for (int j = 0; j < nt_; ++j) {
    if (active_[j]) {
      float* data = LayerData(j);
      const std::uint8_t* flags = evaluated_.data() + static_cast<std::size_t>(j) * LayerSize();
      for (std::size_t c = 0; c < LayerSize(); ++c) {
        if (!mask[c]) continue;
        // Which factor a cell gets depends on whether it was updated; its value before was
        // <= theta exactly when it was left out. A floor keeps every state recoverable.
        const bool updated = flags[c] != 0;
        data[c] = std::max(floor_, data[c] * (updated ? a_likely : a_unlikely));
      }
    } else {
      alpha_[j] *= alpha;
      if (alpha_[j] > 1.0) {  // the rest of the belief lost against this part: wake it.
        WakeLayer(j);
        ++stats.parts_woken;
      }
    }
  }
  if (stats.parts_woken > 0) Normalize();
  if (params_.selective_update) {
    for (int j = 0; j < nt_; ++j) {
      if (!active_[j]) continue;
      const float* data = LayerData(j);
      float mx = 0.0f;
      for (std::size_t c = 0; c < LayerSize(); ++c) mx = std::max(mx, data[c]);
      if (mx < theta) {
        active_[j] = 0;
        alpha_[j] = 1.0;
        stored_sum_[j] = LayerSum(j);
        moved_x_m_[j] = moved_y_m_[j] = moved_var_m2_[j] = 0.0;
      }
    }
  }
  lost_ = detector_.Update(stats.log_likelihood_per_beam);
  if (lost_) {
    MixUniform(params_.lost.relocalization_mass);
    stats.lost_detected = true;
  }
  return stats;
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
