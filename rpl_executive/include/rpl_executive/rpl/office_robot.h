// The behaviour modules and global fluents of the office delivery robot (Beetz et al. section 3:
// NAVIGATION, POSITION-TRACKING, ACTIVE-LOCALIZATION; X*, Y*, O*, POS-CERTAINTY*,
// NAVIGATION-ACTIVE?*, NR-OF-NAV-GOALS*; the valve WHEELS). The node implements the modules on the
// stack (Navigate goals, markov_localization) and sets the fluents; tests implement them with
// scripted fakes. Both take the names and arities from here, so plans check the same way.
#pragma once

#include <vector>

#include "rpl_executive/rpl/vocabulary.h"

namespace rpl_executive {
namespace rpl {
namespace office {

constexpr const char* kNavigation = "NAVIGATION";
constexpr const char* kPositionTracking = "POSITION-TRACKING";
constexpr const char* kActiveLocalization = "ACTIVE-LOCALIZATION";
constexpr const char* kWheels = "WHEELS";

constexpr const char* kX = "X*";                                  // m, map frame
constexpr const char* kY = "Y*";                                  // m, map frame
constexpr const char* kO = "O*";                                  // rad, map frame
constexpr const char* kPosCertainty = "POS-CERTAINTY*";           // [0, 1]
constexpr const char* kNavigationActive = "NAVIGATION-ACTIVE?*";  // T while a plan is executed
constexpr const char* kNrOfNavGoals = "NR-OF-NAV-GOALS*";         // remaining target points

/// (EXECUTE NAVIGATION (X Y)): "can be activated with a destination as its argument" (section 3).
/// On Activate the module generates the structured navigation plan (target points, section 3.1)
/// from the robot's pose at that moment, sets NR-OF-NAV-GOALS* to their number and
/// NAVIGATION-ACTIVE?* to T before it returns, decrements NR-OF-NAV-GOALS* as they are reached,
/// reports success within its goal tolerance of the destination and failure, with the planner's
/// reason, when the destination is unreachable. Deactivate deletes every target point:
/// NR-OF-NAV-GOALS* 0, NAVIGATION-ACTIVE?* NIL. Needs WHEELS.
ModuleSpec NavigationSpec();
/// (ACTIVATE POSITION-TRACKING): passive tracking of the pose (section 2). No valve.
ModuleSpec PositionTrackingSpec();
/// (ACTIVATE ACTIVE-LOCALIZATION): drives the robot to target points that minimize the expected
/// entropy plus travel cost until the pose is certain (section 2.2); reports success when
/// POS-CERTAINTY* exceeds its threshold, failure when it gives up. Needs WHEELS.
ModuleSpec ActiveLocalizationSpec();

/// The six fluents of section 3's table, with their values before the node sets them (not
/// localized: POS-CERTAINTY* 0).
std::vector<FluentSpec> Fluents();

/// The whole vocabulary (modules, fluents, WHEELS): for checking plans without a robot.
Vocabulary OfficeVocabulary();

}  // namespace office
}  // namespace rpl
}  // namespace rpl_executive
