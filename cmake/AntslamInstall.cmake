# Installs the library targets and exports the CMake package `antslam`, so that a downstream
# project can write find_package(antslam) and link antslam::aco.
include(CMakePackageConfigHelpers)

get_property(ANTSLAM_INSTALL_TARGETS GLOBAL PROPERTY ANTSLAM_INSTALL_TARGETS)

install(TARGETS ${ANTSLAM_INSTALL_TARGETS} EXPORT antslamTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT antslamTargets NAMESPACE antslam::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/antslam)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/antslamConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/antslamConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/antslam)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/antslamConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/antslamConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/antslamConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/antslam)
