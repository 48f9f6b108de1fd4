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
// (the paper used cm); a value is a number or a name (`room(R2)`).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

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
  };
  Kind kind = Kind::kDisc;
  TargetGeometry target;
  double min_distance = 0, max_distance = 0, tolerance = 0;
  double goal_x = 0, goal_y = 0;  ///< the point sent to the planners (m, map frame)
  /// kDisc of `beside` / `to-the-side-of`: either side will do, (alt_x, alt_y) is the other.
  bool has_alternative = false;
  double alt_x = 0, alt_y = 0;
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
/// (in-front-of, behind, to-the-left-of, ...) are taken from the robot's point of view.
TaskInterpretResult InterpretTask(const TaskCommand& command, double robot_x, double robot_y,
                                  double robot_yaw, const TaskInterpretationParameters& params,
                                  const PlaceResolver& resolve = nullptr,
                                  const std::string& source = "task");

}  // namespace spott_tr_plus
