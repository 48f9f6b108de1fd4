# A package's ROS-free core built outside catkin (the fuzz targets of tools/fuzz/, the sanitized
# cores of tools/sanitizer/), as the static library <pkg><SUFFIX>:
#   spott_core_library(<pkg> SUFFIX <suffix> [DIR <dir>] [SOURCES <file>...]
#                      [SUBDIRS <dir>...] [DEPENDS <core pkg>...] [LIBS <libs>...])
# builds <dir>/src/*.cpp (or only SOURCES, relative to <dir>) and <dir>/src/<sub>/*.cpp (never
# src/nodes, src/ros, src/render); <dir> defaults to <pkg>. DEPENDS names other cores of the same
# suffix. Needs SPOTT_ROOT and EIGEN3_INCLUDE_DIR. A second call for the same core does nothing.
function(spott_core_library pkg)
  cmake_parse_arguments(ARG "" "DIR;SUFFIX" "DEPENDS;LIBS;SUBDIRS;SOURCES" ${ARGN})
  set(target ${pkg}${ARG_SUFFIX})
  if(TARGET ${target})
    return()
  endif()
  if(NOT ARG_DIR)  # the package's directory when it is not named like the package
    set(ARG_DIR ${pkg})
  endif()
  if(ARG_SOURCES)  # a core that is a few files of a src/ that holds ROS code too
    list(TRANSFORM ARG_SOURCES PREPEND "${SPOTT_ROOT}/${ARG_DIR}/" OUTPUT_VARIABLE sources)
  else()
    file(GLOB sources "${SPOTT_ROOT}/${ARG_DIR}/src/*.cpp")
  endif()
  foreach(dir ${ARG_SUBDIRS})  # cores split into src/<dir>/
    file(GLOB more "${SPOTT_ROOT}/${ARG_DIR}/src/${dir}/*.cpp")
    list(APPEND sources ${more})
  endforeach()
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} PUBLIC "${SPOTT_ROOT}/${ARG_DIR}/include"
                             ${EIGEN3_INCLUDE_DIR})
  foreach(dep ${ARG_DEPENDS})
    target_link_libraries(${target} PUBLIC ${dep}${ARG_SUFFIX})
  endforeach()
  target_link_libraries(${target} PUBLIC ${ARG_LIBS})
endfunction()
