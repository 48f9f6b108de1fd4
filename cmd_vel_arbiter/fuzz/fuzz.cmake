# libFuzzer target of cmd_vel_arbiter (see tools/fuzz/CMakeLists.txt): the node's parameters.
spott_fuzz_core(cmd_vel_arbiter)
spott_add_parameter_fuzzer(cmd_vel_arbiter_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/cmd_vel_arbiter_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/cmd_vel_arbiter/config/cmd_vel_arbiter.yaml"
  SOURCES "${SPOTT_ROOT}/cmd_vel_arbiter/src/ros/parameters.cpp"
  CORES cmd_vel_arbiter)
