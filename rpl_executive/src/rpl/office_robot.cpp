#include "rpl_executive/rpl/office_robot.h"

namespace rpl_executive {
namespace rpl {
namespace office {

ModuleSpec NavigationSpec() {
  return {kNavigation,
          1,
          1,
          {kWheels},
          "moves the robot to a destination (X Y) (m, map) through a structured navigation plan"};
}

ModuleSpec PositionTrackingSpec() {
  return {kPositionTracking, 0, 0, {}, "tracks the robot's pose passively"};
}

ModuleSpec ActiveLocalizationSpec() {
  return {kActiveLocalization,
          0,
          0,
          {kWheels},
          "relocalizes the robot actively until POS-CERTAINTY* is above its threshold"};
}

std::vector<FluentSpec> Fluents() {
  return {
      {kX, Value::Number(0.0), "x of the position estimate (m, map)"},
      {kY, Value::Number(0.0), "y of the position estimate (m, map)"},
      {kO, Value::Number(0.0), "orientation of the position estimate (rad, map)"},
      {kPosCertainty, Value::Number(0.0),
       "confidence in the global maximum of the position probability distribution"},
      {kNavigationActive, Value(), "T whenever the robot executes a navigation plan"},
      {kNrOfNavGoals, Value::Number(0.0),
       "number of remaining target points in the current navigation plan"},
  };
}

Vocabulary OfficeVocabulary() {
  Vocabulary v;
  v.fluents = Fluents();
  v.modules = {NavigationSpec(), PositionTrackingSpec(), ActiveLocalizationSpec()};
  v.valves = {kWheels};
  return v;
}

}  // namespace office
}  // namespace rpl
}  // namespace rpl_executive
