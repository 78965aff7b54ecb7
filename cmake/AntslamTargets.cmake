# Helpers shared by every component's CMakeLists.

# Warnings are per target (never global), so consumers of the installed package are unaffected.
function(antslam_set_warnings target)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    return()
  endif()
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion
                                           -Wshadow -Wnon-virtual-dtor)
endfunction()

# A compiled library of the project: public headers under include/, C++20, warnings, alias
# antslam::<name>. Compiled eight sources at a time (a unity build): each source parses the same
# Eigen, Ceres and engine headers, and CI builds every library four times (Release, two
# sanitizers, fuzzing) on two cores. So names local to a source must differ across the library.
function(antslam_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(antslam_${name} ${ARG_SOURCES})
  add_library(antslam::${name} ALIAS antslam_${name})
  set_target_properties(antslam_${name} PROPERTIES EXPORT_NAME ${name}
                                                   POSITION_INDEPENDENT_CODE ON UNITY_BUILD ON
                                                   UNITY_BUILD_BATCH_SIZE 8)
  target_compile_features(antslam_${name} PUBLIC cxx_std_20)
  target_include_directories(
    antslam_${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(antslam_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  antslam_set_warnings(antslam_${name})
endfunction()

# Marks targets for installation and export in the antslam CMake package.
function(antslam_install_targets)
  set_property(GLOBAL APPEND PROPERTY ANTSLAM_INSTALL_TARGETS ${ARGN})
endfunction()
