// The office delivery plan of section 3.2 (plans/office_delivery.rpl) on in-process, scripted
// behaviour modules, through the kidnap of section 4: the robot is turned about 70 degrees to the
// right shortly after the start; the tracker does not notice at once; its certainty falls below
// 0.8; the policy interrupts the navigation routine, whose goals are removed (EXECUTION-
// INTERRUPTED? pulses); active localization takes the wheels and relocalizes the robot in a room;
// the navigation routine makes a new plan from there and ends at the destination.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/office_robot.h"

namespace rpl_executive {
namespace rpl {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Point {
  double x, y;
};

/// A robot in an open plane (no walls: the fakes script what the stack's modules would do). The
/// tracker integrates the commanded motion, so a turn it did not see (a kidnap) makes the
/// estimate drift from the truth; its certainty falls as the drift grows.
struct FakeRobot {
  double true_x = 25.8, true_y = 10.0;  // east end of the hallway (section 4)
  double est_x = 25.8, est_y = 10.0;
  double heading_error_rad = 0.0;  // true heading - estimated heading
  double certainty = 0.95;
  bool relocalizing = false;
  static constexpr double kSpeedMps = 0.5;

  // Moves towards `target` as the robot believes it (in the estimate's frame).
  void DriveTowardsEstimated(const Point& target, double dt) {
    const double dx = target.x - est_x, dy = target.y - est_y;
    const double d = std::hypot(dx, dy);
    const double step = std::min(d, kSpeedMps * dt);
    if (d < 1e-9) return;
    const double believed = std::atan2(dy, dx);
    est_x += step * std::cos(believed);
    est_y += step * std::sin(believed);
    true_x += step * std::cos(believed + heading_error_rad);
    true_y += step * std::sin(believed + heading_error_rad);
  }
  // Moves towards `target` in truth (active localization, scripted to enter a room).
  void DriveTowardsTrue(const Point& target, double dt) {
    const double dx = target.x - true_x, dy = target.y - true_y;
    const double d = std::hypot(dx, dy);
    const double step = std::min(d, kSpeedMps * dt);
    if (d < 1e-9) return;
    true_x += step * dx / d;
    true_y += step * dy / d;
  }
  double ErrorM() const { return std::hypot(true_x - est_x, true_y - est_y); }
  void UpdateCertainty() {
    if (relocalizing) return;
    certainty = std::clamp(0.95 - 0.15 * std::max(0.0, ErrorM() - 0.5), 0.05, 0.95);
  }
};

/// NAVIGATION: on activation, a structured plan from the estimated position (section 3.1: out of a
/// room straight to the hallway, along it to the front of door_b, through the doorway
/// orthogonally, to the destination); NR-OF-NAV-GOALS* counts the target points left.
class FakeNavigation : public BehaviourModule {
 public:
  struct Plan {
    double start_x, start_y, time_s;
    std::vector<Point> targets;
  };
  FakeNavigation(Executive* e, FakeRobot* r) : executive_(e), robot_(r) {}
  ModuleSpec Spec() const override { return office::NavigationSpec(); }
  void Activate(ActivationId id, const std::vector<Value>& args, double now_s) override {
    id_ = id;
    const Value& dest = args[0];
    dest_ = {dest.items()[0].number(), dest.items()[1].number()};
    targets_.clear();
    if (robot_->est_y > 11.0 || robot_->est_y < 9.0) targets_.push_back({robot_->est_x, 10.0});
    targets_.push_back({17.5, 10.0});  // in front of door_b
    targets_.push_back({17.5, 8.0});   // through door_b
    targets_.push_back(dest_);
    plans.push_back({robot_->est_x, robot_->est_y, now_s, targets_});
    Publish(now_s);
  }
  void Deactivate(ActivationId, double now_s) override {
    id_ = 0;
    targets_.clear();  // "delete all target points"
    Publish(now_s);
  }
  bool active() const { return id_ != 0; }
  void Update(double dt, double now_s) {
    if (!id_ || targets_.empty()) return;
    robot_->DriveTowardsEstimated(targets_.front(), dt);
    const Point& t = targets_.front();
    if (std::hypot(t.x - robot_->est_x, t.y - robot_->est_y) < 0.05) {
      targets_.erase(targets_.begin());
      if (targets_.empty()) {
        executive_->ReportSuccess(id_, Value::Symbol(":ARRIVED"));
        id_ = 0;
      }
      Publish(now_s);
    }
  }
  std::vector<Plan> plans;

