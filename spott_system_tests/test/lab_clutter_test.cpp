// The localization beside objects its map lacks, on robot_sim's core: a B-12 (12 sonars, the
// only sensor) and a Nomad 200 (16) drive west through cim_office's laboratory past the unmapped
// crate and partition (the first legs of `markov_localization_eval tracking --route lab`), from a
// known start. Half of its beams read short there with the pose right; the lost detector must not
// call that a kidnap, because the relocalization that follows a false alarm in this clutter settled
// up to 18 m off (README of markov_localization: lost.judge_without_short_beams).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "eval_harness.h"

namespace markov_localization {
namespace eval {
namespace {

struct LabRun {
  int alarms = 0;
  double max_error_m = 0.0;
  std::string first_reason;
};

LabRun DriveThroughTheLab(const Models& m, std::uint64_t seed) {
  const Pose2 start{25.0, 10.8, 150.0 * M_PI / 180.0};
  Episode e(m, start, seed, /*known_start=*/true);
  GoTo go;
  // Waypoints in the map frame, steered on odometry from the true start (the route is the
  // experiment, not the localization's).
  std::vector<Vec2> waypoints;
  for (const Vec2& p : {Vec2(23.75, 11.55), Vec2(22.5, 12.3), Vec2(20.75, 12.4), Vec2(19.0, 12.5)})
    waypoints.push_back(MapToOdom(e.truth(), e.odom(), p));
  go.Set(waypoints, e.time(), 60.0);
  LabRun run;
  while (!go.done() && e.time() < 60.0) {
    const Status& s = e.Tick(go.Command(e));
    run.max_error_m = std::max(run.max_error_m, s.pos_error);
    if (s.lost_detector && run.alarms++ == 0) run.first_reason = s.lost_reason;
  }
  EXPECT_FALSE(go.timed_out()) << "seed " << seed;
  return run;
}

std::unique_ptr<Models> InCimOffice(const std::string& robot, bool judge_without_short_beams) {
  Settings s;
  s.resolution_m = 0.15;  // the evaluation's tracking grid
  s.heading_bins = 180;
  s.sigma_hit_m = 0.15;
  s.robot_dir = ROBOT_SIM_DIR;
  s.robot_name = robot;
  s.lost.judge_without_short_beams = judge_without_short_beams;
  return Models::Load(std::string(WORLDS_DIR) + "/cim_office.yaml", s);
}

// Seeds 4 and 6 raised a false alarm beside the partition at (22.0, 12.4) in the evaluation
// with the collapse judging every beam (the single scan's fit 0.07 x its usual with the pose
// 0.05 m off); seeds 1 and 5 with the averages judging every beam once the simulated sonar cones
// were sampled by 15 rays (2026-12-08: the fast average at 0.23 x, a collapse at 0.06 x). The
// Nomad 200 (16 sonars in three rows) hears the same clutter lower down.
TEST(LabClutter, PastTheUnmappedPartitionNoRobotIsLost) {
  for (const char* robot : {"b12", "nomad200"}) {
    const auto models = InCimOffice(robot, true);
    for (std::uint64_t seed : {1u, 4u, 5u, 6u, 10u}) {
      const LabRun run = DriveThroughTheLab(*models, seed);
      EXPECT_EQ(run.alarms, 0) << robot << " seed " << seed << ": " << run.first_reason;
      EXPECT_LT(run.max_error_m, 0.5) << robot << " seed " << seed;
    }
  }
}

// The same B-12 runs judging every beam (the rules before): the short beams make the detector
// fire with the pose right. Shows that the scene is the hard one.
TEST(LabClutter, JudgingTheShortBeamsTooRaisesFalseAlarms) {
  const auto models = InCimOffice("b12", false);
  int alarms = 0;
  for (std::uint64_t seed : {1u, 4u, 5u, 6u, 10u})
    alarms += DriveThroughTheLab(*models, seed).alarms;
  EXPECT_GT(alarms, 0);
}

}  // namespace
}  // namespace eval
}  // namespace markov_localization
