// Object recognition from QUADRIS range profiles (Zelek and Levine, sections III-A and V: "the
// QUADRIS range profiles are segmented and recognised as doors, chairs, desks and geons"; FIND's
// "object found", Figs. 11-13).
//
// How (README "Recognition"): the echoes of every profile that the map does not explain (not
// within `known_tolerance_m` of a CAD feature, a door's opening or an object recognised before;
// not the floor) are grouped into objects by 2-D proximity, over many profiles and both
// orientations. Each object keeps
//   - its footprint: the echoes' positions on a `cell_m` grid (horizontal profiles give its
//     faces at the head's height, vertical ones a line of points on each face they cross);
//   - its height: a vertical profile whose ray just above the object's run of echoes goes on
//     past it (its range longer by `top_jump_m`: an echo beyond, or none) has seen the top; a
//     run that reaches the edge of the profile gives only a lower bound; the rays that land on
//     a flat top (a desk's, below the heads) continue the face's run and add the top to the
//     footprint;
//   - whether a horizontal profile saw one face whole (both ends of its run against something
//     farther or nothing): until then a face may continue beyond the profile's field.
// An object is classified once `min_views` profiles saw it and its extent stopped growing (or
// no profile has met it for `quiet_profiles`: the heads moved on). The rectangle around its
// footprint whose sides the echoes lie on (or a circle when they lie on an arc) gives its
// sides, and the first model whose side and height bands contain the object names it (chair,
// desk, partition, shelf, cylinder, cuboid: the geons of [42] and the furniture of SPOTT's lab
// and offices). The
// sides seen are lower bounds of the real ones when only one face was seen, which is why a
// model's bands are wide and height carries most of the decision.
// ROS-free; the caller gives samples in the map frame.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "spott_map/map_database.h"

