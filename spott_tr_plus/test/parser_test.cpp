// Parser of the TR+ text format: good programs and each kind of located error.
#include <gtest/gtest.h>

#include "spott_tr_plus/parser.h"

namespace spott_tr_plus {
namespace {

const char* kGood = R"(# Fig. 8 style: react to a bumper contact.
condition bumper_hit(out where) ballistic at 10 hz;
condition at_goal;
condition path_clear every 200ms;
action stop;
action back_away(dist) ballistic;
action plan(goal);

main run {
  at_goal -> nil;
  bumper_hit(where) -> ballistic stop > back_away(where);
  path_clear and not bumper_hit -> plan("door 3") || stop effects { at_goal };
  true -> GOTO(1.5);
}

sub GOTO(x) {
  at_goal -> nil;
  path_clear &[0.5s] at_goal | not at_goal ^ path_clear -> plan(x);
}
)";

TEST(Parser, ParsesDeclarationsProgramsAndRules) {
  const ParseResult r = ParseProgramText(kGood, "good.tr");
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  const ProgramFile& f = r.program;
  ASSERT_EQ(f.conditions.size(), 3u);
  EXPECT_EQ(f.conditions[0].name, "bumper_hit");
  EXPECT_EQ(f.conditions[0].semantics, Semantics::kBallistic);
  EXPECT_DOUBLE_EQ(f.conditions[0].frequency_hz, 10.0);
  EXPECT_EQ(f.conditions[0].NumOutputs(), 1);
  EXPECT_DOUBLE_EQ(f.conditions[2].frequency_hz, 5.0);  // every 200 ms
  EXPECT_EQ(f.conditions[1].semantics, Semantics::kEnergized);
  ASSERT_EQ(f.actions.size(), 3u);
  EXPECT_EQ(f.actions[1].semantics, Semantics::kBallistic);
  ASSERT_EQ(f.programs.size(), 2u);
  const Program& main = f.programs[0];
  EXPECT_TRUE(main.is_main);
  ASSERT_EQ(main.rules.size(), 4u);
  EXPECT_EQ(main.rules[0].action.op, ActOp::kNil);
  // Rule 2: `ballistic stop > back_away(where)` is a sequence.
  EXPECT_EQ(main.rules[1].semantics, Semantics::kBallistic);
  EXPECT_EQ(main.rules[1].action.op, ActOp::kSequence);
  ASSERT_EQ(main.rules[1].action.children.size(), 2u);
  EXPECT_EQ(main.rules[1].action.children[1].args[0].text, "where");
  // Rule 3: sequential AND, `||` binds tighter than '>', effects.
  EXPECT_EQ(main.rules[2].condition.op, CondOp::kSeqAnd);
  EXPECT_EQ(main.rules[2].condition.children[1].op, CondOp::kNot);
  EXPECT_EQ(main.rules[2].action.op, ActOp::kParallel);
  EXPECT_EQ(main.rules[2].action.children[0].args[0].kind, Arg::Kind::kString);
  EXPECT_TRUE(main.rules[2].has_effects);
  ASSERT_EQ(main.rules[2].effects.size(), 1u);
  // Rule 4: a call, resolved.
  EXPECT_TRUE(main.rules[3].action.is_call);
  EXPECT_DOUBLE_EQ(main.rules[3].action.args[0].number, 1.5);
  EXPECT_EQ(main.rules[3].where.line, 13);
  EXPECT_EQ(main.rules[3].where.column, 3);
}

TEST(Parser, PrecedenceIsAndThenXorThenOr) {
  const ParseResult r = ParseProgramText(kGood, "good.tr");
  ASSERT_TRUE(r.ok());
  // path_clear &[0.5s] at_goal | not at_goal ^ path_clear
  //   == (path_clear &[0.5s] at_goal) | ((not at_goal) ^ path_clear)
  const CondExpr& c = r.program.programs[1].rules[1].condition;
  ASSERT_EQ(c.op, CondOp::kParOr);
  EXPECT_FALSE(c.IsTimed());
  ASSERT_EQ(c.children[0].op, CondOp::kParAnd);
  EXPECT_DOUBLE_EQ(c.children[0].timeout_s, 0.5);
  ASSERT_EQ(c.children[1].op, CondOp::kXor);
  EXPECT_EQ(c.children[1].children[0].op, CondOp::kNot);
}

TEST(Parser, PrintedTextParsesToTheSameText) {
  const ParseResult r = ParseProgramText(kGood, "good.tr");
  ASSERT_TRUE(r.ok());
  const std::string text = ToText(r.program);
  const ParseResult again = ParseProgramText(text, "again.tr");
  ASSERT_TRUE(again.ok()) << FormatDiagnostics(again.diagnostics) << "\n" << text;
  EXPECT_EQ(ToText(again.program), text);
}

struct BadCase {
  const char* text;
  int line;
  int column;
  const char* message_part;
};

class ParserErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(ParserErrors, NamesLineColumnAndWhatWasExpected) {
  const BadCase& c = GetParam();
  const ParseResult r = ParseProgramText(c.text, "bad.tr");
  ASSERT_FALSE(r.ok());
  const Diagnostic& d = r.diagnostics.front();
  EXPECT_EQ(d.file, "bad.tr");
  EXPECT_EQ(d.where.line, c.line) << d.ToString();
  EXPECT_EQ(d.where.column, c.column) << d.ToString();
  EXPECT_NE(d.message.find(c.message_part), std::string::npos) << d.ToString();
}

INSTANTIATE_TEST_SUITE_P(
    EachError, ParserErrors,
    ::testing::Values(
        BadCase{"main m {\n  a b -> nil;\n}", 2, 5, "expected '->'"},
        BadCase{"main m {\n  a -> ;\n}", 2, 8, "expected an action"},
        BadCase{"main m {\n  a -> x\n}", 3, 1, "expected ';'"},
        BadCase{"main m {\n  -> x;\n}", 2, 3, "expected a condition"},
        BadCase{"main m {\n  a -> x;\n", 3, 1, "to close program 'm'"},
        BadCase{"rule x;", 1, 1, "expected 'condition', 'action', 'main' or 'sub'"},
        BadCase{"condition c at 0 hz;", 1, 16, "frequency must be > 0"},
        BadCase{"condition c every 5;", 1, 19, "duration with its unit"},
        BadCase{"condition c fast;", 1, 13, "expected 'energized', 'ballistic'"},
        BadCase{"condition and;", 1, 11, "keyword 'and'"},
        BadCase{"main m {\n  a &[2] b -> x;\n}", 2, 7, "duration with its unit"},
        BadCase{"main m {\n  a -> x(\"open);\n}", 2, 10, "unterminated string"},
        BadCase{"main m {\n  a @ b -> x;\n}", 2, 5, "unexpected character '@'"},
        BadCase{"main m {\n  (a -> x;\n}", 2, 6, "expected ')'"},
        BadCase{"main m {\n  a -> x(1s);\n}", 2, 10, "without a unit"},
        BadCase{"action go(a b);", 1, 13, "expected ',' or ')'"},
        BadCase{"main m {\n  a -> x(1e999);\n}", 2, 10, "number 1e999 is out of range"},
        BadCase{"main m {\n  a -> x effects { not };\n}", 2, 24, "a condition name"}));

TEST(Parser, ReportsSeveralErrorsInOneRun) {
  const ParseResult r = ParseProgramText("main m {\n  a b -> x;\n  c -> ;\n  d -> y;\n}", "f.tr");
  ASSERT_EQ(r.diagnostics.size(), 2u) << FormatDiagnostics(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].where.line, 2);
  EXPECT_EQ(r.diagnostics[1].where.line, 3);
  // Recovery keeps the good rule after the bad ones.
  ASSERT_EQ(r.program.programs.size(), 1u);
  ASSERT_EQ(r.program.programs[0].rules.size(), 1u);
  EXPECT_EQ(r.program.programs[0].rules[0].where.line, 4);
}

