// The office robot's modules as the node runs them on the stack (office_modules.h) and the
// structured reactive navigation plans (navigation_plan.h, section 3.1), with scripted clients
// standing in for Navigate, ActiveLocalize and the travel-mode switch. Expectations are worked out
// by hand on a small building:
//
//   y=10 +--------+--------+--------+
//        | A      | M      | B      |     offices A, M, B; M has doors to A and B (dAM, dMB)
//    y=6 +--dA----+--------+--dB----+     doors dA (2, 6) and dB (8, 6), 0.9 m wide
//        |            H (hallway)   |
//    y=4 +--------------------------+
//        x=0     x=4      x=6     x=10
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/office_modules.h"
#include "rpl_executive/rpl/office_robot.h"

namespace rpl_executive {
namespace rpl {
namespace office {
namespace {

BuildingMap Building(bool middle_doors = true, bool door_b_open = true) {
  BuildingMap map;
  map.rooms = {{"A", false, {{0, 6}, {4, 6}, {4, 10}, {0, 10}}},
               {"M", false, {{4, 6}, {6, 6}, {6, 10}, {4, 10}}},
               {"B", false, {{6, 6}, {10, 6}, {10, 10}, {6, 10}}},
               {"H", true, {{0, 4}, {10, 4}, {10, 6}, {0, 6}}}};
  map.doors = {{"dA", "H", "A", true, {2, 6}, {1.55, 6}, {2.45, 6}},
               {"dB", "H", "B", door_b_open, {8, 6}, {7.55, 6}, {8.45, 6}}};
  if (middle_doors) {
    map.doors.push_back({"dAM", "A", "M", true, {4, 8}, {4, 7.55}, {4, 8.45}});
    map.doors.push_back({"dMB", "M", "B", true, {6, 8}, {6, 7.55}, {6, 8.45}});
  }
  return map;
}

void ExpectPoints(const std::vector<Point>& got, const std::vector<Point>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].x_m, want[i].x_m, 1e-9) << "target " << i;
    EXPECT_NEAR(got[i].y_m, want[i].y_m, 1e-9) << "target " << i;
  }
}

TEST(RplNavigationPlan, TargetPointsPassDoorwaysOrthogonallyAndAvoidOtherOffices) {
  std::string error;
  const auto plan = PlanNavigation(Building(), {2, 8}, {8, 8}, {}, &error);
  ASSERT_TRUE(plan) << error;
  // Through M would be 6 m against 10 m by the hallway, but M is another office.
  EXPECT_EQ(plan->rooms, (std::vector<std::string>{"A", "H", "B"}));
  EXPECT_EQ(plan->doors, (std::vector<std::string>{"dA", "dB"}));
  // 0.8 m before and after each door on its normal, then the destination.
  ExpectPoints(plan->targets, {{2, 6.8}, {2, 5.2}, {8, 5.2}, {8, 6.8}, {8, 8}});
  EXPECT_EQ(plan->Summary(), "A -> dA -> H -> dB -> B: 5 target points");
}

TEST(RplNavigationPlan, WithoutThePenaltyTheShortestWayPassesTheOtherOffice) {
  NavigationPlanParameters p;
  p.office_pass_penalty_m = 0.0;
  std::string error;
  const auto plan = PlanNavigation(Building(), {2, 8}, {8, 8}, p, &error);
  ASSERT_TRUE(plan) << error;
  EXPECT_EQ(plan->rooms, (std::vector<std::string>{"A", "M", "B"}));
  // dAM's pre point (3.2, 8) and dMB's post point (6.8, 8) survive; M is only 2 m deep, so
  // dAM's post (4.8, 8) and dMB's pre (5.2, 8) are 0.4 m apart: both kept (>= 0.3 m).
  ExpectPoints(plan->targets, {{3.2, 8}, {4.8, 8}, {5.2, 8}, {6.8, 8}, {8, 8}});
}

TEST(RplNavigationPlan, AClosedDoorIsNotPassedAndNoOpenWayNamesIt) {
  std::string error;
  const auto around = PlanNavigation(Building(true, false), {2, 8}, {8, 8}, {}, &error);
  ASSERT_TRUE(around) << error;  // dB closed: through M after all (the only way)
  EXPECT_EQ(around->rooms, (std::vector<std::string>{"A", "M", "B"}));
  EXPECT_FALSE(PlanNavigation(Building(false, false), {2, 8}, {8, 8}, {}, &error));
  EXPECT_EQ(error, "no open way from A to B: closed dB");
  EXPECT_FALSE(PlanNavigation(Building(), {20, 8}, {8, 8}, {}, &error));
  EXPECT_EQ(error, "the robot's position (20, 8) is outside every room");
}

TEST(RplNavigationPlan, InTheSameRoomTheDestinationIsTheOnlyTargetPoint) {
  std::string error;
  const auto plan = PlanNavigation(Building(), {1, 5}, {9, 5}, {}, &error);
  ASSERT_TRUE(plan) << error;
  ExpectPoints(plan->targets, {{9, 5}});
  ASSERT_EQ(plan->regions.size(), 1u);
  EXPECT_EQ(plan->regions[0].mode, TravelMode::kHallway);
}

TEST(RplNavigationPlan, ARobotInTheDoorwayAndADestinationBehindTheDoorSkipPoints) {
  std::string error;
  // Standing in dA's doorway: no point back into A; the destination 0.5 m behind dB: no point
  // beyond it.
  const auto plan = PlanNavigation(Building(), {2, 6.2}, {8, 6.5}, {}, &error);
  ASSERT_TRUE(plan) << error;
  ExpectPoints(plan->targets, {{2, 5.2}, {8, 5.2}, {8, 6.5}});
}

TEST(RplNavigationPlan, AnOpeningBetweenTwoHallwayPortionsGetsNoTargetPoints) {
  // H split at x = 5 into H1 and H2, joined by a 2 m opening (as bonn_department's corridor).
  BuildingMap map = Building(false);
  map.rooms[3] = {"H1", true, {{0, 4}, {5, 4}, {5, 6}, {0, 6}}};
  map.rooms.push_back({"H2", true, {{5, 4}, {10, 4}, {10, 6}, {5, 6}}});
  map.doors[1].room_a = "H2";
  map.doors[0].room_a = "H1";
  BuildingDoor opening{"join", "H1", "H2", true, {5, 5}, {5, 4}, {5, 6}};
  opening.opening = true;
  map.doors.push_back(opening);
  std::string error;
  const auto plan = PlanNavigation(map, {2, 8}, {8, 8}, {}, &error);
  ASSERT_TRUE(plan) << error;
  EXPECT_EQ(plan->rooms, (std::vector<std::string>{"A", "H1", "H2", "B"}));
  ExpectPoints(plan->targets, {{2, 6.8}, {2, 5.2}, {8, 5.2}, {8, 6.8}, {8, 8}});
  EXPECT_EQ(TravelModeAt(plan->regions, {5, 5}), TravelMode::kHallway);
}

TEST(RplNavigationPlan, TravelModesOfTheRegions) {
  std::string error;
  const auto plan = PlanNavigation(Building(), {2, 8}, {8, 8}, {}, &error);
  ASSERT_TRUE(plan) << error;
  // dA's doorway: x in [1.45, 2.55] (0.45 + 0.1 margin), y in [5.4, 6.6] (0.6 depth).
  EXPECT_EQ(TravelModeAt(plan->regions, {2, 6}), TravelMode::kDoorway);
  EXPECT_EQ(TravelModeAt(plan->regions, {2.5, 6.55}), TravelMode::kDoorway);
  EXPECT_EQ(TravelModeAt(plan->regions, {2, 6.7}), TravelMode::kOffice);
  EXPECT_EQ(TravelModeAt(plan->regions, {5, 5}), TravelMode::kHallway);
  EXPECT_EQ(TravelModeAt(plan->regions, {5, 8}), TravelMode::kNone);  // M is not on the path
}

TEST(RplNavigationPlan, BadParametersAreNamed) {
  NavigationModuleParameters p;
  p.plan.door_approach_m = 0;
  p.goal_tolerance_m = -1;
  const auto e = ValidateParameters(p);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0], "door_approach_m: must be in (0, 5] m");
  EXPECT_EQ(e[1], "goal_tolerance_m: must be in (0, 5] m");
}

