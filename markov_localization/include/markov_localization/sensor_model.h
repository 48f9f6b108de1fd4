// The table-driven range-sensor model of Beetz et al. section 2 ([BFH97]): P(s | l) by look-up.
// Expected ranges are precomputed by ray casting for every state cell and every absolute beam
// direction (the belief's heading bins); a per-beam likelihood table P(z | expected) mixes a
// Gaussian around the expected range, an exponential term for unexpected obstacles (people,
// unmapped furniture) that shorten readings, a max-range term and a uniform term. The a priori
// likelihood P~(z) (the average of P(z | l) over a uniform belief) serves the selective update.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "markov_localization/map_model.h"
#include "spott_map/geometry.h"

namespace markov_localization {

using spott_map::Pose2;

struct SensorModelParameters {
  /// Beam directions relative to the robot's heading (rad, counter-clockwise); e.g. a 24-sonar
  /// ring every 15 degrees. Each is rounded to the nearest heading bin of the belief.
  std::vector<double> beam_angles_rad;
  double sensor_offset_m = 0.0;  ///< Distance of the sensors from the robot's centre (m), >= 0.
  /// Where each beam starts in the robot frame (m; x ahead, y left), one per beam angle, or
  /// empty: every beam starts sensor_offset_m out along its own axis (a ring). A laser mounted
  /// ahead of the centre has origins off its beams' axes: the tables are cast from
  /// sensor_offset_m along each axis, the rest of the origin's offset along the beam is added
  /// to the reading, and the offset across the beam is rounded to whole cells (the expected
  /// range is read at the neighbouring cell the origin lies in; error at most half a cell,
  /// the tables' own resolution).
  std::vector<Vec2> beam_origins_m;
  double max_range_m = 5.0;  ///< Readings at or beyond this are "no echo" (m), > 0.
  /// Full opening angle of each beam (rad), in [0, pi). A sonar answers with the first echo in
  /// its cone, so the expected range is the shortest ray cast within +-beam_width / 2 (on the
  /// heading grid); 0 casts a single ray (lasers).
  double beam_width_rad = 0.0;
  /// Sonar specular reflection: a surface met at an incidence beyond this angle (rad, from its
  /// normal) reflects the pulse away; the echo is then lost or comes back from a second surface
  /// as a long multipath reading (whole path), as in a corner. pi / 2: every surface scatters
  /// (lasers, infrared). In (0, pi / 2].
  double critical_angle_rad = M_PI / 2;
  double range_bin_m = 0.1;         ///< Width of a range bin of the tables (m), > 0; <= 254 bins.
  double sigma_hit_m = 0.15;        ///< Std. dev. of a reading around the expected range (m), > 0.
  double lambda_short_per_m = 0.3;  ///< Rate of the unexpected-obstacle term (1/m), > 0.
  double z_hit = 0.7;               ///< Mixture weights, each in [0, 1], summing to 1.
  double z_short = 0.1;             ///< Unexpected obstacles (people, furniture not in the map).
  double z_max = 0.1;   ///< Missed echoes (specular sonar reflections) read as max range.
  double z_rand = 0.1;  ///< Anything else.
  /// Each beam's likelihood ratio enters the update raised to this power, in (0, 1]: beams of
  /// one scan are not independent (a laser's neighbours 6 degrees apart see the same wall, the
  /// same desk), and the product of 30 of them made the belief so sharp that a scan with
  /// furniture in view let a look-alike place 26 m away win. 1: independent beams (the
  /// paper's model).
  double likelihood_exponent = 1.0;
};

std::vector<std::string> ValidateParameters(const SensorModelParameters& params);
bool operator==(const SensorModelParameters& a, const SensorModelParameters& b);

/// A 24-beam ring, 15 degrees apart, beam 0 straight ahead (the B21's sonar ring).
std::vector<double> SonarRingAngles(int count = 24);

class SensorModel {
 public:
  /// Precomputes the tables for `map` and `num_headings` heading bins (bin k is heading
  /// k * 2 pi / num_headings). Throws std::invalid_argument on invalid parameters.
  SensorModel(const MapModel& map, int num_headings, const SensorModelParameters& params);
  /// The tables for `map` from `previous`, built on `previous_map` with the same raster
  /// (MapModel::SameRaster): a door opened or closed re-casts only the rays that can reach the
  /// cells whose occupancy changed (a ray's whole path, its specular leg included, lies within its
  /// range of its origin), and the cells that became states; the result equals a full build.
  /// Throws std::invalid_argument when the rasters differ.
  SensorModel(const SensorModel& previous, const MapModel& previous_map, const MapModel& map);

