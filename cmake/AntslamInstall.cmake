# Installs the library targets and exports the CMake package `antslam` with one component per
# library, so that a downstream project finds only what it uses:
#   find_package(antslam REQUIRED COMPONENTS aco)   # the engine: nothing but the standard library
#   find_package(antslam REQUIRED COMPONENTS slamgraph tsp)
#   find_package(antslam REQUIRED)                  # every installed component
# Each target has its own export set (antslam-<component>-targets.cmake); antslamConfig.cmake
# loads a component after the components it links and finds only their packages.
include(CMakePackageConfigHelpers)

get_property(ANTSLAM_INSTALL_TARGETS GLOBAL PROPERTY ANTSLAM_INSTALL_TARGETS)
set(ANTSLAM_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/antslam)

set(ANTSLAM_INSTALLED_COMPONENTS "")
foreach(target IN LISTS ANTSLAM_INSTALL_TARGETS)
  get_target_property(component ${target} EXPORT_NAME)
  list(APPEND ANTSLAM_INSTALLED_COMPONENTS ${component})
  install(TARGETS ${target} EXPORT antslam-${component}-targets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(EXPORT antslam-${component}-targets NAMESPACE antslam::
          DESTINATION ${ANTSLAM_PACKAGE_DIR})
endforeach()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/antslamConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/antslamConfig.cmake
                              INSTALL_DESTINATION ${ANTSLAM_PACKAGE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/antslamConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/antslamConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/antslamConfigVersion.cmake
        DESTINATION ${ANTSLAM_PACKAGE_DIR})