// ---- the modules under the office delivery plan ------------------------------------------------

struct ScriptedNavigate : NavigateClient {
  void SendGoal(const Point& target, double tolerance_m, double) override {
    goals.push_back(target);
    tolerances.push_back(tolerance_m);
    in_flight = true;
  }
  void CancelGoal(double) override {
    ++cancels;
    in_flight = false;
  }
  std::vector<Point> goals;
  std::vector<double> tolerances;
  int cancels = 0;
  bool in_flight = false;
};

struct ScriptedActiveLocalize : ActiveLocalizeClient {
  void Start(bool uniform, double threshold, double, double now_s) override {
    starts.push_back(now_s);
    uniform_start = uniform;
    this->threshold = threshold;
  }
  void Cancel(double now_s) override { cancels.push_back(now_s); }
  std::vector<double> starts, cancels;
  bool uniform_start = false;
  double threshold = 0;
};

struct RecordingTravel : TravelModeSwitch {
  void SetTravelMode(TravelMode mode, const std::string& region, double) override {
    modes.push_back(std::string(TravelModeName(mode)) + (region.empty() ? "" : " " + region));
  }
  std::vector<std::string> modes;
};

std::string ReadPlan() {
  std::ifstream in(std::string(PACKAGE_DIR) + "/plans/office_delivery.rpl");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class Office {
 public:
  explicit Office(BuildingMap map = Building()) {
    for (const auto& f : Fluents()) executive.DeclareFluent(f);
    navigation = std::make_shared<NavigationModule>(&executive, &navigate, &travel,
                                                    NavigationModuleParameters());
    localization = std::make_shared<ActiveLocalizationModule>(&executive, &active,
                                                              ActiveLocalizationParameters());
    tracking = std::make_shared<PositionTrackingModule>(&executive, 2.0);
    executive.AddModule(navigation);
    executive.AddModule(localization);
    executive.AddModule(tracking);
    navigation->SetMap(map);
  }
  void Pose(double x, double y, double certainty) {
    executive.SetFluent(kX, Value::Number(x), t);
    executive.SetFluent(kY, Value::Number(y), t);
    executive.SetFluent(kPosCertainty, Value::Number(certainty), t);
    navigation->OnPose({x, y}, t);
  }
  // One cycle of the node: Step, then the modules' deferred deletions, stepping again on a change.
  void Tick() {
    executive.Step(t);
    while (navigation->AfterStep(t)) executive.Step(t);
    t += 0.1;
  }
  // The robot reaches the target point in flight (the estimate there), Navigate succeeds.
  void Reach() {
    ASSERT_TRUE(navigate.in_flight);
    const Point p = navigate.goals.back();
    Pose(p.x_m, p.y_m, 0.95);
    navigate.in_flight = false;
    navigation->OnGoalDone(GoalOutcome::kSucceeded, "", t);
    Tick();
  }
  std::string Start(double dest_x, double dest_y) {
    const auto d = executive.Load(ReadPlan(), "office_delivery.rpl");
    if (HasErrors(d)) return FormatDiagnostics(d);
    return executive.Start(t, {{"DEST", Value::Point(dest_x, dest_y)}});
  }
  double Nr() const { return executive.GetFluent(kNrOfNavGoals).number(); }
  int Count(Event::Kind kind, const std::string& subject) const {
    int n = 0;
    for (const Event& e : executive.events()) n += e.kind == kind && e.subject == subject;
    return n;
  }

  // The fakes first: the executive, destroyed before them, deactivates the modules, which cancel
  // through them (UBSan found the call on a destroyed client).
  ScriptedNavigate navigate;
  ScriptedActiveLocalize active;
  RecordingTravel travel;
  Executive executive;
  std::shared_ptr<NavigationModule> navigation;
  std::shared_ptr<ActiveLocalizationModule> localization;
  std::shared_ptr<PositionTrackingModule> tracking;
  double t = 0.0;
};

TEST(RplOfficeModules, NavigationSendsItsTargetPointsOneGoalAfterTheOtherAndCountsThem) {
  Office o;
  o.Pose(2, 8, 0.95);
  ASSERT_EQ(o.Start(8, 8), "");
  o.Tick();
  ASSERT_EQ(o.navigate.goals.size(), 1u);
  EXPECT_EQ(o.Nr(), 5);
  EXPECT_TRUE(o.executive.GetFluent(kNavigationActive).Truthy());
  EXPECT_DOUBLE_EQ(o.navigate.tolerances[0], 0.4);  // an intermediate target point
  for (int i = 0; i < 4; ++i) {
    o.Reach();
    EXPECT_EQ(o.Nr(), 4 - i);
  }
  EXPECT_DOUBLE_EQ(o.navigate.tolerances.back(), 0.3);  // the destination
  o.Reach();
  EXPECT_EQ(o.executive.state(), PlanState::kSucceeded)
      << (o.executive.failure() ? o.executive.failure()->ToString() : "");
  ExpectPoints(o.navigate.goals, {{2, 6.8}, {2, 5.2}, {8, 5.2}, {8, 6.8}, {8, 8}});
  EXPECT_EQ(o.Nr(), 0);
  EXPECT_FALSE(o.executive.GetFluent(kNavigationActive).Truthy());
  EXPECT_EQ(o.navigation->plans_generated(), 1);
  // Travel modes as the robot crossed the regions (target points lie in them): office A at the
  // start, A's doorway region is not reached by (2, 6.8) (y > 6.6), ...
  EXPECT_EQ(o.travel.modes, (std::vector<std::string>{"office", "hallway H", "office B", "none"}));
}

TEST(RplOfficeModules, TravelModeChangesAsTheRobotCrossesADoorway) {
  Office o;
  o.Pose(2, 8, 0.95);
  ASSERT_EQ(o.Start(8, 8), "");
  o.Tick();
  for (double y = 8.0; y >= 5.0; y -= 0.1) o.Pose(2, y, 0.95);
  EXPECT_EQ(o.travel.modes, (std::vector<std::string>{"office", "doorway dA", "hallway H"}));
}

TEST(RplOfficeModules, LosingThePositionDeletesTheTargetsRelocalizesAndPlansAgainFromThere) {
  Office o;
  o.Pose(2, 8, 0.95);
  ASSERT_EQ(o.Start(8, 8), "");
  o.Tick();
  o.Reach();
  o.Reach();  // in the hallway at (2, 5.2), heading for (8, 5.2)
  ASSERT_EQ(o.Nr(), 3);
  o.Pose(3, 5.0, 0.5);  // certainty <= 0.8
  o.Tick();
  EXPECT_EQ(o.navigate.cancels, 1);  // the goal in flight
  EXPECT_EQ(o.Nr(), 0);              // "delete all target points"
  EXPECT_EQ(o.Count(Event::Kind::kPulse, "EXECUTION-INTERRUPTED?"), 1);
  ASSERT_EQ(o.active.starts.size(), 1u);
  EXPECT_TRUE(o.active.uniform_start);
  EXPECT_DOUBLE_EQ(o.active.threshold, 0.8);
  EXPECT_EQ(o.navigate.goals.size(), 3u);  // nothing new while the policy holds WHEELS
  // Relocalized elsewhere (in M): the policy lets go, a new plan starts from there.
  o.Pose(5, 8, 0.9);
  o.Tick();
  ASSERT_EQ(o.active.cancels.size(), 1u);
  EXPECT_EQ(o.navigation->plans_generated(), 2);
  ASSERT_TRUE(o.navigation->plan());
  EXPECT_EQ(o.navigation->plan()->rooms.front(), "M");
  ExpectPoints({o.navigate.goals.back()}, {{6.8, 8}});  // out of M through dMB, orthogonally
  while (o.navigate.in_flight && o.executive.state() == PlanState::kRunning) o.Reach();
  EXPECT_EQ(o.executive.state(), PlanState::kSucceeded)
      << (o.executive.failure() ? o.executive.failure()->ToString() : "");
}

TEST(RplOfficeModules, UnreachableTargetsAreCountedAndTheRoutineGivesUpWithThePlannersReason) {
  Office o;
  o.Pose(2, 8, 0.95);
  ASSERT_EQ(o.Start(8, 8), "");
  o.Tick();
  for (int i = 0; i < 3 && o.executive.state() == PlanState::kRunning; ++i) {
    ASSERT_TRUE(o.navigate.in_flight) << i;
    o.navigate.in_flight = false;
    o.navigation->OnGoalDone(GoalOutcome::kUnreachable, "the passage H:dA:dB is blocked", o.t);
    o.Tick();
  }
  ASSERT_EQ(o.executive.state(), PlanState::kFailed);
  EXPECT_EQ(o.executive.failure()->message,
            "gave up after 3 navigation failures in a row: NAVIGATION failed: unreachable: the "
            "passage H:dA:dB is blocked");
  EXPECT_EQ(o.navigation->plans_generated(), 3);
  EXPECT_EQ(o.Nr(), 0);  // deleted after the last report
}

TEST(RplOfficeModules, ADestinationBehindClosedDoorsFailsAtActivationNamingThem) {
  Office o(Building(false, false));
  o.Pose(2, 8, 0.95);
  ASSERT_EQ(o.Start(8, 8), "");
  o.Tick();
  ASSERT_EQ(o.executive.state(), PlanState::kFailed);
  EXPECT_NE(o.executive.failure()->message.find("unreachable: no open way from A to B: closed dB"),
            std::string::npos)
      << o.executive.failure()->message;
  EXPECT_TRUE(o.navigate.goals.empty());
}

TEST(RplOfficeModules, ActiveLocalizationGivingUpFailsThePolicyWithItsReason) {
  Office o;
  o.Pose(2, 8, 0.95);
  ASSERT_EQ(o.Start(8, 8), "");
  o.Tick();
  o.Pose(2, 8, 0.4);
  o.Tick();
  ASSERT_TRUE(o.localization->active());
  o.localization->OnDone(false, "no informative target: a* was the robot's own position", o.t);
  o.Tick();
  ASSERT_EQ(o.executive.state(), PlanState::kFailed);
  EXPECT_NE(o.executive.failure()->ToString().find("no informative target"), std::string::npos)
      << o.executive.failure()->ToString();
}

TEST(RplOfficeModules, PositionTrackingFailsWithoutLocalizationStatus) {
  Executive e;
  for (const auto& f : Fluents()) e.DeclareFluent(f);
  auto tracking = std::make_shared<PositionTrackingModule>(&e, 2.0);
  e.AddModule(tracking);
  ASSERT_FALSE(HasErrors(e.Load("(EXECUTE POSITION-TRACKING)", "t.rpl")));
  ASSERT_EQ(e.Start(0.0), "");
  e.Step(0.0);
  ASSERT_EQ(e.state(), PlanState::kFailed);
  EXPECT_NE(e.failure()->message.find("no localization status yet"), std::string::npos);
  // With a status it runs until the status stops coming.
  tracking->OnStatus(1.0);
  ASSERT_FALSE(HasErrors(e.Load("(EXECUTE POSITION-TRACKING)", "t.rpl")));
  ASSERT_EQ(e.Start(1.5), "");
  e.Step(1.5);
  EXPECT_TRUE(tracking->active());
  tracking->OnTime(2.9);
  e.Step(2.9);
  EXPECT_EQ(e.state(), PlanState::kRunning);
  tracking->OnTime(3.1);  // 2.1 s without a status
  e.Step(3.1);
  ASSERT_EQ(e.state(), PlanState::kFailed);
  EXPECT_NE(e.failure()->message.find("no localization status for 2.1 s"), std::string::npos)
      << e.failure()->message;
}

}  // namespace
}  // namespace office
}  // namespace rpl
}  // namespace rpl_executive
