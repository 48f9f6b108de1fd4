# libFuzzer targets of spott_harmonic_planner (see tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_fuzz_core(spott_harmonic_planner DEPENDS spott_map)

# The node's parameters (ROS-side: spott_ros's reader over XmlRpc; no workspace needed).
spott_add_parameter_fuzzer(harmonic_planner_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/harmonic_planner_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/spott_harmonic_planner/config/harmonic_planner.yaml"
  SOURCES "${SPOTT_ROOT}/spott_harmonic_planner/src/ros/parameters.cpp"
  CORES spott_harmonic_planner)

# The Navigate goal conversion, with ROS's headers and the workspace's generated messages
# (./spott build first).
spott_ros_fuzzcore(spott_harmonic_planner_ros HEADER spott_msgs/NavigateGoal.h
                   SOURCES "${SPOTT_ROOT}/spott_harmonic_planner/src/ros/conversions.cpp"
                           "${SPOTT_ROOT}/spott_ros/src/pose_conversions.cpp"
                   INCLUDES "${SPOTT_ROOT}/spott_ros/include" CORES spott_harmonic_planner spott_map_ros)
if(TARGET spott_harmonic_planner_ros_fuzzcore)
  spott_add_fuzzer(navigate_goal_fuzz "${CMAKE_CURRENT_LIST_DIR}/navigate_goal_fuzz.cpp" CORES spott_harmonic_planner_ros)
endif()
