# libFuzzer target of spott_launch's scenario files (included by tools/fuzz/CMakeLists.txt). The
# package's directory is launch/; its ROS-free core is src/scenario.cpp (the rest of src/ is
# the demo's ROS layer).
spott_fuzz_core(spott_launch DIR launch SOURCES src/scenario.cpp src/leg_metrics.cpp
                DEPENDS robot_sim spott_tr_plus spott_map LIBS yaml-cpp)
spott_add_fuzzer(scenario_fuzz ${CMAKE_CURRENT_LIST_DIR}/scenario_fuzz.cpp CORES spott_launch)
