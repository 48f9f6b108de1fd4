#include "markov_localization/certainty.h"

#include <algorithm>
#include <cmath>

namespace markov_localization {

BeliefSnapshot BeliefSnapshot::Of(const MarkovGrid& grid) {
  BeliefSnapshot s;
  s.nx = grid.nx();
  s.ny = grid.ny();
  s.nt = grid.nt();
  s.origin = grid.map().origin();
  s.resolution = grid.map().resolution();
  s.p = grid.Dense();
  s.num_states = grid.NumStates();
  return s;
}

Pose2 BeliefSnapshot::PoseOf(int ix, int iy, int k) const {
  return Pose2{origin.x() + (ix + 0.5) * resolution, origin.y() + (iy + 0.5) * resolution,
               spott_map::NormalizeAngle(k * angular_resolution())};
}

SparseBelief SparseBelief::Of(const MarkovGrid& grid, float min_probability) {
  SparseBelief s;
  s.nx = grid.nx();
  s.ny = grid.ny();
  s.nt = grid.nt();
  s.origin = grid.map().origin();
  s.resolution = grid.map().resolution();
  s.num_states = grid.NumStates();
  s.min_probability = min_probability;
  const std::size_t layer = static_cast<std::size_t>(s.nx) * s.ny;
  for (int k = 0; k < s.nt; ++k) {
    if (!grid.PartActive(k)) continue;
    const float* data = grid.PartData(k);
    for (std::size_t c = 0; c < layer; ++c) {
      if (data[c] <= min_probability) continue;
      s.index.push_back(static_cast<std::uint32_t>(k * layer + c));
      s.p.push_back(data[c]);
    }
  }
  return s;
}

Pose2 SparseBelief::PoseOf(int ix, int iy, int k) const {
  return Pose2{origin.x() + (ix + 0.5) * resolution, origin.y() + (iy + 0.5) * resolution,
               spott_map::NormalizeAngle(k * angular_resolution())};
}

namespace {

// Both belief layouts seen through one interface, so that certainty and modes are one
// algorithm: Size() entries, each with a dense index and a value; Find(dense index) gives the
// entry or -1.
struct DenseView {
  const BeliefSnapshot& b;
  std::size_t Size() const { return b.p.size(); }
  std::size_t DenseIndex(std::size_t e) const { return e; }
  double Value(std::size_t e) const { return b.p[e]; }
  long Find(std::size_t dense) const { return static_cast<long>(dense); }
};

struct SparseView {
  const SparseBelief& b;
  std::size_t Size() const { return b.p.size(); }
  std::size_t DenseIndex(std::size_t e) const { return b.index[e]; }
  double Value(std::size_t e) const { return b.p[e]; }
  long Find(std::size_t dense) const {
    auto it = std::lower_bound(b.index.begin(), b.index.end(), dense);
    if (it == b.index.end() || *it != dense) return -1;
    return static_cast<long>(it - b.index.begin());
  }
};

}  // namespace

double Entropy(const BeliefSnapshot& belief) {
  double h = 0.0;
  for (float v : belief.p)
    if (v > 0.0f) h -= static_cast<double>(v) * std::log(static_cast<double>(v));
  return h;
}

std::vector<std::string> ValidateParameters(const CertaintyParameters& p) {
  std::vector<std::string> errors;
  if (!(p.mode_radius_m > 0.0)) errors.push_back("mode_radius_m must be > 0 m");
  if (!(p.mode_radius_rad > 0.0 && p.mode_radius_rad < M_PI))
    errors.push_back("mode_radius_rad must be in (0, pi)");
  if (!(p.threshold > 0.0 && p.threshold < 1.0)) errors.push_back("threshold must be in (0, 1)");
  return errors;
}

namespace {

template <typename Belief, typename View>
PositionCertainty PosCertaintyOf(const Belief& b, const View& view,
                                 const CertaintyParameters& params) {
  PositionCertainty out;
  if (view.Size() == 0) return out;
  std::size_t emax = 0;
  for (std::size_t e = 1; e < view.Size(); ++e)
    if (view.Value(e) > view.Value(emax)) emax = e;
  const std::size_t imax = view.DenseIndex(emax);
  const int mx = static_cast<int>(imax % b.nx);
  const int my = static_cast<int>((imax / b.nx) % b.ny);
  const int mk = static_cast<int>(imax / (static_cast<std::size_t>(b.nx) * b.ny));
  out.maximum = b.PoseOf(mx, my, mk);
  const int rxy = static_cast<int>(std::floor(params.mode_radius_m / b.resolution + 1e-9));
  const int rt =
      static_cast<int>(std::floor(params.mode_radius_rad / b.angular_resolution() + 1e-9));
  double mass = 0.0, sx = 0.0, sy = 0.0, ss = 0.0, sc = 0.0;
  for (int dk = -rt; dk <= rt; ++dk) {
    const int k = ((mk + dk) % b.nt + b.nt) % b.nt;
    for (int iy = std::max(0, my - rxy); iy <= std::min(b.ny - 1, my + rxy); ++iy) {
      for (int ix = std::max(0, mx - rxy); ix <= std::min(b.nx - 1, mx + rxy); ++ix) {
        const long e = view.Find((static_cast<std::size_t>(k) * b.ny + iy) * b.nx + ix);
        if (e < 0) continue;
        const double v = view.Value(e);
        if (v <= 0.0) continue;
        const Pose2 pose = b.PoseOf(ix, iy, k);
        mass += v;
        sx += v * pose.x;
        sy += v * pose.y;
        ss += v * std::sin(pose.yaw);
        sc += v * std::cos(pose.yaw);
      }
    }
  }
  // A probability: the float belief's sum exceeds 1 by rounding (0.6f + 0.3f + 0.1f > 1).
  out.certainty = std::min(mass, 1.0);
  if (mass > 0.0) out.estimate = Pose2{sx / mass, sy / mass, std::atan2(ss, sc)};
  return out;
}

template <typename Belief, typename View>
std::vector<Mode> ExtractModesOf(const Belief& b, const View& view, const ModeParameters& params) {
  std::vector<Mode> modes;
  if (view.Size() == 0 || b.num_states == 0) return modes;
  double pmax = 0.0;
  for (std::size_t e = 0; e < view.Size(); ++e) pmax = std::max(pmax, view.Value(e));
  const double threshold = std::max(params.uniform_factor / static_cast<double>(b.num_states),
                                    params.max_fraction * pmax);
  std::vector<std::uint8_t> seen(view.Size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < view.Size(); ++start) {
    if (seen[start] || view.Value(start) <= threshold) continue;
    // Flood fill over the 26-neighbourhood; heading wraps.
    std::vector<std::size_t> members;
    stack.assign(1, start);
    seen[start] = 1;
    while (!stack.empty()) {
      const std::size_t e = stack.back();
      stack.pop_back();
      members.push_back(e);
      const std::size_t i = view.DenseIndex(e);
      const int ix = static_cast<int>(i % b.nx);
      const int iy = static_cast<int>((i / b.nx) % b.ny);
      const int k = static_cast<int>(i / (static_cast<std::size_t>(b.nx) * b.ny));
      for (int dk = -1; dk <= 1; ++dk) {
        const int kk = ((k + dk) % b.nt + b.nt) % b.nt;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = ix + dx, y = iy + dy;
            if (x < 0 || y < 0 || x >= b.nx || y >= b.ny) continue;
            const long n = view.Find((static_cast<std::size_t>(kk) * b.ny + y) * b.nx + x);
            if (n < 0 || seen[n] || view.Value(n) <= threshold) continue;
            seen[n] = 1;
            stack.push_back(n);
          }
        }
      }
    }
    Mode mode;
    double sx = 0.0, sy = 0.0, ss = 0.0, sc = 0.0;
    for (std::size_t e : members) {
      const double v = view.Value(e);
      const std::size_t i = view.DenseIndex(e);
      const Pose2 pose = b.PoseOf(static_cast<int>(i % b.nx), static_cast<int>((i / b.nx) % b.ny),
                                  static_cast<int>(i / (static_cast<std::size_t>(b.nx) * b.ny)));
      mode.mass += v;
      sx += v * pose.x;
      sy += v * pose.y;
      ss += v * std::sin(pose.yaw);
      sc += v * std::cos(pose.yaw);
    }
    mode.cells = members.size();
    mode.mean = Pose2{sx / mode.mass, sy / mode.mass, std::atan2(ss, sc)};
    for (std::size_t e : members) {
      const double v = view.Value(e) / mode.mass;
      const std::size_t i = view.DenseIndex(e);
      const Pose2 pose = b.PoseOf(static_cast<int>(i % b.nx), static_cast<int>((i / b.nx) % b.ny),
                                  static_cast<int>(i / (static_cast<std::size_t>(b.nx) * b.ny)));
      const Eigen::Vector3d d(pose.x - mode.mean.x, pose.y - mode.mean.y,
                              spott_map::NormalizeAngle(pose.yaw - mode.mean.yaw));
      mode.covariance += v * d * d.transpose();
    }
    modes.push_back(mode);
  }
  std::sort(modes.begin(), modes.end(),
            [](const Mode& a, const Mode& c) { return a.mass > c.mass; });
  if (static_cast<int>(modes.size()) > params.max_modes) modes.resize(params.max_modes);
  return modes;
}

}  // namespace