// Errors as "line:column: message", for the multi-error cases below.
std::vector<std::string> Errors(const std::string& text) {
  const ParseResult r = ParseProgramText(text, "f.tr");
  std::vector<std::string> out;
  for (const auto& d : r.diagnostics) {
    out.push_back(std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + ": " +
                  d.message);
  }
  return out;
}

TEST(Parser, AnErrorInsideEffectsDoesNotEndTheProgram) {
  // The '}' of `effects { not }` closes the effects, not the program: no follow-on errors, the
  // later rules are parsed and the error in the last one is reported.
  const std::string text =
      "main m {\n  a -> x effects { not };\n  b -> y;\n  c d -> z;\n  e -> w;\n}\n";
  const std::vector<std::string> e = Errors(text);
  ASSERT_EQ(e.size(), 2u) << ::testing::PrintToString(e);
  EXPECT_EQ(e[0], "2:24: expected a condition name, found '}'");
  EXPECT_EQ(e[1], "4:5: expected '->' or a condition operator (and, or, &, |, ^), found 'd'");
  const ParseResult r = ParseProgramText(text, "f.tr");
  ASSERT_EQ(r.program.programs.size(), 1u);
  ASSERT_EQ(r.program.programs[0].rules.size(), 2u);  // b -> y and e -> w
  EXPECT_EQ(r.program.programs[0].rules[1].where.line, 5);
}

