# libFuzzer targets of spott_tr_plus's parsers (included by tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_tr_plus DEPENDS spott_map LIBS yaml-cpp)
spott_add_fuzzer(tr_program_fuzz ${CMAKE_CURRENT_LIST_DIR}/tr_program_fuzz.cpp CORES spott_tr_plus)
spott_add_fuzzer(task_command_fuzz ${CMAKE_CURRENT_LIST_DIR}/task_command_fuzz.cpp CORES spott_tr_plus)
spott_add_fuzzer(tr_interpreter_fuzz ${CMAKE_CURRENT_LIST_DIR}/tr_interpreter_fuzz.cpp CORES spott_tr_plus)
