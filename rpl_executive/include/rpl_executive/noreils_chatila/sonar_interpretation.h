// The ultrasonic module's line interpretation (section 3.1, Fig. 2's "levels of interpretation":
// echoes -> lines), which S_us-perception and the wall-following process read.
//
// Method (README "Sonar interpretation"): a sonar returns the nearest point of a surface inside
// its beam, not a point on its axis. For a line with normal direction theta (robot frame,
// pointing from the robot to the line) at distance rho from the robot's centre, sensor i at
// m_i with axis alpha_i and half-opening h sees range
//     r_i = (rho - n(theta).m_i) / c_i,  c_i = 1 if |theta - alpha_i| <= h
//                                        c_i = cos(|theta - alpha_i| - h) otherwise
// (the beam's edge nearest the normal). For a window of adjacent sensors with echoes, rho is
// linear given theta (closed-form least squares), so theta is found by a 1-degree grid over
// the window's beams plus a golden-section refinement, minimising the squared range residuals.
// A window is a line when it has at least min_sensors echoes and an RMS residual under
// max_rms_m; windows grow from each sensor while they still fit and only maximal ones are kept.
#pragma once

#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/sensor_data.h"

namespace rpl_executive::noreils_chatila {

struct SonarInterpretationParameters {
  int min_sensors = 3;                ///< echoes in a line, [2, 16]: two echoes fit any line
  double max_rms_m = 0.03;            ///< RMS range residual of a line, (0, 1]
  double max_range_m = 3.0;           ///< echoes farther are not used, (0, inf)
  double search_margin_rad = 0.35;    ///< theta searched this far beyond the beams, [0, pi/2)
  double rho_tolerance_m = 0.10;      ///< S_us-perception match on rho, (0, inf)
  double theta_tolerance_rad = 0.17;  ///< S_us-perception match on theta, (0, pi)
};

/// Every violation, "name: what is wrong" (empty when valid).
std::vector<std::string> ValidateParameters(const SonarInterpretationParameters& p);

/// A line perceived by the belt, in the robot's frame.
struct SonarLine {
  double rho_m = 0.0;      ///< distance from the robot's centre
  double theta_rad = 0.0;  ///< direction of the normal from the robot to the line, (-pi, pi]
  double rms_m = 0.0;      ///< RMS of the range residuals
  int first_sensor = 0;    ///< the window's sensors, numbered from 1, counter-clockwise
  int sensor_count = 0;
};

/// The lines of one scan (maximal windows only; none when no window fits).
std::vector<SonarLine> InterpretLines(const SonarScan& scan, const SonarRing& ring,
                                      const SonarInterpretationParameters& parameters);

/// The range that sensor `mount` would read from the line (rho, theta) by the model above, or a
/// negative value when the sensor is on the far side of the line or the beam cannot reach it.
double PredictedRange(const SonarMount& mount, double half_field_of_view_rad, double rho_m,
                      double theta_rad);

/// True when one of `lines` matches (rho, theta) within the tolerances.
bool PerceivesLine(const std::vector<SonarLine>& lines, double rho_m, double theta_rad,
                   const SonarInterpretationParameters& parameters);

}  // namespace rpl_executive::noreils_chatila
