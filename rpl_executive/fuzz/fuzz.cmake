# libFuzzer targets of rpl_executive's parsers (included by tools/fuzz/CMakeLists.txt).
spott_fuzz_core(rpl_executive DEPENDS spott_text SUBDIRS rpl noreils_chatila)
spott_add_fuzzer(rpl_plan_fuzz ${CMAKE_CURRENT_LIST_DIR}/rpl_plan_fuzz.cpp CORES rpl_executive)
spott_add_fuzzer(rpl_run_fuzz ${CMAKE_CURRENT_LIST_DIR}/rpl_run_fuzz.cpp CORES rpl_executive)
spott_add_fuzzer(nc_mission_fuzz ${CMAKE_CURRENT_LIST_DIR}/nc_mission_fuzz.cpp CORES rpl_executive)
