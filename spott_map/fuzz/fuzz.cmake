# libFuzzer targets of spott_map (see tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_add_fuzzer(world_loader_fuzz "${CMAKE_CURRENT_LIST_DIR}/world_loader_fuzz.cpp" CORES spott_map)
spott_add_fuzzer(pose_text_fuzz "${CMAKE_CURRENT_LIST_DIR}/pose_text_fuzz.cpp" CORES spott_map)

# The message conversions (src/ros/) with ROS's headers and the workspace's generated messages:
# needs a built workspace (./spott build) for spott_msgs' headers.
set(spott_devel_include "${SPOTT_ROOT}/.ws/devel/include")
if(EXISTS "${spott_devel_include}/spott_msgs/MapUpdate.h")
  add_library(spott_map_ros_fuzzcore STATIC "${SPOTT_ROOT}/spott_map/src/ros/conversions.cpp"
              "${SPOTT_ROOT}/spott_map/src/ros/map_update.cpp"
              "${SPOTT_ROOT}/spott_ros/src/markers.cpp")
  target_include_directories(spott_map_ros_fuzzcore PUBLIC "${SPOTT_ROOT}/spott_ros/include"
                             "${spott_devel_include}")
  target_compile_options(spott_map_ros_fuzzcore PRIVATE -fsanitize=fuzzer-no-link)
  target_link_libraries(spott_map_ros_fuzzcore PUBLIC spott_map_fuzzcore roscpp_serialization
                        rostime cpp_common)
  spott_add_fuzzer(map_messages_fuzz "${CMAKE_CURRENT_LIST_DIR}/map_messages_fuzz.cpp"
                   CORES spott_map_ros)
else()
  message(STATUS "map_messages_fuzz left out: no ${spott_devel_include} (run ./spott build)")
endif()

# world_server's parameters (ROS-side: spott_ros's reader over XmlRpc; no workspace needed).
spott_add_parameter_fuzzer(world_server_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/world_server_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/spott_map/config/world_server.yaml"
  SOURCES "${SPOTT_ROOT}/spott_map/src/ros/world_server_parameters.cpp"
  CORES spott_map)
