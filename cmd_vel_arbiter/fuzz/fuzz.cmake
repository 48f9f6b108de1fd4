# libFuzzer targets of cmd_vel_arbiter (see tools/fuzz/CMakeLists.txt): the node's parameters,
# its message conversions and inputs.
spott_fuzz_core(cmd_vel_arbiter)
spott_add_parameter_fuzzer(cmd_vel_arbiter_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/cmd_vel_arbiter_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/cmd_vel_arbiter/config/cmd_vel_arbiter.yaml"
  SOURCES "${SPOTT_ROOT}/cmd_vel_arbiter/src/ros/parameters.cpp"
  CORES cmd_vel_arbiter)

# The RangeRing conversion of the clearance cap: needs a built workspace for spott_msgs' headers.
set(spott_devel_include "${SPOTT_ROOT}/.ws/devel/include")
if(EXISTS "${spott_devel_include}/spott_msgs/RangeRing.h")
  add_library(cmd_vel_arbiter_ros_fuzzcore STATIC
              "${SPOTT_ROOT}/cmd_vel_arbiter/src/ros/conversions.cpp")
  target_include_directories(cmd_vel_arbiter_ros_fuzzcore PUBLIC "${spott_devel_include}")
  target_compile_options(cmd_vel_arbiter_ros_fuzzcore PRIVATE -fsanitize=fuzzer-no-link)
  target_link_libraries(cmd_vel_arbiter_ros_fuzzcore PUBLIC cmd_vel_arbiter_fuzzcore
                        roscpp_serialization rostime cpp_common)
  spott_add_fuzzer(range_ring_fuzz "${CMAKE_CURRENT_LIST_DIR}/range_ring_fuzz.cpp"
                   CORES cmd_vel_arbiter_ros)
  # Every input of the arbiter (twists, bumper and sonar rings, takes, limits) in any order.
  spott_add_fuzzer(arbiter_inputs_fuzz "${CMAKE_CURRENT_LIST_DIR}/arbiter_inputs_fuzz.cpp"
                   CORES cmd_vel_arbiter_ros)
else()
  message(STATUS "range_ring_fuzz, arbiter_inputs_fuzz left out: no ${spott_devel_include}")
endif()