namespace spott_tr_plus::controller {

using spott_map::Vec2;
using Vec3 = Eigen::Vector3d;

/// One sample of a range profile (map frame).
struct ProfileSample {
  Vec3 point{0.0, 0.0, 0.0};  ///< Where the ray ended (m): its echo, or its maximum range.
  bool echo = true;           ///< false: nothing within the sensor's range.
};

/// An object class as range profiles show it (m). Sides: the footprint's longer and shorter
/// sides (a cylinder's diameter for both).
struct ObjectModel {
  std::string label;
  spott_map::FeatureType type = spott_map::FeatureType::kGeonCuboid;
  bool round = false;  ///< Its horizontal profile is an arc (a cylinder), else straight faces.
  double min_long_m = 0.0;
  double max_long_m = 0.0;
  double max_short_m = 0.0;
  double min_height_m = 0.0;
  /// <= 0: taller than the heads see over; the height seen must only reach min_height_m.
  double max_height_m = 0.0;
  /// The short side assumed when less of it was seen (one face only): the footprint grows to it
  /// away from where the heads saw it, so that the centre is not on the face (m; 0: none).
  double depth_m = 0.0;
  /// The short side seen must reach this (m): a shelf shows some depth, a wall seen 0.2 m off
  /// (the estimate's error) shows none.
  double min_short_m = 0.0;
  /// Its long side is open up to max_long_m: a face met at the heads' height that no profile saw
  /// whole (it may go on beyond the field) still names it. A chair must be seen whole (a part of
  /// a desk's face is chair-sized); a lab bench's 2 m face is wider than the field closer than
  /// 2.8 m and was never seen whole in 18 views.
  bool open_long = false;
};

/// Where recognition wants a head to look (ObjectRecognizer::ToLookAt).
struct LookTarget {
  Vec2 at{0.0, 0.0};  ///< The place (map).
  /// Tilt the head down to meet the object's face at this height (m); level when none.
  std::optional<double> height;
};

/// The furniture of SPOTT's lab and offices and the geons of [42], in the order tried.
std::vector<ObjectModel> DefaultObjectModels();

struct RecognitionParameters {
  double cell_m = 0.03;             ///< Footprint grid (m), in [0.005, 0.2].
  double cluster_gap_m = 0.2;       ///< Echoes this close belong to one object (m), > cell_m.
  double known_tolerance_m = 0.25;  ///< Echoes this close to a known feature are it (m), >= 0.
  double floor_m = 0.05;            ///< Echoes lower than this are the floor (m).
  double max_range_m = 3.5;         ///< Echoes farther from the head are not used (m), > 0.
  double top_jump_m = 0.15;         ///< The ray above a run this much farther: the top seen (m).
  /// Successive echoes up a vertical profile this close in height lie on a flat top (m).
  double top_flat_m = 0.02;
  /// A vertical run over a top below the heads within top_flat_m of an object's top joins it
  /// this far away (m), in [cluster_gap_m, max_extent_m]: parts of one desk along its face.
  double top_join_m = 0.8;
  int min_points = 12;  ///< Footprint cells needed (confirmed ones), >= 3.
  /// The same for an object only vertical profiles met, in [3, min_points]: each gives one
  /// line over its face and top, 2-4 cells (a desk passed at 2 m: 13 cells from 7 profiles).
  int min_vertical_points = 6;
  int min_cell_hits = 2;  ///< Profiles that must hit a cell (or a neighbour), in [1, 3].
  /// A cell only vertical profiles hit counts when min_cell_hits profiles hit within the block
  /// of this side around it or the eight beside it (m), in [cell_m, cluster_gap_m]: a vertical
  /// profile is one line up a face and over a top, and the heads' sweep puts the next one
  /// 0.05-0.4 m along the face, never in the same cell (a desk below the heads, seen by vertical
  /// profiles only, had 25 cells and none confirmed).
  double vertical_block_m = 0.15;
  int min_views = 3;       ///< Profiles that saw the object, >= 1.
  double growth_m = 0.06;  ///< Extent growth that resets the stability count (m), > 0.
  int stable_views = 2;    ///< Views without growth before a verdict, >= 0.
  /// Or: this many profiles since any met it (the heads or the robot turned away; a look-around
  /// passes each object once), >= 1.
  int quiet_profiles = 8;
  double circle_residual_m = 0.015;  ///< RMS distance from a fitted circle for "round" (m).
  double min_arc_rad = 0.8;          ///< Arc a round object's echoes must span (rad).
  double max_extent_m = 3.5;         ///< Objects larger than this are structure, never named.
  /// A thing taller than the heads see over whose far side lies this close (m) to a wall of the
  /// map parallel behind it stands with its back to the wall: its depth reaches the wall (a shelf
  /// seen face-on shows only its face, as thin as a partition); 0 = never, in [0, max_extent_m].
  double wall_depth_m = 0.8;
  /// CONTROL_THE_PTU turns a head to an unnamed object that needs a vertical profile (met at the
  /// heads' height with its top unseen) until this many vertical profiles met it; 0 = never.
  /// At 1 Hz the room sweep's vertical profiles lie 20-40 degrees apart as the robot looks
  /// around: a chair 14 degrees wide was passed by all of them and never named (FIND, seed 2).
  int look_views = 3;
  /// ... and, tilted down, meets this far below its top (m, in (0, 1]) an unnamed object whose top
  /// was seen, until 2 x look_views vertical profiles met it: the heads are above a desk, so a
  /// level profile never meets it, and a vertical one gives one footprint cell at 2.7 m (one
  /// 360-degree look-around at 1 Hz put one line on office 101's desk behind its chair).
  double look_below_top_m = 0.15;
  std::vector<ObjectModel> models = DefaultObjectModels();
};

std::vector<std::string> ValidateParameters(const RecognitionParameters& p);

/// The footprint of an object (map frame).
struct Footprint {
  Vec2 centre{0.0, 0.0};
  double yaw = 0.0;  ///< Direction of the long side (rad).
  double long_m = 0.0;
  double short_m = 0.0;
  bool round = false;     ///< The echoes lie on an arc (then the sides are its diameter).
  double radius_m = 0.0;  ///< The fitted circle's radius when round.
};

/// What has been seen of one object.
struct ObjectCandidate {
  std::vector<Vec2> points;  ///< Footprint cells' first echoes.
  /// The last three distinct profiles that hit each of them (0: none).
  std::vector<std::array<std::uint64_t, 3>> seen_by;
  std::vector<char> horizontal_hit;                     ///< A horizontal profile hit the cell.
  std::unordered_map<std::int64_t, std::size_t> cells;  ///< Key on the cell_m grid -> index.
  /// The last three distinct profiles that hit each vertical_block_m block.
  std::unordered_map<std::int64_t, std::array<std::uint64_t, 3>> blocks;
  /// Records an echo at `p` from `profile` (> 0) on the `p.cell_m` grid and its block.
  void Hit(const Vec2& at, std::uint64_t profile, bool vertical, const RecognitionParameters& p);
  /// The cells that `p.min_cell_hits` (<= 3) distinct profiles hit, counted over each cell and
  /// its eight neighbours (a moving robot's profiles scatter a face's echoes by a cell or so), or
  /// for a cell only vertical profiles hit over its block and the eight beside it. One profile
  /// placed with a wrong pose adds cells no other confirms: in a FIND run such a line made a
  /// chair 0.9 m long, so a desk.
  std::vector<Vec2> Confirmed(const RecognitionParameters& p) const;
  double height_seen_m = 0.0;   ///< Highest echo on it (m).
  std::optional<double> top_m;  ///< Height where a ray was seen passing over it (m).
  bool face_whole = false;      ///< A horizontal run with both ends free.
  bool horizontal = false;      ///< A horizontal profile met it.
  int views = 0;
  int vertical_views = 0;          ///< Vertical profiles among them.
  int stable = 0;                  ///< Views since its extent last grew.
  double extent_m = 0.0;           ///< Diagonal of its bounding box at the last view.
  std::uint64_t last_profile = 0;  ///< The last profile that met it.
  Vec2 viewer{0.0, 0.0};           ///< Where the heads were for that profile (map).
  std::string label;               ///< Recognised as ("": not yet).
};

/// The rectangle around `points` whose sides they lie closest to (1-degree steps; the smaller
/// when several fit, as a single straight face does), or the circle they lie on when it
/// fits within `p.circle_residual_m` over at least `p.min_arc_rad` and better than the
/// rectangle's sides.
Footprint FitFootprint(const std::vector<Vec2>& points, const RecognitionParameters& p);

/// The first model that `c` matches (its footprint in `fp`), nullptr when none does yet (seen
/// too little, or its extent still growing while `out_of_view` is false). `map`: its CAD walls
/// give the depth of a tall thing against one (wall_depth_m).
const ObjectModel* Classify(const ObjectCandidate& c, const RecognitionParameters& p, Footprint* fp,
                            bool out_of_view = false, const spott_map::MapDatabase* map = nullptr);

class ObjectRecognizer {
 public:
  explicit ObjectRecognizer(RecognitionParameters p);

