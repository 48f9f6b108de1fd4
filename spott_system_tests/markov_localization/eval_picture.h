// A picture of a belief for the README and the evaluation runs (eval_picture.cpp).
#pragma once

#include <string>
#include <vector>

#include "markov_localization/certainty.h"
#include "markov_localization/map_model.h"

namespace markov_localization {
namespace eval {

/// Writes the belief's marginal over theta as a PNG (log scale, six decades; walls black,
/// non-states light grey), the true pose red and the modes' means blue. False when the file
/// cannot be written.
bool WriteBeliefPicture(const MapModel& map, const BeliefSnapshot& belief, const Pose2& truth,
                        const std::vector<Mode>& modes, const std::string& path);

}  // namespace eval
}  // namespace markov_localization