 private:
  void Publish(double now_s) {
    executive_->SetFluent(office::kNrOfNavGoals,
                          Value::Number(static_cast<double>(targets_.size())), now_s);
    executive_->SetFluent(office::kNavigationActive, Value::Boolean(id_ != 0), now_s);
  }
  Executive* executive_;
  FakeRobot* robot_;
  ActivationId id_ = 0;
  Point dest_{0, 0};
  std::vector<Point> targets_;
};

/// ACTIVE-LOCALIZATION: starts from a uniform belief (certainty 0.05), drives into room C through
/// door_c ("RHINO decided to enter the next room"), where the position is certain again. It keeps
/// running until deactivated, as the policy of section 3.2 expects.
class FakeActiveLocalization : public BehaviourModule {
 public:
  FakeActiveLocalization(Executive* e, FakeRobot* r) : executive_(e), robot_(r) {}
  ModuleSpec Spec() const override { return office::ActiveLocalizationSpec(); }
  void Activate(ActivationId id, const std::vector<Value>&, double now_s) override {
    id_ = id;
    activations.push_back(now_s);
    robot_->relocalizing = true;
    robot_->certainty = 0.05;
    waypoint_ = 0;
  }
  void Deactivate(ActivationId, double now_s) override {
    id_ = 0;
    deactivations.push_back(now_s);
    robot_->relocalizing = false;
  }
  bool active() const { return id_ != 0; }
  void Update(double dt, double now_s) {
    if (!id_ || waypoint_ >= kRoute.size()) return;
    robot_->DriveTowardsTrue(kRoute[waypoint_], dt);
    if (std::hypot(kRoute[waypoint_].x - robot_->true_x, kRoute[waypoint_].y - robot_->true_y) <
        0.05) {
      if (++waypoint_ == kRoute.size()) {  // inside room C: the belief has one peak again
        robot_->est_x = robot_->true_x;
        robot_->est_y = robot_->true_y;
        robot_->heading_error_rad = 0.0;
        robot_->certainty = 0.95;
        localized_at = now_s;
      }
    }
  }
  std::vector<double> activations, deactivations;
  double localized_at = -1;

 private:
  const std::vector<Point> kRoute{{9.5, 10.0}, {9.5, 12.5}};
  Executive* executive_;
  FakeRobot* robot_;
  ActivationId id_ = 0;
  size_t waypoint_ = 0;
};

struct Fixture {
  Fixture() {
    for (const auto& f : office::Fluents()) executive.DeclareFluent(f);
    navigation = std::make_shared<FakeNavigation>(&executive, &robot);
    localization = std::make_shared<FakeActiveLocalization>(&executive, &robot);
    executive.AddModule(navigation);
    executive.AddModule(localization);
    executive.AddModule(std::make_shared<Tracking>());
  }
  struct Tracking : BehaviourModule {
    ModuleSpec Spec() const override { return office::PositionTrackingSpec(); }
    void Activate(ActivationId, const std::vector<Value>&, double) override {}
    void Deactivate(ActivationId, double) override {}
  };
  void PublishPose(double now_s) {
    robot.UpdateCertainty();
    executive.SetFluent(office::kX, Value::Number(robot.est_x), now_s);
    executive.SetFluent(office::kY, Value::Number(robot.est_y), now_s);
    executive.SetFluent(office::kPosCertainty, Value::Number(robot.certainty), now_s);
  }
  std::string Load() {
    const std::string path = std::string(PACKAGE_DIR) + "/plans/office_delivery.rpl";
    const std::string text = ReadFile(path);
    return FormatDiagnostics(executive.Load(text, "office_delivery.rpl"));
  }
  int IndexOf(Event::Kind kind, const std::string& subject) const {
    int i = 0;
    for (const auto& e : executive.events()) {
      if (e.kind == kind && e.subject == subject) return i;
      ++i;
    }
    return -1;
  }

