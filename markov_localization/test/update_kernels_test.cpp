// The optimized update loops (src/update_kernels.cpp: runs of state cells, AVX2/AVX-512
// versions, the fused shift and heading noise, the worker thread) against plain reference
// loops written here in double precision from the model's definition, and every
// instruction-set version and thread count against the others (they must give the same
// floats).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../src/update_kernels.h"
#include "../src/worker_pool.h"
#include "markov_localization/markov_grid.h"

namespace markov_localization {
namespace {

using Belief = std::vector<double>;  // index (k * ny + iy) * nx + ix, like MarkovGrid::Dense()

// 31 x 23 cells of 15 cm: outer walls, an inner wall with a door, a pillar; state cells are the
// free ones (odd sizes: runs of state cells do not fill whole vectors).
MapModel Rooms() {
  const int w = 31, h = 23;
  std::vector<std::int8_t> data(w * h, 0);
  for (int iy = 0; iy < h; ++iy)
    for (int ix = 0; ix < w; ++ix) {
      const bool border = ix == 0 || iy == 0 || ix == w - 1 || iy == h - 1;
      const bool inner = ix == 17 && (iy < 8 || iy > 12);
      const bool pillar = ix >= 6 && ix <= 8 && iy >= 14 && iy <= 16;
      if (border || inner || pillar) data[iy * w + ix] = 100;
    }
  return MapModel::FromOccupancy(Vec2(0, 0), w, h, 0.15, data, 50, 0.0);
}

SensorModelParameters Ring(double range_bin_m) {
  SensorModelParameters p;
  p.beam_angles_rad = SonarRingAngles(8);
  p.max_range_m = 3.0;
  p.range_bin_m = range_bin_m;
  p.sigma_hit_m = 0.5;  // a vague sensor: four scans leave every part above theta
  p.z_hit = 0.5;
  p.z_rand = 0.3;
  return p;
}

MarkovGridParameters Params(bool selective) {
  MarkovGridParameters p;
  p.angular_resolution_rad = 2.0 * M_PI / 36;
  p.selective_update = selective;
  p.motion.sigma_xy_per_m = 0.25;  // several 3-tap passes along x and y for a 1 m move
  // Low enough that no part is deactivated in the sequence below (the motion reference has
  // no inactive parts), high enough that the Gaussian's tails stay below it.
  p.threshold_fraction = 1e-4;
  return p;
}

Belief ToDouble(const std::vector<float>& v) { return Belief(v.begin(), v.end()); }

// Eq. (2) (theta = 0) or eq. (4): P(l) times prod_b P(z_b | l) / P~(z_b) where P(l) > theta,
// times 1 elsewhere, normalized; then no state below the floor.
Belief ReferenceSensorUpdate(const MarkovGrid& g, const Belief& prior, const std::vector<double>& z,
                             double theta, double floor) {
  const SensorModel& s = g.sensor();
  const MapModel& map = g.map();
  Belief post(prior.size(), 0.0);
  double total = 0.0;
  for (int k = 0; k < g.nt(); ++k)
    for (int iy = 0; iy < g.ny(); ++iy)
      for (int ix = 0; ix < g.nx(); ++ix) {
        const std::size_t i = (static_cast<std::size_t>(k) * g.ny() + iy) * g.nx() + ix;
        double f = 1.0;
        if (prior[i] > theta) {
          for (int b = 0; b < s.num_beams(); ++b) {
            const int e = s.ExpectedBin((k + s.beam_offset(b)) % g.nt(), map.Index(ix, iy));
            const int zb = s.RangeBin(z[b]);
            f *= s.Likelihood(e, zb) / s.AverageLikelihood(zb);
          }
        }
        post[i] = prior[i] * f;
        total += post[i];
      }
  for (int k = 0; k < g.nt(); ++k)
    for (int iy = 0; iy < g.ny(); ++iy)
      for (int ix = 0; ix < g.nx(); ++ix) {
        const std::size_t i = (static_cast<std::size_t>(k) * g.ny() + iy) * g.nx() + ix;
        post[i] /= total;
        if (map.IsState(ix, iy)) post[i] = std::max(post[i], floor);
      }
  return post;
}

// Repeated 3-tap passes [w, 1 - 2w, w] of total variance `var` along x or y, zero outside.
void ReferenceBlur(Belief& layer, int nx, int ny, double var, bool along_x) {
  if (!(var > 1e-6)) return;
  const int passes = static_cast<int>(std::ceil(var / 0.5));
  const double w = var / passes / 2.0;
  for (int p = 0; p < passes; ++p) {
    const Belief old = layer;
    auto at = [&](int ix, int iy) {
      return ix < 0 || iy < 0 || ix >= nx || iy >= ny ? 0.0 : old[iy * nx + ix];
    };
    for (int iy = 0; iy < ny; ++iy)
      for (int ix = 0; ix < nx; ++ix) {
        const double side =
            along_x ? at(ix - 1, iy) + at(ix + 1, iy) : at(ix, iy - 1) + at(ix, iy + 1);
        layer[iy * nx + ix] = w * side + (1 - 2 * w) * old[iy * nx + ix];
      }
  }
}

// Eq. (1) with the grid's noise model, every part active: each heading's layer shifted along
// itself (bilinear), blurred by the rest of the position noise, cleared outside the states;
// relabelled by the turn (whole bins here); heading noise between neighbouring bins; normalized.
Belief ReferenceMotionUpdate(const MarkovGrid& g, const Belief& prior, const Motion& m,
                             const MotionModelParameters& mp) {
  const int nx = g.nx(), ny = g.ny(), nt = g.nt();
  const std::size_t layer = static_cast<std::size_t>(nx) * ny;
  const double dist = std::hypot(m.dx, m.dy), turn = std::abs(m.dtheta);
  const double sigma_xy = mp.sigma_xy_per_m * dist + mp.sigma_xy_per_rad * turn;
  const double sigma_th = mp.sigma_theta_per_m * dist + mp.sigma_theta_per_rad * turn;
  const double res = g.map().resolution();
  const double var_cells = sigma_xy * sigma_xy / (res * res);
  const int r = static_cast<int>(std::lround(m.dtheta / g.angular_resolution()));
  Belief moved(prior.size(), 0.0);
  for (int k = 0; k < nt; ++k) {
    const double h = g.Heading(k);
    const double sx = (std::cos(h) * m.dx - std::sin(h) * m.dy) / res;
    const double sy = (std::sin(h) * m.dx + std::cos(h) * m.dy) / res;
    const int ox = static_cast<int>(std::floor(sx)), oy = static_cast<int>(std::floor(sy));
    const double fx = sx - ox, fy = sy - oy;
    Belief out(layer, 0.0);
    for (int iy = 0; iy < ny; ++iy)
      for (int ix = 0; ix < nx; ++ix) {
        const double v = prior[k * layer + iy * nx + ix];
        const double wgt[2][2] = {{(1 - fx) * (1 - fy), fx * (1 - fy)}, {(1 - fx) * fy, fx * fy}};
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int tx = ix + ox + dx, ty = iy + oy + dy;
            if (tx >= 0 && ty >= 0 && tx < nx && ty < ny) out[ty * nx + tx] += v * wgt[dy][dx];
          }
      }
    ReferenceBlur(out, nx, ny, var_cells - fx * (1 - fx), true);
    ReferenceBlur(out, nx, ny, var_cells - fy * (1 - fy), false);
    const int kk = ((k + r) % nt + nt) % nt;
    for (int iy = 0; iy < ny; ++iy)
      for (int ix = 0; ix < nx; ++ix)
        moved[kk * layer + iy * nx + ix] = g.map().IsState(ix, iy) ? out[iy * nx + ix] : 0.0;
  }
  const double var_bins = sigma_th * sigma_th / (g.angular_resolution() * g.angular_resolution());
  if (var_bins > 1e-6) {
    const int passes = static_cast<int>(std::ceil(var_bins / 0.5));
    const double w = var_bins / passes / 2.0;
    for (int p = 0; p < passes; ++p) {
      const Belief old = moved;
      for (int k = 0; k < nt; ++k)
        for (std::size_t c = 0; c < layer; ++c)
          moved[k * layer + c] = (1 - 2 * w) * old[k * layer + c] +
                                 w * old[((k + nt - 1) % nt) * layer + c] +
                                 w * old[((k + 1) % nt) * layer + c];
    }
  }
  double total = 0.0;
  for (double v : moved) total += v;
  for (double& v : moved) v /= total;
  return moved;
}

// Largest deviation relative to the largest probability.
double Deviation(const Belief& ref, const std::vector<float>& got) {
  double mx = 0.0, dev = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    mx = std::max(mx, ref[i]);
    dev = std::max(dev, std::abs(ref[i] - got[i]));
  }
  return dev / mx;
}

