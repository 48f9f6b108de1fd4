// Draws the belief of global localization in bonn_department after driving along the
// symmetric corridor (the situation of Beetz et al. Fig. 3): the marginal over theta, darker =
// more likely on a log scale (six decades), walls black, the true pose red, the modes' means blue.
// Writes a PNG (Cairo). Usage: markov_localization_belief_picture WORLD.yaml OUT.png [RESOLUTION_M
// HEADING_BINS]
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

#include "eval_picture.h"
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
  if (!ml::eval::WriteBeliefPicture(map, b, pose, modes, argv[2])) {
    std::cerr << "cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
