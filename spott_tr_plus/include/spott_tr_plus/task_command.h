// The SPOTT task-command language (Zelek and Levine, section III-B) and its interpretation.
//
// The paper's BNF, with the three decisions it needs (README "Task commands"):
//   TASK        ::= VERB DESTINATION DIRECTION SPEED
//   VERB        ::= go | find
//   DESTINATION ::= TARGET | PREPOSITION TARGET | <>
//   DIRECTION   ::= ORIENTATION | PATH TARGET | <>
//   SPEED       ::= slowly | quickly | normal | <>          (1: omitted speed is normal)
//   PREPOSITION ::= across | against | along | alongside | around | at | behind | beside |
//                   beyond | by | far | in | inside | in-back-of | in-front-of | in-line-with |
//                   near | out | outside | to-the-left-of | to-the-right-of | to-the-side-of
//   ORIENTATION ::= forward | backward | left | right | north | south | east | west
//   PATH        ::= along | around | via | to | toward | from | away-from
//   TARGET      ::= (PLACES | MOVEABLE-OBJ | 2D-MODELS | GEONS) ATTRIBUTES
//   ATTRIBUTES  ::= '(' value { ',' value } ')' | <>        (2: attributes may be omitted)
//   PLACES ::= door | hallway | room | wall     MOVEABLE-OBJ ::= chair | desk
//   2D-MODELS ::= ellipse | line | point | rectangle     GEONS ::= cuboid | cylinder | ellipse
// (3) `ellipse` is a 2-D model with 4 or 5 numbers (x, y, a, b[, theta]) and a geon with 6
// (x, y, z, a, b, c); without attributes it names either. `along` and `around` are both
// prepositions and path words: right after the verb they are the destination's preposition,
// after a destination they are the direction's path word. Values are in metres and radians
// (the paper used cm); a value is a number or a name (`room(R2)`, `point(corner)`): a world
// id, read by exactly spott_map's id rule (spott_map::IsValidId).
// Every part after the verb may be empty, so `go`, `go quickly` and `find` parse, and `find`
// takes a preposition as `go` does (`find near door(1, 2)`: look for a door near (1, 2)). The
// interpretation refuses, with the reason, what names no goal: a `go` without destination,
// orientation or path, a `find` without an object, a preposition about an object whose
// location is not given.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "spott_map/map_database.h"
#include "spott_tr_plus/diagnostic.h"