struct Sequence {
  std::vector<std::vector<float>> beliefs;  // after each update
  std::size_t evaluated = 0;
  std::size_t states = 0;
};

// A fixed sequence of updates; each is checked against the reference from the belief before it.
Sequence RunAndCheck(const MapModel& map, const SensorModel& sensor, bool selective) {
  const MarkovGridParameters params = Params(selective);
  MarkovGrid g(map, sensor, params);
  const float floor = static_cast<float>(params.floor_fraction / g.NumStates());
  const float theta = selective ? static_cast<float>(g.threshold()) : 0.0f;
  Sequence run;
  run.states = g.NumStates();
  const Pose2 truth{1.6, 1.9, 0.4};
  std::vector<double> scan;
  for (double a : sensor.parameters().beam_angles_rad)
    scan.push_back(map.RayCast(truth.Position(), truth.yaw + a, sensor.parameters().max_range_m));
  scan[3] = 0.4;  // an unexpected obstacle
  const double step = g.angular_resolution();
  const std::vector<Motion> motions = {
      {0.2, 0.05, 0.0}, {1.0, -0.1, 7 * step}, {0.35, 0.0, -2 * step}, {0.0, 0.0, 0.0}};
  g.SetGaussian(truth, 0.6, 2.0);  // every part active, cells on both sides of theta
  for (std::size_t i = 0; i < motions.size(); ++i) {
    Belief before = ToDouble(g.Dense());
    const SensorUpdateStats st = g.SensorUpdate(scan);
    run.evaluated += st.states_evaluated;
    run.beliefs.push_back(g.Dense());
    EXPECT_LT(Deviation(ReferenceSensorUpdate(g, before, scan, theta, floor), run.beliefs.back()),
              1e-5)
        << "sensor update " << i;
    if (g.ActiveParts() < g.nt()) break;  // the motion reference has no inactive parts
    before = ToDouble(g.Dense());
    g.MotionUpdate(motions[i]);
    run.beliefs.push_back(g.Dense());
    EXPECT_LT(
        Deviation(ReferenceMotionUpdate(g, before, motions[i], params.motion), run.beliefs.back()),
        1e-5)
        << "motion update " << i;
  }
  return run;
}