TEST(Parser, AMissingSemicolonKeepsTheRuleAndTheNextRuleIsStillChecked) {
  const std::vector<std::string> e = Errors("main m {\n  a -> x\n  b c -> y;\n  d -> z;\n}");
  ASSERT_EQ(e.size(), 2u) << ::testing::PrintToString(e);
  EXPECT_EQ(e[0], "3:3: expected ';' to end the rule ('||' or '>' to compose actions), found 'b'");
  EXPECT_EQ(e[1], "3:5: expected '->' or a condition operator (and, or, &, |, ^), found 'c'");
  const ParseResult r = ParseProgramText("main m {\n  a -> x\n  d -> z;\n}", "f.tr");
  ASSERT_EQ(r.program.programs[0].rules.size(), 2u);
  // A missing operator between two actions is one error, not a second "expected '->'".
  EXPECT_EQ(Errors("main m {\n  a -> x\n     y;\n  b -> z;\n}").size(), 1u);
}

TEST(Parser, AnUnterminatedStringDoesNotHideTheNextRulesError) {
  // The string runs to the end of its line and takes the ';' with it.
  const std::vector<std::string> e =
      Errors("main m {\n  a -> x(\"open);\n  b c -> y;\n  d -> z;\n}");
  ASSERT_EQ(e.size(), 2u) << ::testing::PrintToString(e);
  EXPECT_EQ(e[0].substr(0, 25), "2:10: unterminated string");
  EXPECT_EQ(e[1], "3:5: expected '->' or a condition operator (and, or, &, |, ^), found 'c'");
}

TEST(Parser, AnErrorInAProgramHeaderStillParsesItsRules) {
  const std::vector<std::string> e =
      Errors("sub S(a b) {\n  a -> x;\n  c d -> y;\n}\nmain m {\n  a -> S(1);\n}");
  ASSERT_EQ(e.size(), 2u) << ::testing::PrintToString(e);
  EXPECT_EQ(e[0], "1:9: expected ',' or ')', found 'b'");
  EXPECT_EQ(e[1], "3:5: expected '->' or a condition operator (and, or, &, |, ^), found 'd'");
}

TEST(Parser, AMissingClosingBraceEndsTheProgramAtTheNextDeclaration) {
  const std::vector<std::string> e =
      Errors("main m {\n  a -> x;\nsub s() {\n  b -> y;\n  c d -> z;\n}");
  ASSERT_EQ(e.size(), 2u) << ::testing::PrintToString(e);
  EXPECT_EQ(e[0],
            "3:1: expected a rule or '}' to close program 'm' (opened at line 1), found 'sub'");
  EXPECT_EQ(e[1], "5:5: expected '->' or a condition operator (and, or, &, |, ^), found 'd'");
  const ParseResult r = ParseProgramText("main m {\n  a -> x;\nsub s() {\n  b -> y;\n}", "f.tr");
  ASSERT_EQ(r.program.programs.size(), 2u);
  EXPECT_EQ(r.program.programs[1].rules.size(), 1u);
}

TEST(Parser, SeveralErrorsInOneProgramAreEachReportedOnce) {
  const std::string text =
      "condition a; condition b(out p);\n"  // 1
      "action x; action y(q);\n"            // 2
      "main m {\n"                          // 3
      "  a -> x effects { a, };\n"          // 4: a literal missing after ','
      "  b(p) -> y(p) ||;\n"                // 5: an action missing after '||'
      "  not a -> y(\"z\")\n"               // 6: ';' missing (the next line is a rule)
      "  a &[5] b -> x;\n"                  // 7: a timeout without its unit
      "  true -> x;\n"                      // 8
      "}\n";
  const std::vector<std::string> e = Errors(text);
  ASSERT_EQ(e.size(), 4u) << ::testing::PrintToString(e);
  EXPECT_EQ(e[0].substr(0, 5), "4:23:");
  EXPECT_EQ(e[1].substr(0, 5), "5:18:");
  EXPECT_EQ(e[2].substr(0, 4), "7:3:");
  EXPECT_EQ(e[3].substr(0, 4), "7:7:");
  const ParseResult r = ParseProgramText(text, "f.tr");
  ASSERT_EQ(r.program.programs[0].rules.size(), 2u);  // not a -> y("z"), true -> x
}

TEST(Parser, DeepNestingIsAnErrorNotACrash) {
  std::string text =
      "main m {\n  " + std::string(5000, '(') + "a" + std::string(5000, ')') + " -> x;\n}";
  const ParseResult r = ParseProgramText(text, "deep.tr");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].message.find("nested too deeply"), std::string::npos);
}

TEST(Parser, MissingFileIsALocatedError) {
  const ParseResult r = ParseProgramFile("/nonexistent/x.tr");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].ToString(),
            "/nonexistent/x.tr: cannot read the program file: no such file");
}

}  // namespace
}  // namespace spott_tr_plus
