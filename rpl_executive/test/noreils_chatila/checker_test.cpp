// The checker: unknown names, arity and argument shapes before anything runs.
#include "rpl_executive/noreils_chatila/checker.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace rpl_executive::noreils_chatila {
namespace {

using testing::Parse;
using testing::ParseFile;

std::vector<Diagnostic> Check(const std::string& text) {
  return CheckMissionFile(Parse(text, "c.nc"));
}

std::vector<Diagnostic> Errors(const std::vector<Diagnostic>& all) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : all) {
    if (d.IsError()) out.push_back(d);
  }
  return out;
}

// The one error of `text`, with its message containing `part`, at line:column.
void ExpectError(const std::string& text, const std::string& part, int line, int column) {
  const std::vector<Diagnostic> e = Errors(Check(text));
  ASSERT_EQ(e.size(), 1u) << FormatDiagnostics(e);
  EXPECT_NE(e[0].message.find(part), std::string::npos) << e[0].ToString();
  EXPECT_EQ(e[0].where.line, line) << e[0].ToString();
  EXPECT_EQ(e[0].where.column, column) << e[0].ToString();
}

TEST(MissionChecker, ThePapersMissionsAreClean) {
  for (const char* name :
       {"example1_wall_following.nc", "example2_zone_surveillance.nc", "o_surveillances.nc"}) {
    const std::vector<Diagnostic> d = CheckMissionFile(ParseFile(name));
    EXPECT_TRUE(d.empty()) << name << "\n" << FormatDiagnostics(d);
  }
}

TEST(MissionChecker, ThePapersElidedPathIsReported) {
  // Example 1 as printed writes smooth-move(...): "..." is no path.
  ExpectError(
      "(MISSION m (MAIN: (smooth-move(...) MNTR (S_zone IN ((0 0)(1 0)(1 1))) "
      "=> ((stop)) ((NEXT)))))",
      "each point of the path", 1, 31);
}

TEST(MissionChecker, UnknownOperatorConditionAndVariable) {
  ExpectError("(MISSION m (MAIN: (fly-to (PATH))))", "unknown operator 'fly-to'", 1, 20);
  ExpectError("(MISSION m (MAIN: (smooth-move ((1 1)) MNTR (S_smell IN X) => ((stop)))))",
              "unknown condition 'S_smell'", 1, 45);
  ExpectError("(MISSION m (PRE: (robot-ready)) (MAIN: (read-pos)))",
              "unknown variable 'robot-ready'", 1, 18);
  ExpectError("(MISSION m (PRE: (eq motor $POWER)) (MAIN: (read-pos)))",
              "'$POWER' names no variable", 1, 28);
  ExpectError("(MISSION m (MAIN: (smooth-move ((1 1)) MNTR (S_zone IN ZONE110) => ((stop)))))",
              "'ZONE110' names no variable", 1, 56);
}

TEST(MissionChecker, ArityAndShapes) {
  ExpectError("(MISSION m (MAIN: (set-speed)))", "takes 1 argument(s), found 0", 1, 20);
  ExpectError(
      "(MISSION m (MAIN: (RUN (wall-following (right 25)) MNTR (S_battery-level BELOW 5)"
      " => ((stop)) ((NEXT)))))",
      "expected (right-side <cm>) or (left-side <cm>)", 1, 40);
  ExpectError(
      "(MISSION m (MAIN: (smooth-move ((1 1)) MNTR (S_us-threshold ((17 40))) "
      "=> ((stop)))))",
      "sensor 17 does not exist", 1, 61);
  ExpectError("(MISSION m (MAIN: (draw %G_pos%G_echoes r-position)))", "2 format(s) for 1 datum", 1,
              19);
  ExpectError(
      "(MISSION m (MAIN: (smooth-move ((1 1)) MNTR (S_zone IN ((0 0) (1 1))) "
      "=> ((stop)))))",
      "3 or more points", 1, 56);
}

