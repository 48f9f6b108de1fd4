// The mission formalism's parser (section 5) on the paper's two missions and on bad input.
#include "rpl_executive/noreils_chatila/mission_parser.h"

#include <gtest/gtest.h>

#include "rpl_executive/noreils_chatila/checker.h"
#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::MissionPath;
using testing::Parse;
using testing::ParseFile;

const Diagnostic& OnlyError(const ParseResult& r) {
  EXPECT_EQ(r.diagnostics.size(), 1u) << FormatDiagnostics(r.diagnostics);
  static Diagnostic none;
  return r.diagnostics.empty() ? none : r.diagnostics[0];
}

TEST(MissionParser, Example2ParsesAsPrintedWithItsNestedMonitorsLoopAndConditional) {
  const MissionFile f = ParseFile("example2_zone_surveillance.nc");
  ASSERT_EQ(f.definitions.size(), 3u);
  EXPECT_EQ(f.definitions[0].type, "Tclist");
  EXPECT_EQ(f.definitions[0].size, 4);
  EXPECT_EQ(f.definitions[0].name, "ZONE109");
  EXPECT_EQ(f.definitions[0].value.ToText(), "((150 500) (150 700) (350 700) (350 500))");
  EXPECT_EQ(f.definitions[2].type, "Tpath");
  EXPECT_EQ(f.definitions[2].value.ToText(), "((180 520) (350 520) (360 320 2700))");
  ASSERT_EQ(f.missions.size(), 1u);
  const Mission& m = f.missions[0];
  EXPECT_EQ(m.name, "mission2");
  ASSERT_EQ(m.pre.size(), 2u);
  EXPECT_EQ(m.pre[1].ToText(), "(not (eq robot-in-zone $ZONE109))");
  EXPECT_EQ(m.pre[1].children[0].rhs.kind, ValueExpr::Kind::kDeref);
  ASSERT_EQ(m.env.size(), 1u);
  EXPECT_EQ(m.env[0].ToText(), "(set LOA T)");
  ASSERT_EQ(m.main.size(), 1u);
  const Statement& move = m.main[0];
  EXPECT_EQ(move.op, "smooth-move");
  ASSERT_EQ(move.monitors.size(), 2u);
  const Monitor& s1 = move.monitors[0];
  EXPECT_FALSE(s1.is_static);
  EXPECT_EQ(s1.condition.ToText(), "(S_zone IN ZONE109)");
  EXPECT_EQ(s1.control_form, Monitor::ControlForm::kBraces);
  ASSERT_EQ(s1.control.size(), 4u);
  EXPECT_EQ(s1.control[2].kind, Statement::Kind::kMonitor);  // S1-2, created by S1
  EXPECT_EQ(s1.control[2].monitor->condition.ToText(), "(S_zone OUT ZONE109)");
  EXPECT_EQ(s1.control[3].kind, Statement::Kind::kWhile);
  EXPECT_EQ(s1.control[3].then_body.size(), 2u);
  const Monitor& s2 = move.monitors[1];
  EXPECT_TRUE(s2.is_static);
  ASSERT_EQ(s2.control.size(), 1u);
  const Statement& branch = s2.control[0];
  EXPECT_EQ(branch.kind, Statement::Kind::kIf);
  EXPECT_EQ(branch.then_body.size(), 2u);  // (avoid-obstacle)(resume-order)
  ASSERT_EQ(branch.else_body.size(), 1u);
  EXPECT_EQ(branch.else_body[0].kind, Statement::Kind::kFail);
}

