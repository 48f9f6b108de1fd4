// Range rings, laser scans and their readings as the nodes take them (issue 21's rules, one place
// for every node): NaN is a dropped-out sensor, left out of every update; a reading below 0 or
// beyond max_range is impossible and is discarded as dropped out (sensor_msgs/Range's rule).
#pragma once

#include <string>
#include <vector>

#include <sensor_msgs/LaserScan.h>
#include <spott_msgs/RangeRing.h>

namespace spott_ros {

/// Makes every impossible reading of `ranges` NaN (beyond max_range by more than 0.1 %, which
/// float rounding of a max-range reading may give). Returns the first such index, or -1.
int DiscardImpossibleRanges(double max_range, std::vector<double>* ranges);

/// The refusal's reason for the first reading DiscardImpossibleRanges dropped: "ranges[i] = v is
/// outside [0, max_range]: discarded as dropped out".
std::string DiscardedReadingWhy(int index, double value);

/// Why a ring cannot be used at all, as "field: why", or "": max_range not in (0, 1000) m (every
/// reading would be "no echo"), min_range not in [0, max_range), field_of_view not in (0, pi),
/// not one mount per range, a mount that is not finite or lies beyond 10 m of the base.
std::string RangeRingProblem(const spott_msgs::RangeRing& ring);

/// Why a scan cannot be used at all, as "field: why", or "": angle_min finite, angle_increment
/// finite, not 0 and at most half a turn, 0 <= range_min < range_max < 1000 m, 1 to 100,000
/// beams, and every beam's angle within [-2 pi, 2 pi] (an increment of 1e38 is finite, the beams'
/// angles would not be).
std::string LaserScanProblem(const sensor_msgs::LaserScan& scan);

}  // namespace spott_ros
