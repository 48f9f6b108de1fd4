#include "markov_localization/sensor_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <tuple>

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

// The echo of one ray along unit `dir`: the first surface if it is met within the critical
// angle (`cos_critical`: its cosine); otherwise the pulse reflects and the echo is the whole
// path to a second surface that scatters (a corner), or none (max range).
double EchoRange(const MapModel& map, const Vec2& from, const Vec2& dir, double max_range,
                 double cos_critical, bool with_depth = false, double* first_leg = nullptr) {
  const MapModel::Hit first = map.RayCastHit(from, dir, max_range);
  if (!first.hit) return max_range;
  if (first_leg) *first_leg = first.range_m;
  const double dx = dir.x(), dy = dir.y();
  if ((first.x_face ? std::abs(dx) : std::abs(dy)) >= cos_critical)
    return std::min(max_range, first.range_m + (with_depth ? first.depth_m : 0.0));
  const double left = max_range - first.range_m;
  if (left <= 0.0) return max_range;
  // Reflect off the face, starting just before it (still in free space).
  const double back = std::max(0.0, first.range_m - 1e-6);
  const Vec2 at = from + back * dir;
  const Vec2 reflected = first.x_face ? Vec2(-dx, dy) : Vec2(dx, -dy);
  const MapModel::Hit second = map.RayCastHit(at, reflected, left);
  if (!second.hit) return max_range;
  if ((second.x_face ? std::abs(dx) : std::abs(dy)) < cos_critical) return max_range;
  return std::min(max_range, first.range_m + second.range_m + (with_depth ? second.depth_m : 0.0));
}

double DistanceToBox(const Vec2& p, const spott_map::Box& b) {
  return (b.min - p).cwiseMax(p - b.max).cwiseMax(Vec2::Zero()).norm();
}

// Whether the segment from `from` along unit `dir` for `length` meets box `b` (slabs).
bool SegmentMeetsBox(const Vec2& from, const Vec2& dir, double length, const spott_map::Box& b) {
  double lo = 0.0, hi = length;
  for (int i = 0; i < 2; ++i) {
    if (std::abs(dir[i]) < 1e-12) {
      if (from[i] < b.min[i] || from[i] > b.max[i]) return false;
      continue;
    }
    double t0 = (b.min[i] - from[i]) / dir[i], t1 = (b.max[i] - from[i]) / dir[i];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
    if (lo > hi) return false;
  }
  return true;
}

}  // namespace

bool operator==(const SensorModelParameters& a, const SensorModelParameters& b) {
  return a.beam_angles_rad == b.beam_angles_rad && a.sensor_offset_m == b.sensor_offset_m &&
         a.beam_origins_m == b.beam_origins_m && a.max_range_m == b.max_range_m &&
         a.beam_width_rad == b.beam_width_rad && a.critical_angle_rad == b.critical_angle_rad &&
         a.range_bin_m == b.range_bin_m && a.sigma_hit_m == b.sigma_hit_m &&
         a.lambda_short_per_m == b.lambda_short_per_m && a.z_hit == b.z_hit &&
         a.z_short == b.z_short && a.z_max == b.z_max && a.z_rand == b.z_rand &&
         a.likelihood_exponent == b.likelihood_exponent;
}

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
  cos_critical_ = std::cos(params.critical_angle_rad) - 1e-9;
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
  rays_.assign(num_cells_ * num_headings + 2 * pad_, static_cast<std::uint8_t>(max_bin));
  first_.assign(num_cells_ * num_headings, kNoEcho);
  // One ray per state cell and heading: the node's start waits for these (3.5 s for cim_office's
  // sonar and profiles on one core), so the headings' rows are filled on both cores.
  auto fill_row = [&](int d) {
    std::uint8_t* row = rays_.data() + pad_ + static_cast<std::size_t>(d) * num_cells_;
    std::uint8_t* first = first_.data() + static_cast<std::size_t>(d) * num_cells_;
    for (int iy = 0; iy < map.height(); ++iy) {
      for (int ix = 0; ix < map.width(); ++ix) {
        if (!map.IsState(ix, iy)) continue;
        const std::size_t c = map.Index(ix, iy);
        std::tie(row[c], first[c]) = CastRay(map, ix, iy, d);
      }
    }
  };
  if (WorkerThreadsEnabled()) {
    WorkerPool pool;
    pool.Run(num_headings, fill_row);
  } else {
    for (int d = 0; d < num_headings; ++d) fill_row(d);
  }
  rays_cast_ = map.NumStateCells() * static_cast<std::size_t>(num_headings);
  // A beam with an opening angle reads the nearest echo in its cone: the shortest of the rays
  // of the heading bins within +-beam_width / 2.
  half_cone_ = static_cast<int>(std::floor(0.5 * params.beam_width_rad / heading_res + 1e-9));
  expected_ = rays_;
  if (half_cone_ > 0) {
    for (int d = 0; d < num_headings; ++d) {
      std::uint8_t* row = expected_.data() + pad_ + static_cast<std::size_t>(d) * num_cells_;
      for (int k = -half_cone_; k <= half_cone_; ++k) {
        const int dk = ((d + k) % num_headings + num_headings) % num_headings;
        const std::uint8_t* ray = rays_.data() + pad_ + static_cast<std::size_t>(dk) * num_cells_;
        for (std::size_t c = 0; c < num_cells_; ++c) row[c] = std::min(row[c], ray[c]);
      }
    }
  }
  ComputeTable();
  ComputeAverages(map);
}