TEST(MissionParser, Example1ControlActionsInParenthesesAndRunOfAProcess) {
  const MissionFile f = ParseFile("example1_wall_following.nc");
  const Mission& m = f.missions.at(0);
  ASSERT_EQ(m.main.size(), 2u);
  const Monitor& perceive = m.main[0].monitors.at(0);
  EXPECT_EQ(perceive.control_form, Monitor::ControlForm::kParens);  // ((NEXT))
  ASSERT_EQ(perceive.control.size(), 1u);
  EXPECT_EQ(perceive.control[0].kind, Statement::Kind::kNext);
  EXPECT_EQ(perceive.condition.ToText(), "(S_us-perception line (ρ θ))");  // commas separate
  EXPECT_EQ(m.main[1].kind, Statement::Kind::kRun);
  EXPECT_EQ(m.main[1].op, "wall-following");
  EXPECT_EQ(m.main[1].args.at(0).ToText(), "(right-side 25)");
}

TEST(MissionParser, ThePaperIsMissingTheMissionsLastParenthesisAndTheParserSaysWhere) {
  // Example 2's MISSION exactly as printed (without the closing parenthesis the shipped file
  // adds): the reader reports the unclosed '(' of MISSION on its line and column.
  const std::string printed =
      "(MISSION mission2\n"
      "(PRE: (eq motor ON))\n"
      "(MAIN:\n"
      "  (smooth-move(PATH) MNTR(S_zone IN ZONE109) => ((set-speed 20)){(set LOA NIL)})\n"
      ")\n";
  const ParseResult r = ParseMissionText(printed, "printed.nc");
  const Diagnostic& d = OnlyError(r);
  EXPECT_EQ(d.where.line, 1);
  EXPECT_EQ(d.where.column, 1);
  EXPECT_NE(d.message.find("never closed"), std::string::npos) << d.message;
}

TEST(MissionParser, ControlActionsInBracesAndInParenthesesGiveTheSameTree) {
  const MissionFile a = Parse(
      "(MISSION m (MAIN: (smooth-move ((0 0)) MNTR (S_zone IN ((0 0)(1 0)(1 1))) "
      "=> ((stop)) {(NEXT)})))");
  const MissionFile b = Parse(
      "(MISSION m (MAIN: (smooth-move ((0 0)) MNTR (S_zone IN ((0 0)(1 0)(1 1))) "
      "=> ((stop)) ((NEXT)))))");
  const Monitor& ma = a.missions[0].main[0].monitors[0];
  const Monitor& mb = b.missions[0].main[0].monitors[0];
  ASSERT_EQ(ma.control.size(), 1u);
  ASSERT_EQ(mb.control.size(), 1u);
  EXPECT_EQ(ma.control[0].kind, Statement::Kind::kNext);
  EXPECT_EQ(mb.control[0].kind, Statement::Kind::kNext);
}

TEST(MissionParser, EveryPaperFileRoundTripsThroughItsCanonicalText) {
  for (const char* name :
       {"example1_wall_following.nc", "example2_zone_surveillance.nc", "o_surveillances.nc"}) {
    const MissionFile f = ParseFile(name);
    const std::string text = f.ToText();
    const MissionFile again = Parse(text, "again.nc");
    EXPECT_EQ(again.ToText(), text) << name;
  }
}

TEST(MissionParser, ErrorsNameLineAndColumnCountingCharactersNotBytes) {
  // 'ρ' is two bytes in UTF-8 but one column.
  const ParseResult r = ParseMissionText("(define Tnum ρ 1)\n(define Tnum θ (1 2))\n", "u.nc");
  const Diagnostic& d = OnlyError(r);
  EXPECT_EQ(d.file, "u.nc");
  EXPECT_EQ(d.where.line, 2);
  EXPECT_EQ(d.where.column, 16);
  EXPECT_EQ(d.ToString().rfind("u.nc:2:16: ", 0), 0u) << d.ToString();
}

TEST(MissionParser, DefineChecksTheTypedShape) {
  const ParseResult r = ParseMissionText("(define Tclist[4] Z ((0 0)(1 0)(1 1)))\n", "d.nc");
  EXPECT_NE(OnlyError(r).message.find("needs 4 tuples, found 3"), std::string::npos);
  const ParseResult p = ParseMissionText("(define Tpath P ((0 0 900)(1 0)))", "d.nc");
  EXPECT_NE(OnlyError(p).message.find("only the last point"), std::string::npos);
  const ParseResult t = ParseMissionText("(define Tlist P ((0 0)))", "d.nc");
  EXPECT_NE(OnlyError(t).message.find("unknown type 'Tlist'"), std::string::npos);
  EXPECT_EQ(OnlyError(t).where.column, 9);
}

