// Fuzzes the robot file reader and the URDF reading on top of urdfdom: the input is a robot
// YAML file, optionally followed by "\n<robot" and a URDF.
#include <cstddef>
#include <cstdint>
#include <string>

#include "robot_sim/robot_spec.h"

namespace {
const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="fuzz">
  <link name="base_link"><collision><geometry><cylinder radius="0.15" length="0.6"/></geometry></collision></link>
  <link name="sonar_1"/><joint name="j1" type="fixed"><parent link="base_link"/><child link="sonar_1"/><origin xyz="0.15 0 0.4"/></joint>
  <link name="sonar_2"/><joint name="j2" type="fixed"><parent link="base_link"/><child link="sonar_2"/><origin xyz="0 0.15 0.4" rpy="0 0 1.57"/></joint>
  <link name="laser"/><joint name="j3" type="fixed"><parent link="base_link"/><child link="laser"/><origin xyz="0.1 0 0.3"/></joint>
</robot>)";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto split = input.find("\n<robot");
  const std::string yaml = input.substr(0, split);
  const std::string urdf = split == std::string::npos ? kUrdf : input.substr(split + 1);
  const auto r = robot_sim::LoadRobotSpecFromStrings(yaml, "fuzz.yaml", urdf, "fuzz.urdf");
  if (r.ok() && r.spec->FindRing("sonar")) {
    volatile std::size_t n = r.spec->FindRing("sonar")->mounts.size();
    (void)n;
  }
  return 0;
}
