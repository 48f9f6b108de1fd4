// Checker: names, unreachable rules, completeness, regression (SPOTT III.C.1), with
// hand-worked expectations.
#include <gtest/gtest.h>

#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/parser.h"

namespace spott_tr_plus {
namespace {

CheckReport Check(const std::string& text) {
  const ParseResult r = ParseProgramText(text, "p.tr");
  EXPECT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  return CheckProgram(r.program);
}

bool HasMessage(const CheckReport& r, const std::string& part, int line = 0) {
  for (const auto& d : r.diagnostics) {
    if (d.message.find(part) != std::string::npos && (line == 0 || d.where.line == line)) {
      return true;
    }
  }
  return false;
}

std::string FirstError(const CheckReport& r) {
  for (const auto& d : r.diagnostics) {
    if (d.IsError()) return d.ToString();
  }
  return "";
}

const char* kDecls = "condition a; condition b; condition c; action x; action y;\n";

TEST(Checker, ComplementaryLiteralsMakeAProgramComplete) {
  // a v not a is a tautology.
  const CheckReport r = Check(std::string(kDecls) + "main m {\n a -> nil;\n not a -> x;\n}");
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  EXPECT_TRUE(r.Find("m")->complete);
  EXPECT_FALSE(r.Find("m")->regression);  // rule 2 declares no effects
  EXPECT_EQ(r.Find("m")->Verdict(), "complete");
}

TEST(Checker, IncompleteProgramIsReportedWithASituationWhereNothingFires) {
  const CheckReport r = Check(std::string(kDecls) + "main m {\n a -> nil;\n b -> x;\n}");
  EXPECT_FALSE(r.Find("m")->complete);
  EXPECT_TRUE(HasMessage(r, "not complete: no rule fires when a false, b false", 2));
  EXPECT_EQ(r.Summary(), "m: neither\n");
}

TEST(Checker, CompletenessNeedsTheWholeDisjunction) {
  // (a and b) v (a and not b) v not a is a tautology; no two rules alone are.
  const CheckReport r = Check(std::string(kDecls) +
                              "main m {\n a and b -> nil;\n a and not b -> x;\n not a -> y;\n}");
  EXPECT_TRUE(r.Find("m")->complete);
  EXPECT_TRUE(r.Find("m")->unreachable_rules.empty());
}

TEST(Checker, RuleImpliedByAHigherOneIsUnreachable) {
  const CheckReport r =
      Check(std::string(kDecls) + "main m {\n a -> nil;\n b -> y;\n a and c -> x;\n true -> y;\n}");
  ASSERT_EQ(r.Find("m")->unreachable_rules, std::vector<int>{2});
  EXPECT_TRUE(HasMessage(r,
                         "rule 3 of m (line 5) can never fire: its condition implies the "
                         "condition of rule 1 of m (line 3)",
                         5));
}

TEST(Checker, RuleCoveredByTheRulesAboveTogetherIsUnreachable) {
  // Neither a nor b alone is implied by (a xor b), but a v b is.
  const CheckReport r =
      Check(std::string(kDecls) + "main m {\n a -> nil;\n b -> x;\n a ^ b -> y;\n not a -> y;\n}");
  EXPECT_EQ(r.Find("m")->unreachable_rules, std::vector<int>{2});
  EXPECT_TRUE(HasMessage(r, "whenever its condition holds, a rule above it holds", 5));
  EXPECT_TRUE(r.Find("m")->complete);
}

TEST(Checker, RuleBelowACompletePrefixIsUnreachable) {
  const CheckReport r =
      Check(std::string(kDecls) + "main m {\n a -> nil;\n not a -> x;\n b -> y;\n}");
  EXPECT_EQ(r.Find("m")->unreachable_rules, std::vector<int>{2});
  EXPECT_TRUE(HasMessage(r, "the rules above it are already complete", 5));
}

TEST(Checker, ContradictionNeverFires) {
  const CheckReport r =
      Check(std::string(kDecls) + "main m {\n a -> nil;\n b and not b -> x;\n true -> y;\n}");
  EXPECT_TRUE(HasMessage(r, "its condition is never true", 4));
}

TEST(Checker, DeclaredEffectsGiveTheRegressionProperty) {
  // not a -> x achieves a (rule 1): K_2 AND NOT K_1[a:=true] is unsatisfiable.
  const CheckReport r = Check(std::string(kDecls) +
                              "main m {\n a -> nil;\n not a and b -> x effects { a };\n"
                              " not a and not b -> y effects { b };\n}");
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  const ProgramVerdict& v = *r.Find("m");
  EXPECT_TRUE(v.complete);
  EXPECT_TRUE(v.regression);
  EXPECT_EQ(v.Verdict(), "universal");
  EXPECT_EQ(v.parent, (std::vector<int>{-1, 0, 1}));  // rule 3 achieves rule 2's condition
}

TEST(Checker, EffectsThatAchieveNothingHigherBreakRegression) {
  const CheckReport r =
      Check(std::string(kDecls) + "main m {\n a -> nil;\n not a -> x effects { c };\n}");
  EXPECT_FALSE(r.Find("m")->regression);
  EXPECT_EQ(r.Find("m")->Verdict(), "complete");
  EXPECT_TRUE(HasMessage(r, "do not achieve the condition of any higher rule", 4));
}

TEST(Checker, RegressionWithoutCompletenessIsReportedAsRegression) {
  const CheckReport r =
      Check(std::string(kDecls) + "main m {\n a -> nil;\n b -> x effects { a };\n}");
  EXPECT_EQ(r.Find("m")->Verdict(), "regression");
}

TEST(Checker, TimedOperatorMayTimeOutSoItBreaksCompleteness) {
  // (a and b) v not a v not b is a tautology, but a timed AND may be FALSE whatever a and b say.
  const std::string untimed = "main m {\n a & b -> nil;\n not a -> x;\n not b -> y;\n}";
  const std::string timed = "main m {\n a &[0.5s] b -> nil;\n not a -> x;\n not b -> y;\n}";
  EXPECT_TRUE(Check(std::string(kDecls) + untimed).Find("m")->complete);
  const CheckReport r = Check(std::string(kDecls) + timed);
  EXPECT_FALSE(r.Find("m")->complete);
  EXPECT_TRUE(HasMessage(r, "a true, b true, <in time: operator at line 3, column 4> false"));
}

TEST(Checker, ConditionInputsMakeDistinctAtoms) {
  const CheckReport r = Check(
      "condition near(place); action x;\n"
      "main m {\n near(\"door\") -> nil;\n not near(\"desk\") -> x;\n}");
  EXPECT_FALSE(r.Find("m")->complete);  // near("door") and near("desk") are different atoms
  const CheckReport same = Check(
      "condition near(place); action x;\n"
      "main m {\n near(\"door\") -> nil;\n not near(\"door\") -> x;\n}");
  EXPECT_TRUE(same.Find("m")->complete);
}

struct NameCase {
  const char* text;
  int line;
  int column;
  const char* message_part;
};

class CheckerNameErrors : public ::testing::TestWithParam<NameCase> {};

TEST_P(CheckerNameErrors, AreLocated) {
  const NameCase& c = GetParam();
  const CheckReport r = Check(c.text);
  ASSERT_FALSE(r.ok());
  bool found = false;
  for (const auto& d : r.diagnostics) {
    if (d.IsError() && d.where.line == c.line && d.where.column == c.column &&
        d.message.find(c.message_part) != std::string::npos) {
      found = true;
    }
  }
  EXPECT_TRUE(found) << FormatDiagnostics(r.diagnostics);
}

INSTANTIATE_TEST_SUITE_P(
    EachNameError, CheckerNameErrors,
    ::testing::Values(
        NameCase{"action x;\nmain m {\n  ready -> x;\n}", 3, 3, "undefined condition 'ready'"},
        NameCase{"condition a;\nmain m {\n  a -> fly;\n}", 3, 8, "undefined action or subroutine"},
        NameCase{"condition a; action x(d);\nmain m {\n  a -> x;\n}", 3, 8,
                 "'x' takes 1 argument(s), found 0"},
        NameCase{"condition a; action x(d);\nmain m {\n  a -> x(dist);\n}", 3, 10,
                 "undefined variable 'dist'"},
        NameCase{"condition a(out p); action x;\nmain m {\n  a(3) -> x;\n}", 3, 5,
                 "must be bound to a variable name"},
        NameCase{"condition a; condition a;\naction x;\nmain m {\n  a -> x;\n}", 1, 14,
                 "already declared at line 1"},
        NameCase{"condition a;\nmain m {\n  a -> m;\n}", 3, 8, "cannot be called"},
        NameCase{"condition a; action x;\nmain m {\n  x -> a;\n}", 3, 3, "is an action"},
        NameCase{"condition a;\nmain m {\n  a -> nil;\n}\nsub s() {\n}", 5, 1, "has no rules"},
        NameCase{"condition a; action x;\nmain m {\n  a &[0s] a -> x;\n}", 3, 5,
                 "timeout must be > 0"}));

TEST(Checker, OutputVariablesBindIntoTheRulesAction) {
  // Under `not` the condition is written without its outputs.
  const CheckReport r = Check(
      "condition status(out s); action interpret(s);\n"
      "main m {\n  status(st) -> interpret(st);\n  not status -> nil;\n}");
  EXPECT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  EXPECT_TRUE(r.Find("m")->complete);  // outputs are not part of the atom
}

TEST(Checker, OutputBoundUnderNotIsRefusedWithItsLocation) {
  const CheckReport r = Check(
      "condition status(out s); action interpret(s);\n"
      "main m {\n  status(st) -> interpret(st);\n  not status(st2) -> interpret(st2);\n}");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(FirstError(r),
            "p.tr:4:14: output variable 'st2' of 'status' is bound under 'not': the rule fires "
            "when 'status' is FALSE, and then 'st2' has no value (write 'status' with its inputs "
            "only, outputs left out)");
  // Deeper under a `not` too.
  const CheckReport deep = Check(
      "condition a; condition status(out s); action x;\n"
      "main m {\n  not (a and status(st)) -> x;\n  true -> nil;\n}");
  EXPECT_FALSE(deep.ok());
  EXPECT_TRUE(HasMessage(deep, "'st' of 'status' is bound under 'not'", 3));
}

// SPOTT Fig. 13: "find a new room", then "in that room": the first condition's output is the
// second's input, across a sequential AND.
const char* kRooms =
    "condition new_room(out r); condition in_room(room); action go_to(room); action "
    "search(room);\n";

TEST(Checker, OutputFeedsAnInputToItsRightAcrossASequentialAnd) {
  const CheckReport r = Check(std::string(kRooms) +
                              "main m {\n  new_room(r) and in_room(r) -> search(r);\n"
                              "  new_room(r) -> go_to(r) effects { in_room(r) };\n"
                              "  not new_room -> nil;\n}");
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  EXPECT_TRUE(r.Find("m")->complete);
  EXPECT_EQ(r.Find("m")->parent[1], 0);  // going to the room achieves being in it
}

TEST(Checker, OutputDoesNotFeedAConcurrentOperandOrAConditionToItsLeft) {
  const CheckReport par = Check(std::string(kRooms) +
                                "main m {\n  new_room(r) & in_room(r) -> search(r);\n"
                                "  true -> nil;\n}");
  ASSERT_FALSE(par.ok());
  EXPECT_EQ(FirstError(par),
            "p.tr:3:25: variable 'r' is read before it is bound: 'new_room' binds it at line 3, "
            "column 12; an output feeds an input only to its right across a sequential 'and' "
            "(concurrent operators compute their operands together)");
  const CheckReport left = Check(std::string(kRooms) +
                                 "main m {\n  in_room(r) and new_room(r) -> search(r);\n"
                                 "  true -> nil;\n}");
  ASSERT_FALSE(left.ok());
  EXPECT_TRUE(HasMessage(left,
                         "undefined variable 'r' (neither a parameter of this program nor "
                         "an output variable bound by this rule's condition)",
                         3));
}

TEST(Checker, OutputBoundUnderOrMayHaveNoValueWhereItIsUsed) {
  const CheckReport r = Check(std::string(kRooms) +
                              "condition a;\nmain m {\n  a or new_room(r) -> search(r);\n"
                              "  true -> nil;\n}");
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(HasMessage(r,
                         "variable 'r' may have no value here: 'new_room' binds it under 'or' "
                         "(line 4, column 17)",
                         4));
  // Bound under `or` and not used: nothing to refuse.
  EXPECT_TRUE(Check(std::string(kRooms) +
                    "condition a;\nmain m {\n  a or new_room(r) -> search(\"hall\");\n"
                    "  true -> go_to(\"hall\");\n  not a -> nil;\n}")
                  .ok());
}

TEST(Checker, DeclaredButUnusedConditionsAndActionsAreWarned) {
  const CheckReport r = Check(
      "condition a; condition spare;\naction x; action unused(d);\n"
      "main m {\n  a -> nil;\n  not a -> x;\n}");
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(HasMessage(r, "condition 'spare' is declared but no rule reads it", 1));
  EXPECT_TRUE(HasMessage(r, "action 'unused' is declared but no rule runs it", 2));
  EXPECT_FALSE(HasMessage(r, "'a' is declared"));
  EXPECT_FALSE(HasMessage(r, "'x' is declared"));
}

TEST(Checker, ProgramWithAnUnboundVariableGetsNoVerdict) {
  const CheckReport r = Check(
      "condition a; action x(d);\nmain m {\n  a -> x(dist);\n  not a -> nil;\n}\n"
      "sub s() {\n  a -> nil;\n  not a -> nil;\n}");
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(r.Find("m")->analyzed);
  EXPECT_TRUE(r.Find("s")->analyzed);
  EXPECT_EQ(r.Summary(), "m: no verdict (the program has errors)\ns: complete\n");
  EXPECT_FALSE(HasMessage(r, "not complete"));
}

TEST(Checker, NavigationProgramOfTheRepositoryChecksClean) {
  const ParseResult parsed = ParseProgramFile(PROGRAMS_DIR "/spott_navigation.tr");
  ASSERT_TRUE(parsed.ok()) << FormatDiagnostics(parsed.diagnostics);
  const CheckReport r = CheckProgram(parsed.program);
  EXPECT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  for (const auto& p : r.programs) EXPECT_TRUE(p.complete) << p.program;
}

}  // namespace
}  // namespace spott_tr_plus
