# cmake --install: headers, static libraries and a CMake package config (find_package(exbsp)).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(EXBSP_INSTALL_TARGETS exbsp_options exbsp_gmp exbsp_cgal_flags exbsp_polyclipping exbsp_cairo
    exbsp_core exbsp_mesh exbsp_bsp exbsp_clip exbsp_view exbsp_scene)
install(TARGETS ${EXBSP_INSTALL_TARGETS} EXPORT exbspTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exbsp)
install(TARGETS exbsp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(module core mesh bsp clip view scene)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/${module}/
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exbsp/${module} FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/core/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exbsp/core)
install(EXPORT exbspTargets NAMESPACE exbsp:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exbspConfig.cmake.in
  ${PROJECT_BINARY_DIR}/exbspConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/exbspConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/exbspConfig.cmake ${PROJECT_BINARY_DIR}/exbspConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
