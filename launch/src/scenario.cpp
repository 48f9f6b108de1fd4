#include "spott_launch/scenario.h"

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "spott_map/yaml_reader.h"
#include "spott_tr_plus/task_command.h"

namespace spott_launch {

using spott_map::NumberRule;
using spott_map::SourceError;
using spott_map::YamlReader;

namespace {

constexpr double kMinRealTimeFactor = 0.1;
constexpr double kMaxRealTimeFactor = 20.0;
constexpr double kStartUpAllowanceS = 60.0;  // the door experiment and the nodes' start

Located At(YamlReader& in, const YAML::Node& node, const std::string& text) {
  // yaml-cpp tags a quoted scalar "!": its text starts one column after the node's mark.
  return Located{text, in.Where(node), node.Tag() == "!" ? 1 : 0};
}

/// A list of words or texts (an absent key is an empty list).
std::vector<Located> Strings(YamlReader& in, const YAML::Node& map, const char* key) {
  std::vector<Located> out;
  const YAML::Node list = map[key];
  if (!list || list.IsNull()) return out;
  if (!in.ExpectSequence(list, key)) return out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node item = list[i];
    if (!item.IsScalar() || item.Scalar().empty()) {
      in.Error(item, std::string(key) + "[" + std::to_string(i) + "]: expected a non-empty text");
      continue;
    }
    out.push_back(At(in, item, item.Scalar()));
  }
  return out;
}

/// Places and doors are a world's ids (letters, digits, _): a file's typo gets its column here,
/// and every name reaches demo_report as written.
void CheckIds(YamlReader& in, const std::vector<Located>& names, const char* key) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!spott_map::IsValidId(names[i].text)) {
      in.Error(names[i].where, std::string(key) + "[" + std::to_string(i) + "]: '" + names[i].text +
                                   "' is not a name of the world (letters, digits, _)");
    }
  }
}

/// Task commands parse (SPOTT III-B grammar); a syntax error points into the string.
void CheckTasks(YamlReader& in, const std::vector<Located>& tasks) {
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const auto parsed = spott_tr_plus::ParseTaskCommand(tasks[i].text);
    for (const auto& d : parsed.diagnostics) {
      if (!d.IsError()) continue;
      spott_map::SourceLocation where = tasks[i].where;
      // The grammar's column counts from the task's first character.
      if (where.line > 0 && d.where.line <= 1 && d.where.column > 0)
        where.column += tasks[i].quote + d.where.column - 1;
      in.Error(where, "tasks[" + std::to_string(i) + "]: '" + tasks[i].text + "': " + d.message);
    }
  }
}

/// The `missions:` list: each a map naming a shipped plan or mission and what must happen.
std::vector<MissionSpec> Missions(YamlReader& in, const YAML::Node& map) {
  std::vector<MissionSpec> out;
  const YAML::Node list = map["missions"];
  if (!list || list.IsNull()) return out;
  if (!in.ExpectSequence(list, "missions")) return out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node item = list[i];
    const std::string what = "missions[" + std::to_string(i) + "]";
    if (!in.ExpectMap(item, what,
                      {"name", "language", "bindings", "goal", "outcome", "monitors",
                       "monitors_include", "message_contains"})) {
      continue;
    }
    MissionSpec m;
    if (auto name = in.String(item, "name", what, true)) {
      m.name = At(in, item["name"], *name);
      if (!spott_map::IsValidId(*name))
        in.Error(item["name"], what + ".name: '" + *name +
                                   "' is not a shipped plan's or mission's name (letters, "
                                   "digits, _)");
    }
    m.language = in.String(item, "language", what, false).value_or("rpl");
    if (m.language != "rpl" && m.language != "noreils_chatila")
      in.Error(item["language"],
               what + ".language: expected rpl or noreils_chatila, got '" + m.language + "'");
    for (const Located& b : Strings(in, item, "bindings")) m.bindings.push_back(b.text);
    if (!m.bindings.empty() && m.language != "rpl")
      in.Error(item["bindings"], what + ".bindings: only an RPL plan has DEFVARs to bind");
    if (const YAML::Node goal = item["goal"]; goal && !goal.IsNull()) {
      if (goal.IsScalar()) {
        m.goal_place = At(in, goal, goal.Scalar());
        if (!spott_map::IsValidId(goal.Scalar()))
          in.Error(goal, what + ".goal: '" + goal.Scalar() +
                             "' is not a place's name (letters, digits, _) or [x, y]");
      } else {
        m.goal_point = in.Point(item, "goal", what, false);
      }
    }
    m.outcome = in.String(item, "outcome", what, false).value_or("completed");
    if (m.outcome != "completed" && m.outcome != "failed")
      in.Error(item["outcome"],
               what + ".outcome: expected completed or failed, got '" + m.outcome + "'");
    if (item["monitors"] && !item["monitors"].IsNull()) {
      std::vector<std::string> fired;
      for (const Located& c : Strings(in, item, "monitors")) fired.push_back(c.text);
      m.monitors = fired;
    } else if (item["monitors"]) {
      m.monitors = std::vector<std::string>{};  // `monitors: []` or `monitors:`: none may fire
    }
    for (const Located& c : Strings(in, item, "monitors_include"))
      m.monitors_include.push_back(c.text);
    if (m.monitors && item["monitors_include"])
      in.Error(item["monitors_include"],
               what +
                   ".monitors_include: give monitors (exactly these) or monitors_include "
                   "(these in order, others between), not both");
    m.message_contains = in.String(item, "message_contains", what, false).value_or("");
    out.push_back(std::move(m));
  }
  return out;
}

