// Fuzzes the scenario reader (spott_launch/scenario.h) and what a good scenario turns into:
// robot_sim must read back the fault list the scenario hands it, and demo_report the tasks or
// goals, unchanged, or the file of the missions.
#include <cstddef>
#include <cstdint>
#include <string>

#include <yaml-cpp/yaml.h>

#include "fuzz_values.h"
#include "robot_sim/fault_events.h"
#include "spott_launch/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto r = spott_launch::ParseScenario(input, "fuzz.yaml");
  if (!r.ok()) return 0;
  const spott_launch::Scenario& s = *r.scenario;
  (void)spott_launch::LaunchArguments(s);
  (void)s.EffectiveTimeLimit();
  if (!s.faults_yaml.empty()) {
    const auto schedule = robot_sim::ParseFaultSchedule(s.faults_yaml, "faults.yaml");
    spott_fuzz::Check(schedule.ok() && schedule.events.size() == s.faults.size(), "scenario_fuzz",
                      "robot_sim reads the scenario's fault list back whole");
  }
  if (!s.missions.empty()) {  // demo_report reads them from the file: it must get its name
    const std::string file = "a dir/with \"quotes\": and colons.yaml";
    const YAML::Node params = YAML::Load(spott_launch::DemoParametersYaml(s, file));
    spott_fuzz::Check(
        params["missions_file"].as<std::string>() == file && !params["goals"] && !params["tasks"],
        "scenario_fuzz", "demo_report gets the missions' file and nothing else");
    return 0;
  }
  const YAML::Node params = YAML::Load(spott_launch::DemoParametersYaml(s));
  const auto& legs = s.tasks.empty() ? s.goals : s.tasks;
  const YAML::Node list = params[s.tasks.empty() ? "goals" : "tasks"];
  spott_fuzz::Check(list.IsSequence() && list.size() == legs.size(), "scenario_fuzz",
                    "demo_report gets every leg");
  for (std::size_t i = 0; i < legs.size(); ++i) {
    spott_fuzz::Check(list[i].as<std::string>() == legs[i].text, "scenario_fuzz",
                      "demo_report gets each leg's text unchanged");
  }
  return 0;
}
