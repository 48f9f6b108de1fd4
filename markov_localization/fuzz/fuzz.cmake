# libFuzzer targets of markov_localization's parsers (see tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_fuzz_core(markov_localization DEPENDS spott_map LIBS yaml-cpp pthread)
spott_add_fuzzer(map_file_fuzz ${CMAKE_CURRENT_LIST_DIR}/map_file_fuzz.cpp
                 CORES markov_localization)
