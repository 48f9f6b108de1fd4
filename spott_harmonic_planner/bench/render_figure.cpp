// Renders the README's figure: the harmonic field of the paper's 35 x 35 case (three obstacles
// and a goal) and of a 128 x 128 office window as images (PPM): log10 of p = 1 - u in grey,
// equipotentials u = 1 - 10^-k (k = 1, 2, ...) in orange, padded obstacles dark, the goal green,
// the steepest-descent path from the robot in red, and navfn's path (bench/navfn_peer.h) in blue.
// Usage: spott_harmonic_planner_figure OUT_PREFIX
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "../test/test_maps.h"
#include "navfn_peer.h"
#include "spott_harmonic_planner/potential_field.h"

namespace shp = spott_harmonic_planner;

namespace {

struct Image {
  int w, h;
  std::vector<unsigned char> rgb;
  Image(int w_, int h_) : w(w_), h(h_), rgb(3 * w_ * h_, 255) {}
  void Set(int x, int y, int r, int g, int b) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    const int i = 3 * ((h - 1 - y) * w + x);  // y up
    rgb[i] = r;
    rgb[i + 1] = g;
    rgb[i + 2] = b;
  }
  void Save(const std::string& path) const {
    std::ofstream f(path, std::ios::binary);
    f << "P6\n" << w << " " << h << "\n255\n";
    f.write(reinterpret_cast<const char*>(rgb.data()), rgb.size());
  }
};

void Render(const shp::PotentialField& f, const shp::Vec2& robot,
            const std::vector<shp::bench::NavfnPeer::Point>& peer, int scale,
            const std::string& path) {
  Image img(f.width() * scale, f.height() * scale);
  const double decades = 14.0;
  auto level = [&](double px, double py) {
    const double p = f.InterpolatedGoalProbability(shp::Vec2(px, py));
    return p > 0 ? std::log10(p) : -1e9;
  };
  for (int y = 0; y < img.h; ++y) {
    for (int x = 0; x < img.w; ++x) {
      const double px = (x + 0.5) / scale, py = (y + 0.5) / scale;  // resolution 1 m per cell
      const auto c = f.CellOf(shp::Vec2(px, py));
      const shp::FieldCell k = f.cell(c->first, c->second);
      if (k == shp::FieldCell::kObstacle || k == shp::FieldCell::kUnreachable) {
        img.Set(x, y, 60, 60, 70);
        continue;
      }
      if (k == shp::FieldCell::kGoal) {
        img.Set(x, y, 40, 200, 40);
        continue;
      }
      const double l = level(px, py);
      const int grey = static_cast<int>(255 * std::clamp(1.0 + l / decades, 0.0, 1.0));
      img.Set(x, y, grey, grey, grey);
      // A contour where floor(log10 p) changes between this pixel and the next one.
      const double lr = level(px + 1.0 / scale, py), lu = level(px, py + 1.0 / scale);
      if (std::floor(l) != std::floor(lr) || std::floor(l) != std::floor(lu)) {
        img.Set(x, y, 240, 150, 20);
      }
    }
  }
  for (std::size_t i = 0; i + 1 < peer.size(); ++i) {
    // navfn's path points are cell indices plus sub-cell offsets (cell centres at + 0.5).
    const double x0 = peer[i].x + 0.5, y0 = peer[i].y + 0.5;
    const double x1 = peer[i + 1].x + 0.5, y1 = peer[i + 1].y + 0.5;
    for (int s = 0; s <= 2 * scale; ++s) {
      const double t = s / (2.0 * scale);
      img.Set(static_cast<int>(((1 - t) * x0 + t * x1) * scale),
              static_cast<int>(((1 - t) * y0 + t * y1) * scale), 30, 60, 230);
    }
  }
  const auto p = f.DescendPath(robot);
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
    for (int s = 0; s <= 2 * scale; ++s) {
      const double t = s / (2.0 * scale);
      const shp::Vec2 q = (1 - t) * p.points[i] + t * p.points[i + 1];
      for (int d = -1; d <= 1; ++d) {
        img.Set(static_cast<int>(q.x() * scale) + d, static_cast<int>(q.y() * scale), 220, 20, 20);
      }
    }
  }
  img.Save(path);
  std::printf("%s: path %s, %.1f cells long\n", path.c_str(),
              p.reached_goal ? "reaches the goal" : "does NOT reach the goal", p.length_m);
}

std::vector<shp::bench::NavfnPeer::Point> PeerPath(const spott_map::OccupancyRaster& r,
                                                   const shp::Vec2& goal, const shp::Vec2& robot) {
  std::vector<std::uint8_t> blocked(r.width() * r.height());
  for (int y = 0; y < r.height(); ++y) {
    for (int x = 0; x < r.width(); ++x) {
      blocked[y * r.width() + x] =
          x == 0 || y == 0 || x == r.width() - 1 || y == r.height() - 1 || r.Blocked(x, y);
    }
  }
  shp::bench::NavfnPeer peer;
  peer.MakePlan(blocked, r.width(), r.height(),
                static_cast<int>(robot.y()) * r.width() + static_cast<int>(robot.x()),
                static_cast<int>(goal.y()) * r.width() + static_cast<int>(goal.x()));
  return peer.path();
}

void Case(const spott_map::OccupancyRaster& r, const shp::Vec2& goal, const shp::Vec2& robot,
          int scale, const std::string& path) {
  shp::PotentialField f{shp::FieldOptions{}};  // the defaults (the node's)
  f.SetOccupancy(r);
  f.SetGoalPoint(goal);
  f.ColdStart();
  f.Solve(100000);
  Render(f, robot, PeerPath(r, goal, robot), scale, path);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string prefix = argc > 1 ? argv[1] : "field";
  auto paper = shp::testing_maps::EmptyRaster(35, 35);
  shp::testing_maps::Block(paper, 8, 11, 12, 22);
  shp::testing_maps::Block(paper, 17, 2, 21, 14);
  shp::testing_maps::Block(paper, 18, 21, 23, 30);
  Case(paper, shp::Vec2(30.5, 17.5), shp::Vec2(3.5, 17.5), 16, prefix + "_paper35.ppm");
  auto office = shp::testing_maps::RandomOffice(128, 10, 2, 2, 105);
  Case(office, shp::Vec2(110.5, 100.5), shp::Vec2(12.5, 20.5), 5, prefix + "_office128.ppm");
  return 0;
}
