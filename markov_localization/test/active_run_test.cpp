// The sequencing of an active localization run (ActiveLocalizationRun): random motion first,
// then choose / drive / re-choose until certain, and each way of giving up with its reason.
#include <gtest/gtest.h>

#include "markov_localization/active_run.h"

namespace markov_localization {
namespace {

RunInput At(double t, double certainty, double distance, Pose2 frame = Pose2{0, 0, 0},
            Pose2 odom = Pose2{0, 0, 0}) {
  RunInput in;
  in.odom = odom;
  in.now_s = t;
  in.certainty = certainty;
  in.odom_distance_m = distance;
  in.map_to_odom = frame;
  return in;
}

TEST(ActiveRun, BadRequestsAreRefusedWithTheirReason) {
  ActiveRequest r;
  EXPECT_EQ(CheckRequest(r), "");  // 0 / 0: the node's threshold, no time limit
  r.timeout_s = -1.0;
  EXPECT_NE(CheckRequest(r).find("timeout must be >= 0"), std::string::npos) << CheckRequest(r);
  r.timeout_s = std::nan("");
  EXPECT_NE(CheckRequest(r).find("timeout"), std::string::npos);
  r.timeout_s = 30.0;
  for (double bad : {1.0, 1.5, -0.2}) {
    r.certainty_threshold = bad;
    EXPECT_NE(CheckRequest(r).find("certainty_threshold must be in (0, 1)"), std::string::npos)
        << bad;
  }
  r.certainty_threshold = 0.9;
  EXPECT_EQ(CheckRequest(r), "");
  EXPECT_DOUBLE_EQ(EffectiveThreshold(r, 0.8), 0.9);
  r.certainty_threshold = 0.0;
  EXPECT_DOUBLE_EQ(EffectiveThreshold(r, 0.8), 0.8);
}

TEST(ActiveRun, RandomMotionOfTenMetresComesBeforeTheFirstChoice) {
  ActiveRunParameters p;  // random_motion_m = 10
  ActiveLocalizationRun run(p, 0.8, 0.0, true, At(100.0, 0.0, 50.0));
  EXPECT_EQ(run.phase(), RunPhase::kWander);
  EXPECT_EQ(run.Step(At(101.0, 0.1, 50.0)), RunAction::kWander);
  EXPECT_EQ(run.Step(At(120.0, 0.4, 59.9)), RunAction::kWander);  // 9.9 m since the start
  EXPECT_EQ(run.Step(At(121.0, 0.5, 60.0)), RunAction::kChoose);  // 10 m
  EXPECT_EQ(run.phase(), RunPhase::kChoose);
  EXPECT_EQ(run.Step(At(121.1, 0.5, 60.0)), RunAction::kChoose);  // until a choice is reported
}

TEST(ActiveRun, WithoutRandomMotionItChoosesAtOnce) {
  ActiveLocalizationRun run(ActiveRunParameters{}, 0.8, 0.0, false, At(0, 0.5, 0));
  EXPECT_EQ(run.Step(At(0.1, 0.5, 0)), RunAction::kChoose);
}

TEST(ActiveRun, ChoosesDrivesAndRechoosesUntilCertain) {
  ActiveRunParameters p;
  p.confirm_s = 0.0;  // the paper: done at the first scan above the threshold
  ActiveLocalizationRun run(p, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 0)), RunAction::kChoose);
  run.OnChoice(true, 4.0, -3.0, At(1, 0.5, 0));
  EXPECT_EQ(run.phase(), RunPhase::kNavigate);
  EXPECT_EQ(run.Step(At(2, 0.5, 1)), RunAction::kWait);
  run.OnNavigationDone(true, "", At(9, 0.6, 5));
  EXPECT_EQ(run.targets_visited(), 1);
  EXPECT_EQ(run.Step(At(9.1, 0.6, 5)), RunAction::kChoose);  // re-choose after each target
  run.OnChoice(true, 2.0, 0.0, At(9.1, 0.6, 5));
  EXPECT_EQ(run.Step(At(10, 0.79, 6)), RunAction::kWait);
  EXPECT_EQ(run.Step(At(11, 0.81, 7)), RunAction::kSucceed);  // certain while driving: done
  EXPECT_EQ(run.phase(), RunPhase::kSucceeded);
  EXPECT_EQ(run.Step(At(12, 0.5, 7)), RunAction::kSucceed);  // terminal
}

