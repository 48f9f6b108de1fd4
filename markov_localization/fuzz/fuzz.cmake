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
spott_ros_fuzzcore(markov_localization_ros HEADER spott_msgs/RangeProfile.h
                   SOURCES "${SPOTT_ROOT}/markov_localization/src/ros/conversions.cpp"
                   CORES markov_localization spott_map_ros spott_ros_messages)
if(TARGET markov_localization_ros_fuzzcore)
  spott_add_fuzzer(sensor_messages_fuzz "${CMAKE_CURRENT_LIST_DIR}/sensor_messages_fuzz.cpp"
                   CORES markov_localization_ros)
endif()
spott_add_parameter_fuzzer(sensed_map_localization_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/sensed_map_localization_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/markov_localization/config/sensed_map_localization.yaml"
  SOURCES "${SPOTT_ROOT}/markov_localization/src/ros/sensed_map_parameters.cpp"
          "${SPOTT_ROOT}/markov_localization/src/ros/parameters.cpp"
  CORES markov_localization)
