// The checker: unknown names and arity errors, with file:line:column, before anything runs.
#include <gtest/gtest.h>

#include "rpl_executive/rpl/office_robot.h"
#include "rpl_executive/rpl/plan.h"

namespace rpl_executive {
namespace rpl {
namespace {

std::vector<std::string> Errors(const std::string& text) {
  const CompileResult r = CompilePlan(text, "plan.rpl", office::OfficeVocabulary());
  std::vector<std::string> out;
  for (const auto& d : r.diagnostics) {
    if (d.IsError()) out.push_back(d.ToString());
  }
  if (!out.empty()) {
    EXPECT_FALSE(r.ok());
  }
  return out;
}

std::string OneError(const std::string& text) {
  const auto errors = Errors(text);
  EXPECT_EQ(errors.size(), 1u) << ::testing::PrintToString(errors);
  return errors.empty() ? "" : errors[0];
}

TEST(RplChecker, AcceptsThePaperPolicyAsPrinted) {
  const CompileResult r = CompilePlan(
      "(DEFUN ACTIVATE-ACTIVE-LOCALIZATION () (DEACTIVATE NAVIGATION) "
      "  (ACTIVATE ACTIVE-LOCALIZATION))\n"
      "(DEFUN DEACTIVATE-ACTIVE-LOCALIZATION () (DEACTIVATE ACTIVE-LOCALIZATION))\n"
      "(WITH-POLICY (WHENEVER (<= POS-CERTAINTY* 0.8)\n"
      "               (ACTIVATE-ACTIVE-LOCALIZATION)\n"
      "               (WAIT-FOR (> POS-CERTAINTY* 0.8))\n"
      "               (DEACTIVATE-ACTIVE-LOCALIZATION))\n"
      "  (EXECUTE NAVIGATION '(19.6 6)))",
      "plan.rpl", office::OfficeVocabulary());
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty()) << FormatDiagnostics(r.diagnostics);
}

TEST(RplChecker, UnknownOperatorIsLocatedAndGetsASuggestion) {
  EXPECT_EQ(OneError("(SEQ\n  (WAIT-FRO (> X* 1)))"),
            "plan.rpl:2:4: unknown operator WAIT-FRO (did you mean WAIT-FOR?)");
}

TEST(RplChecker, UnknownVariableOrFluentIsLocated) {
  EXPECT_EQ(OneError("(WAIT-FOR (<= POS-CERTAINTY 0.8))"),
            "plan.rpl:1:15: unknown name POS-CERTAINTY (not a variable, a DEFVAR, a fluent or a "
            "constant) (did you mean POS-CERTAINTY*?)");
}

TEST(RplChecker, ArityOfSpecialFormsBuiltinsProceduresAndModules) {
  EXPECT_EQ(OneError("(EVAP-PROTECT (WAIT-TIME 1))"),
            "plan.rpl:1:1: EVAP-PROTECT takes 2 arguments, got 1");
  EXPECT_EQ(OneError("(IF T)"), "plan.rpl:1:1: IF takes 2 to 3 arguments, got 1");
  EXPECT_EQ(OneError("(SEQ (<= 1))"), "plan.rpl:1:6: <= takes at least 2 arguments, got 1");
  EXPECT_EQ(OneError("(DEFUN GO (DEST) (EXECUTE NAVIGATION DEST))\n(GO)"),
            "plan.rpl:2:1: procedure GO takes 1 argument, got 0");
  EXPECT_EQ(OneError("(EXECUTE NAVIGATION)"),
            "plan.rpl:1:1: behaviour module NAVIGATION takes 1 argument, got 0");
  EXPECT_EQ(OneError("(ACTIVATE ACTIVE-LOCALIZATION 3)"),
            "plan.rpl:1:1: behaviour module ACTIVE-LOCALIZATION takes 0 arguments, got 1");
}

TEST(RplChecker, UnknownModuleAndValveAreLocated) {
  EXPECT_EQ(OneError("(EXECUTE NAVIGATON '(1 2))"),
            "plan.rpl:1:10: unknown behaviour module NAVIGATON (did you mean NAVIGATION?)");
  EXPECT_EQ(OneError("(WITH-VALVE WHEEL (WAIT-TIME 1))"),
            "plan.rpl:1:13: unknown valve WHEEL (valves: WHEELS)");
}

TEST(RplChecker, ModuleNamedAsAProcedureSaysHowToRunIt) {
  EXPECT_EQ(OneError("(NAVIGATION '(1 2))"),
            "plan.rpl:1:2: NAVIGATION is a behaviour module: run it with (EXECUTE NAVIGATION "
            "...), start it with (ACTIVATE NAVIGATION ...), stop it with (DEACTIVATE NAVIGATION)");
}

TEST(RplChecker, ConditionsMustBeFluentExpressions) {
  EXPECT_EQ(OneError("(DEFUN SLOW () (WAIT-TIME 1) T)\n(WAIT-FOR (AND (SLOW) X*))"),
            "plan.rpl:2:16: the condition of WAIT-FOR must be a fluent expression (fluents, "
            "variables, constants, operators and procedures that are one such expression); "
            "(SLOW) can block");
}

TEST(RplChecker, PureProceduresAreAllowedInConditions) {
  const CompileResult r =
      CompilePlan("(DEFUN NEAR? (P) (<= (DISTANCE (LIST X* Y*) P) 0.5))\n(WAIT-FOR (NEAR? '(1 2)))",
                  "plan.rpl", office::OfficeVocabulary());
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  const Form* wait = r.plan->main->args[0];
  EXPECT_EQ(wait->args[0]->fluent_deps.size(), 2u);  // X* and Y*, read inside NEAR?
}

TEST(RplChecker, RobotFluentsAreReadOnlyForPlans) {
  EXPECT_EQ(OneError("(SETF POS-CERTAINTY* 1)"),
            "plan.rpl:1:7: POS-CERTAINTY* is set by the robot; plans only read it");
}

TEST(RplChecker, DefinitionsOnlyAtTopLevelAndNotTwice) {
  EXPECT_EQ(OneError("(SEQ (DEFUN F () 1))"),
            "plan.rpl:1:7: DEFUN is allowed only at the top level of a plan");
  EXPECT_EQ(OneError("(DEFUN F () 1)\n(DEFVAR F 2)\n(F)"),
            "plan.rpl:2:9: F is already defined at plan.rpl:1:8");
  EXPECT_EQ(OneError("(DEFVAR WITH-VALVE 1)\n1"),
            "plan.rpl:1:9: cannot define WITH-VALVE: WITH-VALVE is a special form");
  EXPECT_EQ(OneError("(DEFVAR X* 1)\n1"),
            "plan.rpl:1:9: cannot define X*: X* is a fluent of the robot");
}

TEST(RplChecker, UntilOnlyInsideLoop) {
  EXPECT_EQ(OneError("(SEQ (UNTIL T))"),
            "plan.rpl:1:7: UNTIL is allowed only directly inside LOOP: (LOOP body... UNTIL "
            "condition)");
  EXPECT_EQ(OneError("(LOOP (WAIT-TIME 1) UNTIL)"),
            "plan.rpl:1:21: UNTIL must be followed by a condition");
}

TEST(RplChecker, PlanWithOnlyDefinitionsHasNothingToDo) {
  EXPECT_EQ(OneError("(DEFUN F () 1)"),
            "plan.rpl:1:1: the plan has no top-level activity (only definitions)");
}

TEST(RplChecker, ReportsAllErrorsOfAPlan) {
  const auto errors = Errors("(SEQ (FOO) (BAR))\n(WAIT-FOR Q*)\n(EXECUTE ARM)");
  ASSERT_EQ(errors.size(), 4u) << ::testing::PrintToString(errors);
  EXPECT_EQ(errors[0].substr(0, 15), "plan.rpl:1:7: u");
  EXPECT_EQ(errors[1].substr(0, 16), "plan.rpl:1:13: u");
  EXPECT_EQ(errors[2].substr(0, 16), "plan.rpl:2:11: u");
  EXPECT_EQ(errors[3].substr(0, 16), "plan.rpl:3:10: u");
}

TEST(RplChecker, SyntaxErrorsComeFirstAndStopChecking) {
  const auto errors = Errors("(SEQ (FOO)");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0], "plan.rpl:1:1: unclosed '(': the text ends before its ')'");
}