namespace spott_tr_plus {

enum class Verb { kGo, kFind };
enum class Speed { kSlowly, kNormal, kQuickly };
enum class TargetClass { kPlace, kMoveableObject, kModel2D, kGeon };

struct Target {
  std::string word;  ///< "door", "chair", "ellipse", ...
  TargetClass klass = TargetClass::kPlace;
  bool either_ellipse = false;  ///< bare `ellipse`: a 2-D model or a geon
  std::vector<double> numbers;  ///< numeric attributes (m, rad)
  std::string name;             ///< a named attribute: `room(R2)`
  bool has_attributes = false;
  Location where;
};

struct TaskCommand {
  Verb verb = Verb::kGo;
  Location where;           ///< the verb
  std::string preposition;  ///< empty: no preposition (a bare target or no destination)
  std::optional<Target> destination;
  std::string orientation;  ///< forward, ..., west; empty if none
  std::string path;         ///< along, ..., away-from; empty if none
  std::optional<Target> path_target;
  Speed speed = Speed::kNormal;
  bool speed_given = false;
};

struct TaskParseResult {
  std::optional<TaskCommand> command;
  std::vector<Diagnostic> diagnostics;  ///< "task:1:COLUMN: expected ..., found ..."
  bool ok() const { return command.has_value(); }
};

/// Parses one task command. Errors name the column and what was expected.
TaskParseResult ParseTaskCommand(const std::string& text, const std::string& source = "task");

/// The command back as text in the grammar's words (parsing it gives the same command).
std::string ToText(const TaskCommand& command);

// --- Interpretation ------------------------------------------------------------------------------

/// A target's footprint in the map frame: an oriented box (a point has zero half-extents, a
/// line or wall zero width) and, for places looked up in the map, their polygon.
struct TargetGeometry {
  double x = 0, y = 0;                             ///< centre (m)
  double theta = 0;                                ///< orientation of the long axis (rad)
  double half_length = 0;                          ///< along the long axis (m)
  double half_width = 0;                           ///< across it (m)
  std::vector<std::pair<double, double>> polygon;  ///< optional exact outline (m)
  /// The map element it was looked up as (a room, door, feature or place id); empty when
  /// given by coordinates.
  std::string map_id;
};

/// A goal region (SPOTT III-B: "spatial prepositions act as modifiers of the target location").
struct GoalRegion {
  enum class Kind {
    kWithin,     ///< distance to the target's footprint in [min_distance, max_distance]
    kBeyond,     ///< distance to the footprint >= min_distance
    kInside,     ///< inside the footprint
    kOutside,    ///< outside it, within max_distance of it
    kAlongside,  ///< within max_distance, beside the long axis (projection inside its extent)
    kDisc,       ///< within `tolerance` of (goal_x, goal_y)
    /// On one side of the footprint: past its extent in direction (side_x, side_y), at a
    /// distance in [min_distance, max_distance] from it; with `both_sides` the opposite side too.
    kSide,
  };
  Kind kind = Kind::kDisc;
  TargetGeometry target;
  double min_distance = 0, max_distance = 0, tolerance = 0;
  double side_x = 0, side_y = 0;  ///< kSide: unit vector (map frame)
  double half_span = 0;     ///< kSide: largest distance from the target's centre across it (m)
  bool both_sides = false;  ///< kSide: `beside`, `to-the-side-of`: either side will do
  /// The point sent to the planners (m, map frame). With a map (TaskMap) it lies in the free,
  /// reachable part of the region in `rooms`.
  double goal_x = 0, goal_y = 0;
  /// With a map: the rooms the goal is restricted to (the target's room(s)), and the area of
  /// the region's free part reachable from the robot there (m^2). Without a map: empty, 0.
  std::vector<std::string> rooms;
  double free_area_m2 = 0;
  /// Geometric membership (the map is not consulted).
  bool Contains(double x, double y) const;
};

/// How the direction biases the local planner's gradient descent (SPOTT III-B: "the role of
/// specifying the direction is to bias the local path planning execution").
struct DirectionBias {
  enum class Kind {
    kNone,
    kRelativeHeading,  ///< forward/backward/left/right: `angle` in base_link (rad)
    kAbsoluteHeading,  ///< north/south/east/west and fixed headings: `angle` in map (rad)
    kAttract,          ///< `to`: toward (x, y), recomputed as the robot moves
    kRepel,            ///< `away-from`: away from (x, y), recomputed
    kWaypoint,         ///< `via`: toward (x, y) until within `radius`, then no bias
    kCirculate,        ///< `around`: tangent to the circle about (x, y), sense `sense` (+1 ccw)
  };
  Kind kind = Kind::kNone;
  double angle = 0;
  double x = 0, y = 0;
  double radius = 0;
  double sense = 1;
  /// The unit bias vector in the map frame for a robot at (rx, ry) with heading ryaw; (0, 0)
  /// when there is no bias.
  std::pair<double, double> At(double rx, double ry, double ryaw) const;
};

/// Parameters of the interpretation (metres, fractions of the maximum speed).
struct TaskInterpretationParameters {
  double at_distance_m = 0.3;       ///< `at`, and the offset of side/front/behind goals
  double against_distance_m = 0.1;  ///< `against`: touching
  double near_distance_m = 1.0;     ///< `near`, `by`, `around`, `outside`, `alongside`
  double far_distance_m = 3.0;      ///< `far`
  double beyond_distance_m = 1.0;   ///< `beyond`: past the far side
  double goal_tolerance_m = 0.25;   ///< radius of point goals
  double default_door_width_m = 0.9, default_chair_radius_m = 0.3;
  double default_desk_length_m = 1.2, default_desk_width_m = 0.6;
  double slow_fraction = 0.3, normal_fraction = 0.6, quick_fraction = 1.0;
  /// Cell side of the free-space raster goals are fitted in (m), in (0, 0.5] (TaskMap).
  double free_space_resolution_m = 0.05;
};

/// Every violation by parameter name (empty: valid).
std::vector<std::string> ValidateParameters(const TaskInterpretationParameters& p);

struct TaskInterpretation {
  enum class Mode { kGoTo, kSearch, kTeleoperate };
  Mode mode = Mode::kGoTo;
  std::optional<GoalRegion> goal;  ///< kGoTo; kSearch when the object's location is given
  std::optional<Target> sought;    ///< kSearch: the object to find
  DirectionBias bias;
  double speed_fraction = 0.6;   ///< of the robot's maximum speed
  std::string ToString() const;  ///< human-readable, for ParseTask.srv
};

/// Looks up a named place (`room(R2)`) or a place given without attributes in the map.
using PlaceResolver = std::function<std::optional<TargetGeometry>(const Target&)>;

/// The map a goal point must respect (SPOTT III-A, the map database). With it a goal region is
/// intersected with the free space of the target's room(s) that the robot can reach (through
/// open doors, around known obstacles), obstacles grown by `padding_m`, before its point is
/// chosen: the point the geometry prefers when it is there, else the nearest one there; a
/// region with no such point is refused with the reason.
struct TaskMap {
  /// Walls and sensed features (every feature is an obstacle, as in the planners' rasters),
  /// rooms and doors with their states (closed doors are obstacles). Must outlive the call.
  /// Without rooms (no a priori map) goals are not fitted: they are the geometry's.
  const spott_map::MapDatabase* database = nullptr;
  /// Robot radius + localization error (m), >= 0: the same padding as the planners'.
  double padding_m = 0.0;
};

/// A resolver looking names up in a map database (ids of its rooms and hallways, doors and
/// features: walls, chairs, desks, ...) and in `places` (`point(NAME)`). Captures references:
/// `db` and `places` must outlive it.
PlaceResolver MapPlaceResolver(const spott_map::MapDatabase& db,
                               const std::vector<spott_map::Place>& places = {});

struct TaskInterpretResult {
  std::optional<TaskInterpretation> interpretation;
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return interpretation.has_value(); }
};

/// The footprint a target's attributes give (nullopt when they do not give one).
std::optional<TargetGeometry> GeometryFromAttributes(const Target& t,
                                                     const TaskInterpretationParameters& p);

/// Turns a parsed task into a goal region + direction bias + speed, a search, or tele-operation.
/// (robot_x, robot_y, robot_yaw) is the robot's pose in the map frame: the deictic prepositions
/// (in-front-of, behind, to-the-left-of, ...) are taken from the robot's point of view. This
/// form has no map: goal points are the geometry's (SPOTT without an a priori map).
TaskInterpretResult InterpretTask(const TaskCommand& command, double robot_x, double robot_y,
                                  double robot_yaw, const TaskInterpretationParameters& params,
                                  const PlaceResolver& resolve = nullptr,
                                  const std::string& source = "task");

/// The same with the map: goal points lie in the free space of the right room that the robot
/// can reach (TaskMap); unreachable goal regions are refused with why.
TaskInterpretResult InterpretTask(const TaskCommand& command, double robot_x, double robot_y,
                                  double robot_yaw, const TaskInterpretationParameters& params,
                                  const TaskMap& map, const PlaceResolver& resolve = nullptr,
                                  const std::string& source = "task");

}  // namespace spott_tr_plus
