// The perceptual mapping of SPOTT's condition processes MAP_OBJECTS_WITH_SONAR and
// MAP_OBJECTS_WITH_QUADRIS (Figs. 5-6, section III-A): range data collected at the condition's
// frequency, outliers removed, the rest fused into line segments; a feature enters the map
// database only when it is not already there. Door states are sensed from the same beams (the
// map database's graph keeps them: "sensor data may label existing map features").
//
// How (README "Sensed map"): every echo votes on an evidence grid (occupancy-grid fusion, the
// paper's reference [10]): the cell of the echo gains, the cells the beam crossed lose. A cell is
// confirmed when its score reaches `confirm_score`, which takes several consistent echoes: single
// echoes (multipath, crosstalk) do not make features. Echoes are discarded when
//   - they lie within `known_tolerance_m` of a feature the map holds (the CAD walls, closed door
//     leaves, features another sensor or the recognition made): already there. The mapper's
//     own features are not: their echoes keep voting, and Take refines them (below);
//   - their beam crossed a known obstacle first (a reflection from beyond a wall);
//   - they lie in a door's opening (the opening votes on the door's state instead) or outside
//     every room;
//   - the sonar reading is within `sonar_min_margin_m` of its minimum range (clamped readings say
//     only "closer than this") or beyond `sonar_max_range_m`.
// A newly confirmed cell's cluster (every confirmed cell within `cluster_gap_m` of another, old
// ones included; each cell stands for the mean of the echoes it gained) is fused into line segments
// by recursive splitting at the principal axis (a cluster whose cells all lie within
// `segment_residual_m` of its axis is one segment; single cells are points); a sonar's groups are
// then fitted to their echoes (sonar_echo_fit.h: a wall spans where its echoes reflected, a
// group whose echoes a corner explains better is a point), and the result
// replaces the mapper's features fused from that cluster before: a wall confirmed reading by
// reading ends as one segment, not a row of points. ROS-free; the caller passes the robot's pose
// with each reading.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "spott_map/map_database.h"
#include "spott_map/occupancy_raster.h"
#include "spott_tr_plus/controller/sonar_echo_fit.h"

