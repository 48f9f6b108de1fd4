// Structured reactive navigation plans (Beetz et al. section 3.1, Fig. 12): for a destination, a
// sequence of target points that "ensures that, for instance, the robot goes orthogonally through
// doorways and does not pass other offices on its way to the destination", and the regions of the
// travel modes "office" (slow: offices are cluttered), "hallway" (fast) and "doorway" (the sonars
// off against crosstalk) that the robot crosses on the way. "The navigation between the target
// points is accomplished by a standard path planner": on the stack, each target point is one
// Navigate goal.
//
// ROS-free: the building is given as rooms (polygons, office or hallway) and doors (the opening on
// the shared boundary, open or closed), as world_server's room/door graph carries them. Map frame,
// metres.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rpl_executive {
namespace rpl {
namespace office {

struct Point {
  double x_m = 0.0;
  double y_m = 0.0;
};

struct BuildingRoom {
  std::string id;
  bool hallway = false;        ///< a portion of hallway (else an office or room)
  std::vector<Point> polygon;  ///< outline, either orientation
};

struct BuildingDoor {
  std::string id;
  std::string room_a, room_b;  ///< the rooms it joins
  bool open = true;            ///< closed doors are not passed (unknown ones count as open)
  Point centre;                ///< of the opening
  Point end_a, end_b;          ///< the opening's two ends on the shared boundary
  /// An access way without a door leaf (world_server's KIND_OPENING), e.g. between two portions
  /// of one hallway: passed without target points of its own and not a doorway region, unless it
  /// leads into an office.
  bool opening = false;
};

struct BuildingMap {
  std::vector<BuildingRoom> rooms;
  std::vector<BuildingDoor> doors;
  const BuildingRoom* FindRoom(const std::string& id) const;
  /// The room holding `p` (border included); else the nearest within `tolerance_m` (a pose just
  /// inside a wall's thickness); else null.
  const BuildingRoom* RoomAt(const Point& p, double tolerance_m = 0.3) const;
};

enum class TravelMode { kNone, kOffice, kHallway, kDoorway };
/// "none", "office", "hallway", "doorway".
const char* TravelModeName(TravelMode mode);

/// One region of the plan's second component (Fig. 12's textures).
struct TravelRegion {
  TravelMode mode = TravelMode::kNone;
  std::string id;              ///< the room's or the door's id
  std::vector<Point> polygon;  ///< map frame (m)
};

struct NavigationPlanParameters {
  /// Target points this far before and after each door, on the line through the door's centre
  /// normal to the opening: the robot passes doorways orthogonally. (0, 5] m.
  double door_approach_m = 0.8;
  /// The doorway region reaches this far from the door line on either side. (0, 5] m.
  double doorway_depth_m = 0.6;
  /// ... and this far beyond the opening's ends. [0, 2] m.
  double doorway_margin_m = 0.1;
  /// Cost of passing through an office that is neither the start's nor the destination's room,
  /// added to the path length: plans "do not pass other offices" unless there is no other way.
  /// [0, 1e6] m.
  double office_pass_penalty_m = 1000.0;
  /// A target point nearer than this to the one after it (or to the start, for the first) is
  /// left out. [0, 5] m.
  double min_target_spacing_m = 0.3;
};

/// Every violation, by parameter name.
std::vector<std::string> ValidateParameters(const NavigationPlanParameters& p);

struct NavigationPlan {
  std::vector<std::string> rooms;     ///< from the start's room to the destination's
  std::vector<std::string> doors;     ///< doors[i] joins rooms[i] and rooms[i + 1]
  std::vector<Point> targets;         ///< the target points in order; the last is the destination
  std::vector<TravelRegion> regions;  ///< doorways first, then the rooms on the path
  /// "room_c -> door_c -> corridor_c -> door_b -> room_b: 5 target points".
  std::string Summary() const;
};

/// The plan from `start` to `destination`; nullopt with `*error` when either lies outside every
/// room or every way between them is closed ("no open way from room_c to room_b: door_b is
/// closed").
std::optional<NavigationPlan> PlanNavigation(const BuildingMap& map, const Point& start,
                                             const Point& destination,
                                             const NavigationPlanParameters& parameters,
                                             std::string* error);

/// The travel mode at `p`: a doorway region wins over the rooms; kNone outside every region.
TravelMode TravelModeAt(const std::vector<TravelRegion>& regions, const Point& p);

/// Point in polygon (border included, either orientation).
bool InsidePolygon(const std::vector<Point>& polygon, const Point& p);

}  // namespace office
}  // namespace rpl
}  // namespace rpl_executive