  const SensorModelParameters& parameters() const { return params_; }
  int num_bins() const { return num_bins_; }  ///< Range bins; the last is max range.
  int num_headings() const { return num_headings_; }
  /// Rays cast to build these tables (a full build: every state cell in every direction).
  std::size_t rays_cast() const { return rays_cast_; }
  std::size_t num_cells() const { return num_cells_; }  ///< Cells of the map it was built on.
  int num_beams() const { return static_cast<int>(beam_offsets_.size()); }
  /// Heading-bin offset of beam b (its angle rounded to the heading grid).
  int beam_offset(int b) const { return beam_offsets_[b]; }

  /// The range bin of a reading (m); NaN, infinite and >= max range give the max-range bin.
  int RangeBin(double range_m) const;
  /// The range bin of beam b's reading, measured from the beam's origin (beam_origins_m).
  int BeamBin(int b, double range_m) const;
  /// Expected range bins of beam b when its absolute direction is heading bin `direction`, for
  /// every map cell (row-major): ExpectedRow(direction) read at the cell its origin lies in.
  const std::uint8_t* BeamRow(int b, int direction) const {
    return ExpectedRow(direction) + shift_[static_cast<std::size_t>(b) * num_headings_ + direction];
  }
  /// Expected range bins of all map cells for absolute beam direction bin `direction`
  /// (row-major like the map); cells that are not states hold the max-range bin.
  const std::uint8_t* ExpectedRow(int direction) const {
    return expected_.data() + pad_ + static_cast<std::size_t>(direction) * num_cells_;
  }
  int ExpectedBin(int direction, std::size_t cell) const { return ExpectedRow(direction)[cell]; }
  /// P(z | expected): probability of range bin z when the map predicts bin `expected`.
  double Likelihood(int expected, int z) const { return table_[expected * num_bins_ + z]; }
  /// The expected range (m) of beam b from a continuous robot pose (map frame), cast on `map`
  /// (the map the tables were built on) with the tables' physics (cone, specular echoes) but
  /// the beam's exact angle and origin: what the tables approximate at cell centres.
  double ExpectedRange(const MapModel& map, const Pose2& pose, int b) const;
  /// log P(z | expected range) with the expected range continuous (the table interpolated
  /// linearly between range bins); `range_m` a reading of beam b from its origin.
  double LogLikelihood(double expected_m, double range_m) const;
  /// The same mixture without the tables: continuous in the expected range and with the hit
  /// term's spread `sigma_hit_m` (the tables' sigma_hit covers the cells' quantization; a pose
  /// off the cell centres needs only the sensor's own spread). Probability of the reading's
  /// range bin.
  double LogLikelihood(double expected_m, double range_m, double sigma_hit_m) const;
  /// E[log P(z | expected)] over z ~ P(. | expected): the log-likelihood a reading has on average
  /// when the map's expected bin is right (for the lost detector's surprise).
  double ExpectedLogLikelihood(int expected) const { return expected_log_[expected]; }
  /// P~(z): the likelihood of bin z averaged over a uniform belief (every state, every heading).
  double AverageLikelihood(int z) const { return average_[z]; }
  /// P(z | expected) / P~(z): the factor of the selective update, eq. (4).
  float Ratio(int expected, int z) const { return ratio_[expected * num_bins_ + z]; }

 private:
  static constexpr std::uint8_t kNoEcho = 255;  ///< first_: the first leg met nothing.
  /// The ray from cell (ix, iy) in heading bin d: its expected bin and its first leg's bin.
  std::pair<std::uint8_t, std::uint8_t> CastRay(const MapModel& map, int ix, int iy, int d) const;
  /// The cosine of the critical angle, a hair below (an incidence exactly at it reflects).
  double CosCritical() const { return cos_critical_; }
  /// table_ from the parameters.
  void ComputeTable();
  /// average_, expected_log_ and ratio_ from table_ and the expected bins of `map`'s states.
  void ComputeAverages(const MapModel& map);

  SensorModelParameters params_;
  int num_headings_ = 0;
  int num_bins_ = 0;
  std::size_t num_cells_ = 0;
  std::vector<int> beam_offsets_;
  int half_cone_ = 0;                   // rays each side of a beam's axis (heading bins)
  double cos_critical_ = 0.0;           // CosCritical()
  std::vector<double> along_m_;         // [beam]: added to a reading (origin behind the table's)
  std::vector<std::ptrdiff_t> shift_;   // [beam][direction]: cells to the origin's cell
  std::size_t pad_ = 0;                 // max-range cells before and after the tables
  std::vector<std::uint8_t> expected_;  // pad, [direction][cell], pad
  std::vector<std::uint8_t> rays_;      // like expected_, one ray per direction (before the cone)
  std::vector<std::uint8_t> first_;     // [direction][cell]: a ray's first leg's bin, or kNoEcho
  std::size_t rays_cast_ = 0;
  std::vector<double> table_;         // [expected][z]
  std::vector<double> average_;       // [z]
  std::vector<float> ratio_;          // [expected][z]
  std::vector<double> expected_log_;  // [expected]
};

}  // namespace markov_localization
