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

# The service requests and velocity commands as the node takes them (conversions, then
# ApplyFaultEvent / SetCommand on a simulator): needs a built workspace for spott_msgs' headers.
spott_ros_fuzzcore(robot_sim_ros HEADER spott_msgs/Kidnap.h
                   SOURCES "${SPOTT_ROOT}/robot_sim/src/ros/conversions.cpp"
                           "${SPOTT_ROOT}/spott_ros/src/markers.cpp"
                   INCLUDES "${SPOTT_ROOT}/spott_ros/include" /usr/include/bullet CORES robot_sim)
if(TARGET robot_sim_ros_fuzzcore)
  spott_add_fuzzer(sim_requests_fuzz "${CMAKE_CURRENT_LIST_DIR}/sim_requests_fuzz.cpp"
                   CORES robot_sim_ros)
  target_compile_definitions(sim_requests_fuzz PRIVATE SPOTT_ROOT="${SPOTT_ROOT}")
endif()