TEST(RplChecker, FailureHandlerClassesAreChecked) {
  EXPECT_EQ(OneError("(WITH-FAILURE-HANDLING (FAIL \"x\") (MODULE-FAILUR (C) C))"),
            "plan.rpl:1:36: unknown failure class MODULE-FAILUR (did you mean MODULE-FAILURE?) "
            "(classes: FAILURE (any), MODULE-FAILURE, INTERRUPTED, PLAN-FAILURE, RUNTIME-ERROR, "
            "ALL-FAILED)");
}

TEST(RplChecker, PulseNeedsAPulsedFluentAndSetfNeedsAValueFluent) {
  EXPECT_EQ(OneError("(DEF-FLUENT LOST? (<= POS-CERTAINTY* 0.8))\n(SETF LOST? T)"),
            "plan.rpl:2:1: LOST? is computed from other fluents; SETF sets only fluents defined "
            "with an initial value");
  EXPECT_EQ(OneError("(DEF-FLUENT N 0)\n(PULSE N)"),
            "plan.rpl:2:8: N is not a pulsed fluent of the plan (define it with (DEF-PULSE NAME))");
}

TEST(RplChecker, DerivedFluentsMayNotDependOnThemselves) {
  const auto errors = Errors("(DEF-FLUENT A (NOT B))\n(DEF-FLUENT B (AND A X*))\n(WAIT-FOR A)");
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0], "plan.rpl:1:1: fluent A depends on itself");
  EXPECT_EQ(errors[1], "plan.rpl:2:1: fluent B depends on itself");
}

TEST(RplChecker, ConditionWithoutFluentIsAWarningNotAnError) {
  const CompileResult r = CompilePlan("(WAIT-FOR NIL)", "plan.rpl", office::OfficeVocabulary());
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].ToString(),
            "plan.rpl:1:11: warning: the condition of WAIT-FOR reads no fluent: if it is false "
            "the thread waits forever");
}

}  // namespace
}  // namespace rpl
}  // namespace rpl_executive
