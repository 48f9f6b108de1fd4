# libFuzzer targets of spott_map (see tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_add_fuzzer(world_loader_fuzz "${CMAKE_CURRENT_LIST_DIR}/world_loader_fuzz.cpp" CORES spott_map)
spott_add_fuzzer(pose_text_fuzz "${CMAKE_CURRENT_LIST_DIR}/pose_text_fuzz.cpp" CORES spott_map)
