// Inputs found by the fuzzers (fuzz/rpl_plan_fuzz.cpp, fuzz/rpl_run_fuzz.cpp), kept as tests.
#include <gtest/gtest.h>

#include "test_support.h"

namespace rpl_executive {
namespace rpl {
namespace {

// rpl_run_fuzz, empty input: declaring the first fluent of an executive indexed past the end of
// an empty vector (undefined behaviour caught by UBSan); the empty plan is then refused.
TEST(RplFuzzRegression, AnEmptyPlanIsRefusedWithALocatedError) {
  Executive e;
  for (const auto& f : office::Fluents()) e.DeclareFluent(f);
  EXPECT_EQ(e.FluentIndex(office::kX), 0);
  EXPECT_EQ(e.FluentIndex(office::kNrOfNavGoals), 5);
  const auto diagnostics = e.Load("", "empty.rpl");
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].ToString(),
            "empty.rpl:1:1: the plan has no top-level activity (only definitions)");
  EXPECT_EQ(e.state(), PlanState::kNoPlan);
}

// rpl_run_fuzz, slow unit (17 s): a procedure that forks two copies of itself. Each Step grows
// the tree by its instruction budget; aborting it must end the whole tree at once (it took
// seconds while every evaporated thread built a message it did not need).
TEST(RplFuzzRegression, AbortingAForkBombEndsEveryTask) {
  ExecutiveParameters p;
  p.max_instructions_per_step = 2000;
  p.max_call_depth = 40;
  testing::Harness h(p);
  h.Run("(DEFUN F1 (A) (PAR (F1 (+ A 1)) (F1 (+ A 1))))\n(F1 1)\n(F1 1)");
  for (int i = 0; i < 40; ++i) h.Step(0.5 * i);
  EXPECT_GT(h.executive.NumLiveTasks(), 40000u);
  EXPECT_EQ(h.executive.state(), PlanState::kRunning);
  h.executive.Abort(20);
  EXPECT_EQ(h.executive.state(), PlanState::kAborted);
  EXPECT_EQ(h.executive.NumLiveTasks(), 0u);
}

}  // namespace
}  // namespace rpl
}  // namespace rpl_executive
