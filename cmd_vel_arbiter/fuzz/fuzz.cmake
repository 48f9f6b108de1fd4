# libFuzzer targets of cmd_vel_arbiter (see tools/fuzz/CMakeLists.txt): the node's parameters,
# its message conversions and inputs.
spott_fuzz_core(cmd_vel_arbiter)
spott_add_parameter_fuzzer(cmd_vel_arbiter_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/cmd_vel_arbiter_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/cmd_vel_arbiter/config/cmd_vel_arbiter.yaml"
  SOURCES "${SPOTT_ROOT}/cmd_vel_arbiter/src/ros/parameters.cpp"
  CORES cmd_vel_arbiter)

# The RangeRing and LaserScan conversions of the clearance cap and every input of the arbiter (twists, bumper
# and sonar rings, takes, limits) in any order: needs a built workspace for spott_msgs' headers.
spott_ros_fuzzcore(cmd_vel_arbiter_ros HEADER spott_msgs/RangeRing.h
                   SOURCES "${SPOTT_ROOT}/cmd_vel_arbiter/src/ros/conversions.cpp"
                           "${SPOTT_ROOT}/spott_ros/src/markers.cpp"
                   INCLUDES "${SPOTT_ROOT}/spott_ros/include" CORES cmd_vel_arbiter)
if(TARGET cmd_vel_arbiter_ros_fuzzcore)
  spott_add_fuzzer(range_ring_fuzz "${CMAKE_CURRENT_LIST_DIR}/range_ring_fuzz.cpp" CORES cmd_vel_arbiter_ros)
  spott_add_fuzzer(laser_scan_fuzz "${CMAKE_CURRENT_LIST_DIR}/laser_scan_fuzz.cpp" CORES cmd_vel_arbiter_ros)
  spott_add_fuzzer(arbiter_inputs_fuzz "${CMAKE_CURRENT_LIST_DIR}/arbiter_inputs_fuzz.cpp" CORES cmd_vel_arbiter_ros)
endif()