PositionCertainty PosCertainty(const BeliefSnapshot& b, const CertaintyParameters& params) {
  return PosCertaintyOf(b, DenseView{b}, params);
}

PositionCertainty PosCertainty(const SparseBelief& b, const CertaintyParameters& params) {
  return PosCertaintyOf(b, SparseView{b}, params);
}

std::vector<Mode> ExtractModes(const BeliefSnapshot& b, const ModeParameters& params) {
  return ExtractModesOf(b, DenseView{b}, params);
}

std::vector<Mode> ExtractModes(const SparseBelief& b, const ModeParameters& params) {
  return ExtractModesOf(b, SparseView{b}, params);
}

BeliefSummary Summarize(const MarkovGrid& grid, const CertaintyParameters& certainty,
                        const ModeParameters& modes, bool with_entropy) {
  BeliefSummary out;
  // Sparse only pays while few states are above theta (a sorted index of millions of states
  // and its binary searches cost more than the dense pass).
  if (grid.ActiveParts() * 4 <= grid.nt()) {
    SparseBelief sparse = SparseBelief::Of(grid, static_cast<float>(grid.threshold()));
    if (sparse.p.size() * 50 < grid.NumStates()) {
      out.sparse = true;
      out.certainty = PosCertainty(sparse, certainty);
      out.modes = ExtractModes(sparse, modes);
    }
  }
  if (!out.sparse || with_entropy) {
    const BeliefSnapshot dense = BeliefSnapshot::Of(grid);
    if (!out.sparse) {
      out.certainty = PosCertainty(dense, certainty);
      out.modes = ExtractModes(dense, modes);
    }
    if (with_entropy) out.entropy = Entropy(dense);
  }
  return out;
}

}  // namespace markov_localization