TEST(MissionChecker, KeywordsWhereTheyBelong) {
  ExpectError("(MISSION m (MAIN: (NEXT)))", "key-word of control actions", 1, 19);
  ExpectError("(MISSION m (MAIN: (MNTR (S_battery-level BELOW 5) => ((stop)))))",
              "nested (MNTR ...) is created by a control action", 1, 19);
  ExpectError("(MISSION m (MAIN: (resume-order)))", "belongs in a monitor's control action", 1, 20);
  ExpectError(
      "(MISSION m (MAIN: (smooth-move ((1 1)) MNTR (S_battery-level BELOW 5) "
      "=> ((avoid-obstacle)))))",
      "cannot be a reflex action", 1, 76);
  ExpectError("(MISSION m (MAIN: (wall-following (right-side 25))))",
              "start it with (RUN (wall-following", 1, 20);
  ExpectError("(MISSION m (MAIN: (RUN (smooth-move ((1 1))))))", "is not a process", 1, 25);
  ExpectError("(MISSION m (ENV: (read-pos)) (MAIN: (read-pos)))", "ENV: holds (set", 1, 18);
}

TEST(MissionChecker, WarningsForProcessesWithoutMonitorsAndTerminalMonitorsWithoutDecision) {
  const std::vector<Diagnostic> d = Check(
      "(MISSION m (MAIN: (RUN (obstacle-avoidance)) (smooth-move ((1 1)) MNTR "
      "(S_battery-level BELOW 5) => ((stop)))))");
  ASSERT_EQ(d.size(), 2u) << FormatDiagnostics(d);
  EXPECT_FALSE(d[0].IsError());
  EXPECT_NE(d[0].message.find("never stops by itself"), std::string::npos);
  EXPECT_NE(d[1].message.find("holds no NEXT, FAIL or resume-order"), std::string::npos);
}

TEST(MissionChecker, DefinitionsCannotRepeatOrTakeTheExecutivesNames) {
  const std::vector<Diagnostic> e = Errors(Check(
      "(define Tnum a 1)\n(define Tnum a 2)\n(define Tsym LOA T)\n(MISSION m (MAIN: (read-pos)))"));
  ASSERT_EQ(e.size(), 2u) << FormatDiagnostics(e);
  EXPECT_NE(e[0].message.find("already defined at line 1"), std::string::npos);
  EXPECT_NE(e[1].message.find("variable of the executive"), std::string::npos);
}

TEST(MissionChecker, WorldVariablesAreKnownAndADifferentDefineIsAWarning) {
  CheckOptions options;
  options.world_variables["ZONE109"] =
      Value::List({Value::List({Value::Number(150), Value::Number(500)}),
                   Value::List({Value::Number(150), Value::Number(700)}),
                   Value::List({Value::Number(350), Value::Number(700)})});
  const MissionFile uses = Parse(
      "(MISSION m (MAIN: (smooth-move ((1 1)) MNTR (S_zone IN ZONE109) => ((stop)) ((NEXT)))))");
  EXPECT_TRUE(CheckMissionFile(uses, options).empty());
  const MissionFile redefines = Parse(
      "(define Tclist[3] ZONE109 ((0 0)(1 0)(1 1)))\n"
      "(MISSION m (MAIN: (smooth-move ((1 1)) MNTR (S_zone IN ZONE109) => ((stop)) ((NEXT)))))");
  const std::vector<Diagnostic> d = CheckMissionFile(redefines, options);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_FALSE(d[0].IsError());
  EXPECT_NE(d[0].message.find("overrides the world's ZONE109"), std::string::npos);
}

TEST(MissionChecker, TerminalIsTheMonitorWhoseReflexStops) {
  const MissionFile f = ParseFile("example2_zone_surveillance.nc");
  const auto& monitors = f.missions[0].main[0].monitors;
  EXPECT_FALSE(IsTerminal(monitors[0]));  // S1: set-speed, smooth-move goes on
  EXPECT_TRUE(IsTerminal(monitors[1]));   // S2: stop
}

}  // namespace
}  // namespace rpl_executive::noreils_chatila
