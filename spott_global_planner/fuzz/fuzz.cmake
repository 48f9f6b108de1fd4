# libFuzzer targets of spott_global_planner (see tools/fuzz/CMakeLists.txt). The package reads no
# files; its input from outside is the room/door graph, features, robot, goal and window, which
# graph_projection_fuzz builds from the fuzzer's bytes, and the node's parameters
# (global_planner_parameters_fuzz).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_fuzz_core(spott_global_planner DEPENDS spott_map)
spott_add_fuzzer(graph_projection_fuzz ${CMAKE_CURRENT_LIST_DIR}/graph_projection_fuzz.cpp
                 CORES spott_global_planner)
spott_add_parameter_fuzzer(global_planner_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/global_planner_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/spott_global_planner/config/global_planner.yaml"
  SOURCES "${SPOTT_ROOT}/spott_global_planner/src/ros/parameters.cpp"
  CORES spott_global_planner)
