// Interpreter semantics (SPOTT III.C): priority, re-evaluation on events, short-circuit,
// concurrency, timeouts, energized vs ballistic conditions and actions, subroutine activation
// and deactivation, output variables. The clock is the test's: no sleeping, no timing.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "spott_tr_plus/interpreter.h"
#include "spott_tr_plus/parser.h"

namespace spott_tr_plus {
namespace {

// A registry whose conditions are external (pushed by the test) unless made otherwise, and
// whose actions log "start NAME(args)" / "stop NAME" and run until completed by the test.
class World {
 public:
  Registry registry;
  std::vector<std::string> log;
  std::map<std::string, Ticket> running;  // action name -> ticket of its latest start
  std::map<std::string, int> computed;    // condition name -> computations
  std::map<std::string, bool> truth;      // values of synchronous conditions

  void External(const std::string& name) { registry.ExternalCondition(name); }
  void Sync(const std::string& name) {
    registry.Condition(name, [this, name](const ConditionCall&, std::vector<Value>&) {
      ++computed[name];
      return truth[name];
    });
  }
  void LongAction(const std::string& name) {
    registry.Action(
        name,
        [this, name](const ActionCall& c) {
          std::string s = "start " + name;
          if (!c.args.empty()) {
            s += "(";
            for (size_t i = 0; i < c.args.size(); ++i)
              s += (i ? "," : "") + ValueToString(c.args[i]);
            s += ")";
          }
          log.push_back(s);
          running[name] = c.ticket;
        },
        [this, name](Ticket) { log.push_back("stop " + name); });
  }
  void InstantAction(const std::string& name) {
    registry.InstantAction(
        name, [this, name](const std::vector<Value>&, double) { log.push_back("run " + name); });
  }

