// Draws the belief of global localization in bonn_department after driving along the
// symmetric corridor (the situation of Beetz et al. Fig. 3): the marginal over theta, darker =
// more likely on a log scale (six decades), walls black, the true pose red, the modes' means blue.
// Writes a PNG (Cairo). Usage: markov_localization_belief_picture WORLD.yaml OUT.png [RESOLUTION_M
// HEADING_BINS]
#include <cairo.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

#include "markov_localization/certainty.h"
#include "markov_localization/markov_grid.h"
#include "spott_map/world_loader.h"

namespace ml = markov_localization;

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    std::cerr << "usage: " << argv[0] << " WORLD.yaml OUT.png [RESOLUTION_M HEADING_BINS]\n";
    return 2;
  }
  auto loaded = spott_map::LoadWorldFile(argv[1]);
  if (!loaded.ok()) {
    std::cerr << spott_map::FormatErrors(loaded.errors);
    return 1;
  }
  ml::MapModelParameters mp;
  int nt = 180;
  if (argc == 5) {
    mp.resolution_m = std::atof(argv[3]);
    nt = std::atoi(argv[4]);
  }
  const ml::MapModel map = ml::MapModel::FromWorld(*loaded.world, mp);
  ml::SensorModelParameters sp;
  sp.beam_angles_rad = ml::SonarRingAngles(24);
  const ml::SensorModel sensor(map, nt, sp);
  ml::MarkovGridParameters gp;
  gp.angular_resolution_rad = 2 * M_PI / nt;
  ml::MarkovGrid grid(map, sensor, gp);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  ml::Pose2 pose{11.0, 10.0, 0.0};
  for (int i = 1; i <= 44; ++i) {  // 6.6 m east along the corridor, 15 cm steps
    const ml::Pose2 next{pose.x + 0.15, pose.y, 0.0};
    grid.MotionUpdate(ml::MotionBetween(pose, next));
    pose = next;
    std::vector<double> ranges;
    for (double a : sp.beam_angles_rad) {
      double r = map.RayCast(pose.Position(), pose.yaw + a, sp.max_range_m);
      if (r < sp.max_range_m) r = std::max(0.0, r + noise(rng));
      ranges.push_back(r);
    }
    grid.SensorUpdate(ranges);
  }
  const auto b = ml::BeliefSnapshot::Of(grid);
  const auto modes = ml::ExtractModes(b, ml::ModeParameters{});
  const auto c = ml::PosCertainty(b, ml::CertaintyParameters{});
  std::cout << "truth " << pose.x << " " << pose.y << "; certainty " << c.certainty << ", entropy "
            << ml::Entropy(b) << " of max " << std::log(double(grid.NumStates())) << ", "
            << modes.size() << " modes:\n";
  for (const auto& m : modes)
    std::cout << "  " << m.mean.x << " " << m.mean.y << " " << m.mean.yaw << " mass " << m.mass
              << "\n";
  std::vector<double> marginal(map.NumCells(), 0.0);
  for (int k = 0; k < b.nt; ++k)
    for (int iy = 0; iy < b.ny; ++iy)
      for (int ix = 0; ix < b.nx; ++ix) marginal[map.Index(ix, iy)] += b.p[b.Index(ix, iy, k)];
  double mx = 0.0;
  for (double v : marginal) mx = std::max(mx, v);
  const int s = static_cast<int>(std::ceil(0.6 / map.resolution()));  // pixels per cell
  const int w = map.width() * s, h = map.height() * s;
  std::vector<unsigned char> img(static_cast<std::size_t>(w) * h * 3, 255);
  auto put = [&](int px, int py, int r, int g, int bl) {
    if (px < 0 || py < 0 || px >= w || py >= h) return;
    unsigned char* p = &img[(static_cast<std::size_t>(py) * w + px) * 3];
    p[0] = r, p[1] = g, p[2] = bl;
  };
  for (int iy = 0; iy < map.height(); ++iy)
    for (int ix = 0; ix < map.width(); ++ix) {
      int v = 255;
      if (map.Occupied(ix, iy))
        v = 0;
      else if (!map.IsState(ix, iy))
        v = 225;
      else {  // logarithmic: six decades below the maximum fade to white
        const double r = marginal[map.Index(ix, iy)] / mx;
        const double shade = r > 0 ? std::max(0.0, 1.0 + std::log10(r) / 6.0) : 0.0;
        v = 255 - static_cast<int>(std::lround(230.0 * shade));
      }
      for (int dy = 0; dy < s; ++dy)
        for (int dx = 0; dx < s; ++dx) put(ix * s + dx, (map.height() - 1 - iy) * s + dy, v, v, v);
    }
  auto mark = [&](const ml::Pose2& p, int r, int g, int bl) {
    const double px = (p.x - map.origin().x()) / map.resolution() * s;
    const double py = h - (p.y - map.origin().y()) / map.resolution() * s;
    for (int d = -6; d <= 6; ++d)
      for (int t = -1; t <= 1; ++t) {
        put(int(px) + d, int(py) + t, r, g, bl);
        put(int(px) + t, int(py) + d, r, g, bl);
      }
    for (int d = 0; d <= 18; ++d)
      put(int(px + d * std::cos(p.yaw)), int(py - d * std::sin(p.yaw)), r, g, bl);
  };
  for (const auto& m : modes) mark(m.mean, 0, 0, 255);
  mark(pose, 255, 0, 0);
  std::vector<unsigned char> argb(static_cast<std::size_t>(w) * h * 4);
  for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h; ++i) {
    argb[4 * i + 0] = img[3 * i + 2];  // Cairo's ARGB32 is B, G, R, A in memory (little endian)
    argb[4 * i + 1] = img[3 * i + 1];
    argb[4 * i + 2] = img[3 * i + 0];
    argb[4 * i + 3] = 255;
  }
  cairo_surface_t* surface =
      cairo_image_surface_create_for_data(argb.data(), CAIRO_FORMAT_ARGB32, w, h, w * 4);
  const bool ok = cairo_surface_write_to_png(surface, argv[2]) == CAIRO_STATUS_SUCCESS;
  cairo_surface_destroy(surface);
  if (!ok) {
    std::cerr << "cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
