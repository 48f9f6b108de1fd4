// SPOTT's navigation program (programs/spott_navigation.tr, Figs. 3-13) run by the interpreter
// with every condition pushed from the test: the subroutine chain follows the task and the map,
// and the bumper reaction (Fig. 7) runs while the task goes on.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "spott_tr_plus/interpreter.h"
#include "spott_tr_plus/parser.h"

namespace spott_tr_plus {
namespace {

class Navigation : public ::testing::Test {
 protected:
  void SetUp() override {
    const ParseResult parsed = ParseProgramFile(PROGRAMS_DIR "/spott_navigation.tr");
    ASSERT_TRUE(parsed.ok()) << FormatDiagnostics(parsed.diagnostics);
    for (const auto& c : parsed.program.conditions) registry_.ExternalCondition(c.name);
    for (const auto& a : parsed.program.actions) {
      registry_.Action(
          a.name,
          [this](const ActionCall& c) {
            std::string s = c.name + "(";
            for (size_t i = 0; i < c.args.size(); ++i)
              s += (i ? ", " : "") + ValueToString(c.args[i]);
            log_.push_back(s + ")");
            tickets_[c.name] = c.ticket;
          },
          [this, name = a.name](Ticket) { log_.push_back("stop " + name); });
    }
    std::vector<Diagnostic> d;
    in_ = Interpreter::Create(parsed.program, registry_, &d);
    ASSERT_TRUE(in_) << FormatDiagnostics(d);
  }
  std::vector<std::string> Chain() const {
    std::vector<std::string> c;
    for (const auto& f : in_->State().frames) c.push_back(f.program);
    return c;
  }
  bool Logged(const std::string& entry) const {
    return std::find(log_.begin(), log_.end(), entry) != log_.end();
  }
  Registry registry_;
  std::vector<std::string> log_;
  std::map<std::string, Ticket> tickets_;
  // Last: destroying the interpreter stops running actions, whose callbacks write to log_.
  std::unique_ptr<Interpreter> in_;
};

TEST_F(Navigation, TaskWithAPrioriMapSetsTheGoalAndBumperReactionRunsAlongside) {
  const Value task = std::string("go near door(3.2, 1.0)");
  in_->Start(0.0);
  // No task yet: localize, map with sonar and QUADRIS, monitor bumper and infrared (the last
  // rule of main; with nothing close the infrared maps what it sees), nothing else.
  const std::vector<std::string> monitors{
      "SPOTT",        "LOCALIZE_THE_ROBOT", "MAP_OBJECTS_WITH_SONAR",   "MAP_OBJECTS_WITH_QUADRIS",
      "BUMPER_CHECK", "INFRARED_CHECK",     "MAP_OBJECTS_WITH_INFRARED"};
  EXPECT_EQ(Chain(), monitors);
  in_->SetCondition("apriori_map", true, 0.1);
  in_->SetCondition("target_known", true, 0.1, {}, {task});
  in_->SetCondition("task_status", true, 0.2, {task});
  in_->SetCondition("task_given", true, 0.2);
  // Fig. 3 -> Fig. 9 -> Fig. 11: the goal is set from the task.
  const std::vector<std::string> chain = Chain();
  EXPECT_NE(std::find(chain.begin(), chain.end(), "INTERPRET_TASK"), chain.end());
  EXPECT_NE(std::find(chain.begin(), chain.end(), "APRIORI_MAP_TASK"), chain.end());
  EXPECT_NE(std::find(chain.begin(), chain.end(), "BUMPER_CHECK"), chain.end());
  EXPECT_TRUE(Logged("set_goal(\"go near door(3.2, 1.0)\")"));
  EXPECT_TRUE(Logged("set_ptu_pattern(\"hallway\")"));  // not in a room (Fig. 10)
  // Fig. 7: a contact maps the obstacle, then backs off (ballistic), with the contact point.
  in_->SetCondition("bumper_contact", true, 0.5, {std::vector<double>{1.0, 0.2}});
  EXPECT_TRUE(Logged("add_obstacle_at([1, 0.2])"));
  ASSERT_TRUE(in_->CompleteAction(tickets_["add_obstacle_at"], true, 0.6));
  EXPECT_TRUE(Logged("move_away_from([1, 0.2], 0.3)"));
  // The contact ends before the back-off does: the ballistic reaction runs to completion.
  in_->SetCondition("bumper_contact", false, 0.7);
  EXPECT_FALSE(Logged("stop move_away_from"));
  ASSERT_TRUE(in_->CompleteAction(tickets_["move_away_from"], true, 1.0));
  EXPECT_FALSE(Logged("stop set_goal"));  // the task went on meanwhile
  // The task is done: the main goal rule fires, the task subroutines are deactivated; the
  // monitors are handed over to it, not restarted.
  in_->SetCondition("task_done", true, 2.0);
  EXPECT_TRUE(Logged("report_done()"));
  EXPECT_EQ(Chain(), monitors);
}

size_t Count(const std::vector<std::string>& log, const std::string& entry) {
  return std::count(log.begin(), log.end(), entry);
}

// The case: a task given, then a new task. Localization, sonar mapping and the bumper
// and infrared monitors are called by the rules before and after: they keep running (their
// actions are not stopped, their conditions keep their values); only INTERPRET_TASK follows
// the new task.
TEST_F(Navigation, NewTaskDoesNotRestartLocalizationMappingOrBumperMonitoring) {
  const Value first = std::string("go near door(3.2, 1.0)");
  const Value second = std::string("go in room(lab)");
  in_->Start(0.0);
  in_->SetCondition("apriori_map", true, 0.1);
  in_->SetCondition("target_known", true, 0.1, {}, {first});
  in_->SetCondition("target_known", true, 0.1, {}, {second});
  // Localized, sonar segments arriving: update_pose and add_features run.
  in_->SetCondition("localized", true, 0.2);
  in_->SetCondition("sonar_segments", true, 0.2, {std::vector<double>{0, 0, 1, 0}});
  ASSERT_TRUE(Logged("update_pose()"));
  ASSERT_TRUE(Logged("add_features([0, 0, 1, 0])"));
  const auto frames_before = Chain();
  // Idle (main rule 3) -> a task (rule 2).
  in_->SetCondition("task_status", true, 0.3, {first});
  in_->SetCondition("task_given", true, 0.3);
  EXPECT_TRUE(Logged("set_goal(\"go near door(3.2, 1.0)\")"));
  EXPECT_FALSE(Logged("stop update_pose"));
  EXPECT_FALSE(Logged("stop add_features"));
  EXPECT_EQ(Count(log_, "update_pose()"), 1u);
  EXPECT_EQ(Count(log_, "add_features([0, 0, 1, 0])"), 1u);
  const auto with_task = Chain();
  ASSERT_NE(std::find(with_task.begin(), with_task.end(), "BUMPER_CHECK"), with_task.end());
  // A new task: the task subroutines restart with it, nothing else does.
  in_->SetCondition("task_status", true, 0.4, {second});
  EXPECT_TRUE(Logged("stop set_goal"));
  EXPECT_TRUE(Logged("set_goal(\"go in room(lab)\")"));
  EXPECT_FALSE(Logged("stop update_pose"));
  EXPECT_FALSE(Logged("stop add_features"));
  EXPECT_FALSE(Logged("stop set_ptu_pattern"));
  EXPECT_EQ(Count(log_, "update_pose()"), 1u);
  EXPECT_EQ(Count(log_, "set_ptu_pattern(\"hallway\")"), 1u);
  // The pose condition kept its value throughout (it never read FALSE).
  for (const auto& p : in_->State().processes) {
    if (p.name == "localized") {
      EXPECT_TRUE(p.value);
    }
  }
  // The bumper monitor is the same one: a contact now still gets its reaction.
  in_->SetCondition("bumper_contact", true, 0.5, {std::vector<double>{1.0, 0.2}});
  EXPECT_TRUE(Logged("add_obstacle_at([1, 0.2])"));
  (void)frames_before;
}

TEST_F(Navigation, FindWithoutKnownTargetSearchesRoomByRoom) {
  const Value task = std::string("find chair");
  in_->Start(0.0);
  in_->SetCondition("apriori_map", true, 0.1);
  in_->SetCondition("task_is_find", true, 0.1, {}, {task});
  in_->SetCondition("room_to_search", true, 0.1, {std::string("R2")});
  in_->SetCondition("task_status", true, 0.2, {task});
  in_->SetCondition("task_given", true, 0.2);
  const std::vector<std::string> chain = Chain();
  EXPECT_NE(std::find(chain.begin(), chain.end(), "SEARCH_THE_MAP_ENVIRONMENT"), chain.end());
  EXPECT_TRUE(Logged("goto_room(\"R2\")"));
  // In that room (Fig. 13): 'in that room' reads the room 'find a new room' gave.
  in_->SetCondition("in_that_room", true, 0.25, {}, {std::string("R2")});
  EXPECT_TRUE(Logged("stop goto_room"));
  EXPECT_TRUE(Logged("search_room(\"R2\", \"find chair\")"));
  // No room left: random search (Fig. 13, footnote 14).
  in_->SetCondition("room_to_search", false, 0.3);
  const std::vector<std::string> after = Chain();
  EXPECT_NE(std::find(after.begin(), after.end(), "RANDOM_SEARCH"), after.end());
  EXPECT_TRUE(Logged("head(\"current\")"));
}

}  // namespace
}  // namespace spott_tr_plus
