// markov_localization's inbound message conversions on messages built field by field from the
// fuzzer's bytes (any sizes, NaN, infinities, huge and negative numbers), as the node takes
// them: a LaserScan through spott_ros::LaserScanProblem, then LaserBeams / LaserBeamAngles /
// LaserRanges; a RangeProfile through ProfileReadings and through spott_ros::ProfileEchoes into
// the wall lattice's lines (WallLatticeHeading); a RangeRing's mounts through RingTurn (a
// turned ring's turn must be finite, the model's beams turned by it within the tolerance); an
// OccupancyGrid through FromOccupancyGrid and MapModel::FromOccupancy. Whatever is accepted must be
// usable by the sensor model: beam indices inside the scan, finite beam angles, readings that are
// NaN (left out), +infinity (no echo) or a finite distance in range. A refusal must say why.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "fuzz_values.h"
#include "markov_localization/map_model.h"
#include "markov_localization/ros/conversions.h"
#include "markov_localization/wall_lattice_heading.h"
#include "spott_ros/range_profiles.h"
#include "spott_ros/range_readings.h"

namespace conv = markov_localization::ros_conversions;

namespace {

using spott_fuzz::AnyNumber;
void Check(bool ok, const char* what) { spott_fuzz::Check(ok, "sensor_messages_fuzz", what); }

void Scan(FuzzedDataProvider& in) {
  sensor_msgs::LaserScan scan;
  scan.angle_min = AnyNumber<float>(in, -7.0f, 7.0f);
  scan.angle_increment = AnyNumber<float>(in, -0.1f, 0.1f);
  scan.range_min = AnyNumber<float>(in, -1.0f, 2.0f);
  scan.range_max = AnyNumber<float>(in, -1.0f, 100.0f);
  const int n = in.ConsumeIntegralInRange<int>(0, 400);
  for (int i = 0; i < n; ++i) scan.ranges.push_back(AnyNumber<float>(in, -1.0f, 120.0f));
  const int max_beams = in.ConsumeIntegralInRange<int>(-2, 500);
  const std::string problem = spott_ros::LaserScanProblem(scan);
  if (!problem.empty()) {
    Check(problem.find(": ") != std::string::npos, "a refusal without 'field: why'");
    return;
  }
  const std::vector<int> beams = conv::LaserBeams(n, max_beams);
  Check(!beams.empty(), "an accepted scan with no beam");
  for (std::size_t k = 0; k < beams.size(); ++k) {
    Check(beams[k] >= 0 && beams[k] < n, "a beam index outside the scan");
    Check(k == 0 || beams[k] > beams[k - 1], "beam indices not increasing");
  }
  for (double a : conv::LaserBeamAngles(scan, beams))
    Check(std::isfinite(a) && std::abs(a) <= 2.0 * M_PI + 1e-2, "a beam angle not finite");
  for (double r : conv::LaserRanges(scan, beams)) {
    Check(std::isnan(r) || r == std::numeric_limits<double>::infinity() ||
              (r >= scan.range_min && r < scan.range_max),
          "a reading neither left out, no echo, nor in [range_min, range_max)");
  }
}

void Profile(FuzzedDataProvider& in) {
  spott_msgs::RangeProfile msg;
  msg.orientation = in.ConsumeIntegralInRange<std::uint8_t>(0, 2);
  msg.max_range = AnyNumber<float>(in, -1.0f, 20.0f);
  const int n = in.ConsumeIntegralInRange<int>(0, 200);
  const bool same_sizes = in.ConsumeBool();
  for (int i = 0; i < n; ++i) {
    msg.angles.push_back(AnyNumber<float>(in, -4.0f, 4.0f));
    msg.ranges.push_back(AnyNumber<float>(in, -1.0f, 25.0f));
    geometry_msgs::Point32 p;
    p.x = AnyNumber<float>(in, -20.0f, 20.0f);
    p.y = AnyNumber<float>(in, -20.0f, 20.0f);
    p.z = AnyNumber<float>(in, -2.0f, 2.0f);
    msg.points.push_back(p);
  }
  if (!same_sizes && n > 0) msg.points.pop_back();
  geometry_msgs::Transform t;
  t.translation.x = AnyNumber<double>(in, -1.0, 1.0);
  t.translation.y = AnyNumber<double>(in, -1.0, 1.0);
  t.translation.z = AnyNumber<double>(in, 0.0, 2.0);
  t.rotation.x = AnyNumber<double>(in, -1.0, 1.0);
  t.rotation.y = AnyNumber<double>(in, -1.0, 1.0);
  t.rotation.z = AnyNumber<double>(in, -1.0, 1.0);
  t.rotation.w = AnyNumber<double>(in, -1.0, 1.0);
  const int bins = in.ConsumeIntegralInRange<int>(-1, 720);
  const double lo = AnyNumber<double>(in, -1.0, 1.0), hi = AnyNumber<double>(in, 0.0, 3.0);
  // sensed_map_localization's path: the echoes placed by the head, the wall lattice's lines.
  Eigen::Vector3d origin;
  if (const auto echoes = spott_ros::ProfileEchoes(msg, t, lo, hi, &origin)) {
    Check(origin.allFinite(), "an accepted head pose whose origin is not finite");
    for (const Eigen::Vector2d& p : *echoes) Check(p.allFinite(), "a profile echo not finite");
    markov_localization::WallLatticeHeading lattice{markov_localization::WallLatticeParameters{}};
    lattice.AddProfile(1.0, *echoes);
    const auto c = lattice.Estimate(1.0, AnyNumber<double>(in, -4.0, 4.0));
    Check(!c.ok || (std::isfinite(c.dyaw) && std::abs(c.dyaw) <= lattice.parameters().gate_rad),
          "a wall lattice correction not finite or beyond the gate");
  }
  std::string why;
  const std::vector<double> z = conv::ProfileReadings(msg, t, bins, lo, hi, &why);
  if (z.empty()) {
    Check(!why.empty(), "a profile refused without a reason");
    return;
  }
  Check(static_cast<int>(z.size()) == bins, "not one reading per beam");
  for (double r : z)
    Check(std::isnan(r) || r == std::numeric_limits<double>::infinity() || r >= 0.0,
          "a profile reading negative or -infinity");
}

void Ring(FuzzedDataProvider& in) {
  spott_msgs::RangeRing ring;
  std::vector<double> beams;
  const int n = in.ConsumeIntegralInRange<int>(0, 32);
  const double turn = AnyNumber<double>(in, -7.0, 7.0);
  for (int i = 0; i < n; ++i) {
    beams.push_back(AnyNumber<double>(in, -4.0, 4.0));
    geometry_msgs::Pose2D m;
    m.theta = in.ConsumeBool() ? beams.back() + turn : AnyNumber<double>(in, -7.0, 7.0);
    m.x = AnyNumber<double>(in, -1.0, 1.0);
    m.y = AnyNumber<double>(in, -1.0, 1.0);
    ring.mounts.push_back(m);
  }
  if (in.ConsumeBool() && !beams.empty()) beams.pop_back();
  const double tolerance = in.ConsumeFloatingPointInRange<double>(0.0, 0.1);
  std::string why;
  const auto turned = conv::RingTurn(ring, beams, tolerance, &why);
  if (!turned) {
    Check(!why.empty(), "a ring refused without a reason");
    return;
  }
  Check(std::isfinite(*turned) && std::abs(*turned) <= M_PI + 1e-9, "a turn not in [-pi, pi]");
  for (std::size_t i = 0; i < ring.mounts.size(); ++i)
    Check(std::abs(std::remainder(ring.mounts[i].theta - beams[i] - *turned, 2 * M_PI)) <=
              tolerance + 1e-9,
          "a mount off the turned beam beyond the tolerance");
}

void Grid(FuzzedDataProvider& in) {
  nav_msgs::OccupancyGrid grid;
  grid.info.resolution = AnyNumber<float>(in, 0.0f, 1.0f);
  grid.info.width = in.ConsumeIntegralInRange<std::uint32_t>(0, 48);
  grid.info.height = in.ConsumeIntegralInRange<std::uint32_t>(0, 48);
  if (in.ConsumeBool()) grid.info.width = in.ConsumeIntegral<std::uint32_t>();
  grid.info.origin.position.x = AnyNumber<double>(in, -50.0, 50.0);
  grid.info.origin.position.y = AnyNumber<double>(in, -50.0, 50.0);
  grid.info.origin.orientation.z = AnyNumber<double>(in, -1.0, 1.0);
  grid.info.origin.orientation.w = AnyNumber<double>(in, -1.0, 1.0);
  const std::size_t cells = in.ConsumeIntegralInRange<std::size_t>(0, 48 * 48);
  for (std::size_t i = 0; i < cells; ++i) grid.data.push_back(in.ConsumeIntegral<std::int8_t>());
  markov_localization::MapModelParameters p;
  p.resolution_m = in.ConsumeFloatingPointInRange<double>(0.01, 2.0);
  p.ray_cast_subdivision = in.ConsumeIntegralInRange<int>(1, 8);
  try {
    const auto map = markov_localization::MapModel::FromOccupancy(conv::FromOccupancyGrid(grid), p);
    Check(map.width() > 0 && map.height() > 0, "an accepted map with no cell");
  } catch (const std::invalid_argument& e) {
    Check(std::string(e.what()).size() > 0, "a map refused without a reason");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  switch (in.ConsumeIntegralInRange<int>(0, 3)) {
    case 0:
      Scan(in);
      break;
    case 1:
      Profile(in);
      break;
    case 2:
      Ring(in);
      break;
    default:
      Grid(in);
      break;
  }
  return 0;
}