  std::unique_ptr<Interpreter> Load(const std::string& text) {
    const ParseResult r = ParseProgramText(text, "t.tr");
    EXPECT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
    std::vector<Diagnostic> d;
    auto in = Interpreter::Create(r.program, registry, &d);
    EXPECT_TRUE(in) << FormatDiagnostics(d);
    return in;
  }
  std::string Log() const {
    std::string s;
    for (const auto& l : log) s += (s.empty() ? "" : "; ") + l;
    return s;
  }
};

const FrameState* FindFrame(const InterpreterState& s, const std::string& program) {
  for (const auto& f : s.frames) {
    if (f.program == program) return &f;
  }
  return nullptr;
}

const ProcessState* FindProcess(const InterpreterState& s, const std::string& name) {
  for (const auto& p : s.processes) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

TEST(Interpreter, HighestTrueRuleFiresAndAConditionChangeSwitchesAtOnce) {
  World w;
  w.External("goal");
  w.External("near");
  w.LongAction("approach");
  w.LongAction("wander");
  auto in = w.Load(
      "condition goal; condition near; action approach; action wander;\n"
      "main m { goal -> nil; near -> approach; true -> wander; }");
  ASSERT_TRUE(in);
  in->Start(0.0);
  EXPECT_EQ(w.Log(), "start wander");
  EXPECT_EQ(in->State().frames[0].firing_rule, 2);
  // A pushed change scans at once: no Advance, no tick.
  in->SetCondition("near", true, 0.1);
  EXPECT_EQ(w.Log(), "start wander; stop wander; start approach");
  EXPECT_EQ(in->State().frames[0].firing_rule, 1);
  in->SetCondition("goal", true, 0.2);
  EXPECT_EQ(w.Log(), "start wander; stop wander; start approach; stop approach");
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
  // Falling back: the goal is lost, `near` still holds.
  in->SetCondition("goal", false, 0.3);
  EXPECT_EQ(w.log.back(), "start approach");
  EXPECT_EQ(in->NextWakeTime(), std::numeric_limits<double>::infinity());  // nothing timed
}

TEST(Interpreter, EnergizedActionIsSustainedNotRestartedWhileItRuns) {
  World w;
  w.External("a");
  w.LongAction("x");
  auto in = w.Load("condition a; action x;\nmain m { not a -> nil; a -> x; }");
  in->Start(0.0);
  in->SetCondition("a", true, 0.1);
  in->Scan(0.2);
  in->Scan(0.3);
  EXPECT_EQ(w.Log(), "start x");  // one start while it runs
  EXPECT_TRUE(in->State().frames[0].action_running);
  // It finishes while its rule is still the highest true: it is started again.
  ASSERT_TRUE(in->CompleteAction(w.running["x"], true, 0.4));
  EXPECT_EQ(w.Log(), "start x; start x");
  // A stale ticket is ignored.
  EXPECT_FALSE(in->CompleteAction(12345, true, 0.5));
}

TEST(Interpreter, BallisticActionRunsToCompletionAndIsNotRestartedWhileConditionHolds) {
  World w;
  w.External("goal");
  w.External("bump");
  w.External("danger");
  w.LongAction("back_off");
  w.LongAction("halt");
  w.LongAction("go");
  auto in = w.Load(
      "condition goal; condition bump; condition danger; action back_off ballistic; action halt;"
      " action go;\n"
      "main m { goal -> nil; danger -> halt; bump -> back_off; true -> go; }");
  in->Start(0.0);
  in->SetCondition("bump", true, 0.1);
  EXPECT_EQ(w.Log(), "start go; stop go; start back_off");
  // A higher rule fires meanwhile: its action starts, the ballistic one is not cancelled.
  in->SetCondition("danger", true, 0.2);
  EXPECT_EQ(w.Log(), "start go; stop go; start back_off; start halt");
  EXPECT_EQ(in->State().frames[0].ballistic_running, 1);
  in->SetCondition("danger", false, 0.3);
  EXPECT_EQ(w.log.back(), "stop halt");  // back_off keeps running, not restarted
  ASSERT_TRUE(in->CompleteAction(w.running["back_off"], true, 0.4));
  EXPECT_EQ(in->State().frames[0].ballistic_running, 0);
  // Condition still TRUE after completion: not restarted.
  in->Scan(0.5);
  EXPECT_EQ(w.log.back(), "stop halt");
  // A new FALSE-to-TRUE transition starts it again (the lower rule's `go` ran meanwhile).
  in->SetCondition("bump", false, 0.6);
  EXPECT_EQ(w.log.back(), "start go");
  in->SetCondition("bump", true, 0.7);
  EXPECT_EQ(w.log.back(), "start back_off");
}

TEST(Interpreter, SequentialAndDoesNotComputeItsRightOperandWhenTheLeftDecides) {
  World w;
  w.Sync("a");
  w.Sync("b");
  w.Sync("c");
  w.Sync("d");
  w.InstantAction("x");
  auto in = w.Load(
      "condition a; condition b; condition c; condition d; action x;\n"
      "main m { a and b -> nil; c or d -> x; true -> x; }");
  w.truth["c"] = true;
  in->Start(0.0);
  EXPECT_EQ(w.computed["b"], 0);  // a is FALSE: b not even demanded
  EXPECT_EQ(w.computed["d"], 0);  // c is TRUE: d not demanded
  EXPECT_GE(w.computed["a"], 1);
  EXPECT_FALSE(FindProcess(in->State(), "b")->computing);
}

TEST(Interpreter, FiringRuleActsBeforeTheRulesBelowAreEvaluated) {
  // The latency from a change to the action does not depend on the rules below the firing one:
  // its action starts first, then the lower conditions are computed in the same scan.
  World w;
  w.External("a");
  w.registry.Condition("below", [&w](const ConditionCall&, std::vector<Value>&) {
    w.log.push_back("compute below");
    return false;
  });
  w.InstantAction("x");
  w.InstantAction("y");
  auto in = w.Load(
      "condition a; condition below; action x; action y;\n"
      "main m { a -> x; below -> y; true -> y; }");
  in->Start(0.0);
  w.log.clear();
  in->SetCondition("a", true, 0.1);
  ASSERT_GE(w.log.size(), 2u);
  EXPECT_EQ(w.log[0], "run x");
  EXPECT_EQ(w.log[1], "compute below");
  EXPECT_TRUE(in->State().frames[0].rule_values == (std::vector<bool>{true, false, true}));
}

TEST(Interpreter, ConcurrentAndComputesBothOperands) {
  World w;
  w.Sync("a");
  w.Sync("b");
  w.InstantAction("x");
  auto in = w.Load("condition a; condition b; action x;\nmain m { a & b -> nil; true -> x; }");
  in->Start(0.0);
  EXPECT_GE(w.computed["a"], 1);
  EXPECT_GE(w.computed["b"], 1);
}

TEST(Interpreter, ExclusiveOr) {
  World w;
  w.External("a");
  w.External("b");
  w.LongAction("x");
  w.LongAction("y");
  auto in = w.Load(
      "condition a; condition b; action x; action y;\n"
      "main m { a ^ b -> x; true -> y; }");
  in->Start(0.0);
  in->SetCondition("a", true, 0.1);
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
  in->SetCondition("b", true, 0.2);
  EXPECT_EQ(in->State().frames[0].firing_rule, 1);
}

TEST(Interpreter, TimedOperatorIsFalseWhenAnOperandHasNoFreshValueWhateverItSays) {
  World w;
  w.External("a");
  w.External("b");
  w.LongAction("x");
  w.LongAction("y");
  auto in = w.Load(
      "condition a; condition b; action x; action y;\n"
      "main m { a &[0.5s] b -> x; true -> y; }");
  in->Start(0.0);
  in->SetCondition("a", true, 0.0);
  in->SetCondition("b", true, 0.2);
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
  // a's value is from t=0: the expression times out just after t=0.5, and the interpreter asks
  // to be woken then.
  EXPECT_GT(in->NextWakeTime(), 0.5);
  EXPECT_LT(in->NextWakeTime(), 0.5 + 1e-9);
  in->Advance(0.4);
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
  in->Advance(0.51);
  EXPECT_EQ(in->State().frames[0].firing_rule, 1);  // a and b still say TRUE
  // A fresh value of a brings it back.
  in->SetCondition("a", true, 0.6);
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
}

TEST(Interpreter, ConditionComputesAtItsOwnFrequency) {
  World w;
  w.Sync("slow");
  w.Sync("fast");
  w.InstantAction("x");
  auto in = w.Load(
      "condition slow at 2 hz; condition fast; action x;\n"
      "main m { slow -> nil; fast -> nil; true -> x; }");
  in->Start(0.0);
  EXPECT_EQ(w.computed["slow"], 1);
  EXPECT_DOUBLE_EQ(in->NextWakeTime(), 0.5);
  in->Scan(0.2);
  in->Scan(0.4);
  EXPECT_EQ(w.computed["slow"], 1);  // not due yet
  EXPECT_GE(w.computed["fast"], 3);  // frequency 0: on every scan
  in->Advance(0.3);                  // not due: no scan
  w.truth["slow"] = true;
  in->Advance(0.5);
  EXPECT_EQ(w.computed["slow"], 2);
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
}

class AsyncWorld : public World {
 public:
  std::map<std::string, Ticket> pending;
  void Async(const std::string& name) {
    registry.AsyncCondition(name, [this, name](const ConditionCall& c) {
      ++computed[name];
      pending[name] = c.ticket;
    });
  }
};

// kSharedCalls' bindings: `located` computed asynchronously, the rest pushed or long-running.
class AsyncWorldForShared : public AsyncWorld {
 public:
  AsyncWorldForShared() {
    External("task");
    Async("located");
    External("arrived");
    LongAction("update_pose");
    LongAction("drive");
    LongAction("beep");
  }
};

TEST(Interpreter, BallisticConditionIsFalseWhileItRecomputesEnergizedHoldsItsValue) {
  AsyncWorld w;
  w.Async("e");
  w.Async("b");
  w.LongAction("x");
  auto in = w.Load(
      "condition e energized every 1s; condition b ballistic every 1s; action x;\n"
      "main m { e & b -> nil; true -> x; }");
  in->Start(0.0);
  ASSERT_EQ(w.computed["e"], 1);
  ASSERT_EQ(w.computed["b"], 1);
  in->CompleteCondition(w.pending["e"], true, 0.1);
  in->CompleteCondition(w.pending["b"], true, 0.1);
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
  EXPECT_DOUBLE_EQ(in->NextWakeTime(), 1.1);
  in->Advance(1.1);  // both start recomputing
  EXPECT_EQ(w.computed["e"], 2);
  const InterpreterState s = in->State();
  EXPECT_TRUE(FindProcess(s, "e")->value);   // energized: last value while computing
  EXPECT_FALSE(FindProcess(s, "b")->value);  // ballistic: FALSE while computing
  EXPECT_EQ(s.frames[0].firing_rule, 1);
  in->CompleteCondition(w.pending["b"], true, 1.2);
  EXPECT_EQ(in->State().frames[0].firing_rule, 0);
}

const char* kSubProgram =
    "condition done; condition at(place); condition blocked; action drive(place); action "
    "report;\n"
    "main m { done -> nil; blocked -> report; true -> GOTO(\"door\") > report; }\n"
    "sub GOTO(P) { at(P) -> nil; true -> drive(P); }";

TEST(Interpreter, SubroutineConditionsAreActiveOnlyWhileItIsCalled) {
  World w;
  w.External("done");
  w.External("blocked");
  w.Sync("at");
  w.LongAction("drive");
  w.LongAction("report");
  auto in = w.Load(kSubProgram);
  in->Start(0.0);
  EXPECT_EQ(w.Log(), "start drive(\"door\")");
  InterpreterState s = in->State();
  ASSERT_EQ(s.frames.size(), 2u);
  EXPECT_EQ(s.frames[1].program, "GOTO");
  ASSERT_NE(FindFrame(s, "GOTO"), nullptr);
  EXPECT_EQ(FindFrame(s, "GOTO")->firing_rule, 1);
  EXPECT_EQ(s.frames[1].args, std::vector<std::string>{"\"door\""});
  EXPECT_EQ(s.frames[1].caller, 0);
  EXPECT_TRUE(FindProcess(s, "at(\"door\")")->active);
  const int computed = w.computed["at"];
  // A higher rule of main fires: the call is cancelled, the subroutine deactivated.
  in->SetCondition("blocked", true, 0.1);
  EXPECT_EQ(w.Log(), "start drive(\"door\"); stop drive; start report");
  s = in->State();
  ASSERT_EQ(s.frames.size(), 1u);
  EXPECT_EQ(FindFrame(s, "GOTO"), nullptr);
  EXPECT_FALSE(FindProcess(s, "at(\"door\")")->active);
  in->Scan(0.2);
  in->Scan(0.3);
  EXPECT_EQ(w.computed["at"], computed);  // inactive: not computed any more
}

TEST(Interpreter, CallCompletesWhenTheSubroutineGoalHoldsAndTheSequenceGoesOn) {
  World w;
  w.External("done");
  w.External("blocked");
  w.Sync("at");
  w.LongAction("drive");
  w.LongAction("report");
  auto in = w.Load(kSubProgram);
  in->Start(0.0);
  w.truth["at"] = true;
  in->Scan(0.1);  // GOTO's goal holds: the call completes, then `report` starts
  EXPECT_EQ(w.Log(), "start drive(\"door\"); stop drive; start report");
  EXPECT_EQ(in->State().frames.size(), 1u);
  EXPECT_TRUE(in->State().frames[0].action_running);
}

TEST(Interpreter, MonitoringSubroutineStaysActiveWhileTheCallingRuleIsSustained) {
  // SPOTT's main program calls BUMPER_CHECK in parallel with the task: its goal (no contact)
  // holds at once, yet it must keep watching the bumper while the main rule stays highest.
  World w;
  w.External("done");
  w.External("bump");
  w.LongAction("work");
  w.LongAction("react");
  auto in = w.Load(
      "condition done; condition bump; action work; action react;\n"
      "main m { done -> nil; true -> WATCH() || work; }\n"
      "sub WATCH() { not bump -> nil; bump -> react; }");
  in->Start(0.0);
  EXPECT_EQ(w.Log(), "start work");
  ASSERT_NE(FindFrame(in->State(), "WATCH"), nullptr);
  EXPECT_EQ(FindFrame(in->State(), "WATCH")->firing_rule, 0);
  in->SetCondition("bump", true, 0.1);
  EXPECT_EQ(w.Log(), "start work; start react");
  in->SetCondition("bump", false, 0.2);
  EXPECT_EQ(w.Log(), "start work; start react; stop react");
  EXPECT_NE(FindFrame(in->State(), "WATCH"), nullptr);
  // Not restarted while parts of it run: `work` was started once.
  in->Scan(0.3);
  EXPECT_EQ(w.Log(), "start work; start react; stop react");
  // The main goal: the sustained action is cancelled and WATCH deactivated.
  in->SetCondition("done", true, 0.4);
  EXPECT_EQ(w.log.back(), "stop work");
  EXPECT_EQ(FindFrame(in->State(), "WATCH"), nullptr);
}

TEST(Interpreter, ASwitchedOffSubroutineIsNeverEnteredAndItsConditionsNeverRead) {
  // SPOTT's program on the B-12: the bumper subroutine off, the rest of the rule runs.
  World w;
  w.External("done");
  w.External("bump");
  w.LongAction("work");
  w.LongAction("react");
  const char* text =
      "condition done; condition bump; action work; action react;\n"
      "main m { done -> nil; true -> WATCH() || work; }\n"
      "sub WATCH() { not bump -> nil; bump -> react; }";
  const ParseResult parsed = ParseProgramText(text, "t.tr");
  ASSERT_TRUE(parsed.ok());
  Interpreter::Options options;
  options.off_subroutines = {"WATCH"};
  std::vector<Diagnostic> d;
  auto in = Interpreter::Create(parsed.program, w.registry, &d, "", options);
  ASSERT_TRUE(in) << FormatDiagnostics(d);
  in->Start(0.0);
  EXPECT_EQ(w.Log(), "start work");
  EXPECT_EQ(FindFrame(in->State(), "WATCH"), nullptr);
  EXPECT_EQ(FindProcess(in->State(), "bump"), nullptr) << "the off subroutine's condition is read";
  in->SetCondition("bump", true, 0.1);
  EXPECT_EQ(w.Log(), "start work");
  in->SetCondition("done", true, 0.2);
  EXPECT_EQ(w.log.back(), "stop work");
  // A name that is no subroutine, or the main program, is refused by name.
  for (const char* bad : {"WATCHER", "m"}) {
    options.off_subroutines = {bad};
    d.clear();
    EXPECT_FALSE(Interpreter::Create(parsed.program, w.registry, &d, "", options)) << bad;
    EXPECT_NE(FormatDiagnostics(d).find(std::string("'") + bad + "'"), std::string::npos)
        << FormatDiagnostics(d);
  }
}

TEST(Interpreter, BallisticCallRunsUntilTheSubroutineGoalEvenWhenAHigherRuleFires) {
  World w;
  w.External("goal");
  w.External("trigger");
  w.External("urgent");
  w.External("parked");
  w.LongAction("park");
  w.LongAction("alarm");
  w.LongAction("idle");
  auto in = w.Load(
      "condition goal; condition trigger; condition urgent; condition parked;\n"
      "action park; action alarm; action idle;\n"
      "main m { goal -> nil; urgent -> alarm; trigger -> ballistic PARK(); true -> idle; }\n"
      "sub PARK() { parked -> nil; true -> park; }");
  in->Start(0.0);
  in->SetCondition("trigger", true, 0.1);
  EXPECT_EQ(w.Log(), "start idle; stop idle; start park");
  in->SetCondition("urgent", true, 0.2);  // higher rule: PARK keeps running beside it
  EXPECT_EQ(w.Log(), "start idle; stop idle; start park; start alarm");
  EXPECT_NE(FindFrame(in->State(), "PARK"), nullptr);
  in->SetCondition("parked", true, 0.3);  // the call completes: PARK is deactivated
  EXPECT_EQ(w.log.back(), "stop park");
  EXPECT_EQ(FindFrame(in->State(), "PARK"), nullptr);
  EXPECT_EQ(in->State().frames[0].ballistic_running, 0);
}

TEST(Interpreter, ConcurrentActionsStartTogetherAndCompleteWhenBothHave) {
  World w;
  w.External("goal");
  w.LongAction("x");
  w.LongAction("y");
  w.LongAction("z");
  auto in = w.Load(
      "condition goal; action x; action y; action z;\n"
      "main m { goal -> nil; true -> ballistic (x || y) > z; }");
  in->Start(0.0);
  EXPECT_EQ(w.Log(), "start x; start y");
  in->CompleteAction(w.running["y"], true, 0.1);
  EXPECT_EQ(w.Log(), "start x; start y");  // x still running
  in->CompleteAction(w.running["x"], true, 0.2);
  EXPECT_EQ(w.Log(), "start x; start y; start z");
}

TEST(Interpreter, OutputVariablesBindIntoTheAction) {
  World w;
  w.registry.Condition("bumper", [](const ConditionCall&, std::vector<Value>& out) {
    out[0] = std::vector<double>{1.5, -0.25};
    return true;
  });
  w.LongAction("move_away");
  auto in = w.Load(
      "condition bumper(out where); action move_away(p, d);\n"
      "main m { not bumper -> nil; bumper(w) -> move_away(w, 0.3); }");
  in->Start(0.0);
  EXPECT_EQ(w.Log(), "start move_away([1.5, -0.25],0.3)");
  EXPECT_EQ(FindProcess(in->State(), "bumper")->outputs[0].second, "[1.5, -0.25]");
}

// SPOTT Fig. 13: "find a new room", then "in that room". The first condition's output is the
// second's input: the second's process follows the room the first one gives.
TEST(Interpreter, AnOutputFeedsTheInputOfTheConditionToItsRight) {
  World w;
  std::string next = "R2";
  w.registry.Condition("new_room", [&next](const ConditionCall&, std::vector<Value>& out) {
    out[0] = next;
    return true;
  });
  std::vector<std::string> asked;
  w.registry.Condition("in_room", [&asked](const ConditionCall& c, std::vector<Value>&) {
    asked.push_back(ValueToString(c.inputs[0]));
    return std::get<std::string>(c.inputs[0]) == "R3";
  });
  w.LongAction("search");
  w.LongAction("go_to");
  auto in = w.Load(
      "condition new_room(out r); condition in_room(room); action search(room);"
      " action go_to(room);\n"
      "main m { new_room(r) and in_room(r) -> search(r); new_room(r) -> go_to(r);"
      " not new_room -> nil; }");
  in->Start(0.0);
  EXPECT_EQ(w.Log(), "start go_to(\"R2\")");
  ASSERT_FALSE(asked.empty());
  EXPECT_EQ(asked.back(), "\"R2\"");
  EXPECT_TRUE(FindProcess(in->State(), "in_room(\"R2\")")->active);
  // The schedule moves on to R3, where the robot is: the rule with both conditions fires.
  next = "R3";
  in->Scan(0.1);
  EXPECT_EQ(asked.back(), "\"R3\"");
  EXPECT_EQ(w.Log(), "start go_to(\"R2\"); stop go_to; start search(\"R3\")");
  const InterpreterState s = in->State();
  EXPECT_TRUE(FindProcess(s, "in_room(\"R3\")")->active);
  // No atom reads in_room("R2") any more: its process is dropped, not kept forever.
  in->Scan(0.2);
  EXPECT_EQ(FindProcess(in->State(), "in_room(\"R2\")"), nullptr);
}

// The program of SPOTT's main rule 2 and 3 in small: LOC() runs in both rules, the task only in
// rule 1. SPOTT III.C.1 footnote 11: only the conditions "in the currently called set of
// subroutines" are active; a rule change keeps in that set the subroutines both rules call.
const char* kSharedCalls =
    "condition task(out t); condition located every 1s; condition arrived(goal);\n"
    "action update_pose; action drive(goal); action beep;\n"
    "main m { task(t) -> LOC() || beep || TASK(t); true -> LOC() || beep; }\n"
    "sub LOC() { not located -> nil; located -> update_pose; }\n"
    "sub TASK(G) { arrived(G) -> nil; true -> drive(G); }";

TEST(Interpreter, SubroutinesBothRulesCallKeepRunningWhenTheFiringRuleChanges) {
  AsyncWorldForShared w;
  auto in = w.Load(kSharedCalls);
  in->Start(0.0);
  ASSERT_EQ(w.computed["located"], 1);
  ASSERT_TRUE(in->CompleteCondition(w.pending["located"], true, 0.1));
  EXPECT_EQ(w.Log(), "start beep; start update_pose");
  // A task: rule 1 replaces rule 2. LOC and beep run in both: neither is stopped or restarted,
  // LOC's condition keeps its value and is not recomputed before its period.
  in->SetCondition("task", true, 0.2, {std::string("door")});
  EXPECT_EQ(w.Log(), "start beep; start update_pose; start drive(\"door\")");
  EXPECT_EQ(w.computed["located"], 1);
  EXPECT_TRUE(FindProcess(in->State(), "located")->value);
  EXPECT_EQ(FindFrame(in->State(), "LOC")->firing_rule, 1);
  EXPECT_TRUE(FindFrame(in->State(), "LOC")->action_running);
  // The kept action completes into the new rule: its ticket is the new rule's.
  ASSERT_TRUE(in->CompleteAction(w.running["update_pose"], true, 0.3));
  EXPECT_EQ(w.log.back(), "start update_pose");  // sustained in LOC, restarted
  // The task ends: back to rule 2; TASK leaves, LOC and beep go on.
  in->SetCondition("task", false, 0.4);
  EXPECT_EQ(w.log.back(), "stop drive");
  EXPECT_EQ(FindFrame(in->State(), "TASK"), nullptr);
  EXPECT_NE(FindFrame(in->State(), "LOC"), nullptr);
  EXPECT_EQ(std::count(w.log.begin(), w.log.end(), "start beep"), 1);
  EXPECT_EQ(std::count(w.log.begin(), w.log.end(), "stop beep"), 0);
}

TEST(Interpreter, NewOutputValuesRestartTheActionKeepingWhatBothBindingsRun) {
  AsyncWorldForShared w;
  auto in = w.Load(kSharedCalls);
  in->Start(0.0);
  in->SetCondition("task", true, 0.1, {std::string("door")});
  EXPECT_EQ(w.Log(), "start beep; start drive(\"door\")");
  // A new task while rule 1 stays the highest: TASK is called with the new value; LOC and beep,
  // called the same way by both, keep running.
  in->SetCondition("task", true, 0.2, {std::string("desk")});
  EXPECT_EQ(w.Log(), "start beep; start drive(\"door\"); stop drive; start drive(\"desk\")");
  const InterpreterState s = in->State();
  EXPECT_EQ(FindFrame(s, "TASK")->args, std::vector<std::string>{"\"desk\""});
  EXPECT_EQ(FindProcess(s, "arrived(\"door\")")->active, false);
  EXPECT_EQ(FindProcess(s, "arrived(\"desk\")")->active, true);
  // The same value again: nothing restarts.
  in->SetCondition("task", true, 0.3, {std::string("desk")});
  EXPECT_EQ(w.log.back(), "start drive(\"desk\")");
  EXPECT_EQ(std::count(w.log.begin(), w.log.end(), "start beep"), 1);
}

TEST(Interpreter, OutputsThatChangeOnEveryComputationRestartTheActionOncePerScan) {
  World w;
  double n = 0;
  w.registry.Condition("counter", [&n](const ConditionCall&, std::vector<Value>& out) {
    out[0] = ++n;  // a new value each time it is computed (every scan pass at frequency 0)
    return true;
  });
  w.LongAction("show");
  auto in = w.Load("condition counter(out n); action show(n);\nmain m { counter(n) -> show(n); }");
  in->Start(0.0);
  EXPECT_EQ(w.log.size(), 1u) << w.Log();
  EXPECT_LT(in->scans(), 5u);
  in->Scan(0.1);
  ASSERT_EQ(w.log.size(), 3u) << w.Log();  // stop show; start show(newer value)
  EXPECT_EQ(w.log[1], "stop show");
}

TEST(Interpreter, UnboundNamesAreRefusedWithLocatedErrors) {
  World w;
  w.External("a");
  const ParseResult r =
      ParseProgramText("condition a;\naction fly;\nmain m { a -> nil; not a -> fly; }", "u.tr");
  std::vector<Diagnostic> d;
  EXPECT_FALSE(Interpreter::Create(r.program, w.registry, &d));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].ToString(),
            "u.tr:2:1: action 'fly' is not bound to a C++ function in the registry");
}

TEST(Interpreter, RecursionIsBoundedByTheCallDepth) {
  World w;
  w.External("a");
  w.LongAction("x");
  const ParseResult r = ParseProgramText(
      "condition a; action x;\nmain m { a -> nil; true -> R(); }\n"
      "sub R() { a -> nil; true -> R(); }",
      "r.tr");
  std::vector<Diagnostic> d;
  Interpreter::Options o;
  o.max_call_depth = 5;
  auto in = Interpreter::Create(r.program, w.registry, &d, "", o);
  ASSERT_TRUE(in) << FormatDiagnostics(d);
  in->Start(0.0);
  EXPECT_EQ(in->State().frames.size(), 6u);  // main + 5 nested calls
  in->SetCondition("a", true, 0.1);
  EXPECT_EQ(in->State().frames.size(), 1u);
}

}  // namespace
}  // namespace spott_tr_plus
