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
set(spott_devel_include "${SPOTT_ROOT}/.ws/devel/include")
if(EXISTS "${spott_devel_include}/spott_msgs/NavigateGoal.h")
  add_library(spott_harmonic_planner_ros_fuzzcore STATIC
              "${SPOTT_ROOT}/spott_harmonic_planner/src/ros/conversions.cpp"
              "${SPOTT_ROOT}/spott_ros/src/pose_conversions.cpp")
  target_include_directories(spott_harmonic_planner_ros_fuzzcore PUBLIC
                             "${SPOTT_ROOT}/spott_ros/include" "${spott_devel_include}")
  target_compile_options(spott_harmonic_planner_ros_fuzzcore PRIVATE -fsanitize=fuzzer-no-link)
  target_link_libraries(spott_harmonic_planner_ros_fuzzcore PUBLIC spott_harmonic_planner_fuzzcore
                        spott_map_ros_fuzzcore roscpp_serialization rostime cpp_common)
  spott_add_fuzzer(navigate_goal_fuzz "${CMAKE_CURRENT_LIST_DIR}/navigate_goal_fuzz.cpp"
                   CORES spott_harmonic_planner_ros)
else()
  message(STATUS "navigate_goal_fuzz left out: no ${spott_devel_include} (run ./spott build)")
endif()