SensorModel::SensorModel(const SensorModel& previous, const MapModel& previous_map,
                         const MapModel& map)
    : SensorModel(previous) {
  if (!map.SameRaster(previous_map) || map.NumCells() != num_cells_)
    throw std::invalid_argument("SensorModel: the new map's raster differs from the previous");
  const std::uint8_t max_bin = static_cast<std::uint8_t>(num_bins_ - 1);
  const auto changed = map.OccupancyChangedFrom(previous_map);
  // A ray is cast again when its cell became a state, or when its path in the old map came
  // within a fine cell of the changed box: a path that kept off it meets the same cells in both
  // maps. The path: the first leg up to its echo, then the specular leg, which lies within the
  // rest of the range around the first echo.
  const double margin = map.resolution() / map.subdivision();
  const spott_map::Box box = changed ? changed->Inflated(margin) : spott_map::Box{};
  std::vector<std::pair<std::size_t, bool>> cells;  // (cell, every ray)
  std::vector<std::size_t> dropped;                 // states no more
  for (int iy = 0; iy < map.height(); ++iy) {
    for (int ix = 0; ix < map.width(); ++ix) {
      const std::size_t c = map.Index(ix, iy);
      const bool was = previous_map.IsState(ix, iy), is = map.IsState(ix, iy);
      if (was && !is) dropped.push_back(c);
      if (!is) continue;
      if (!was) {
        cells.emplace_back(c, true);
      } else if (changed && DistanceToBox(map.CellCentre(ix, iy), box) <=
                                params_.max_range_m + params_.sensor_offset_m) {
        cells.emplace_back(c, false);
      }
    }
  }
  std::vector<std::uint8_t> touched(num_cells_, 0);
  for (std::size_t c : dropped) {
    touched[c] = 1;
    for (int d = 0; d < num_headings_; ++d) {
      const std::size_t at = static_cast<std::size_t>(d) * num_cells_ + c;
      rays_[pad_ + at] = expected_[pad_ + at] = max_bin;
      first_[at] = kNoEcho;
    }
  }
  const double bin_m = params_.range_bin_m;
  // The cells whose rays were cast again, per direction (each written by one thread).
  std::vector<std::vector<std::size_t>> recast_cells(num_headings_);
  auto recast = [&](int d) {
    const double angle = d * 2.0 * M_PI / num_headings_;
    const Vec2 dir(std::cos(angle), std::sin(angle));
    std::uint8_t* row = rays_.data() + pad_ + static_cast<std::size_t>(d) * num_cells_;
    std::uint8_t* first = first_.data() + static_cast<std::size_t>(d) * num_cells_;
    for (const auto& [c, every] : cells) {
      const int ix = static_cast<int>(c % map.width()), iy = static_cast<int>(c / map.width());
      if (!every) {
        const Vec2 from = map.CellCentre(ix, iy) + params_.sensor_offset_m * dir;
        // Bins hold ranges to half a bin above their centre.
        const double reach = row[c] >= max_bin ? params_.max_range_m : (row[c] + 0.5) * bin_m;
        const bool echo = first[c] != kNoEcho;
        const double leg = echo ? std::min(reach, (first[c] + 0.5) * bin_m) : reach;
        bool near = SegmentMeetsBox(from, dir, leg, box);
        if (!near && echo && reach > (first[c] - 0.5) * bin_m) {
          // The specular leg starts at the first echo (within half a bin) and runs the rest.
          const Vec2 at = from + first[c] * bin_m * dir;
          near = DistanceToBox(at, box) <= reach - (first[c] - 0.5) * bin_m + 0.5 * bin_m;
        }
        if (!near) continue;
      }
      std::tie(row[c], first[c]) = CastRay(map, ix, iy, d);
      recast_cells[d].push_back(c);
    }
  };
  if (WorkerThreadsEnabled()) {
    WorkerPool pool;
    pool.Run(num_headings_, recast);
  } else {
    for (int d = 0; d < num_headings_; ++d) recast(d);
  }
  rays_cast_ = 0;
  for (const auto& row : recast_cells) {
    rays_cast_ += row.size();
    for (std::size_t c : row) touched[c] = 1;
  }
  std::vector<std::size_t> cone_cells;
  for (std::size_t c = 0; c < num_cells_; ++c)
    if (touched[c] && map.state_mask()[c]) cone_cells.push_back(c);
  // The cone again where a ray changed, row by row (a row's cells lie together in memory).
  auto cone = [&](int d) {
    std::uint8_t* row = expected_.data() + pad_ + static_cast<std::size_t>(d) * num_cells_;
    for (std::size_t c : cone_cells) {
      std::uint8_t best = max_bin;
      for (int k = -half_cone_; k <= half_cone_; ++k) {
        const int dk = ((d + k) % num_headings_ + num_headings_) % num_headings_;
        best = std::min(best, rays_[pad_ + static_cast<std::size_t>(dk) * num_cells_ + c]);
      }
      row[c] = best;
    }
  };
  if (WorkerThreadsEnabled()) {
    WorkerPool pool;
    pool.Run(num_headings_, cone);
  } else {
    for (int d = 0; d < num_headings_; ++d) cone(d);
  }
  ComputeAverages(map);
}

