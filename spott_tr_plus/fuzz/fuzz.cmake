# libFuzzer targets of spott_tr_plus's parsers (included by tools/fuzz/CMakeLists.txt).
spott_fuzz_core(spott_tr_plus DEPENDS spott_map LIBS yaml-cpp SUBDIRS controller)
spott_add_fuzzer(tr_program_fuzz ${CMAKE_CURRENT_LIST_DIR}/tr_program_fuzz.cpp CORES spott_tr_plus)
spott_add_fuzzer(task_command_fuzz ${CMAKE_CURRENT_LIST_DIR}/task_command_fuzz.cpp CORES spott_tr_plus)
spott_add_fuzzer(tr_interpreter_fuzz ${CMAKE_CURRENT_LIST_DIR}/tr_interpreter_fuzz.cpp CORES spott_tr_plus)
# The parameters of tr_plus_node and tr_plus_controller (ROS-side: spott_ros's reader over
# XmlRpc; no workspace needed). CONFIG names one file; the fuzzer reads both.
spott_add_parameter_fuzzer(tr_plus_parameters_fuzz
  "${CMAKE_CURRENT_LIST_DIR}/tr_plus_parameters_fuzz.cpp"
  CONFIG "${SPOTT_ROOT}/spott_tr_plus/config/tr_plus_controller.yaml"
  SOURCES "${SPOTT_ROOT}/spott_tr_plus/src/ros/parameters.cpp"
  CORES spott_tr_plus)
target_compile_definitions(tr_plus_parameters_fuzz PRIVATE
  NODE_CONFIG_FILE="${SPOTT_ROOT}/spott_tr_plus/config/tr_plus_node.yaml"
  CONTROLLER_CONFIG_FILE="${SPOTT_ROOT}/spott_tr_plus/config/tr_plus_controller.yaml")

# tr_plus_node's external condition messages (src/ros/conversions.cpp): needs a built workspace
# for spott_msgs' headers.
spott_ros_fuzzcore(spott_tr_plus_ros HEADER spott_msgs/ConditionState.h
                   SOURCES "${SPOTT_ROOT}/spott_tr_plus/src/ros/conversions.cpp" CORES spott_tr_plus)
if(TARGET spott_tr_plus_ros_fuzzcore)
  spott_add_fuzzer(condition_state_fuzz "${CMAKE_CURRENT_LIST_DIR}/condition_state_fuzz.cpp" CORES spott_tr_plus_ros)
endif()

# The controller's sensor messages (src/ros/sensor_conversions.cpp) into its evidence grids.
spott_ros_fuzzcore(spott_tr_plus_sensors HEADER spott_msgs/RangeProfile.h
                   SOURCES "${SPOTT_ROOT}/spott_tr_plus/src/ros/sensor_conversions.cpp"
                   CORES spott_tr_plus spott_map_ros spott_ros_messages)
if(TARGET spott_tr_plus_sensors_fuzzcore)
  spott_add_fuzzer(controller_messages_fuzz "${CMAKE_CURRENT_LIST_DIR}/controller_messages_fuzz.cpp"
                   CORES spott_tr_plus_sensors)
endif()
