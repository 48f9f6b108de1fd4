// The checker of mission files: unknown operators, conditions and variables, arity and the
// shape of every argument that is known before the mission runs, and where each keyword may
// appear, all reported with file, line and column before anything runs.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/diagnostic.h"
#include "rpl_executive/noreils_chatila/mission.h"
#include "rpl_executive/noreils_chatila/value.h"

namespace rpl_executive::noreils_chatila {

struct CheckOptions {
  /// Variables the caller serves (the world's zones and paths from world_server), in mission
  /// units. A define of the same name overrides them (a warning when the values differ).
  std::map<std::string, Value> world_variables;
  int sonar_count = 16;  ///< sensors of S_us-threshold are numbered 1..sonar_count
};

/// Terminal or not (section 5): the grammar marks only STATIC; a monitor is terminal when its
/// reflex action stops the current action, i.e. holds an operator that halts it (stop), as
/// Example 1's monitors and Example 2's S2 do; otherwise it is non-terminal, as Example 2's S1
/// (reflex set-speed: smooth-move goes on while the control action runs beside it).
bool IsTerminal(const Monitor& monitor);

/// Every variable some (set ...) of the file assigns (mission, sub-missions, O-surveillances).
std::set<std::string> AssignedVariables(const MissionFile& file);

/// Every error and warning of `file` (empty when it is fine).
std::vector<Diagnostic> CheckMissionFile(const MissionFile& file,
                                         const CheckOptions& options = CheckOptions());

}  // namespace rpl_executive::noreils_chatila
