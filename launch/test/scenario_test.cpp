// Scenario files (spott_launch/scenario.h): what a user's mistake is told, with its line and
// column, and what a good file turns into for roslaunch, demo_report and robot_sim.
#include "spott_launch/scenario.h"

#include <dirent.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "robot_sim/fault_events.h"
#include "spott_map/world_loader.h"

namespace spott_launch {
namespace {

std::string Errors(const ScenarioResult& r) { return spott_map::FormatErrors(r.errors); }

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

spott_map::World World(const std::string& name) {
  const auto loaded = spott_map::LoadWorldFile(std::string(WORLDS_DIR) + "/" + name + ".yaml");
  EXPECT_TRUE(loaded.ok()) << name;
  return *loaded.world;
}

TEST(Scenario, EveryShippedScenarioParsesAndFitsItsWorld) {
  DIR* dir = opendir(SCENARIOS_DIR);
  ASSERT_NE(dir, nullptr);
  int files = 0;
  while (const dirent* entry = readdir(dir)) {
    const std::string name = entry->d_name;
    if (name.size() < 5 || name.substr(name.size() - 5) != ".yaml") continue;
    ++files;
    const auto r = ParseScenario(ReadFile(std::string(SCENARIOS_DIR) + "/" + name), name);
    ASSERT_TRUE(r.ok()) << Errors(r);
    const auto errors = CheckAgainstWorld(*r.scenario, World(r.scenario->world.text));
    EXPECT_TRUE(errors.empty()) << name << ": " << spott_map::FormatErrors(errors);
    const auto names = CheckMissionNames(*r.scenario, RPL_EXECUTIVE_DIR);
    EXPECT_TRUE(names.empty()) << name << ": " << spott_map::FormatErrors(names);
  }
  closedir(dir);
  EXPECT_GE(files, 4);
}

TEST(Scenario, AnUnknownKeyIsNamedAtItsLineAndColumnWithTheLikelyWord) {
  const auto r = ParseScenario("world: cim_office\ntaks: [\"go in room(lab)\"]\n", "s.yaml");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(Errors(r).find("s.yaml:2:1:"), std::string::npos) << Errors(r);
  EXPECT_NE(Errors(r).find("taks"), std::string::npos) << Errors(r);
  EXPECT_NE(Errors(r).find("tasks"), std::string::npos) << Errors(r);
}

TEST(Scenario, ATaskSyntaxErrorPointsIntoItsString) {
  // Column 21 of the line is the task's 12th character (after `tasks: ["`), where the grammar
  // wanted the '(' of `door(...)` and found a name.
  const auto r = ParseScenario("world: cim_office\ntasks: [\"go to door d_106)\"]\n", "s.yaml");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.errors.size(), 1u) << Errors(r);
  EXPECT_EQ(r.errors[0].where.line, 2);
  EXPECT_EQ(r.errors[0].where.column, 21) << Errors(r);
  // Unquoted, the same task starts one column earlier.
  const auto plain = ParseScenario("world: cim_office\ntasks: [go to door d_106)]\n", "s.yaml");
  ASSERT_EQ(plain.errors.size(), 1u) << Errors(plain);
  EXPECT_EQ(plain.errors[0].where.column, 20) << Errors(plain);
  EXPECT_NE(Errors(r).find("tasks[0]"), std::string::npos) << Errors(r);
}

TEST(Scenario, TasksAndGoalsTogetherOrNeitherAreRefused) {
  const auto both = ParseScenario(
      "world: cim_office\ntasks: [\"go in room(lab)\"]\ngoals: [lab_bench]\n", "s.yaml");
  ASSERT_FALSE(both.ok());
  EXPECT_NE(Errors(both).find("s.yaml:3:"), std::string::npos) << Errors(both);
  EXPECT_NE(Errors(both).find("one of them"), std::string::npos) << Errors(both);
  const auto neither = ParseScenario("world: cim_office\nseed: 3\n", "s.yaml");
  ASSERT_FALSE(neither.ok());
  EXPECT_NE(Errors(neither).find("nothing to do"), std::string::npos) << Errors(neither);
  const auto empty = ParseScenario("", "s.yaml");
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(Errors(empty).find("s.yaml:1:1:"), std::string::npos) << Errors(empty);
}

// scenario_fuzz: a goal with bytes that are not UTF-8 reached demo_report's parameters changed.
TEST(Scenario, GoalsAndDoorsAreNamesOfTheWorld) {
  const auto r = ParseScenario(
      "world: bonn_department\ngoals: [position_1, w\xf2\xff\xffolframs]\n"
      "doors_to_close: [\"door b\"]\n",
      "s.yaml");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.errors.size(), 2u) << Errors(r);
  EXPECT_NE(Errors(r).find("s.yaml:2:21: goals[1]:"), std::string::npos) << Errors(r);
  EXPECT_NE(Errors(r).find("s.yaml:3:18: doors_to_close[0]:"), std::string::npos) << Errors(r);
}

