// Fluents (section 3.2): comparison fluents, pulsed fluents, derived fluents, and that a thread
// wait-blocked on a fluent costs nothing until the fluent changes.
#include <gtest/gtest.h>

#include "test_support.h"

namespace rpl_executive {
namespace rpl {
namespace {

using testing::Harness;

TEST(RplFluent, WaitForWakesWhenTheComparisonBecomesTrue) {
  Harness h;
  h.Set("POS-CERTAINTY*", Value::Number(0.95));
  h.Run("(TRACE \"start\")\n(WAIT-FOR (<= POS-CERTAINTY* 0.8))\n(TRACE \"woken\")");
  h.Step(0.0);
  EXPECT_EQ(h.Trace(), "start");
  h.now = 1.0;
  h.Set("POS-CERTAINTY*", Value::Number(0.85));
  EXPECT_EQ(h.Step(1.0).instructions, 0);  // still false: nothing runs
  h.now = 2.0;
  h.Set("POS-CERTAINTY*", Value::Number(0.8));  // <= 0.8 holds at 0.8 exactly
  h.Step(2.0);
  EXPECT_EQ(h.Trace(), "start, woken");
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

TEST(RplFluent, AWaitBlockedThreadRunsNoInstructionWhileNothingChanges) {
  Harness h;
  h.Run("(WHENEVER (<= POS-CERTAINTY* 0.8) (TRACE \"lost\"))");
  h.Set("POS-CERTAINTY*", Value::Number(0.9));
  h.Step(0.0);
  const size_t tasks = h.executive.NumLiveTasks();
  for (int i = 1; i <= 100; ++i) EXPECT_EQ(h.Step(i).instructions, 0);
  h.Set("X*", Value::Number(3.0));  // a fluent the condition does not read
  EXPECT_EQ(h.Step(101).instructions, 0);
  EXPECT_EQ(h.executive.NumLiveTasks(), tasks);
  EXPECT_EQ(h.Trace(), "");
}

TEST(RplFluent, TenThousandWaitBlockedThreadsRunNothingUntilTheirConditionHolds) {
  std::string plan = "(DEFUN SLEEPER (I) (WAIT-FOR (> X* 100)) (TRACE I))\n(PAR";
  for (int i = 0; i < 10000; ++i) plan += " (SLEEPER " + std::to_string(i) + ")";
  plan += ")";
  Harness h;
  h.Run(plan);
  EXPECT_GT(h.Step(0).instructions, 10000);
  EXPECT_EQ(h.Step(1).instructions, 0);
  h.now = 2;
  h.Set("X*", Value::Number(50));  // one shared condition recomputed, no thread woken
  EXPECT_EQ(h.Step(2).instructions, 0);
  h.now = 3;
  h.Set("X*", Value::Number(150));
  h.Step(3);
  EXPECT_EQ(h.trace.size(), 10000u);
  EXPECT_EQ(h.trace.front(), "0");
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

TEST(RplFluent, PulseWakesOnlyTheThreadsWaitingAtThatInstant) {
  Harness h;
  h.Set("NR-OF-NAV-GOALS*", Value::Number(3));
  h.Run(
      "(DEF-PULSE INTERRUPTED? (= NR-OF-NAV-GOALS* 0))\n"
      "(PAR (SEQ (WAIT-FOR INTERRUPTED?) (TRACE \"a\"))\n"
      "     (SEQ (WAIT-FOR (> F* 0)) (WAIT-FOR INTERRUPTED?) (TRACE \"b\")))");
  h.Step(0);
  h.Set("NR-OF-NAV-GOALS*", Value::Number(0));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "a");
  // b begins to wait after the pulse: the pulse is over, b goes on waiting.
  h.Set("F*", Value::Number(1));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "a");
  EXPECT_TRUE(h.executive.GetFluent("INTERRUPTED?").IsNil());
  h.Set("NR-OF-NAV-GOALS*", Value::Number(2));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "a");
  h.Set("NR-OF-NAV-GOALS*", Value::Number(0));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "a, b");
  EXPECT_EQ(h.Events(Event::Kind::kPulse).size(), 2u);
}

TEST(RplFluent, PulseComesWhenTheCountDropsToZeroNotWhileItIsZeroOrFalls) {
  Harness h;  // NR-OF-NAV-GOALS* starts at 0: no pulse at start
  h.Run("(DEF-PULSE INTERRUPTED? (= NR-OF-NAV-GOALS* 0))\n(WAIT-FOR NIL)");
  h.Step(0);
  for (double n : {3.0, 2.0, 1.0}) h.Set("NR-OF-NAV-GOALS*", Value::Number(n));
  EXPECT_EQ(h.Events(Event::Kind::kPulse).size(), 0u);
  h.Set("NR-OF-NAV-GOALS*", Value::Number(0));
  EXPECT_EQ(h.Events(Event::Kind::kPulse).size(), 1u);
  h.Set("NR-OF-NAV-GOALS*", Value::Number(0));  // unchanged: no pulse
  EXPECT_EQ(h.Events(Event::Kind::kPulse).size(), 1u);
}

TEST(RplFluent, PulseStatementPulsesAPlanFluent) {
  Harness h;
  h.Run(
      "(DEF-PULSE DONE)\n"
      "(PAR (SEQ (WAIT-FOR DONE) (TRACE \"seen\")) (SEQ (WAIT-TIME 1) (PULSE DONE)))");
  h.Step(0);
  EXPECT_EQ(h.Trace(), "");
  h.Step(1);
  EXPECT_EQ(h.Trace(), "seen");
  EXPECT_EQ(h.executive.state(), PlanState::kSucceeded);
}

TEST(RplFluent, DerivedFluentsUpdateGlitchFree) {
  // IN? is T only for 1 < F* < 3. A jump of F* from 0 to 5 makes A true and B false: a
  // propagation that recomputed IN? between the two would wake the waiter by mistake.
  Harness h;
  h.Run(
      "(DEF-FLUENT A (> F* 1))\n(DEF-FLUENT B (< F* 3))\n(DEF-FLUENT IN? (AND A B))\n"
      "(WAIT-FOR IN?)\n(TRACE \"inside\")");
  h.Step(0);
  h.Set("F*", Value::Number(5));
  EXPECT_EQ(h.Step(0).instructions, 0);
  EXPECT_TRUE(h.executive.GetFluent("IN?").IsNil());
  h.Set("F*", Value::Number(2));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "inside");
}