std::pair<std::uint8_t, std::uint8_t> SensorModel::CastRay(const MapModel& map, int ix, int iy,
                                                           int d) const {
  const double angle = d * 2.0 * M_PI / num_headings_;
  const Vec2 dir(std::cos(angle), std::sin(angle));
  double first = params_.max_range_m;
  const double range = EchoRange(map, map.CellCentre(ix, iy) + params_.sensor_offset_m * dir, dir,
                                 params_.max_range_m, CosCritical(), /*with_depth=*/false, &first);
  // Bins up to 254 (ValidateParameters), so kNoEcho is no bin.
  const std::uint8_t first_bin =
      first >= params_.max_range_m ? kNoEcho : static_cast<std::uint8_t>(RangeBin(first));
  return {static_cast<std::uint8_t>(RangeBin(range)), first_bin};
}

void SensorModel::ComputeTable() {
  const SensorModelParameters& params = params_;
  const int max_bin = num_bins_ - 1;
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
}

void SensorModel::ComputeAverages(const MapModel& map) {
  std::vector<double> histogram(num_bins_, 0.0);
  for (int d = 0; d < num_headings_; ++d) {
    const std::uint8_t* row = ExpectedRow(d);
    for (std::size_t c = 0; c < num_cells_; ++c)
      if (map.state_mask()[c]) histogram[row[c]] += 1.0;
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
          static_cast<float>(std::pow(Likelihood(e, z) / average_[z], params_.likelihood_exponent));
}

double SensorModel::ExpectedRange(const MapModel& map, const Pose2& pose, int b) const {
  const double beam = params_.beam_angles_rad[b];
  const double axis = pose.yaw + beam;
  const double heading_res = 2.0 * M_PI / num_headings_;
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  double best = params_.max_range_m;
  const double cos_critical = CosCritical();
  for (int k = -half_cone_; k <= half_cone_; ++k) {
    const double a = axis + k * heading_res;
    const Vec2 dir(std::cos(a), std::sin(a));
    Vec2 from;
    if (!params_.beam_origins_m.empty()) {
      const Vec2& o = params_.beam_origins_m[b];
      from = pose.Position() + Vec2(c * o.x() - s * o.y(), s * o.x() + c * o.y());
    } else {
      from = pose.Position() + params_.sensor_offset_m * dir;
    }
    best = std::min(best, EchoRange(map, from, dir, params_.max_range_m, cos_critical,
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