std::string Joined(const std::vector<Located>& items) {
  std::ostringstream out;
  out << "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    YAML::Emitter e;  // quotes what a YAML reader would take otherwise
    e << YAML::DoubleQuoted << items[i].text;
    out << (i ? ", " : "") << e.c_str();
  }
  out << "]";
  return out.str();
}

}  // namespace

double Scenario::EffectiveTimeLimit() const {
  if (time_limit_s > 0.0) return time_limit_s;
  const std::size_t legs = tasks.size() + goals.size() + missions.size();
  return kStartUpAllowanceS + static_cast<double>(legs) * leg_timeout_s;
}

ScenarioResult ParseScenario(const std::string& text, const std::string& file) {
  ScenarioResult result;
  YamlReader in(file);
  const YAML::Node root = in.Parse(text);
  if (!in.errors().empty()) {
    result.errors = in.errors();
    return result;
  }
  if (!root || root.IsNull()) {
    in.Error(spott_map::SourceLocation{file, 1, 1},
             "empty scenario: it needs at least `world:` and `tasks:`, `goals:` or `missions:`");
    result.errors = in.errors();
    return result;
  }
  const std::string what = "scenario";
  if (!in.ExpectMap(root, what,
                    {"description", "world", "robot", "start_pose", "seed", "real_time_factor",
                     "localization", "a_priori_map", "global_localization", "tasks", "goals",
                     "missions", "doors_to_close", "leg_timeout_s", "goal_tolerance_m",
                     "time_limit_s", "faults", "subroutines_off", "sonar_scan_period_s"})) {
    result.errors = in.errors();
    return result;
  }
  Scenario s;
  s.description = in.String(root, "description", what, false).value_or("");
  if (auto world = in.String(root, "world", what, true)) {
    s.world = At(in, root["world"], *world);
    if (!spott_map::IsValidId(*world))
      in.Error(root["world"], "world: '" + *world + "' is not a world's name (letters, digits, _)");
  }
  if (auto robot = in.String(root, "robot", what, false)) {
    s.robot = At(in, root["robot"], *robot);
    if (!spott_map::IsValidId(*robot))
      in.Error(root["robot"], "robot: '" + *robot + "' is not a robot's name (letters, digits, _)");
  }
  s.start = in.Pose(root, "start_pose", what, false);
  s.start_where = in.Where(root["start_pose"]);
  if (auto seed = in.Number(root, "seed", what, false, NumberRule::kNonNegative)) {
    if (*seed != std::floor(*seed) || *seed > 2147483647.0)
      in.Error(root["seed"], "seed: expected a whole number from 0 to 2147483647");
    else
      s.seed = static_cast<int>(*seed);
  }
  if (auto rtf = in.Number(root, "real_time_factor", what, false, NumberRule::kPositive)) {
    if (*rtf < kMinRealTimeFactor || *rtf > kMaxRealTimeFactor)
      in.Error(root["real_time_factor"], "real_time_factor: expected 0.1 to 20");
    else
      s.real_time_factor = *rtf;
  }
  s.localization = in.String(root, "localization", what, false).value_or("markov");
  if (s.localization != "markov" && s.localization != "truth" && s.localization != "odometry" &&
      s.localization != "sensed")
    in.Error(
        root["localization"],
        "localization: expected markov, truth, odometry or sensed, got '" + s.localization + "'");
  s.a_priori_map = in.Bool(root, "a_priori_map", what, false).value_or(true);
  s.global_localization = in.Bool(root, "global_localization", what, false).value_or(false);
  if (s.global_localization && s.localization != "markov")
    in.Error(root["global_localization"],
             "global_localization: only markov localization starts from a uniform belief, not " +
                 s.localization);
  s.tasks = Strings(in, root, "tasks");
  s.goals = Strings(in, root, "goals");
  s.doors_to_close = Strings(in, root, "doors_to_close");
  CheckTasks(in, s.tasks);
  CheckIds(in, s.goals, "goals");
  CheckIds(in, s.doors_to_close, "doors_to_close");
  s.subroutines_off = Strings(in, root, "subroutines_off");
  for (std::size_t i = 0; i < s.subroutines_off.size(); ++i) {
    const std::string& name = s.subroutines_off[i].text;
    if (name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
      in.Error(
          s.subroutines_off[i].where,
          "subroutines_off[" + std::to_string(i) + "]: '" + name +
              "' is not a TR+ subroutine's name (capitals, digits, _: MAP_OBJECTS_WITH_QUADRIS)");
  }
  if (!s.subroutines_off.empty() && !root["tasks"])
    in.Error(root["subroutines_off"],
             "subroutines_off: switches off subroutines of the TR+ controller, which runs only "
             "for `tasks:`");
  if (auto period = in.Number(root, "sonar_scan_period_s", what, false, NumberRule::kNonNegative)) {
    if (*period > 600.0)
      in.Error(root["sonar_scan_period_s"], "sonar_scan_period_s: expected 0 to 600 s");
    else if (!root["tasks"])
      in.Error(root["sonar_scan_period_s"],
               "sonar_scan_period_s: the dense sonar scan is the TR+ controller's, which runs "
               "only for `tasks:`");
    else
      s.sonar_scan_period_s = *period;
  }
  s.missions = Missions(in, root);
  const int kinds = (root["tasks"] ? 1 : 0) + (root["goals"] ? 1 : 0) + (root["missions"] ? 1 : 0);
  if (kinds > 1) {
    in.Error(root["missions"] ? root["missions"] : root["goals"],
             "scenario: give tasks (the TR+ controller), goals (Navigate) or missions "
             "(rpl_executive), one of them");
  } else if (s.tasks.empty() && s.goals.empty() && s.missions.empty() && in.errors().empty()) {
    in.Error(root,
             "scenario: nothing to do: give `tasks:` (task commands), `goals:` (places) or "
             "`missions:` (plans and missions)");
  }
  s.leg_timeout_s =
      in.Number(root, "leg_timeout_s", what, false, NumberRule::kPositive).value_or(240.0);
  s.goal_tolerance_m =
      in.Number(root, "goal_tolerance_m", what, false, NumberRule::kPositive).value_or(0.25);
  s.time_limit_s =
      in.Number(root, "time_limit_s", what, false, NumberRule::kPositive).value_or(0.0);
  if (root["faults"] && !root["faults"].IsNull()) {
    s.faults = robot_sim::ReadFaultEvents(in, root["faults"], "faults");
    YAML::Emitter out;
    out << YAML::BeginMap << YAML::Key << "faults" << YAML::Value << root["faults"] << YAML::EndMap;
    s.faults_yaml = std::string(out.c_str()) + "\n";
  }
  if (s.time_limit_s > 0.0) {
    for (const auto& f : s.faults) {
      if (f.time > s.time_limit_s) {
        in.Error(f.where, "faults: at " + std::to_string(f.time) +
                              " s, after the scenario's time_limit_s: it would never happen");
      }
    }
  }
  result.errors = in.errors();
  if (result.errors.empty()) result.scenario = std::move(s);
  return result;
}

std::vector<SourceError> CheckAgainstWorld(const Scenario& s, const spott_map::World& world) {
  std::vector<SourceError> errors;
  const std::string in_world = " in world " + world.name;
  if (s.start) {
    if (!world.RoomContaining({s.start->x, s.start->y}))
      errors.push_back({s.start_where, "start_pose: (" + std::to_string(s.start->x) + ", " +
                                           std::to_string(s.start->y) + ") is in no room" +
                                           in_world});
  }
  for (const auto& g : s.goals) {
    if (!world.FindPlace(g.text))
      errors.push_back({g.where, "goals: no place '" + g.text + "'" + in_world});
  }
  for (std::size_t i = 0; i < s.missions.size(); ++i) {
    const Located& g = s.missions[i].goal_place;
    if (!g.text.empty() && !world.FindPlace(g.text))
      errors.push_back({g.where, "missions[" + std::to_string(i) + "].goal: no place '" + g.text +
                                     "'" + in_world});
  }
  for (const auto& d : s.doors_to_close) {
    if (!world.FindDoor(d.text))
      errors.push_back({d.where, "doors_to_close: no door '" + d.text + "'" + in_world});
  }
  for (const auto& f : s.faults) {
    using Kind = robot_sim::FaultEvent::Kind;
    if (f.kind == Kind::kDoor && !world.FindDoor(f.name))
      errors.push_back({f.where, "faults: no door '" + f.name + "'" + in_world});
    if (f.kind == Kind::kKidnap && !f.relative && !world.RoomContaining({f.pose.x, f.pose.y}))
      errors.push_back({f.where, "faults: the kidnap's pose is in no room" + in_world});
  }
  return errors;
}

std::vector<std::string> LaunchArguments(const Scenario& s) {
  std::vector<std::string> args;
  auto number = [](double v) {
    std::ostringstream out;
    out.precision(17);
    out << v;
    return out.str();
  };
  args.push_back("world:=" + s.world.text);
  if (!s.robot.text.empty()) args.push_back("robot:=" + s.robot.text);
  if (s.start)
    args.push_back("start_pose:=" + number(s.start->x) + " " + number(s.start->y) + " " +
                   number(s.start->yaw));
  args.push_back("seed:=" + std::to_string(s.seed));
  args.push_back("real_time_factor:=" + number(s.real_time_factor));
  args.push_back("localization:=" + s.localization);
  if (!s.a_priori_map) args.push_back("a_priori_map:=false");
  if (s.global_localization) args.push_back("global_localization:=true");
  args.push_back("controller:=" + s.Controller());
  if (!s.subroutines_off.empty()) {
    std::string list;
    for (const auto& name : s.subroutines_off) list += (list.empty() ? "" : ", ") + name.text;
    args.push_back("subroutines_off:=[" + list + "]");
  }
  if (s.sonar_scan_period_s >= 0)
    args.push_back("sonar_scan_period_s:=" + number(s.sonar_scan_period_s));
  args.push_back("executive:=" + s.Executive());
  return args;
}

std::string FileStems(const std::string& dir, const std::string& ext) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (const dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > ext.size() && n.compare(n.size() - ext.size(), ext.size(), ext) == 0)
        names.push_back(n.substr(0, n.size() - ext.size()));
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  std::string joined;
  for (const auto& n : names) joined += (joined.empty() ? "" : ", ") + n;
  return joined;
}