TEST(Scenario, NumbersOutOfTheirRangesAreNamed) {
  const std::string head = "world: cim_office\ngoals: [lab_bench]\n";
  for (const auto& [line, field] : std::vector<std::pair<std::string, std::string>>{
           {"seed: 1.5", "seed"},
           {"seed: -2", "seed"},
           {"real_time_factor: 50", "real_time_factor"},
           {"leg_timeout_s: 0", "leg_timeout_s"},
           {"goal_tolerance_m: .nan", "goal_tolerance_m"},
           {"localization: amcl", "localization"},
           {"a_priori_map: partly", "a_priori_map"},
           {"global_localization: maybe", "global_localization"},
           {"start_pose: [1, 2]", "start_pose"}}) {
    const auto r = ParseScenario(head + line + "\n", "s.yaml");
    ASSERT_FALSE(r.ok()) << line;
    EXPECT_NE(Errors(r).find("s.yaml:3:"), std::string::npos) << line << ": " << Errors(r);
    EXPECT_NE(Errors(r).find(field), std::string::npos) << line << ": " << Errors(r);
  }
}

TEST(Scenario, FaultsAreRobotSimsEventsAndReachItUnchanged) {
  const auto r = ParseScenario(
      "world: bonn_department\n"
      "goals: [position_1]\n"
      "faults:\n"
      "  - {time: 45, kind: door, door: door_b, state: closed}\n"
      "  - {time: 30, kind: kidnap, pose: [0, 0, -1.22], relative: true}\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const Scenario& s = *r.scenario;
  ASSERT_EQ(s.faults.size(), 2u);
  EXPECT_EQ(s.faults[0].kind, robot_sim::FaultEvent::Kind::kKidnap);  // sorted by time
  EXPECT_EQ(s.faults[0].where.line, 5);
  // What robot_sim's ~faults gets parses to the same events.
  const auto schedule = robot_sim::ParseFaultSchedule(s.faults_yaml, "faults.yaml");
  ASSERT_TRUE(schedule.ok()) << spott_map::FormatErrors(schedule.errors);
  ASSERT_EQ(schedule.events.size(), 2u);
  EXPECT_DOUBLE_EQ(schedule.events[0].pose.yaw, -1.22);
  EXPECT_TRUE(schedule.events[0].relative);
  EXPECT_EQ(schedule.events[1].name, "door_b");
  EXPECT_TRUE(schedule.events[1].closed);

  const auto bad = ParseScenario(
      "world: bonn_department\ngoals: [position_1]\nfaults:\n  - {time: 5, kind: explode}\n",
      "s.yaml");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(Errors(bad).find("s.yaml:4:"), std::string::npos) << Errors(bad);
  EXPECT_NE(Errors(bad).find("explode"), std::string::npos) << Errors(bad);

  const auto late = ParseScenario(
      "world: bonn_department\ngoals: [position_1]\ntime_limit_s: 100\n"
      "faults:\n  - {time: 200, kind: kidnap, pose: [0, 0, 1], relative: true}\n",
      "s.yaml");
  ASSERT_FALSE(late.ok());
  EXPECT_NE(Errors(late).find("s.yaml:5:"), std::string::npos) << Errors(late);
}

TEST(Scenario, TheWorldNamesWhatItLacks) {
  const auto r = ParseScenario(
      "world: cim_office\n"
      "start_pose: [-50, -50, 0]\n"
      "goals: [lab_bench, nowhere]\n"
      "doors_to_close: [d_nope]\n"
      "faults:\n"
      "  - {time: 5, kind: door, door: d_none, state: closed}\n"
      "  - {time: 9, kind: kidnap, pose: [-40, 3, 0]}\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const auto errors = CheckAgainstWorld(*r.scenario, World("cim_office"));
  const std::string text = spott_map::FormatErrors(errors);
  ASSERT_EQ(errors.size(), 5u) << text;
  EXPECT_NE(text.find("s.yaml:2:"), std::string::npos) << text;  // start in no room
  EXPECT_NE(text.find("s.yaml:3:20: goals: no place 'nowhere'"), std::string::npos) << text;
  EXPECT_NE(text.find("s.yaml:4:"), std::string::npos) << text;
  EXPECT_NE(text.find("s.yaml:6:"), std::string::npos) << text;
  EXPECT_NE(text.find("s.yaml:7:"), std::string::npos) << text;
}

TEST(Scenario, LaunchArgumentsAndDemoParametersSayWhatTheFileSays) {
  const auto r = ParseScenario(
      "world: cim_office\nrobot: b12\nstart_pose: [3.5, 4, 1.5]\nseed: 7\n"
      "real_time_factor: 2\nlocalization: truth\n"
      "tasks: [\"go to door(d_106)\", 'go near point(meeting_room) quickly']\n"
      "leg_timeout_s: 100\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const auto args = LaunchArguments(*r.scenario);
  const std::vector<std::string> expected = {
      "world:=cim_office",   "robot:=b12",          "start_pose:=3.5 4 1.5", "seed:=7",
      "real_time_factor:=2", "localization:=truth", "controller:=tr_plus",   "executive:=none"};
  EXPECT_EQ(args, expected);
  const YAML::Node params = YAML::Load(DemoParametersYaml(*r.scenario));
  ASSERT_TRUE(params["tasks"].IsSequence());
  EXPECT_EQ(params["tasks"][1].as<std::string>(), "go near point(meeting_room) quickly");
  EXPECT_FALSE(params["goals"]);
  EXPECT_DOUBLE_EQ(params["leg_timeout_s"].as<double>(), 100.0);
  EXPECT_DOUBLE_EQ(r.scenario->EffectiveTimeLimit(), 60.0 + 2 * 100.0);
}

TEST(Scenario, AStackWithoutAPrioriMapCanLocalizeOnTheSensedMap) {
  const auto r = ParseScenario(
      "world: cim_office\nlocalization: sensed\na_priori_map: false\n"
      "tasks: [\"go to point(27, 15.5)\"]\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const auto args = LaunchArguments(*r.scenario);
  EXPECT_NE(std::find(args.begin(), args.end(), "localization:=sensed"), args.end());
  const auto bad = ParseScenario("world: cim_office\nlocalization: slam\ngoals: [x]\n", "s.yaml");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(Errors(bad).find("expected markov, truth, odometry or sensed, got 'slam'"),
            std::string::npos)
      << Errors(bad);
}

TEST(Scenario, AStackWithoutAPrioriMapRunsOnDeadReckoning) {
  const auto r = ParseScenario(
      "world: cim_office\nlocalization: odometry\na_priori_map: false\n"
      "tasks: [\"go to point(19, 15.5)\"]\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  EXPECT_FALSE(r.scenario->a_priori_map);
  const auto args = LaunchArguments(*r.scenario);
  EXPECT_NE(std::find(args.begin(), args.end(), "localization:=odometry"), args.end());
  EXPECT_NE(std::find(args.begin(), args.end(), "a_priori_map:=false"), args.end());
  // The default says nothing: the stack's own default (the map) holds.
  const auto with_map = ParseScenario("world: cim_office\ngoals: [lab_bench]\n", "s.yaml");
  ASSERT_TRUE(with_map.ok());
  EXPECT_TRUE(with_map.scenario->a_priori_map);
  const auto plain = LaunchArguments(*with_map.scenario);
  EXPECT_EQ(std::find(plain.begin(), plain.end(), "a_priori_map:=false"), plain.end());
}

// MAP_OBJECTS_WITH_SONAR's dense scan for a run (issue 19's sonar map).
TEST(Scenario, TheSonarScanPeriodReachesTheControllerAndIsCheckedWhereItIsWritten) {
  const auto r = ParseScenario(
      "world: cim_office\ntasks: [\"go in room(lab)\"]\nsonar_scan_period_s: 5\n", "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const auto args = LaunchArguments(*r.scenario);
  EXPECT_NE(std::find(args.begin(), args.end(), "sonar_scan_period_s:=5"), args.end());
  const auto plain = LaunchArguments(
      *ParseScenario("world: cim_office\ntasks: [\"go in room(lab)\"]\n", "s.yaml").scenario);
  for (const auto& a : plain) EXPECT_EQ(a.find("sonar_scan"), std::string::npos) << a;
  const auto negative = ParseScenario(
      "world: cim_office\ntasks: [\"go in room(lab)\"]\nsonar_scan_period_s: -1\n", "s.yaml");
  ASSERT_FALSE(negative.ok());
  EXPECT_NE(Errors(negative).find("s.yaml:3:"), std::string::npos) << Errors(negative);
  const auto goals =
      ParseScenario("world: cim_office\ngoals: [lab_bench]\nsonar_scan_period_s: 5\n", "s.yaml");
  ASSERT_FALSE(goals.ok());
  EXPECT_NE(Errors(goals).find("s.yaml:3:22: sonar_scan_period_s: the dense sonar scan"),
            std::string::npos)
      << Errors(goals);
}

// A map from the sonar alone (issue 19): QUADRIS's mapping switched off for the run.
TEST(Scenario, SubroutinesOffReachTheControllerAsAYamlList) {
  const auto r = ParseScenario(
      "world: cim_office\ntasks: [\"go in room(lab)\"]\n"
      "subroutines_off: [MAP_OBJECTS_WITH_QUADRIS, CONTROL_THE_PTU]\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const auto args = LaunchArguments(*r.scenario);
  EXPECT_NE(std::find(args.begin(), args.end(),
                      "subroutines_off:=[MAP_OBJECTS_WITH_QUADRIS, CONTROL_THE_PTU]"),
            args.end());
  const auto bad = ParseScenario(
      "world: cim_office\ngoals: [lab_bench]\nsubroutines_off: [\"MAP QUADRIS\"]\n", "s.yaml");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(Errors(bad).find("s.yaml:3:19: subroutines_off[0]: 'MAP QUADRIS' is not a TR+"),
            std::string::npos)
      << Errors(bad);
  EXPECT_NE(Errors(bad).find("s.yaml:3:18: subroutines_off: switches off subroutines of the TR+"),
            std::string::npos)
      << Errors(bad);
}

// Beetz et al. 2.3: the robot knows the map, not where it is.
TEST(Scenario, GlobalLocalizationStartsTheMarkovBeliefUniform) {
  const auto r = ParseScenario(
      "world: bonn_department\nglobal_localization: true\ngoals: [room_a_target]\n", "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  EXPECT_TRUE(r.scenario->global_localization);
  const auto args = LaunchArguments(*r.scenario);
  EXPECT_NE(std::find(args.begin(), args.end(), "global_localization:=true"), args.end());
  const auto plain = ParseScenario("world: bonn_department\ngoals: [room_a_target]\n", "s.yaml");
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(plain.scenario->global_localization);
  const auto plain_args = LaunchArguments(*plain.scenario);
  EXPECT_EQ(std::find(plain_args.begin(), plain_args.end(), "global_localization:=true"),
            plain_args.end());
  // Only the grid localization has a belief to start uniform.
  const auto truth = ParseScenario(
      "world: bonn_department\nlocalization: truth\nglobal_localization: true\n"
      "goals: [room_a_target]\n",
      "s.yaml");
  ASSERT_FALSE(truth.ok());
  EXPECT_NE(Errors(truth).find("s.yaml:3:22: global_localization"), std::string::npos)
      << Errors(truth);
}

TEST(Scenario, MissionsAreReadWithWhatTheRunMustShow) {
  const auto r = ParseScenario(
      "world: hilare_room\nmissions:\n"
      "  - {name: office_delivery, bindings: [\"DEST (19.6 6.0)\"], goal: zone_exit}\n"
      "  - name: example2_zone_surveillance\n"
      "    language: noreils_chatila\n"
      "    outcome: failed\n"
      "    monitors: [\"(S_zone IN ZONE109)\", \"(S_us-threshold sensors-list)\"]\n"
      "    message_contains: FAIL\n"
      "    goal: [2.5, 6]\n"
      "  - {name: example1_wall_following, language: noreils_chatila, monitors: []}\n"
      "  - {name: example2_zone_surveillance, language: noreils_chatila,\n"
      "     monitors_include: [\"(S_zone IN ZONE109)\", \"(S_zone OUT ZONE109)\"]}\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const auto& m = r.scenario->missions;
  ASSERT_EQ(m.size(), 4u);
  EXPECT_FALSE(m[3].monitors.has_value());
  EXPECT_EQ(m[3].monitors_include,
            (std::vector<std::string>{"(S_zone IN ZONE109)", "(S_zone OUT ZONE109)"}));
  EXPECT_EQ(m[0].name.text, "office_delivery");
  EXPECT_EQ(m[0].language, "rpl");
  EXPECT_EQ(m[0].bindings, std::vector<std::string>{"DEST (19.6 6.0)"});
  EXPECT_EQ(m[0].goal_place.text, "zone_exit");
  EXPECT_EQ(m[0].outcome, "completed");
  EXPECT_FALSE(m[0].monitors.has_value());  // not judged
  EXPECT_EQ(m[1].language, "noreils_chatila");
  EXPECT_EQ(m[1].outcome, "failed");
  ASSERT_TRUE(m[1].monitors.has_value());
  EXPECT_EQ(m[1].monitors->size(), 2u);
  EXPECT_EQ(m[1].message_contains, "FAIL");
  ASSERT_TRUE(m[1].goal_point.has_value());
  EXPECT_DOUBLE_EQ(m[1].goal_point->y(), 6.0);
  ASSERT_TRUE(m[2].monitors.has_value());  // `monitors: []`: none may fire
  EXPECT_TRUE(m[2].monitors->empty());
  // The executive runs them, nothing else does: demo_report reads them from the file.
  const auto args = LaunchArguments(*r.scenario);
  EXPECT_NE(std::find(args.begin(), args.end(), "executive:=rpl"), args.end());
  EXPECT_NE(std::find(args.begin(), args.end(), "controller:=none"), args.end());
  const YAML::Node params = YAML::Load(DemoParametersYaml(*r.scenario, "/x/s.yaml"));
  EXPECT_EQ(params["missions_file"].as<std::string>(), "/x/s.yaml");
  EXPECT_FALSE(params["goals"]);
  EXPECT_DOUBLE_EQ(r.scenario->EffectiveTimeLimit(), 60.0 + 4 * 240.0);
  // Places are the world's; names are rpl_executive's shipped plans and missions.
  EXPECT_TRUE(CheckAgainstWorld(*r.scenario, World("hilare_room")).empty());
  EXPECT_TRUE(CheckMissionNames(*r.scenario, RPL_EXECUTIVE_DIR).empty());
}

TEST(Scenario, BadMissionsAreNamedAtTheirLineAndColumn) {
  const auto r = ParseScenario(
      "world: hilare_room\nmissions:\n"
      "  - {name: office_delivery, langauge: rpl}\n"
      "  - {name: example1_wall_following, language: nc}\n"
      "  - {name: example1_wall_following, language: noreils_chatila, bindings: [\"X 1\"]}\n"
      "  - {name: office_delivery, outcome: reached}\n"
      "  - {name: \"office delivery\"}\n"
      "  - {name: office_delivery, monitors: [], monitors_include: [\"(X)\"]}\n",
      "s.yaml");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(Errors(r).find("s.yaml:8:"), std::string::npos) << Errors(r);
  EXPECT_NE(Errors(r).find("give monitors (exactly these) or monitors_include"), std::string::npos)
      << Errors(r);
  const std::string e = Errors(r);
  EXPECT_NE(e.find("s.yaml:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("langauge"), std::string::npos) << e;
  EXPECT_NE(e.find("s.yaml:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected rpl or noreils_chatila, got 'nc'"), std::string::npos) << e;
  EXPECT_NE(e.find("s.yaml:5:"), std::string::npos) << e;
  EXPECT_NE(e.find("only an RPL plan has DEFVARs"), std::string::npos) << e;
  EXPECT_NE(e.find("s.yaml:6:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected completed or failed, got 'reached'"), std::string::npos) << e;
  EXPECT_NE(e.find("s.yaml:7:"), std::string::npos) << e;
  // Missions with goals are one kind too many.
  const auto both = ParseScenario(
      "world: hilare_room\ngoals: [zone_exit]\nmissions: [{name: office_delivery}]\n", "s.yaml");
  ASSERT_FALSE(both.ok());
  EXPECT_NE(Errors(both).find("s.yaml:3:"), std::string::npos) << Errors(both);
}

TEST(Scenario, AMissionNamesAShippedPlanOrMissionAndAPlaceOfTheWorld) {
  const auto r = ParseScenario(
      "world: hilare_room\nmissions:\n"
      "  - {name: office_delivry, goal: nowhere}\n"
      "  - {name: office_delivery, language: noreils_chatila}\n",
      "s.yaml");
  ASSERT_TRUE(r.ok()) << Errors(r);
  const std::string names =
      spott_map::FormatErrors(CheckMissionNames(*r.scenario, RPL_EXECUTIVE_DIR));
  EXPECT_NE(names.find("s.yaml:3:12: missions[0].name: no shipped RPL plan 'office_delivry'"),
            std::string::npos)
      << names;
  EXPECT_NE(names.find("office_delivery"), std::string::npos) << names;  // what there is
  // office_delivery is a plan, not a Noreils-Chatila mission.
  EXPECT_NE(names.find("s.yaml:4:"), std::string::npos) << names;
  EXPECT_NE(names.find("example1_wall_following"), std::string::npos) << names;
  const std::string world =
      spott_map::FormatErrors(CheckAgainstWorld(*r.scenario, World("hilare_room")));
  EXPECT_NE(world.find("s.yaml:3:34: missions[0].goal: no place 'nowhere'"), std::string::npos)
      << world;
}

}  // namespace
}  // namespace spott_launch
