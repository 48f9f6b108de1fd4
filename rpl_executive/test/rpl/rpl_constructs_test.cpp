// The semantics of every construct: sequencing, concurrency, TRY-ALL, EVAP-PROTECT, WHENEVER,
// policies, valves, behaviour modules, failures and their causes.
#include <gtest/gtest.h>

#include "test_support.h"

namespace rpl_executive {
namespace rpl {
namespace {

using testing::Harness;

// ---- sequencing, variables, loops ------------------------------------------------------------

TEST(RplSeq, RunsInOrderAndReturnsTheLastValue) {
  Harness h;
  h.Run("(SEQ (TRACE 1) (WAIT-TIME 1) (TRACE 2) (+ 40 2))");
  h.Step(0);
  EXPECT_EQ(h.Trace(), "1");
  h.Step(1);
  EXPECT_EQ(h.Trace(), "1, 2");
  ASSERT_EQ(h.executive.state(), PlanState::kSucceeded);
  EXPECT_EQ(h.executive.result(), Value::Number(42));
}

TEST(RplLet, BindsInParallelAndSetfChangesTheBinding) {
  Harness h;
  h.Run("(LET ((A 1) (B 2)) (LET ((A B) (B A)) (SETF A (* A 10)) (LIST A B)))");
  h.Step(0);
  EXPECT_EQ(h.executive.result().ToString(), "(20 1)");
}

TEST(RplIf, ChoosesTheBranchAndAMissingElseIsNil) {
  Harness h;
  h.Run("(LIST (IF (> 2 1) :YES :NO) (IF NIL :YES) (IF (SEQ (WAIT-TIME 1) T) (SEQ :LATE)))");
  h.Step(0);
  h.Step(1);
  EXPECT_EQ(h.executive.result().ToString(), "(:YES NIL :LATE)");
}

TEST(RplLoop, UntilIsTestedWhereItIsWritten) {
  Harness h;
  h.Run("(LET ((N 0)) (LOOP (SETF N (+ N 1)) (TRACE N) UNTIL (>= N 3)) N)");
  h.Step(0);
  EXPECT_EQ(h.Trace(), "1, 2, 3");
  EXPECT_EQ(h.executive.result(), Value::Number(3));
  Harness first;
  first.Run("(LOOP UNTIL T (TRACE \"never\"))");
  first.Step(0);
  EXPECT_EQ(first.Trace(), "");
  EXPECT_EQ(first.executive.state(), PlanState::kSucceeded);
}

TEST(RplLoop, ALoopThatNeverWaitsIsCutByTheInstructionBudgetAndResumedNextStep) {
  ExecutiveParameters p;
  p.max_instructions_per_step = 500;
  Harness h(p);
  h.Run("(DEF-FLUENT N 0)\n(LOOP (SETF N (+ N 1)) UNTIL (>= N 1000))");
  const StepResult r = h.Step(0);
  EXPECT_EQ(r.instructions, 500);
  EXPECT_EQ(r.state, PlanState::kRunning);
  const double n = h.executive.GetFluent("N").number();
  EXPECT_GT(n, 100);
  EXPECT_LT(n, 1000);
  for (int i = 1; i < 10 && h.executive.state() == PlanState::kRunning; ++i) h.Step(i);
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
  EXPECT_EQ(h.executive.GetFluent("N"), Value::Number(1000));
}

TEST(RplProcedures, RecursionDeeperThanTheLimitFailsCleanly) {
  ExecutiveParameters p;
  p.max_call_depth = 50;
  Harness h(p);
  h.Run("(DEFUN DOWN (N) (TRACE N) (DOWN (+ N 1)))\n(DOWN 0)");
  h.Step(0);
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  EXPECT_EQ(h.executive.failure()->failure_class, FailureClass::kRuntimeError);
  EXPECT_EQ(h.executive.failure()->message,
            "procedure calls nested deeper than max_call_depth (50)");
  EXPECT_EQ(h.trace.size(), 50u);
}

TEST(RplProcedures, APlanThatForksWithoutEndFailsAtTheTaskLimit) {
  ExecutiveParameters p;
  p.max_live_tasks = 1000;
  p.max_instructions_per_step = 100000;
  Harness h(p);
  h.Run("(DEFUN FORK () (PAR (FORK) (FORK)))\n(EVAP-PROTECT (FORK) (TRACE \"cleanup ran\"))");
  for (int i = 0; i < 10 && h.executive.state() == PlanState::kRunning; ++i) h.Step(i);
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  EXPECT_EQ(h.executive.failure()->failure_class, FailureClass::kRuntimeError);
  EXPECT_EQ(h.executive.failure()->message,
            "more than max_live_tasks (1000) tasks would be live (a plan that forks without end?)");
  EXPECT_EQ(h.Trace(), "cleanup ran");
  EXPECT_EQ(h.executive.NumLiveTasks(), 0u);
}

TEST(RplProcedures, StartOverridesADefvar) {
  Harness h;
  ASSERT_FALSE(HasErrors(h.executive.Load("(DEFVAR DEST '(1 2))\nDEST", "p.rpl")));
  EXPECT_EQ(h.executive.Start(0, {{"DESTINATION", Value()}}),
            "the plan has no DEFVAR DESTINATION to set");
  ASSERT_EQ(h.executive.Start(0, {{"DEST", Value::Point(19.6, 6)}}), "");
  h.Step(0);
  EXPECT_EQ(h.executive.result().ToString(), "(19.6 6)");
}

// ---- PAR, TRY-ALL, TRY-IN-ORDER ---------------------------------------------------------------

TEST(RplPar, SucceedsWhenAllBranchesSucceed) {
  Harness h;
  h.Run("(PAR (SEQ (WAIT-FOR (> F* 0)) (TRACE \"f\")) (SEQ (WAIT-FOR (> G* 0)) (TRACE \"g\")))");
  h.Step(0);
  h.Set("G*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.executive.state(), PlanState::kRunning);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "g, f");
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

TEST(RplPar, FailsWithTheFirstFailureAndEvaporatesTheOtherBranches) {
  Harness h;
  h.Run(
      "(PAR (SEQ (WAIT-FOR (> F* 0)) (FAIL \"branch one gave up\"))\n"
      "     (EVAP-PROTECT (WAIT-FOR (> G* 0)) (TRACE \"cleanup two\")))");
  h.Step(0);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "cleanup two");
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  EXPECT_EQ(h.executive.failure()->failure_class, FailureClass::kPlanFailure);
  EXPECT_EQ(h.executive.failure()->message, "branch one gave up");
  EXPECT_EQ(h.executive.failure()->where.ToString(), "test.rpl:1:31");
}

TEST(RplTryAll, SucceedsWithTheFirstSuccessAndEvaporatesItsSiblingsWhoseCleanupsRun) {
  Harness h;
  h.Run(
      "(TRY-ALL (SEQ (WAIT-FOR (> F* 0)) :FIRST)\n"
      "         (EVAP-PROTECT (SEQ (WAIT-FOR (> G* 0)) :SECOND) (TRACE \"second cleaned up\"))\n"
      "         (SEQ (WAIT-FOR (> G* 0)) :THIRD))");
  h.Step(0);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  ASSERT_EQ(h.executive.state(), PlanState::kSucceeded);
  EXPECT_EQ(h.executive.result(), Value::Symbol(":FIRST"));
  EXPECT_EQ(h.Trace(), "second cleaned up");
  EXPECT_EQ(h.executive.NumLiveTasks(), 0u);
}

TEST(RplTryAll, EveryThreadOfControlReportsHowItEnded) {
  Harness h;
  h.Run(
      "(TRY-ALL (PROCESS WINNER (WAIT-FOR (> F* 0)))\n"
      "         (PROCESS LOSER (FAIL \"no way\"))\n"
      "         (PROCESS SLOW (WAIT-FOR NIL)))");
  h.Step(0);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.Events(Event::Kind::kThreadEnded),
            (std::vector<std::string>{"LOSER: failed: no way", "WINNER: done", "SLOW: evaporated",
                                      "PLAN: done"}));
}

TEST(RplTryAll, ReportsSuccessOnlyAfterTheEvaporatedSiblingsCleanupsHaveEnded) {
  Harness h;
  h.Run(
      "(TRY-ALL (SEQ (WAIT-FOR (> F* 0)) :FIRST)\n"
      "         (EVAP-PROTECT (WAIT-FOR NIL)\n"
      "           (SEQ (TRACE \"cleanup starts\") (WAIT-TIME 2) (TRACE \"cleanup ends\"))))\n"
      "(TRACE \"after TRY-ALL\")");
  h.Step(0);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "cleanup starts");
  h.Step(1);
  EXPECT_EQ(h.Trace(), "cleanup starts");
  h.Step(2);
  EXPECT_EQ(h.Trace(), "cleanup starts, cleanup ends, after TRY-ALL");
}

TEST(RplTryAll, FailsOnlyWhenEverySubtaskHasFailedWithAllTheirCauses) {
  Harness h;
  h.Run(
      "(TRY-ALL (SEQ (WAIT-FOR (> F* 0)) (FAIL \"first\"))\n"
      "         (SEQ (WAIT-FOR (> G* 0)) (FAIL \"second\")))");
  h.Step(0);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.executive.state(), PlanState::kRunning);  // one subtask is still going
  h.Set("G*", Value::Number(1));
  h.Step(0);
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  const Failure* f = h.executive.failure();
  EXPECT_EQ(f->failure_class, FailureClass::kAllFailed);
  EXPECT_EQ(f->message, "all 2 subtasks of TRY-ALL failed");
  ASSERT_EQ(f->causes.size(), 2u);
  EXPECT_EQ(f->causes[0].message, "first");
  EXPECT_EQ(f->causes[1].message, "second");
  EXPECT_EQ(f->ToString(),
            "test.rpl:1:1: ALL-FAILED: all 2 subtasks of TRY-ALL failed (in TRY-ALL)\n"
            "  test.rpl:1:35: PLAN-FAILURE: first (in FAIL)\n"
            "  test.rpl:2:35: PLAN-FAILURE: second (in FAIL)");
}

TEST(RplTryInOrder, TriesTheAlternativesOneAfterTheOther) {
  Harness h;
  h.Run("(TRY-IN-ORDER (SEQ (TRACE 1) (FAIL \"no\")) (SEQ (TRACE 2) :TWO) (TRACE 3))");
  h.Step(0);
  EXPECT_EQ(h.Trace(), "1, 2");
  EXPECT_EQ(h.executive.result(), Value::Symbol(":TWO"));
}

// ---- EVAP-PROTECT -----------------------------------------------------------------------------

TEST(RplEvapProtect, RunsTheCleanupWhenTheBodyIsDeactivatedByAbort) {
  Harness h;
  h.Run("(EVAP-PROTECT (EXECUTE NAVIGATION '(1 2)) (SEQ (TRACE \"remove goals\") (WAIT-TIME 1)))");
  h.Step(0);
  ASSERT_TRUE(h.navigation->IsActive());
  h.executive.Abort(0.5);
  EXPECT_FALSE(h.navigation->IsActive());               // the body's module stops at once
  EXPECT_EQ(h.executive.state(), PlanState::kRunning);  // the cleanup still runs
  h.Step(0.5);
  EXPECT_EQ(h.Trace(), "remove goals");
  h.Step(1.5);
  EXPECT_EQ(h.executive.state(), PlanState::kAborted);
  EXPECT_EQ(h.executive.NumLiveTasks(), 0u);
}

TEST(RplEvapProtect, RunsTheCleanupWhenTheBodyEndsOrFailsToo) {
  Harness ok;
  ok.Run("(EVAP-PROTECT (SEQ (TRACE \"body\") :DONE) (TRACE \"cleanup\"))");
  ok.Step(0);
  EXPECT_EQ(ok.Trace(), "body, cleanup");
  EXPECT_EQ(ok.executive.result(), Value::Symbol(":DONE"));  // the body's value
  Harness failed;
  failed.Run("(EVAP-PROTECT (FAIL \"body failed\") (TRACE \"cleanup\"))");
  failed.Step(0);
  EXPECT_EQ(failed.Trace(), "cleanup");
  ASSERT_EQ(failed.executive.state(), PlanState::kFailed);
  EXPECT_EQ(failed.executive.failure()->message, "body failed");  // the body's cause
}

TEST(RplEvapProtect, NestedCleanupsRunInnerFirst) {
  Harness h;
  h.Run(
      "(TRY-ALL (WAIT-FOR (> F* 0))\n"
      "  (EVAP-PROTECT (EVAP-PROTECT (WAIT-FOR NIL) (TRACE \"inner\")) (TRACE \"outer\")))");
  h.Step(0);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  // The outer cleanup starts once the outer body, inner cleanup included, is gone.
  EXPECT_EQ(h.Trace(), "inner, outer");
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

// ---- WHENEVER ---------------------------------------------------------------------------------

TEST(RplWhenever, IsWaitBlockedWhileFalseAndRunsItsBodyEachTimeItBecomesTrue) {
  Harness h;
  h.Run("(WHENEVER (> F* 0) (TRACE \"fired\" F*) (WAIT-FOR (<= F* 0)))");
  h.Step(0);
  const auto tree = h.executive.TaskTree();
  ASSERT_FALSE(tree.empty());
  bool blocked = false;
  for (const auto& t : tree) {
    if (t.label == "WHENEVER") {
      blocked = t.state == TaskInfo::State::kWaitBlocked && t.waiting_for == "(> F* 0)";
    }
  }
  EXPECT_TRUE(blocked);
  for (int i = 1; i <= 3; ++i) {
    h.Set("F*", Value::Number(i));
    h.Step(i);
    h.Set("F*", Value::Number(0));
    h.Step(i);
  }
  EXPECT_EQ(h.Trace(), "fired 1, fired 2, fired 3");
  EXPECT_EQ(h.executive.state(), PlanState::kRunning);  // an endless loop
}

TEST(RplWhenever, RunsAgainAtOnceWhenTheFluentIsStillTrueAfterTheBody) {
  Harness h;
  h.Run("(WHENEVER FLAG* (TRACE \"tick\") (WAIT-TIME 1))");
  h.Set("FLAG*", Value::True());
  h.Step(0);
  h.Step(1);
  h.Step(2);
  EXPECT_EQ(h.Trace(), "tick, tick, tick");
  h.Set("FLAG*", Value());
  h.Step(3);
  h.Step(4);
  EXPECT_EQ(h.Trace(), "tick, tick, tick");
}

// ---- WITH-POLICY ------------------------------------------------------------------------------

TEST(RplPolicy, RunsBeforeItsPrimaryActivityWhenBothAreWokenTogether) {
  Harness h;
  h.Run(
      "(WITH-POLICY (SEQ (WAIT-TIME 1) (WAIT-FOR (> F* 0)) (TRACE \"policy\"))\n"
      "  (SEQ (WAIT-FOR (> F* 0)) (TRACE \"primary\")))");
  h.Step(0);
  h.Step(1);  // both wait on F* now; the primary began to wait first
  h.Set("F*", Value::Number(1));
  h.Step(1);
  EXPECT_EQ(h.Trace(), "policy, primary");
}

TEST(RplPolicy, PreemptsThePrimaryAtTheNextInstructionWhenThePrimaryWakesIt) {
  Harness h;
  h.Run(
      "(DEF-FLUENT GO 0)\n"
      "(WITH-POLICY (WHENEVER (> GO 0) (TRACE \"policy\") (WAIT-FOR (= GO 0)))\n"
      "  (SEQ (TRACE \"p1\") (SETF GO 1) (TRACE \"p2\") (SETF GO 0) (TRACE \"p3\")))");
  h.Step(0);
  EXPECT_EQ(h.Trace(), "p1, policy, p2, p3");
}

TEST(RplPolicy, EndsWithThePrimaryActivityAndThePolicyIsEvaporatedWithItsCleanup) {
  Harness h;
  h.Run(
      "(WITH-POLICY (EVAP-PROTECT (WHENEVER (> F* 0) (TRACE \"never\")) (TRACE \"policy gone\"))\n"
      "  (SEQ (WAIT-TIME 1) :DELIVERED))");
  h.Step(0);
  h.Step(1);
  EXPECT_EQ(h.Trace(), "policy gone");
  ASSERT_EQ(h.executive.state(), PlanState::kSucceeded);
  EXPECT_EQ(h.executive.result(), Value::Symbol(":DELIVERED"));
}

TEST(RplPolicy, AFailingPolicyFailsTheWithPolicyAndEvaporatesThePrimary) {
  Harness h;
  h.Run(
      "(WITH-POLICY (SEQ (WAIT-FOR (> F* 0)) (FAIL \"constraint violated\"))\n"
      "  (EVAP-PROTECT (EXECUTE NAVIGATION '(1 2)) (TRACE \"primary cleaned up\")))");
  h.Step(0);
  ASSERT_TRUE(h.navigation->IsActive());
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_FALSE(h.navigation->IsActive());
  EXPECT_EQ(h.Trace(), "primary cleaned up");
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  EXPECT_EQ(h.executive.failure()->message, "constraint violated");
  EXPECT_EQ(h.executive.failure()->task_path, "WITH-POLICY policy > FAIL");
}

TEST(RplPolicy, APolicyThatEndsLeavesThePrimaryRunning) {
  Harness h;
  h.Run("(WITH-POLICY (TRACE \"policy done\") (SEQ (WAIT-TIME 1) (TRACE \"primary done\")))");
  h.Step(0);
  EXPECT_EQ(h.executive.state(), PlanState::kRunning);
  h.Step(1);
  EXPECT_EQ(h.Trace(), "policy done, primary done");
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

// ---- valves -----------------------------------------------------------------------------------

TEST(RplValve, IsExclusiveAndServesEqualPrioritiesInTurn) {
  Harness h;
  h.Run(
      "(PAR (WITH-VALVE WHEELS (TRACE \"a in\") (WAIT-FOR (> F* 0)) (TRACE \"a out\"))\n"
      "     (WITH-VALVE WHEELS (TRACE \"b in\") (WAIT-FOR (> G* 0)) (TRACE \"b out\")))");
  h.Step(0);
  EXPECT_EQ(h.Trace(), "a in");
  h.Set("G*", Value::Number(1));  // b cannot take the valve from a
  h.Step(0);
  EXPECT_EQ(h.Trace(), "a in");
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "a in, a out, b in, b out");
}

TEST(RplValve, AHigherPriorityThreadPreemptsItAndThePreemptedRoutineNoticesAndResumes) {
  Harness h;
  h.navigation->on_deactivate = [&](ActivationId, double) { h.trace.push_back("goals deleted"); };
  h.Run(
      "(WITH-POLICY (WHENEVER FLAG* (WITH-VALVE WHEELS (TRACE \"policy drives\")\n"
      "                                (WAIT-FOR (NOT FLAG*)) (TRACE \"policy done\")))\n"
      "  (WITH-VALVE WHEELS\n"
      "    (WITH-FAILURE-HANDLING (EXECUTE NAVIGATION '(1 2))\n"
      "      (INTERRUPTED (WHY) (TRACE \"interrupted:\" WHY)))\n"
      "    (EXECUTE NAVIGATION '(3 4))))");
  h.Step(0);
  ASSERT_EQ(h.navigation->activations.size(), 1u);
  EXPECT_EQ(h.executive.ValveHolder("WHEELS"), "WITH-VALVE");
  h.Set("FLAG*", Value::True());
  h.Step(1);
  // The module under the pre-empted valve stops before the pre-empting thread drives; the
  // pre-empted routine is told (INTERRUPTED) and its next move waits for the valve.
  ASSERT_EQ(h.trace.size(), 3u) << h.Trace();
  EXPECT_EQ(h.trace[0], "goals deleted");
  EXPECT_EQ(h.trace[1], "policy drives");
  EXPECT_EQ(h.trace[2],
            "interrupted: NAVIGATION valve WHEELS pre-empted by WITH-POLICY policy > WITH-VALVE");
  EXPECT_EQ(h.navigation->activations.size(), 1u);
  EXPECT_EQ(h.executive.ValveHolder("WHEELS"), "WITH-POLICY policy > WITH-VALVE");
  int waiting_for_wheels = 0;
  for (const auto& t : h.executive.TaskTree()) {
    waiting_for_wheels += t.label == "EXECUTE NAVIGATION" &&
                          t.state == TaskInfo::State::kWaitBlocked &&
                          t.waiting_for == "valve WHEELS";
  }
  EXPECT_EQ(waiting_for_wheels, 1);
  h.Set("FLAG*", Value());
  h.Step(2);
  ASSERT_EQ(h.navigation->activations.size(), 2u);  // resumed once the valve came back
  EXPECT_EQ(h.navigation->activations[1].args[0].ToString(), "(3 4)");
  EXPECT_DOUBLE_EQ(h.navigation->activations[1].time_s, 2.0);
  EXPECT_EQ(h.executive.ValveHolder("WHEELS"), "WITH-VALVE");
  h.navigation->Succeed();
  h.Step(3);
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
  EXPECT_EQ(h.executive.ValveHolder("WHEELS"), "");
  EXPECT_EQ(
      h.Events(Event::Kind::kValvePreempted),
      std::vector<std::string>{"WHEELS: WITH-VALVE lost it to WITH-POLICY policy > WITH-VALVE"});
}

TEST(RplValve, AModuleOutsideWithValveRequestsItsValveItself) {
  Harness h;
  h.Run("(PAR (EXECUTE NAVIGATION '(1 2)) (SEQ (WAIT-TIME 1) (EXECUTE ACTIVE-LOCALIZATION)))");
  h.Step(0);
  h.Step(1);
  EXPECT_TRUE(h.navigation->IsActive());
  EXPECT_FALSE(h.localization->IsActive());  // waits for WHEELS
  h.navigation->Succeed();
  h.Step(2);
  EXPECT_TRUE(h.localization->IsActive());
  h.localization->Succeed();
  h.Step(3);
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

TEST(RplValve, AnOutsideAgentCanSeizeItAboveEveryThread) {
  Harness h;
  h.Run("(WITH-POLICY (WAIT-FOR NIL) (EXECUTE NAVIGATION '(1 2)))");
  h.Step(0);
  ASSERT_TRUE(h.navigation->IsActive());
  h.executive.SeizeValve("WHEELS", "bumper reflex", 1);
  EXPECT_FALSE(h.navigation->IsActive());
  EXPECT_EQ(h.executive.ValveHolder("WHEELS"), "bumper reflex");
  h.Step(1);
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  EXPECT_EQ(h.executive.failure()->failure_class, FailureClass::kInterrupted);
  EXPECT_EQ(h.executive.failure()->message, "NAVIGATION valve WHEELS pre-empted by bumper reflex");
  h.executive.ReturnValve("WHEELS", 2);
  EXPECT_EQ(h.executive.ValveHolder("WHEELS"), "");
}

// ---- behaviour modules ------------------------------------------------------------------------

TEST(RplModule, ExecuteWaitsForTheModulesSignalAndReturnsItsValue) {
  Harness h;
  h.Run("(EXECUTE NAVIGATION (LIST 1 (+ 1 1)))");
  h.Step(0);
  ASSERT_EQ(h.navigation->activations.size(), 1u);
  EXPECT_EQ(h.navigation->activations[0].args[0].ToString(), "(1 2)");
  bool waiting = false;
  for (const auto& t : h.executive.TaskTree()) {
    if (t.label == "EXECUTE NAVIGATION") {
      waiting = t.state == TaskInfo::State::kWaitBlocked && t.waiting_for == "NAVIGATION";
    }
  }
  EXPECT_TRUE(waiting);
  EXPECT_EQ(h.Step(1).instructions, 0);
  h.navigation->Succeed(Value::Symbol(":ARRIVED"));
  h.Step(2);
  EXPECT_EQ(h.executive.result(), Value::Symbol(":ARRIVED"));
  EXPECT_TRUE(h.navigation->deactivations.empty());  // it ended by itself
}

TEST(RplModule, AnActivationLastsAsLongAsTheThreadThatMadeIt) {
  Harness h;
  h.Run("(PROCESS TRACKER (ACTIVATE POSITION-TRACKING) (WAIT-TIME 1))\n(TRACE \"tracker ended\")");
  h.Step(0);
  EXPECT_TRUE(h.tracking->IsActive());
  h.Step(1);
  EXPECT_FALSE(h.tracking->IsActive());
  EXPECT_EQ(h.tracking->deactivations.size(), 1u);
  EXPECT_EQ(h.Trace(), "tracker ended");
}

TEST(RplModule, DeactivateStopsAnotherThreadsActivationWhichIsInterrupted) {
  Harness h;
  h.Run(
      "(PAR (WITH-FAILURE-HANDLING (EXECUTE NAVIGATION '(1 2)) (INTERRUPTED (WHY) (TRACE WHY)))\n"
      "     (SEQ (WAIT-TIME 1) (DEACTIVATE NAVIGATION)))");
  h.Step(0);
  h.Step(1);
  EXPECT_FALSE(h.navigation->IsActive());
  EXPECT_EQ(h.Trace(),
            "NAVIGATION deactivated by (DEACTIVATE NAVIGATION) at test.rpl:2:25 in DEACTIVATE");
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

TEST(RplModule, AFailureOfAnActivatedModuleNobodyWaitsForFailsItsThread) {
  Harness h;
  h.Run(
      "(PAR (PROCESS RELOCALIZE (ACTIVATE ACTIVE-LOCALIZATION) (WAIT-FOR NIL))\n"
      "     (EVAP-PROTECT (WAIT-FOR NIL) (TRACE \"other thread cleaned up\")))");
  h.Step(0);
  h.localization->FailWith("no informative target point");
  h.Step(1);
  EXPECT_EQ(h.Trace(), "other thread cleaned up");
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  const Failure* f = h.executive.failure();
  EXPECT_EQ(f->failure_class, FailureClass::kModuleFailure);
  EXPECT_EQ(f->message,
            "ACTIVE-LOCALIZATION (activated at RELOCALIZE > ACTIVATE ACTIVE-LOCALIZATION) "
            "failed: no informative target point");
  EXPECT_EQ(f->task_path, "RELOCALIZE");
}

// ---- failures ---------------------------------------------------------------------------------

TEST(RplFailure, AModuleFailurePropagatesWithItsCauseLocationAndTaskPath) {
  Harness h;
  h.Run(
      "(DEFUN GO-TO (DEST)\n  (PROCESS NAVIGATION-PROC\n    (EXECUTE NAVIGATION DEST)))\n"
      "(GO-TO '(19.6 6))");
  h.Step(0);
  h.navigation->FailWith("unreachable: door_b closed");
  h.Step(1);
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  EXPECT_EQ(h.executive.failure()->ToString(),
            "test.rpl:3:5: MODULE-FAILURE: NAVIGATION failed: unreachable: door_b closed (in "
            "GO-TO > NAVIGATION-PROC > EXECUTE NAVIGATION)");
}

TEST(RplFailure, RuntimeErrorsNameTheFormThatFailed) {
  Harness h;
  h.Run("(SEQ (WAIT-TIME 1)\n     (+ 1 \"two\"))");
  h.Step(0);
  h.Step(1);
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  EXPECT_EQ(h.executive.failure()->ToString(),
            "test.rpl:2:6: RUNTIME-ERROR: (+ ...): argument 2 is \"two\", not a number (in SEQ)");
}

TEST(RplFailure, WithFailureHandlingCatchesOnlyItsClasses) {
  Harness h;
  h.Run(
      "(LIST (WITH-FAILURE-HANDLING (FAIL \"x\") (PLAN-FAILURE (WHY) (CONCAT \"caught \" WHY)))\n"
      "      (WITH-FAILURE-HANDLING (SEQ (WAIT-TIME 1) (+ 1 \"a\"))\n"
      "         (MODULE-FAILURE () :WRONG) (FAILURE () :ANY)))");
  h.Step(0);
  h.Step(1);
  EXPECT_EQ(h.executive.result().ToString(), "(\"caught x\" :ANY)");
  Harness uncaught;
  uncaught.Run("(WITH-FAILURE-HANDLING (FAIL \"x\") (MODULE-FAILURE () :WRONG))");
  uncaught.Step(0);
  EXPECT_EQ(uncaught.executive.state(), PlanState::kFailed);
}

// ---- the executive as a component -------------------------------------------------------------

TEST(RplExecutive, WaitTimeFollowsTheCallersClock) {
  Harness h;
  h.Run("(WAIT-TIME 2.5)\n(TRACE \"late\")", 10.0);
  h.Step(10.0);
  ASSERT_TRUE(h.executive.NextWakeUp().has_value());
  EXPECT_DOUBLE_EQ(*h.executive.NextWakeUp(), 12.5);
  h.Step(12.4);
  EXPECT_EQ(h.Trace(), "");
  h.Step(12.5);
  EXPECT_EQ(h.Trace(), "late");
}

TEST(RplExecutive, LoadingABadPlanKeepsTheLoadedPlanAndRefusesWhileRunning) {
  Harness h;
  h.Run("(WAIT-FOR (> F* 0))");
  h.Step(0);
  const auto refused = h.executive.Load("(TRACE 1)", "other.rpl");
  ASSERT_TRUE(HasErrors(refused));
  EXPECT_EQ(refused[0].message,
            "a plan is running: abort it (and let its cleanups end) before loading another");
  EXPECT_EQ(h.executive.state(), PlanState::kRunning);
  h.executive.Abort(1);
  EXPECT_EQ(h.executive.state(), PlanState::kAborted);
  const auto bad = h.executive.Load("(TRACE", "bad.rpl");
  ASSERT_TRUE(HasErrors(bad));
  EXPECT_EQ(bad[0].ToString(), "bad.rpl:1:1: unclosed '(': the text ends before its ')'");
  EXPECT_EQ(h.executive.state(), PlanState::kAborted);
  ASSERT_EQ(h.executive.Start(2), "");  // the old plan is still loaded
  h.Set("F*", Value::Number(1));
  h.Step(2);
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

TEST(RplExecutive, RejectsInvalidParametersByName) {
  ExecutiveParameters p;
  p.max_call_depth = 0;
  p.event_log_capacity = -1;
  p.max_live_tasks = 0;
  const auto errors = ValidateParameters(p);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0], "max_call_depth: must be in [1, 100000], got 0");
  EXPECT_EQ(errors[1], "event_log_capacity: must be in [0, 10000000], got -1");
  EXPECT_EQ(errors[2], "max_live_tasks: must be in [1, 100000000], got 0");
  EXPECT_THROW(Executive e(p), std::invalid_argument);
}

TEST(RplExecutive, DestroyingTheExecutiveStopsTheModulesStillActive) {
  auto h = std::make_unique<Harness>();
  auto navigation = h->navigation;
  h->Run("(EXECUTE NAVIGATION '(1 2))");
  h->Step(0);
  ASSERT_TRUE(navigation->IsActive());
  h.reset();
  EXPECT_FALSE(navigation->IsActive());
}

}  // namespace
}  // namespace rpl
}  // namespace rpl_executive
