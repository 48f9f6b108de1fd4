// A planar pose written as text, "x y yaw" (m, m, rad in the map frame): how launch files and
// parameters name a start pose (robot_sim's start_pose, markov_localization's initial_pose).
#pragma once

#include <optional>
#include <string>

#include "spott_map/world.h"

namespace spott_map {

/// Three finite numbers separated by white space and nothing else. On failure returns nullopt
/// and, if `error` is given, says what was wrong ("expected 'x y yaw' ...").
std::optional<Pose2> ParsePoseText(const std::string& text, std::string* error = nullptr);

}  // namespace spott_map