namespace spott_tr_plus::controller {

using spott_map::Pose2;
using spott_map::Vec2;

/// One reading of a ring of range sensors (spott_msgs/RangeRing), in the robot's base frame.
struct RangeRing {
  std::vector<Pose2> mounts;   ///< Each transducer's position (m) and axis (rad), base frame.
  std::vector<double> ranges;  ///< (m); NaN = dropped out; >= max_range_m = no echo.
  double min_range_m = 0.0;
  double max_range_m = 0.0;
  double field_of_view_rad = 0.0;  ///< Full cone angle of each transducer.
};

struct MappingParameters {
  double cell_m = 0.1;               ///< Evidence grid cell side (m), in [0.02, 0.5].
  double sonar_max_range_m = 3.0;    ///< Sonar echoes farther away are not mapped (m), > 0.
  double sonar_min_margin_m = 0.03;  ///< Echoes this close to the minimum range are clamped (m).
  double range_finder_max_range_m = 3.5;  ///< QUADRIS points farther away are not mapped (m).
  int sonar_hit_score = 1;                ///< Gained by an echo's cell, >= 1.
  int range_finder_hit_score = 2;   ///< Gained by a QUADRIS point's cell (a laser line), >= 1.
  int miss_score = 1;               ///< Lost by each cell a beam crossed, >= 0.
  int confirm_score = 4;            ///< A cell this sure is an obstacle, >= 1.
  int max_score = 8;                ///< Scores are clamped to [-max_score, max_score].
  double known_tolerance_m = 0.25;  ///< Echoes this close to a map feature are that feature (m).
  /// A range finder's profile is refused when more of its points lie between known_tolerance_m
  /// and this (m) from the map's features than within known_tolerance_m, and at least
  /// near_miss_points do: the pose it was taken from is off. <= known_tolerance_m: no check.
  double near_miss_m = 0.6;
  int near_miss_points = 3;
  double door_zone_m = 0.3;  ///< Half depth of a door opening's zone (m), > 0.
  double segment_residual_m =
      0.07;  ///< Fusion: cells whose squares come this close to an axis form a segment (m).
  double cluster_gap_m = 0.15;  ///< Confirmed cells this close form one cluster (m), > 0.
  /// ... for a ring's echoes (sonar, infrared), fused from the echoes' physics one reflector at
  /// a time (m), > 0: a wall's cells are confirmed with gaps (the stretch passed while the
  /// dense scan turned the turret), and only its echoes across them fix its direction; at
  /// 0.15 m cim_office's hallway walls came out as rows of points (recall 0.56, 0.89 at 0.45).
  double echo_cluster_gap_m = 0.45;
  /// Side of the square the grid covers, centred on the robot, when the map has no rooms (no a
  /// priori map: SPOTT's Experiment 1) (m), in [5, 200].
  double mapless_extent_m = 40.0;
  /// Sonar fusion by the echoes' physics (sonar_echo_fit.h): tolerances and critical incidence.
  EchoFitParameters echo_fit;
  /// Sonar echoes kept per cell for the fusion (the latest), in [1, 64].
  int echoes_per_cell = 8;
};

/// Door states from the beams that cross a door's opening.
struct DoorSensingParameters {
  double range_m = 3.0;        ///< Openings farther than this from the transducer: no vote (m).
  double end_margin_m = 0.12;  ///< Beams crossing this close to a jamb: no vote (m), >= 0.
  /// The estimate's error along an opening (m), >= 0. A "closed" vote needs the whole cone on
  /// the opening even with the robot this far off along it: else the echo may come from the
  /// wall beside the door, collinear with the leaf (doors lie in hallway walls, where the
  /// localization's error is largest along the hallway). An "open" vote needs no such margin:
  /// a beam that echoes beyond the opening went through it wherever the robot really was.
  double pose_error_m = 0.15;
  double match_m = 0.15;          ///< An echo this close to the opening's line: the leaf (m), > 0.
  double beyond_m = 0.3;          ///< An echo this far past the opening: open (m), > 0.
  double normal_angle_rad = 0.3;  ///< A sonar beam this close to the door's normal votes (rad).
  /// A range finder's ray (QUADRIS: diffuse, a leaf answers it at any angle) this close to the
  /// door's normal votes (rad): a head turned to a side door from 3 m ahead meets it at 60-65
  /// degrees, and with the sonar's 0.3 the state was sensed only as the robot turned into it.
  double profile_normal_angle_rad = 1.15;
  int votes = 3;      ///< Net votes that decide a state, >= 1.
  int max_votes = 6;  ///< Votes are clamped to [-max_votes, max_votes], >= votes.
  /// Whether the sonar still votes once range profiles (QUADRIS) arrive. A profile's point lies
  /// on the leaf or beyond the opening; a sonar's echo is the nearest reflector in a 30-degree
  /// cone, and in one Fig. 18 run it sensed three doors wrong (two open ones closed, a closed
  /// one open).
  bool sonar_with_profiles = false;
};

std::vector<std::string> ValidateParameters(const MappingParameters& p);
std::vector<std::string> ValidateParameters(const DoorSensingParameters& p);

/// What the sensors found that the map does not hold yet.
struct SensedBatch {
  std::vector<spott_map::MapFeature> features;  ///< New features (ids empty: the owner names them).
  std::vector<std::pair<std::string, spott_map::DoorState>> doors;  ///< Door states that changed.
  /// The mapper's earlier features that `features` supersede (refined: their cells' cluster grew).
  std::vector<std::string> replaced;
  bool empty() const { return features.empty() && doors.empty() && replaced.empty(); }
};

class SensorMapper {
 public:
  /// `sensor` labels the features' "sensor" attribute (sonar, quadris).
  SensorMapper(std::string sensor, MappingParameters mapping, DoorSensingParameters doors,
               bool sense_doors);

  /// The map the echoes are compared with. Call when its features or door states change: what
  /// is known is redrawn. The grid, the rooms and the doors' openings are taken from the first
  /// map that has rooms (they do not change while the robot runs); a map without rooms (no a
  /// priori map) lays the grid out as a square of mapless_extent_m around `robot`, with every
  /// cell inside (nothing is known to be beyond a wall), or waits for `robot` when not given.
  void SetMap(const spott_map::MapDatabase& db, const std::optional<Vec2>& robot = std::nullopt);

  /// Integrates a sonar (or infrared) ring read with the robot at `robot` (map frame).
  void AddRing(const RangeRing& ring, const Pose2& robot);
  /// Integrates a range finder's points (QUADRIS profile; base frame) measured from `origin`
  /// (base frame), with the robot at `robot`. Each point votes on the doors its ray crosses when
  /// the mapper senses doors (as a beam without cone).
  void AddPoints(const Vec2& origin, const std::vector<Vec2>& points, const Pose2& robot);

  /// Whether the beams vote on door states (the controller stops the sonar's once profiles come).
  void SetSenseDoors(bool sense) {
    sense_doors_ = sense;
    if (!sense) door_votes_.clear();
  }

  /// Drops the evidence gathered so far (cell scores, confirmations not taken yet, door votes):
  /// it was placed with a pose that turned out wrong (the estimate jumped). The next SetMap or
  /// Take confirms the cells under the mapper's features that are still in the map again (the
  /// caller takes back the wrong ones first), so that Take keeps refining them.
  void Forget();