TEST(MissionParser, MalformedMonitorsAreLocated) {
  const ParseResult r = ParseMissionText(
      "(MISSION m\n (MAIN:\n  (smooth-move (P) MNTR (S_zone IN Z) ((stop)))))", "m.nc");
  const Diagnostic& d = OnlyError(r);
  EXPECT_EQ(d.where.line, 3);
  EXPECT_EQ(d.where.column, 39);
  EXPECT_NE(d.message.find("expected '=>'"), std::string::npos) << d.message;
}

TEST(MissionParser, OneRunReportsErrorsOfSeveralForms) {
  const ParseResult r = ParseMissionText("(foo)\n(define Tnum)\n(MISSION)\n", "e.nc");
  ASSERT_EQ(r.diagnostics.size(), 3u) << FormatDiagnostics(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].where.line, 1);
  EXPECT_EQ(r.diagnostics[1].where.line, 2);
  EXPECT_EQ(r.diagnostics[2].where.line, 3);
}

TEST(MissionParser, MissingMainAndUnknownSectionsAreErrors) {
  const ParseResult r = ParseMissionText("(MISSION m (PRE: (LOA)) (POST: (LOA)))", "s.nc");
  ASSERT_EQ(r.diagnostics.size(), 2u) << FormatDiagnostics(r.diagnostics);
  EXPECT_NE(r.diagnostics[0].message.find("unknown section 'POST:'"), std::string::npos);
  EXPECT_NE(r.diagnostics[1].message.find("has no (MAIN: ...)"), std::string::npos);
}

TEST(MissionParser, DeepNestingIsAnErrorNotACrash) {
  const std::string deep(5000, '(');
  const ParseResult r = ParseMissionText(deep, "deep.nc");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].message.find("nested deeper"), std::string::npos);
}

TEST(MissionParser, UnreadableFileIsAnErrorAtTheFile) {
  const ParseResult r = ParseMissionFile(MissionPath("no_such_mission.nc"));
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].ToString().find("no_such_mission.nc: cannot read"), std::string::npos);
}

TEST(MissionParser, SubMissionInMainAndLsurv) {
  const MissionFile f = Parse(
      "(MISSION outer (LSURV: MNTR (S_battery-level BELOW 20) => ((stop)) ((FAIL)))"
      " (MAIN: (MISSION inner (PRE: (LOA)) (MAIN: (read-pos)))))");
  const Mission& m = f.missions[0];
  ASSERT_EQ(m.lsurv.size(), 1u);
  ASSERT_EQ(m.main.size(), 1u);
  ASSERT_EQ(m.main[0].kind, Statement::Kind::kMission);
  EXPECT_EQ(m.main[0].mission->name, "inner");
}

// Regression inputs (fuzzing): each once crashed or misbehaved, now an error or a tree.
TEST(MissionParser, FuzzRegressionsParseOrFailCleanly) {
  for (const char* text :
       {"(", ")", "{", "[", "(define Tclist[0] x ())", "(MISSION m (MAIN: (IF",
        "(MISSION m (MAIN: (MNTR)))", "(OSURV: MNTR (S_zone) =>)", "(MISSION m (MAIN: (set)))",
        "(MISSION m (MAIN: (x MNTR STATIC)))", "(define Tnum x 1e999)",
        "(MISSION m (MAIN: (WHILE (and))))", "\"", "(MISSION m (MAIN: ($)))"}) {
    const ParseResult r = ParseMissionText(text, "f.nc");
    for (const Diagnostic& d : r.diagnostics) EXPECT_GE(d.where.line, 0);
    if (r.ok()) {
      EXPECT_EQ(ParseMissionText(r.file.ToText(), "g.nc").file.ToText(), r.file.ToText());
    }
  }
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
