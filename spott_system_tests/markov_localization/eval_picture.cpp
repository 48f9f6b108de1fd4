// A picture of a belief (the marginal over theta on a log scale, six decades; walls black,
// non-states light grey; the true pose red, the modes' means blue), as Cairo PNG: the README's
// picture (belief_picture.cpp) and the evaluation runs' (eval_main.cpp).
#include <cairo.h>

#include <algorithm>
#include <cmath>

#include "eval_picture.h"

namespace markov_localization {
namespace eval {

bool WriteBeliefPicture(const MapModel& map, const BeliefSnapshot& b, const Pose2& truth,
                        const std::vector<Mode>& modes, const std::string& path) {
  std::vector<double> marginal(map.NumCells(), 0.0);
  for (int k = 0; k < b.nt; ++k)
    for (int iy = 0; iy < b.ny; ++iy)
      for (int ix = 0; ix < b.nx; ++ix) marginal[map.Index(ix, iy)] += b.p[b.Index(ix, iy, k)];
  double mx = 0.0;
  for (double v : marginal) mx = std::max(mx, v);
  const int s = static_cast<int>(std::ceil(0.6 / map.resolution()));  // pixels per cell
  const int w = map.width() * s, h = map.height() * s;
  std::vector<unsigned char> argb(static_cast<std::size_t>(w) * h * 4, 255);
  auto put = [&](int px, int py, int r, int g, int bl) {
    if (px < 0 || py < 0 || px >= w || py >= h) return;
    unsigned char* p = &argb[(static_cast<std::size_t>(py) * w + px) * 4];
    p[0] = bl, p[1] = g, p[2] = r, p[3] = 255;  // Cairo ARGB32, little endian: B G R A
  };
  for (int iy = 0; iy < map.height(); ++iy)
    for (int ix = 0; ix < map.width(); ++ix) {
      int v = 255;
      if (map.Occupied(ix, iy)) {
        v = 0;
      } else if (!map.IsState(ix, iy)) {
        v = 225;
      } else if (mx > 0) {
        const double r = marginal[map.Index(ix, iy)] / mx;
        const double shade = r > 0 ? std::max(0.0, 1.0 + std::log10(r) / 6.0) : 0.0;
        v = 255 - static_cast<int>(std::lround(230.0 * shade));
      }
      for (int dy = 0; dy < s; ++dy)
        for (int dx = 0; dx < s; ++dx) put(ix * s + dx, (map.height() - 1 - iy) * s + dy, v, v, v);
    }
  auto mark = [&](const Pose2& p, int r, int g, int bl) {
    const double px = (p.x - map.origin().x()) / map.resolution() * s;
    const double py = h - (p.y - map.origin().y()) / map.resolution() * s;
    for (int d = -6; d <= 6; ++d)
      for (int t = -1; t <= 1; ++t) {
        put(static_cast<int>(px) + d, static_cast<int>(py) + t, r, g, bl);
        put(static_cast<int>(px) + t, static_cast<int>(py) + d, r, g, bl);
      }
    for (int d = 0; d <= 18; ++d)
      put(static_cast<int>(px + d * std::cos(p.yaw)), static_cast<int>(py - d * std::sin(p.yaw)), r,
          g, bl);
  };
  for (const auto& m : modes) mark(m.mean, 0, 0, 255);
  mark(truth, 255, 0, 0);
  cairo_surface_t* surface =
      cairo_image_surface_create_for_data(argb.data(), CAIRO_FORMAT_ARGB32, w, h, w * 4);
  const bool ok = cairo_surface_write_to_png(surface, path.c_str()) == CAIRO_STATUS_SUCCESS;
  cairo_surface_destroy(surface);
  return ok;
}

}  // namespace eval
}  // namespace markov_localization