  /// The features confirmed since the last call that `db` does not hold yet (fused), and the
  /// door states sensed that differ from `db`'s. A newly confirmed cell's whole cluster (cells
  /// confirmed before included) is fused anew; the mapper's features in `db` that the cluster's
  /// cells or the features fused from it cover (its own: sensed, with this mapper's `sensor`
  /// attribute) are listed as replaced.
  SensedBatch Take(const spott_map::MapDatabase& db);
  /// Whether `f` is one of this mapper's features (a sensed segment or point of its sensor).
  bool IsOwn(const spott_map::MapFeature& f) const;

  /// Range-finder profiles refused as taken from a wrong pose (MappingParameters::near_miss_m).
  int profiles_refused() const { return profiles_refused_; }
  /// Confirmed cells waiting for Take (for tests and the live state).
  std::size_t pending() const { return pending_.size(); }
  /// Net door votes (> 0 closed, < 0 open) by door id.
  const std::map<std::string, int>& door_votes() const { return door_votes_; }
  int Score(const Vec2& p) const;  ///< Evidence at `p` (0 outside the grid).

 private:
  struct DoorZone {
    std::string id;
    spott_map::Segment opening;
  };
  /// After Forget: the cells under the mapper's features in `db` confirmed again.
  void Reseed(const spott_map::MapDatabase& db);
  /// `half_cone`: the beam's half width (rad; 0 for a range finder's point).
  void Beam(const Vec2& from, double angle, double range, bool echo, double max_range, int hit,
            double half_cone);
  /// Whether a known obstacle meets the arc at `range` (+- half a cell) across the cone.
  bool ArcMeetsKnown(const Vec2& from, double angle, double range, double half_cone) const;
  /// `ballot`: the votes are added there (one reading's, counted once by the caller), else to
  /// the doors' votes at once.
  void VoteDoors(const Vec2& from, double angle, double range, bool echo, double max_range,
                 double half_cone, std::map<std::string, int>* ballot = nullptr);
  /// The grid cell holding `p`; false when it lies outside the grid.
  bool CellOf(const Vec2& p, int* ix, int* iy) const;
  std::size_t Index(int ix, int iy) const { return static_cast<std::size_t>(iy) * width_ + ix; }

  std::string sensor_;
  MappingParameters p_;
  DoorSensingParameters d_;
  bool sense_doors_;
  std::uint64_t revision_ = ~0ull;
  bool have_map_ = false;
  bool reseed_ = false;  ///< Forget() ran: the next SetMap or Take reseeds from the features.
  bool static_drawn_ = false;
  Vec2 origin_{0.0, 0.0};
  int width_ = 0, height_ = 0;
  std::vector<std::int8_t> score_;
  /// The mean of the echoes each cell gained (fusion fits lines through them).
  struct EchoMean {
    float sx = 0.f, sy = 0.f;
    std::uint32_t n = 0;
    void Add(const Vec2& p) {
      sx += static_cast<float>(p.x());
      sy += static_cast<float>(p.y());
      ++n;
    }
    Vec2 Mean() const { return Vec2(sx / n, sy / n); }
  };
  std::vector<EchoMean> echoes_;
  /// The latest sonar echoes of each cell (index), echoes_per_cell at most, for the fusion.
  std::unordered_map<std::size_t, std::vector<SonarEcho>> heard_;
  bool rings_ = false;               ///< Rings come (AddRing): clusters by echo_cluster_gap_m.
  std::vector<std::uint8_t> flags_;  ///< kKnown | kBlocked | kDoor | kOutside | kConfirmed.
  std::vector<std::pair<int, int>> pending_;
  std::vector<DoorZone> doors_;
  std::map<std::string, int> door_votes_;
  int profiles_refused_ = 0;
};

/// Fuses cell centres into line segments (recursive split at the principal axis, then merge of
/// groups that share one) and points; `residual_m`: largest distance of a cell's square from its
/// segment (a centre may lie residual_m + cell_m / 2 off), `cell_m`: the cells' side. With
/// `echoes` (one list per cell: the sonar echoes it gained), a group heard at least 3 times is
/// fused from its echoes instead: the wall that explains most of them, spanning where they
/// reflected, or a point where a corner explains them better (plus a corner the wall's leftover
/// echoes show).
std::vector<spott_map::MapFeature> FuseIntoSegments(
    const std::vector<Vec2>& cells, double residual_m, double cell_m,
    const std::vector<std::vector<SonarEcho>>* echoes = nullptr,
    const EchoFitParameters& echo_fit = EchoFitParameters());

}  // namespace spott_tr_plus::controller
