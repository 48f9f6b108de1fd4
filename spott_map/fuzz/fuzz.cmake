# libFuzzer targets of spott_map (see tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_map LIBS yaml-cpp)
spott_add_fuzzer(world_loader_fuzz "${CMAKE_CURRENT_LIST_DIR}/world_loader_fuzz.cpp" CORES spott_map)
spott_add_fuzzer(pose_text_fuzz "${CMAKE_CURRENT_LIST_DIR}/pose_text_fuzz.cpp" CORES spott_map)

# The message conversions (src/ros/) with ROS's headers and the workspace's generated messages:
# needs a built workspace (./spott build) for spott_msgs' headers.
spott_ros_fuzzcore(spott_map_ros HEADER spott_msgs/MapUpdate.h
                   SOURCES "${SPOTT_ROOT}/spott_map/src/ros/conversions.cpp"
                           "${SPOTT_ROOT}/spott_map/src/ros/map_update.cpp" "${SPOTT_ROOT}/spott_ros/src/markers.cpp"
                   INCLUDES "${SPOTT_ROOT}/spott_ros/include" CORES spott_map)
if(TARGET spott_map_ros_fuzzcore)
  spott_add_fuzzer(map_messages_fuzz "${CMAKE_CURRENT_LIST_DIR}/map_messages_fuzz.cpp" CORES spott_map_ros)
endif()

# world_server's parameters (ROS-side: spott_ros's reader over XmlRpc; no workspace needed).
spott_add_parameter_fuzzer(world_server_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/world_server_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/spott_map/config/world_server.yaml"
  SOURCES "${SPOTT_ROOT}/spott_map/src/ros/world_server_parameters.cpp"
  CORES spott_map)
