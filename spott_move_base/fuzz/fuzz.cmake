# libFuzzer target of spott_move_base (see tools/fuzz/CMakeLists.txt): the node's parameters
# (the package has no ROS-free core; its parameters need spott_ros only).
spott_add_parameter_fuzzer(move_base_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/move_base_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/spott_move_base/config/move_base.yaml"
  SOURCES "${SPOTT_ROOT}/spott_move_base/src/parameters.cpp")
target_include_directories(move_base_parameters_fuzz PRIVATE "${SPOTT_ROOT}/spott_move_base/include")