TEST(RplFluent, ConditionsOverThreadVariablesAreSeparatePerThread) {
  Harness h;
  h.Run(
      "(DEFUN WAIT-ABOVE (LIMIT) (WAIT-FOR (> F* LIMIT)) (TRACE LIMIT))\n"
      "(PAR (WAIT-ABOVE 1) (WAIT-ABOVE 3))");
  h.Step(0);
  h.Set("F*", Value::Number(2));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "1");
  h.Set("F*", Value::Number(4));
  h.Step(0);
  EXPECT_EQ(h.Trace(), "1, 3");
}

TEST(RplFluent, FluentStampsAreTheCallersTime) {
  Harness h;
  h.executive.SetFluent("X*", Value::Number(1.5), 12.5);
  for (const auto& f : h.executive.Fluents()) {
    if (f.name == "X*") {
      EXPECT_DOUBLE_EQ(f.stamp_s, 12.5);
      EXPECT_EQ(f.value, Value::Number(1.5));
    }
  }
  EXPECT_THROW(h.executive.SetFluent("NO-SUCH*", Value(), 0), std::invalid_argument);
}

TEST(RplFluent, AConditionThatCannotBeEvaluatedFailsTheWaitingThreadWithItsLocation) {
  Harness h;
  h.Run("(SEQ\n  (WAIT-FOR (<= F* 0.8)))\n", 0);
  h.Set("F*", Value::Number(1));
  h.Step(0);
  h.Set("F*", Value::String("high"));
  h.Step(0);
  ASSERT_EQ(h.executive.state(), PlanState::kFailed);
  const Failure* f = h.executive.failure();
  EXPECT_EQ(f->failure_class, FailureClass::kRuntimeError);
  EXPECT_EQ(f->message, "test.rpl:2:13: (<= ...): argument 1 is \"high\", not a number");
  EXPECT_EQ(f->where.line, 2);
}

}  // namespace
}  // namespace rpl
}  // namespace rpl_executive
