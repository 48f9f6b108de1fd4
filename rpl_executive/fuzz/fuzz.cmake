# libFuzzer targets of rpl_executive's parsers (included by tools/fuzz/CMakeLists.txt).
spott_fuzz_core(rpl_executive DEPENDS spott_text SUBDIRS rpl noreils_chatila)
spott_add_fuzzer(rpl_plan_fuzz ${CMAKE_CURRENT_LIST_DIR}/rpl_plan_fuzz.cpp CORES rpl_executive)
spott_add_fuzzer(rpl_run_fuzz ${CMAKE_CURRENT_LIST_DIR}/rpl_run_fuzz.cpp CORES rpl_executive)
spott_add_fuzzer(nc_mission_fuzz ${CMAKE_CURRENT_LIST_DIR}/nc_mission_fuzz.cpp CORES rpl_executive)
# The node's parameters (ROS-side: spott_ros's reader over XmlRpc; no workspace needed).
spott_add_parameter_fuzzer(rpl_executive_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/rpl_executive_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/rpl_executive/config/rpl_executive.yaml"
  SOURCES "${SPOTT_ROOT}/rpl_executive/src/ros/parameters.cpp"
  CORES rpl_executive)

# The node's inbound messages (src/ros/conversions.cpp: the edge's checks, then the conversions
# and the cores): needs a built workspace for spott_msgs' headers.
spott_ros_fuzzcore(rpl_executive_ros HEADER spott_msgs/MissionAction.h
                   SOURCES "${SPOTT_ROOT}/rpl_executive/src/ros/conversions.cpp"
                           "${SPOTT_ROOT}/spott_ros/src/pose_conversions.cpp"
                   INCLUDES "${SPOTT_ROOT}/spott_ros/include" "${SPOTT_ROOT}/rpl_executive/src/ros"
                   CORES rpl_executive spott_map_ros spott_ros_messages)
if(TARGET rpl_executive_ros_fuzzcore)
  spott_add_fuzzer(executive_messages_fuzz "${CMAKE_CURRENT_LIST_DIR}/executive_messages_fuzz.cpp"
                   CORES rpl_executive_ros)
endif()