  /// The map that explains echoes; it must outlive the recognizer (the controller's own).
  void SetMap(const spott_map::MapDatabase* db) { db_ = db; }

  /// One profile, its samples in the sensor's order (across the field), from `origin` (map).
  void AddProfile(const Vec3& origin, const std::vector<ProfileSample>& samples, bool vertical);

  /// Objects recognised since the last call, as labelled features (ids empty: the owner names
  /// them; attribute sensor=quadris).
  std::vector<spott_map::MapFeature> Take();

  /// Where a head should look (RecognitionParameters::look_views): at the middle of the echoes
  /// of the nearest unnamed object within max_range_m of `from`, met in the last kLookProfiles
  /// profiles, that no vertical profile has shown the top of (level), or whose top was seen
  /// (tilted down, look_below_top_m); nullopt when none.
  std::optional<LookTarget> ToLookAt(const Vec2& from) const;

  /// Drops everything seen (the pose they were placed with was wrong).
  void Forget() { candidates_.clear(); }

  const std::vector<ObjectCandidate>& candidates() const { return candidates_; }

 private:
  /// `near`: the features around the profile (FeaturesIn once per profile).
  bool Known(const Vec2& p, const std::vector<const spott_map::MapFeature*>& near) const;
  /// The index of the candidate `run` belongs to (merging those it bridges), or of a new one.
  /// `top`: the run is a vertical profile's that went over the object's top, below the heads, at
  /// this height.
  std::size_t CandidateFor(const std::vector<Vec2>& run, std::optional<double> top);

  /// An object no profile met for this many (6 s of two heads' profiles in both orientations)
  /// is no longer looked at: the looks at it miss.
  static constexpr std::uint64_t kLookProfiles = 24;

  RecognitionParameters p_;
  const spott_map::MapDatabase* db_ = nullptr;
  std::vector<ObjectCandidate> candidates_;
  std::uint64_t profiles_ = 0;
};

}  // namespace spott_tr_plus::controller
