// Range readings as the nodes take them from a ring or a scan (issue 21's rule, one place for
// every node): NaN is a dropped-out sensor, left out of every update; a reading below 0 or
// beyond max_range is impossible and is discarded as dropped out (sensor_msgs/Range's rule).
#pragma once

#include <vector>

namespace spott_ros {

/// Makes every impossible reading of `ranges` NaN (beyond max_range by more than 0.1 %, which
/// float rounding of a max-range reading may give). Returns the first such index, or -1.
int DiscardImpossibleRanges(double max_range, std::vector<double>* ranges);

}  // namespace spott_ros