  Executive executive;
  FakeRobot robot;
  std::shared_ptr<FakeNavigation> navigation;
  std::shared_ptr<FakeActiveLocalization> localization;
};

TEST(RplOfficeDelivery, ThePlanFileChecksAgainstTheOfficeRobotsVocabulary) {
  const std::string text = ReadFile(std::string(PACKAGE_DIR) + "/plans/office_delivery.rpl");
  ASSERT_FALSE(text.empty());
  const CompileResult r = CompilePlan(text, "office_delivery.rpl", office::OfficeVocabulary());
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty()) << FormatDiagnostics(r.diagnostics);
}

TEST(RplOfficeDelivery, SurvivesAKidnapByRelocalizingAndEndsAtTheDestination) {
  Fixture f;
  ASSERT_EQ(f.Load(), "");
  f.PublishPose(0.0);
  ASSERT_EQ(f.executive.Start(0.0), "");
  const double dt = 0.1, kidnap_s = 2.0;
  double lost_at = -1, relocalized_at = -1;
  size_t lost_event = 0;
  double t = 0.0;
  for (int i = 0; i < 3000 && f.executive.state() == PlanState::kRunning; ++i) {
    t = i * dt;
    if (std::fabs(t - kidnap_s) < 1e-9) f.robot.heading_error_rad = -70.0 * kPi / 180.0;
    f.navigation->Update(dt, t);
    f.localization->Update(dt, t);
    f.PublishPose(t);
    if (lost_at < 0 && f.robot.certainty <= 0.8) {
      lost_at = t;
      lost_event = f.executive.events().size();
    }
    f.executive.Step(t);
    // The valve: never both modules moving the robot.
    ASSERT_FALSE(f.navigation->active() && f.localization->active()) << "at t = " << t;
    if (relocalized_at < 0 && f.localization->localized_at >= 0) relocalized_at = t;
  }
  ASSERT_EQ(f.executive.state(), PlanState::kSucceeded)
      << (f.executive.failure() ? f.executive.failure()->ToString() : "still running");

  // The first plan went from the start along the hallway.
  ASSERT_EQ(f.navigation->plans.size(), 2u);
  EXPECT_NEAR(f.navigation->plans[0].start_x, 25.8, 1e-9);
  EXPECT_NEAR(f.navigation->plans[0].targets[0].x, 17.5, 1e-9);

  // The tracker did not notice the kidnap at once; then the certainty fell below 0.8.
  ASSERT_GT(lost_at, kidnap_s + 1.0);
  // In the Step where it fell: goals removed, EXECUTION-INTERRUPTED? pulsed, WHEELS pre-empted,
  // active localization started, in this order.
  const auto& events = f.executive.events();
  int deactivated = -1, pulse = -1, preempted = -1, activated = -1;
  for (size_t i = lost_event; i < events.size(); ++i) {
    const Event& e = events[i];
    if (deactivated < 0 && e.kind == Event::Kind::kModuleDeactivated &&
        e.subject == office::kNavigation) {
      deactivated = static_cast<int>(i);
      EXPECT_DOUBLE_EQ(e.time_s, lost_at);
      EXPECT_NE(e.detail.find("deactivated by (DEACTIVATE NAVIGATION)"), std::string::npos)
          << e.detail;
    }
    if (pulse < 0 && e.kind == Event::Kind::kPulse && e.subject == "EXECUTION-INTERRUPTED?") {
      pulse = static_cast<int>(i);
      EXPECT_DOUBLE_EQ(e.time_s, lost_at);
    }
    if (preempted < 0 && e.kind == Event::Kind::kValvePreempted && e.subject == office::kWheels) {
      preempted = static_cast<int>(i);
      EXPECT_EQ(e.detail,
                "GO-TO > NAVIGATION-PROC > WITH-VALVE lost it to WITH-POLICY policy > "
                "ACTIVATE-ACTIVE-LOCALIZATION > ACTIVATE ACTIVE-LOCALIZATION");
    }
    if (activated < 0 && e.kind == Event::Kind::kModuleActivated &&
        e.subject == office::kActiveLocalization) {
      activated = static_cast<int>(i);
      EXPECT_DOUBLE_EQ(e.time_s, lost_at);
    }
  }
  ASSERT_GE(deactivated, 0);
  EXPECT_LT(deactivated, pulse);
  EXPECT_LT(pulse, preempted);
  EXPECT_LT(preempted, activated);
  ASSERT_EQ(f.localization->activations.size(), 1u);
  EXPECT_DOUBLE_EQ(f.localization->activations[0], lost_at);

  // Relocalized in room C; the policy deactivated active localization once certain again.
  ASSERT_GT(relocalized_at, lost_at);
  ASSERT_EQ(f.localization->deactivations.size(), 1u);
  EXPECT_DOUBLE_EQ(f.localization->deactivations[0], relocalized_at);

  // Navigation resumed with a new plan from the relocalized position (room C, out through door_c).
  const auto& second = f.navigation->plans[1];
  EXPECT_DOUBLE_EQ(second.time_s, relocalized_at);
  EXPECT_NEAR(second.start_x, 9.5, 0.06);
  EXPECT_NEAR(second.start_y, 12.5, 0.06);
  EXPECT_NEAR(second.targets[0].x, 9.5, 0.06);
  EXPECT_NEAR(second.targets[0].y, 10.0, 1e-9);

  // It ended at the destination, in truth.
  EXPECT_LT(std::hypot(f.robot.true_x - 19.6, f.robot.true_y - 6.0), 0.5);
  EXPECT_EQ(f.executive.GetFluent(office::kNrOfNavGoals), Value::Number(0));
  EXPECT_EQ(f.executive.ValveHolder(office::kWheels), "");
  EXPECT_FALSE(f.navigation->active());
  EXPECT_FALSE(f.localization->active());
  EXPECT_EQ(f.executive.NumLiveTasks(), 0u);
  std::printf(
      "kidnap at %.1f s, certainty <= 0.8 at %.1f s, relocalized at %.1f s, arrived at "
      "%.1f s\n",
      kidnap_s, lost_at, relocalized_at, t);
}

TEST(RplOfficeDelivery, GivesUpWithTheModulesCauseWhenTheDestinationIsUnreachable) {
  Fixture f;
  // A NAVIGATION that cannot plan: fails at once, its target points gone.
  struct Unreachable : BehaviourModule {
    explicit Unreachable(Executive* e) : e_(e) {}
    ModuleSpec Spec() const override { return office::NavigationSpec(); }
    void Activate(ActivationId id, const std::vector<Value>&, double) override {
      ++activations;
      e_->ReportFailure(id, "unreachable: door_b is closed");
    }
    void Deactivate(ActivationId, double) override {}
    Executive* e_;
    int activations = 0;
  };
  Executive executive;
  for (const auto& fl : office::Fluents()) executive.DeclareFluent(fl);
  auto navigation = std::make_shared<Unreachable>(&executive);
  executive.AddModule(navigation);
  executive.AddModule(std::make_shared<FakeActiveLocalization>(&executive, &f.robot));
  const std::string text = ReadFile(std::string(PACKAGE_DIR) + "/plans/office_delivery.rpl");
  ASSERT_FALSE(HasErrors(executive.Load(text, "office_delivery.rpl")));
  executive.SetFluent(office::kPosCertainty, Value::Number(0.95), 0);
  ASSERT_EQ(executive.Start(0), "");
  executive.Step(0);
  ASSERT_EQ(executive.state(), PlanState::kFailed);
  EXPECT_EQ(navigation->activations, 3);
  const Failure* failure = executive.failure();
  EXPECT_EQ(failure->failure_class, FailureClass::kPlanFailure);
  EXPECT_EQ(failure->message,
            "gave up after 3 navigation failures in a row: NAVIGATION failed: unreachable: "
            "door_b is closed");
  EXPECT_EQ(failure->task_path, "GO-TO > NAVIGATION-PROC > AT-DESTINATION? > FAIL");
  EXPECT_EQ(executive.ValveHolder(office::kWheels), "");
}

}  // namespace
}  // namespace rpl
}  // namespace rpl_executive
