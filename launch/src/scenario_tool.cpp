// scenario_tool: checks a scenario file and writes what `./spott run` launches it with.
//   scenario_tool FILE [--worlds DIR] [--rpl-executive DIR] [--out DIR] [--seed N]
// Errors go to stderr as "file:line:column: message" (exit 1); usage errors exit 2. With --out
// it writes DIR/launch_args (roslaunch arguments, one per line), DIR/demo_params.yaml
// (demo_report's parameters), DIR/faults.yaml (robot_sim's ~faults, when the scenario has any)
// and DIR/time_limit_s. --seed replaces the scenario's seed (a suite runs one file with many).
// ROS-free.

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "spott_launch/scenario.h"
#include "spott_map/world_loader.h"

namespace {

int Usage(const std::string& why) {
  std::cerr << "scenario_tool: " << why
            << "\nusage: scenario_tool FILE [--worlds DIR] [--rpl-executive DIR] [--out DIR] "
               "[--seed N]\n";
  return 2;
}

/// An error at `where` when `dir` has no NAME.yaml for `name`, listing what it has.
bool Known(const spott_launch::Located& name, const std::string& what, const std::string& dir) {
  if (name.text.empty() || std::ifstream(dir + "/" + name.text + ".yaml")) return true;
  std::cerr << spott_map::SourceError{name.where, what + ": no " + what + " '" + name.text +
                                                      "' (there are: " +
                                                      spott_launch::FileStems(dir, ".yaml") + ")"}
                   .ToString()
            << "\n";
  return false;
}

bool Write(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) std::cerr << "scenario_tool: cannot write " << path << "\n";
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  std::string file, worlds = SPOTT_WORLDS_DIR, out_dir, rpl_dir = SPOTT_RPL_EXECUTIVE_DIR;
  std::optional<int> seed;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--worlds" || arg == "--out" || arg == "--rpl-executive") && i + 1 < argc) {
      (arg == "--worlds" ? worlds : arg == "--out" ? out_dir : rpl_dir) = argv[++i];
    } else if (arg == "--seed" && i + 1 < argc) {
      const std::string value = argv[++i];
      if (value.empty() || value.size() > 9 ||
          value.find_first_not_of("0123456789") != std::string::npos) {
        return Usage("--seed must be a whole number from 0 to 999999999, not '" + value + "'");
      }
      seed = std::stoi(value);
    } else if (arg == "-h" || arg == "--help") {
      std::cout << "usage: scenario_tool FILE [--worlds DIR] [--rpl-executive DIR] [--out DIR] "
                   "[--seed N]\n";
      return 0;
    } else if (!arg.empty() && arg[0] == '-') {
      return Usage("unknown option " + arg);
    } else if (file.empty()) {
      file = arg;
    } else {
      return Usage("one scenario file only");
    }
  }
  if (file.empty()) return Usage("no scenario file");
  std::ifstream in(file);
  if (!in) {
    std::cerr << file << ": cannot read the file\n";
    return 1;
  }
  std::stringstream text;
  text << in.rdbuf();
  const auto parsed = spott_launch::ParseScenario(text.str(), file);
  if (!parsed.ok()) {
    std::cerr << spott_map::FormatErrors(parsed.errors) << "\n";
    return 1;
  }
  spott_launch::Scenario s = *parsed.scenario;
  if (seed) s.seed = *seed;
  if (!Known(s.world, "world", worlds) || !Known(s.robot, "robot", SPOTT_ROBOTS_DIR)) return 1;
  const auto world = spott_map::LoadWorldFile(worlds + "/" + s.world.text + ".yaml");
  if (!world.ok()) {
    std::cerr << spott_map::FormatErrors(world.errors) << "\n";
    return 1;
  }
  auto errors = spott_launch::CheckAgainstWorld(s, *world.world);
  const auto names = spott_launch::CheckMissionNames(s, rpl_dir);
  errors.insert(errors.end(), names.begin(), names.end());
  if (!errors.empty()) {
    std::cerr << spott_map::FormatErrors(errors) << "\n";
    return 1;
  }
  if (!out_dir.empty()) {
    // demo_report reads the missions from the file itself: by a path that holds anywhere.
    char* real = realpath(file.c_str(), nullptr);
    const std::string absolute = real ? real : file;
    free(real);
    std::string args;
    for (const auto& a : spott_launch::LaunchArguments(s)) args += a + "\n";
    std::ostringstream limit;
    limit << s.EffectiveTimeLimit() << "\n";
    if (!Write(out_dir + "/launch_args", args) ||
        !Write(out_dir + "/demo_params.yaml", spott_launch::DemoParametersYaml(s, absolute)) ||
        !Write(out_dir + "/faults.yaml", s.faults_yaml.empty() ? "faults: []\n" : s.faults_yaml) ||
        !Write(out_dir + "/time_limit_s", limit.str())) {
      return 1;
    }
  }
  std::cout << file << ": world " << s.world.text << ", robot "
            << (s.robot.text.empty() ? "(the world's)" : s.robot.text) << ", "
            << (s.tasks.empty() ? std::to_string(s.goals.size()) + " goals"
                                : std::to_string(s.tasks.size()) + " tasks")
            << ", " << s.faults.size() << " faults, seed " << s.seed << ", time limit "
            << s.EffectiveTimeLimit() << " s (simulated)\n";
  return 0;
}
