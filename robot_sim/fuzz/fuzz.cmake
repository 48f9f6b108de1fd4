# libFuzzer targets of robot_sim's parsers (see tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_fuzz_core(robot_sim DEPENDS spott_map
                LIBS yaml-cpp BulletCollision LinearMath octomap octomath urdfdom_model)
target_include_directories(robot_sim_fuzzcore SYSTEM PUBLIC /usr/include/bullet)
spott_add_fuzzer(robot_file_fuzz ${CMAKE_CURRENT_LIST_DIR}/robot_file_fuzz.cpp CORES robot_sim)
spott_add_fuzzer(fault_schedule_fuzz ${CMAKE_CURRENT_LIST_DIR}/fault_schedule_fuzz.cpp
                 CORES robot_sim)
# The node's parameters and its `faults` list (ROS-side: spott_ros's reader over XmlRpc).
spott_add_parameter_fuzzer(robot_sim_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/robot_sim_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/robot_sim/config/robot_sim.yaml"
  SOURCES "${SPOTT_ROOT}/robot_sim/src/ros/parameters.cpp"
  CORES robot_sim)