std::vector<SourceError> CheckMissionNames(const Scenario& s, const std::string& rpl_dir) {
  std::vector<SourceError> errors;
  for (std::size_t i = 0; i < s.missions.size(); ++i) {
    const MissionSpec& m = s.missions[i];
    const bool rpl = m.language == "rpl";
    const std::string dir = rpl_dir + (rpl ? "/plans" : "/missions");
    const std::string ext = rpl ? ".rpl" : ".nc";
    if (std::ifstream(dir + "/" + m.name.text + ext)) continue;
    const std::string known = FileStems(dir, ext);
    errors.push_back({m.name.where, "missions[" + std::to_string(i) + "].name: no shipped " +
                                        (rpl ? "RPL plan '" : "Noreils-Chatila mission '") +
                                        m.name.text + "' in " + dir + " (there are: " + known +
                                        ")"});
  }
  return errors;
}

std::string DemoParametersYaml(const Scenario& s, const std::string& file) {
  std::ostringstream out;
  out.precision(17);
  out << "doors_to_close: " << Joined(s.doors_to_close) << "\n";
  if (!s.missions.empty()) {
    YAML::Emitter e;
    e << YAML::DoubleQuoted << file;
    out << "missions_file: " << e.c_str() << "\n";
  } else if (s.tasks.empty()) {
    out << "goals: " << Joined(s.goals) << "\n";
  } else {
    out << "tasks: " << Joined(s.tasks) << "\n";
  }
  out << "leg_timeout_s: " << s.leg_timeout_s << "\n";
  out << "goal_tolerance_m: " << s.goal_tolerance_m << "\n";
  return out.str();
}

}  // namespace spott_launch
