# libFuzzer targets of markov_localization's parsers (see tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_fuzz_core(markov_localization DEPENDS spott_map LIBS yaml-cpp pthread)
spott_add_fuzzer(map_file_fuzz ${CMAKE_CURRENT_LIST_DIR}/map_file_fuzz.cpp
                 CORES markov_localization)
# The node's parameters (ROS-side: spott_ros's reader over XmlRpc; no workspace needed).
spott_add_parameter_fuzzer(markov_localization_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/markov_localization_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/markov_localization/config/markov_localization.yaml"
  SOURCES "${SPOTT_ROOT}/markov_localization/src/ros/parameters.cpp"
  CORES markov_localization)

# The node's inbound message conversions (src/ros/conversions.cpp: LaserScan, RangeProfile,
# OccupancyGrid): needs a built workspace for spott_msgs' headers.
set(spott_devel_include "${SPOTT_ROOT}/.ws/devel/include")
if(EXISTS "${spott_devel_include}/spott_msgs/RangeProfile.h")
  add_library(markov_localization_ros_fuzzcore STATIC
              "${SPOTT_ROOT}/markov_localization/src/ros/conversions.cpp")
  target_include_directories(markov_localization_ros_fuzzcore PUBLIC "${spott_devel_include}")
  target_compile_options(markov_localization_ros_fuzzcore PRIVATE -fsanitize=fuzzer-no-link)
  # spott_map_ros_fuzzcore: defined by spott_map/fuzz/fuzz.cmake (resolved at generation).
  target_link_libraries(markov_localization_ros_fuzzcore PUBLIC markov_localization_fuzzcore
                        spott_map_ros_fuzzcore roscpp_serialization rostime cpp_common)
  spott_add_fuzzer(sensor_messages_fuzz "${CMAKE_CURRENT_LIST_DIR}/sensor_messages_fuzz.cpp"
                   CORES markov_localization_ros)
else()
  message(STATUS "sensor_messages_fuzz left out: no ${spott_devel_include} (run ./spott build)")
endif()