TEST(ActiveRun, CertaintyDuringTheRandomMotionEndsTheRun) {
  ActiveRunParameters p;
  p.confirm_s = 0.0;
  ActiveLocalizationRun run(p, 0.9, 0.0, true, At(0, 0.0, 0));
  EXPECT_EQ(run.Step(At(1, 0.89, 3)), RunAction::kWander);
  EXPECT_EQ(run.Step(At(2, 0.91, 4)), RunAction::kSucceed);
}

TEST(ActiveRun, SuccessNeedsTheCertaintyToStayAboveTheThresholdForConfirmS) {
  ActiveRunParameters p;
  p.confirm_s = 2.0;
  ActiveLocalizationRun run(p, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 0)), RunAction::kChoose);
  run.OnChoice(true, 3, 0, At(1, 0.5, 0));
  EXPECT_EQ(run.Step(At(2.0, 0.81, 1)), RunAction::kWait);  // above since 2.0
  EXPECT_EQ(run.Step(At(3.0, 0.85, 1)), RunAction::kWait);
  EXPECT_EQ(run.Step(At(3.5, 0.60, 1)), RunAction::kWait);  // fell back: the clock restarts
  EXPECT_EQ(run.Step(At(4.0, 0.90, 1)), RunAction::kWait);  // above since 4.0
  EXPECT_EQ(run.Step(At(5.9, 0.90, 1)), RunAction::kWait);
  EXPECT_EQ(run.Step(At(6.0, 0.90, 1)), RunAction::kSucceed);
}

TEST(ActiveRun, GivesUpAfterNFailedTargetsNamingTheLastReason) {
  ActiveRunParameters p;
  p.max_navigation_failures = 2;
  ActiveLocalizationRun run(p, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 0)), RunAction::kChoose);
  run.OnChoice(true, 5, 0, At(1, 0.5, 0));
  run.OnNavigationDone(false, "no path through door_b", At(5, 0.5, 1));
  EXPECT_EQ(run.navigation_failures(), 1);
  ASSERT_EQ(run.Step(At(5.1, 0.5, 1)), RunAction::kChoose);
  run.OnChoice(true, 5, 0, At(5.1, 0.5, 1));
  run.OnNavigationDone(false, "blocked", At(8, 0.5, 2));
  EXPECT_EQ(run.phase(), RunPhase::kAborted);
  EXPECT_EQ(run.Step(At(8.1, 0.5, 2)), RunAction::kAbort);
  EXPECT_NE(run.reason().find("navigation failed 2 times"), std::string::npos) << run.reason();
  EXPECT_NE(run.reason().find("blocked"), std::string::npos) << run.reason();
}

TEST(ActiveRun, NoReachableTargetEndsTheRun) {
  ActiveLocalizationRun run(ActiveRunParameters{}, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 0)), RunAction::kChoose);
  run.OnChoice(false, 0, 0, At(1, 0.5, 0));
  EXPECT_EQ(run.Step(At(1.1, 0.5, 0)), RunAction::kAbort);
  EXPECT_NE(run.reason().find("no reachable target"), std::string::npos);
}

TEST(ActiveRun, TimeoutEndsTheRunWithTheCertaintyReached) {
  ActiveLocalizationRun run(ActiveRunParameters{}, 0.8, 30.0, true, At(10, 0.0, 0));
  EXPECT_EQ(run.Step(At(39.9, 0.3, 5)), RunAction::kWander);
  EXPECT_EQ(run.Step(At(40.0, 0.3, 5)), RunAction::kAbort);
  EXPECT_NE(run.reason().find("timeout"), std::string::npos) << run.reason();
  EXPECT_NE(run.reason().find("0.30"), std::string::npos) << run.reason();
}

TEST(ActiveRun, AStarAtTheRobotMeansWanderAgainThenGiveUp) {
  ActiveRunParameters p;
  p.max_navigation_failures = 2;
  p.rewander_m = 3.0;
  ActiveLocalizationRun run(p, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 10)), RunAction::kChoose);
  run.OnChoice(true, 0.25, 0.0, At(1, 0.5, 10));  // closer than min_target_distance_m
  EXPECT_EQ(run.phase(), RunPhase::kWander);
  EXPECT_EQ(run.Step(At(2, 0.5, 12.9)), RunAction::kWander);
  EXPECT_EQ(run.Step(At(3, 0.5, 13.0)), RunAction::kChoose);
  run.OnChoice(true, 0.0, 0.0, At(3, 0.5, 13));
  EXPECT_EQ(run.Step(At(3.1, 0.5, 13)), RunAction::kAbort);
  EXPECT_NE(run.reason().find("own position"), std::string::npos) << run.reason();
}