class UpdateKernels : public ::testing::TestWithParam<double> {
 protected:
  void TearDown() override {
    kernels::ForceIsa(kernels::SupportedIsa());
    EnableWorkerThreads(threads_);
  }
  const bool threads_ = WorkerThreadsEnabled();
};

TEST_P(UpdateKernels, EveryVersionEqualsThePlainReferenceLoopsAndTheOthers) {
  const MapModel map = Rooms();
  const SensorModel sensor(map, 36, Ring(GetParam()));
  for (bool selective : {false, true}) {
    std::vector<Sequence> runs;
    for (kernels::Isa isa : {kernels::Isa::kScalar, kernels::Isa::kAvx2, kernels::Isa::kAvx512}) {
      if (kernels::ForceIsa(isa) != isa) continue;  // not on this CPU
      // One thread and (where the machine has two cores) two threads.
      for (bool threads : {false, threads_}) {
        EnableWorkerThreads(threads);
        SCOPED_TRACE(std::string(kernels::IsaName(isa)) + (selective ? " selective" : " full") +
                     (threads ? ", two threads" : ", one thread"));
        runs.push_back(RunAndCheck(map, sensor, selective));
        ASSERT_EQ(runs.back().beliefs.size(), 8u);  // four sensor and four motion updates
        // Selective: some states were left out (at or below theta).
        if (selective) {
          EXPECT_LT(runs.back().evaluated, 4 * runs.back().states);
        }
      }
    }
    for (std::size_t r = 1; r < runs.size(); ++r) {
      EXPECT_EQ(runs[r].evaluated, runs[0].evaluated);
      ASSERT_EQ(runs[r].beliefs.size(), runs[0].beliefs.size());
      for (std::size_t i = 0; i < runs[0].beliefs.size(); ++i)
        EXPECT_TRUE(runs[r].beliefs[i] == runs[0].beliefs[i])
            << "version " << r << ", update " << i;
    }
  }
}

// 31 range bins (the AVX-512 version looks columns up in registers) and 76 (it gathers).
INSTANTIATE_TEST_SUITE_P(RangeBins, UpdateKernels, ::testing::Values(0.1, 0.04));

TEST(UpdateKernels, StateSpansCoverEveryStateCell) {
  const std::vector<std::uint8_t> mask = {0, 1, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0, 0, 1, 0};
  EXPECT_EQ(kernels::StateSpans(mask, 1), (std::vector<std::uint32_t>{1, 3, 6, 7, 8, 10, 15, 16}));
  // Gaps shorter than 4 cells are bridged; the 5-cell gap is not.
  EXPECT_EQ(kernels::StateSpans(mask, 4), (std::vector<std::uint32_t>{1, 10, 15, 16}));
  EXPECT_TRUE(kernels::StateSpans(std::vector<std::uint8_t>(5, 0), 4).empty());
}

}  // namespace
}  // namespace markov_localization
