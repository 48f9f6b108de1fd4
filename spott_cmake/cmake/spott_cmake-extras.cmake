# Build conventions of every SPOTT-ROS package, included by find_package(catkin REQUIRED
# COMPONENTS spott_cmake ...) in the package's own directory scope (CONTRIBUTING.md).
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
add_compile_options(-Wall -Wextra)
# ./spott test --sanitize configures SPOTT_SANITIZE_FLAGS (ASan + UBSan) in a workspace of its
# own: every target of the package, libraries, nodes and tests alike, is built and linked with it.
if(SPOTT_SANITIZE_FLAGS)
  add_compile_options(${SPOTT_SANITIZE_FLAGS})
  add_link_options(${SPOTT_SANITIZE_FLAGS})
endif()
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE RelWithDebInfo)
endif()
# RelWithDebInfo keeps line tables only (-g1): backtraces, perf and gdb breakpoints still name
# file and line, and the build takes a third less time than with -g (measured on the 2-core CI
# machine: 33.5 s -> 23.6 s for tr_plus_controller_node.cpp). -DSPOTT_FULL_DEBUG_INFO=ON brings
# back -g for a session in gdb that needs local variables.
option(SPOTT_FULL_DEBUG_INFO "RelWithDebInfo with -g (variables) instead of -g1 (lines)" OFF)
if(NOT SPOTT_FULL_DEBUG_INFO)
  string(REGEX REPLACE "(^| )-g( |$)" "\\1-g1\\2" CMAKE_CXX_FLAGS_RELWITHDEBINFO
         "${CMAKE_CXX_FLAGS_RELWITHDEBINFO}")
  string(REGEX REPLACE "(^| )-g( |$)" "\\1-g1\\2" CMAKE_C_FLAGS_RELWITHDEBINFO
         "${CMAKE_C_FLAGS_RELWITHDEBINFO}")
endif()

# Test sources (the package's test/ directory) compile at -O0: they are a third of CI's build
# time, while every gtest of the suite runs in about 20 s in all and the rostests' time is the
# simulated robot's. The code under test (libraries, nodes) keeps the build type's -O2.
# -DSPOTT_OPTIMIZED_TESTS=ON compiles them like the rest.
option(SPOTT_OPTIMIZED_TESTS "compile test/ sources with the build type's optimization" OFF)
if(NOT SPOTT_OPTIMIZED_TESTS)
  file(GLOB_RECURSE _spott_test_sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/test/*.cpp")
  set_source_files_properties(${_spott_test_sources} PROPERTIES COMPILE_OPTIONS -O0)
endif()

# spott_catkin_package(CORE <core library target> <catkin_package arguments>...)
# catkin_package() plus an export of the ROS-free core library alone: a consumer that must not
# link ROS (another core) links ${<pkg>_CORE_LIBRARIES}; ${<pkg>_LIBRARIES} (and
# ${catkin_LIBRARIES}) keep every exported library, the ROS layer included.
macro(spott_catkin_package)
  cmake_parse_arguments(_spott "" "CORE" "" ${ARGN})
  set(_spott_extras "")
  if(_spott_CORE)
    set(_spott_extras "${CMAKE_CURRENT_BINARY_DIR}/${PROJECT_NAME}_core-extras.cmake")
    file(WRITE "${_spott_extras}"
         "# ${PROJECT_NAME}'s ROS-free core alone (spott_catkin_package, spott_cmake).\n"
         "if(TARGET ${_spott_CORE})\n"
         "  set(${PROJECT_NAME}_CORE_LIBRARIES ${_spott_CORE})\n"
         "else()\n"
         "  find_library(${PROJECT_NAME}_CORE_LIBRARIES ${_spott_CORE}\n"
         "               PATHS \"\${${PROJECT_NAME}_DIR}/../../../lib\" NO_DEFAULT_PATH)\n"
         "endif()\n")
  endif()
  catkin_package(${_spott_UNPARSED_ARGUMENTS} CFG_EXTRAS ${_spott_extras})
endmacro()
