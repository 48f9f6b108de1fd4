#include "markov_localization/sensor_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "worker_pool.h"

namespace markov_localization {

std::vector<std::string> ValidateParameters(const SensorModelParameters& p) {
  std::vector<std::string> errors;
  if (p.beam_angles_rad.empty()) errors.push_back("beam_angles_rad must not be empty");
  for (double a : p.beam_angles_rad)
    if (!std::isfinite(a)) errors.push_back("beam_angles_rad holds a non-finite angle");
  if (!(p.sensor_offset_m >= 0.0 && p.sensor_offset_m < 2.0))
    errors.push_back("sensor_offset_m must be in [0, 2) m");
  if (!p.beam_origins_m.empty() && p.beam_origins_m.size() != p.beam_angles_rad.size())
    errors.push_back("beam_origins_m must be empty or hold one origin per beam angle");
  for (const Vec2& o : p.beam_origins_m)
    if (!(o.allFinite() && o.norm() < 2.0))
      errors.push_back("beam_origins_m must be finite and within 2 m of the centre");
  if (!(p.max_range_m > 0.0 && p.max_range_m <= 100.0))
    errors.push_back("max_range_m must be in (0, 100] m");
  if (!(p.beam_width_rad >= 0.0 && p.beam_width_rad < M_PI))
    errors.push_back("beam_width_rad must be in [0, pi) rad");
  if (!(p.critical_angle_rad > 0.0 && p.critical_angle_rad <= M_PI / 2 + 1e-12))
    errors.push_back("critical_angle_rad must be in (0, pi/2] rad");
  if (!(p.range_bin_m > 0.0))
    errors.push_back("range_bin_m must be > 0 m");
  else if (p.max_range_m / p.range_bin_m > 254.0)
    errors.push_back("range_bin_m too small: max_range_m / range_bin_m must be <= 254");
  if (!(p.sigma_hit_m > 0.0)) errors.push_back("sigma_hit_m must be > 0 m");
  if (!(p.lambda_short_per_m > 0.0)) errors.push_back("lambda_short_per_m must be > 0 1/m");
  const double w[] = {p.z_hit, p.z_short, p.z_max, p.z_rand};
  const char* names[] = {"z_hit", "z_short", "z_max", "z_rand"};
  for (int i = 0; i < 4; ++i)
    if (!(w[i] >= 0.0 && w[i] <= 1.0))
      errors.push_back(std::string(names[i]) + " must be in [0, 1]");
  if (std::abs(w[0] + w[1] + w[2] + w[3] - 1.0) > 1e-6)
    errors.push_back("z_hit + z_short + z_max + z_rand must be 1");
  if (!(p.likelihood_exponent > 0.0 && p.likelihood_exponent <= 1.0))
    errors.push_back("likelihood_exponent must be in (0, 1]");
  if (!(p.z_rand > 0.0 || p.z_max > 0.0))
    errors.push_back("z_rand must be > 0 (or z_max > 0) so that no reading has likelihood 0");
  return errors;
}

std::vector<double> SonarRingAngles(int count) {
  std::vector<double> angles;
  for (int i = 0; i < count; ++i) angles.push_back(2.0 * M_PI * i / count);
  return angles;
}

namespace {

// The echo of one ray: the first surface if it is met within the critical angle; otherwise the
// pulse reflects and the echo is the whole path to a second surface that scatters (a corner), or
// none (max range).
double EchoRange(const MapModel& map, const Vec2& from, double angle, double max_range,
                 double critical_angle, bool with_depth = false) {
  const MapModel::Hit first = map.RayCastHit(from, angle, max_range);
  if (!first.hit) return max_range;
  const double cos_critical = std::cos(critical_angle) - 1e-9;
  const double dx = std::cos(angle), dy = std::sin(angle);
  if ((first.x_face ? std::abs(dx) : std::abs(dy)) >= cos_critical)
    return std::min(max_range, first.range_m + (with_depth ? first.depth_m : 0.0));
  const double left = max_range - first.range_m;
  if (left <= 0.0) return max_range;
  // Reflect off the face, starting just before it (still in free space).
  const double back = std::max(0.0, first.range_m - 1e-6);
  const Vec2 at = from + back * Vec2(dx, dy);
  const double reflected = first.x_face ? std::atan2(dy, -dx) : std::atan2(-dy, dx);
  const MapModel::Hit second = map.RayCastHit(at, reflected, left);
  if (!second.hit) return max_range;
  const double rx = std::cos(reflected), ry = std::sin(reflected);
  if ((second.x_face ? std::abs(rx) : std::abs(ry)) < cos_critical) return max_range;
  return std::min(max_range, first.range_m + second.range_m + (with_depth ? second.depth_m : 0.0));
}

}  // namespace

SensorModel::SensorModel(const MapModel& map, int num_headings, const SensorModelParameters& params)
    : params_(params), num_headings_(num_headings) {
  auto errors = ValidateParameters(params);
  if (num_headings < 4 || num_headings > 3600)
    errors.push_back("num_headings must be in [4, 3600]");
  if (!errors.empty()) {
    std::ostringstream out;
    for (std::size_t i = 0; i < errors.size(); ++i) out << (i ? "; " : "") << errors[i];
    throw std::invalid_argument(out.str());
  }
  const double heading_res = 2.0 * M_PI / num_headings;
  for (double a : params.beam_angles_rad) {
    int off = static_cast<int>(std::lround(a / heading_res)) % num_headings;
    if (off < 0) off += num_headings;
    beam_offsets_.push_back(off);
  }
  const int max_bin = static_cast<int>(std::ceil(params.max_range_m / params.range_bin_m - 1e-9));
  num_bins_ = max_bin + 1;

  // Beam origins off the axis: the part along the beam corrects the reading, the part across
  // it selects the cell the table is read at (rounded to whole cells).
  num_cells_ = map.NumCells();
  const int nb = static_cast<int>(params.beam_angles_rad.size());
  along_m_.assign(nb, 0.0);
  shift_.assign(static_cast<std::size_t>(nb) * num_headings, 0);
  std::ptrdiff_t max_shift = 0;
  if (!params.beam_origins_m.empty()) {
    for (int b = 0; b < nb; ++b) {
      const double beta = params.beam_angles_rad[b];
      const Vec2& o = params.beam_origins_m[b];
      along_m_[b] = o.x() * std::cos(beta) + o.y() * std::sin(beta) - params.sensor_offset_m;
      const double across = -o.x() * std::sin(beta) + o.y() * std::cos(beta);
      for (int d = 0; d < num_headings; ++d) {
        const double dir = d * heading_res;  // the beam's absolute direction
        const long sx = std::lround(-across * std::sin(dir) / map.resolution());
        const long sy = std::lround(across * std::cos(dir) / map.resolution());
        const std::ptrdiff_t s = static_cast<std::ptrdiff_t>(sy) * map.width() + sx;
        shift_[static_cast<std::size_t>(b) * num_headings + d] = s;
        max_shift = std::max<std::ptrdiff_t>(max_shift, s < 0 ? -s : s);
      }
    }
  }
  // Reads shifted past the first or last cell land in padding that holds the max-range bin.
  pad_ = static_cast<std::size_t>(max_shift);
  expected_.assign(num_cells_ * num_headings + 2 * pad_, static_cast<std::uint8_t>(max_bin));
  // One ray per state cell and heading: the node's start waits for these (3.5 s for cim_office's
  // sonar and profiles on one core), so the headings' rows are filled on both cores.
  auto fill_row = [&](int d) {
    const double angle = d * heading_res;
    const Vec2 offset(params.sensor_offset_m * std::cos(angle),
                      params.sensor_offset_m * std::sin(angle));
    std::uint8_t* row = expected_.data() + pad_ + static_cast<std::size_t>(d) * num_cells_;
    for (int iy = 0; iy < map.height(); ++iy) {
      for (int ix = 0; ix < map.width(); ++ix) {
        if (!map.IsState(ix, iy)) continue;
        const double range = EchoRange(map, map.CellCentre(ix, iy) + offset, angle,
                                       params.max_range_m, params.critical_angle_rad);
        const int bin = RangeBin(range);
        row[map.Index(ix, iy)] = static_cast<std::uint8_t>(bin);
      }
    }
  };
  if (WorkerThreadsEnabled()) {
    WorkerPool pool;
    pool.Run(num_headings, fill_row);
  } else {
    for (int d = 0; d < num_headings; ++d) fill_row(d);
  }
  // A beam with an opening angle reads the nearest echo in its cone: the shortest of the rays
  // of the heading bins within +-beam_width / 2.
  const int half_cone =
      static_cast<int>(std::floor(0.5 * params.beam_width_rad / heading_res + 1e-9));
  half_cone_ = half_cone;
  if (half_cone > 0) {
    const std::vector<std::uint8_t> rays = expected_;
    for (int d = 0; d < num_headings; ++d) {
      std::uint8_t* row = expected_.data() + pad_ + static_cast<std::size_t>(d) * num_cells_;
      for (int k = -half_cone; k <= half_cone; ++k) {
        const int dk = ((d + k) % num_headings + num_headings) % num_headings;
        const std::uint8_t* ray = rays.data() + pad_ + static_cast<std::size_t>(dk) * num_cells_;
        for (std::size_t c = 0; c < num_cells_; ++c) row[c] = std::min(row[c], ray[c]);
      }
    }
  }
  std::vector<double> histogram(num_bins_, 0.0);
  for (int d = 0; d < num_headings; ++d) {
    const std::uint8_t* row = ExpectedRow(d);
    for (std::size_t c = 0; c < num_cells_; ++c)
      if (map.state_mask()[c]) histogram[row[c]] += 1.0;
  }

  // P(z | e): the mixture, integrated over each bin and normalized over the bins.
  table_.assign(static_cast<std::size_t>(num_bins_) * num_bins_, 0.0);
  const double bw = params.range_bin_m;
  for (int e = 0; e < num_bins_; ++e) {
    const double expected_m = e * bw;
    double* row = &table_[static_cast<std::size_t>(e) * num_bins_];
    double hit_sum = 0.0, short_sum = 0.0;
    std::vector<double> hit(num_bins_), shrt(num_bins_);
    for (int z = 0; z < num_bins_; ++z) {
      const double lo = z == 0 ? -1e9 : (z - 0.5) * bw;
      const double hi = z == max_bin ? 1e9 : (z + 0.5) * bw;
      auto cdf = [&](double x) {
        return 0.5 * std::erfc(-(x - expected_m) / (params.sigma_hit_m * std::sqrt(2.0)));
      };
      hit[z] = cdf(hi) - cdf(lo);
      hit_sum += hit[z];
      // Unexpected obstacles end the beam before the expected range.
      if (z < e) {
        const double a = std::max(0.0, lo), b = std::min(hi, expected_m);
        shrt[z] =
            std::exp(-params.lambda_short_per_m * a) - std::exp(-params.lambda_short_per_m * b);
        short_sum += shrt[z];
      }
    }
    for (int z = 0; z < num_bins_; ++z) {
      double p = params.z_hit * (hit_sum > 0 ? hit[z] / hit_sum : 0.0);
      if (short_sum > 0)
        p += params.z_short * shrt[z] / short_sum;
      else if (z == e)
        p += params.z_short;  // nothing can be shorter than 0: mass to the hit
      if (z == max_bin) p += params.z_max;
      p += params.z_rand / num_bins_;
      row[z] = p;
    }
  }

  // P~(z) = (1/|L|) sum_l P(z | l): every beam sees the same average under a uniform belief,
  // since its absolute direction is uniform over the heading bins.
  double total = 0.0;
  for (double h : histogram) total += h;
  average_.assign(num_bins_, 0.0);
  for (int e = 0; e < num_bins_; ++e)
    for (int z = 0; z < num_bins_; ++z)
      average_[z] += histogram[e] / std::max(total, 1.0) * Likelihood(e, z);
  expected_log_.assign(num_bins_, 0.0);
  for (int e = 0; e < num_bins_; ++e)
    for (int z = 0; z < num_bins_; ++z)
      expected_log_[e] += Likelihood(e, z) * std::log(Likelihood(e, z));
  ratio_.assign(table_.size(), 0.0f);
  for (int e = 0; e < num_bins_; ++e)
    for (int z = 0; z < num_bins_; ++z)
      ratio_[e * num_bins_ + z] =
          static_cast<float>(std::pow(Likelihood(e, z) / average_[z], params.likelihood_exponent));
}

double SensorModel::ExpectedRange(const MapModel& map, const Pose2& pose, int b) const {
  const double beam = params_.beam_angles_rad[b];
  const double axis = pose.yaw + beam;
  const double heading_res = 2.0 * M_PI / num_headings_;
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  double best = params_.max_range_m;
  for (int k = -half_cone_; k <= half_cone_; ++k) {
    const double a = axis + k * heading_res;
    Vec2 from;
    if (!params_.beam_origins_m.empty()) {
      const Vec2& o = params_.beam_origins_m[b];
      from = pose.Position() + Vec2(c * o.x() - s * o.y(), s * o.x() + c * o.y());
    } else {
      from = pose.Position() + params_.sensor_offset_m * Vec2(std::cos(a), std::sin(a));
    }
    best = std::min(best, EchoRange(map, from, a, params_.max_range_m, params_.critical_angle_rad,
                                    /*with_depth=*/true));
  }
  return best;
}

double SensorModel::LogLikelihood(double expected_m, double range_m) const {
  const int z = RangeBin(range_m);
  const int max_bin = num_bins_ - 1;
  const double e = std::clamp(expected_m / params_.range_bin_m, 0.0, static_cast<double>(max_bin));
  const int e0 = std::min(static_cast<int>(std::floor(e)), max_bin);
  const int e1 = std::min(e0 + 1, max_bin);
  const double f = e - e0;
  return std::log((1.0 - f) * Likelihood(e0, z) + f * Likelihood(e1, z));
}

double SensorModel::LogLikelihood(double e, double z, double sigma) const {
  const auto& p = params_;
  const double w = p.range_bin_m, max = p.max_range_m;
  const double s2 = sigma * std::sqrt(2.0);
  const double rand = p.z_rand * w / (max + w);
  if (!std::isfinite(z) || z >= max - 0.5 * w) {  // no echo: the max-range bin
    const double beyond = 0.5 * std::erfc((max - 0.5 * w - e) / s2);
    return std::log(p.z_max + p.z_hit * beyond + rand);
  }
  z = std::max(z, 0.0);
  double prob =
      p.z_hit * 0.5 * (std::erf((z + 0.5 * w - e) / s2) - std::erf((z - 0.5 * w - e) / s2));
  const double l = p.lambda_short_per_m;
  if (z < e && e > 0.0) prob += p.z_short * l * std::exp(-l * z) * w / (1.0 - std::exp(-l * e));
  return std::log(prob + rand);
}

int SensorModel::BeamBin(int b, double range_m) const {
  if (!std::isfinite(range_m) || range_m >= params_.max_range_m) return num_bins_ - 1;
  return RangeBin(range_m + along_m_[b]);
}

int SensorModel::RangeBin(double range_m) const {
  const int max_bin = num_bins_ - 1;
  if (!std::isfinite(range_m) || range_m >= params_.max_range_m) return max_bin;
  if (range_m <= 0.0) return 0;
  // The epsilon makes ranges a rounding error apart (a beam and its mirror image) share a bin.
  return std::min(max_bin,
                  static_cast<int>(std::floor(range_m / params_.range_bin_m + 0.5 + 1e-6)));
}

}  // namespace markov_localization