TEST(ActiveRun, AJumpOfTheEstimateWhileDrivingMeansChooseAgainWithoutFailure) {
  ActiveLocalizationRun run(ActiveRunParameters{}, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 0)), RunAction::kChoose);
  run.OnChoice(true, 6, 2, At(1, 0.5, 0, Pose2{3.0, 4.0, 0.1}));
  // Small corrections of map->odom: keep driving.
  EXPECT_EQ(run.Step(At(2, 0.5, 1, Pose2{3.5, 4.3, 0.3})), RunAction::kWait);
  // The maximum moved to the twin: the target sent in the map frame is wrong now.
  EXPECT_EQ(run.Step(At(3, 0.5, 2, Pose2{24.0, 16.0, 3.2})), RunAction::kCancelAndChoose);
  EXPECT_EQ(run.phase(), RunPhase::kChoose);
  EXPECT_EQ(run.navigation_failures(), 0);
  // A late result of the cancelled goal changes nothing.
  run.OnNavigationDone(false, "preempted", At(3.1, 0.5, 2));
  EXPECT_EQ(run.navigation_failures(), 0);
  // A heading jump alone (the half-turn twin at the same place) also counts.
  run.OnChoice(true, 6, 2, At(3.2, 0.5, 2, Pose2{0, 0, 3.0}));
  EXPECT_EQ(run.Step(At(4, 0.5, 3, Pose2{0, 0, -3.0})), RunAction::kWait);  // 0.28 rad, wrapped
  EXPECT_EQ(run.Step(At(5, 0.5, 4, Pose2{0, 0, 1.0})), RunAction::kCancelAndChoose);
}

TEST(ActiveRun, ASmallTurnOfMapToOdomFarFromTheOdometryOriginIsNoJump) {
  ActiveLocalizationRun run(ActiveRunParameters{}, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 0)), RunAction::kChoose);
  const Pose2 odom{13.0, 0.0, 0.0};
  // map -> odom turned by 5 degrees about the robot at (20, 10): its translation moves by
  // 13 m x 0.087 = 1.1 m, the robot by nothing.
  const double a = 5.0 * M_PI / 180.0;
  const Pose2 before{7.0, 10.0, 0.0};
  const Pose2 after{20.0 - 13.0 * std::cos(a), 10.0 - 13.0 * std::sin(a), a};
  run.OnChoice(true, 6, 2, At(1, 0.5, 0, before, odom));
  EXPECT_EQ(run.Step(At(2, 0.5, 1, after, odom)), RunAction::kWait);
  // The same frames with the robot moved 2.5 m across: a jump.
  const Pose2 across{after.x, after.y + 2.5, a};
  EXPECT_EQ(run.Step(At(3, 0.5, 1, across, odom)), RunAction::kCancelAndChoose);
}

TEST(ActiveRun, ATargetNotReachedInTimeCountsAsAFailure) {
  ActiveRunParameters p;
  p.target_timeout_s = 20.0;
  ActiveLocalizationRun run(p, 0.8, 0.0, false, At(0, 0.5, 0));
  ASSERT_EQ(run.Step(At(1, 0.5, 0)), RunAction::kChoose);
  run.OnChoice(true, 6, 2, At(1, 0.5, 0));
  EXPECT_EQ(run.Step(At(21, 0.5, 1)), RunAction::kWait);
  EXPECT_EQ(run.Step(At(21.1, 0.5, 1)), RunAction::kCancelAndChoose);
  EXPECT_EQ(run.navigation_failures(), 1);
}

TEST(ActiveRun, BadParametersAreNamed) {
  ActiveRunParameters p;
  p.random_motion_m = -1;
  p.max_navigation_failures = 0;
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find("random_motion_m"), std::string::npos);
  EXPECT_NE(errors[1].find("max_navigation_failures"), std::string::npos);
  EXPECT_THROW(ActiveLocalizationRun(p, 0.8, 0, true, At(0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(ActiveLocalizationRun(ActiveRunParameters{}, 1.2, 0, true, At(0, 0, 0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace markov_localization
