# SPDX-License-Identifier: LGPL-3.0-or-later
# cmake --install: the public headers, the component libraries libexbsp_core, libexbsp_render
# and libexbsp_gpl (static, and shared with EXBSP_BUILD_SHARED), the exbsp command line, a CMake
# package (find_package(exbsp [COMPONENTS core render gpl openmesh])) and pkg-config files.
#
# The public headers are the folder include/exbsp/, installed as it is under
# <prefix>/include/exbsp/, with the generated <exbsp/core/version.h> and <exbsp/core/export.h>.
# They include each other as <exbsp/module/x.h>, so a consumer's include path holds
# <prefix>/include alone. No installed header includes CGAL (but adapters/cgal_face_graph.h),
# Boost, OpenMP, nlohmann-json or a private exbsp header (src/): tests/install_consumer.sh
# compiles each one alone against the installed tree, and tests/test_layout.cpp checks the
# include lines. adapters/openmesh.h is installed only when OpenMesh was found.
include(CMakePackageConfigHelpers)
set(EXBSP_INSTALL_EXCLUDE)
if(NOT EXBSP_HAVE_OPENMESH)
  list(APPEND EXBSP_INSTALL_EXCLUDE PATTERN openmesh.h EXCLUDE)
endif()
if(NOT EXBSP_BUILD_RENDER)  # no render library: no view headers, and exbsp.h includes them
  list(APPEND EXBSP_INSTALL_EXCLUDE PATTERN view EXCLUDE PATTERN exbsp.h EXCLUDE)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/exbsp ${PROJECT_BINARY_DIR}/include/exbsp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h" ${EXBSP_INSTALL_EXCLUDE})

# One export set per component, so that exbspConfig.cmake loads only the requested ones.
foreach(component ${EXBSP_COMPONENTS})
  set(targets)
  foreach(variant ${EXBSP_VARIANTS})
    list(APPEND targets exbsp_${component}_${variant})
  endforeach()
  install(TARGETS ${targets} EXPORT exbsp_${component}_targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(EXPORT exbsp_${component}_targets NAMESPACE exbsp:: FILE exbsp_${component}_targets.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
endforeach()
if(EXBSP_BUILD_RENDER)
  install(TARGETS exbsp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(FILES ${PROJECT_BINARY_DIR}/src/app/exbsp.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  install(FILES ${PROJECT_BINARY_DIR}/src/app/exbsp.bash
    DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME exbsp)
endif()

# exbspConfig.cmake re-finds the libraries the requested components link (GMP and MPFR; for
# the static render library also libpng, cairo and Clipper; for the static gpl library dxflib) with the same lookup files exbsp's
# build used, so the exported link interface names imported targets (exbsp::gmp, ...) and
# never this machine's absolute paths.
set(EXBSP_PACKAGE_STATIC ON)
set(EXBSP_PACKAGE_SHARED ${EXBSP_BUILD_SHARED})
set(EXBSP_PACKAGE_OPENMESH ${EXBSP_HAVE_OPENMESH})
set(EXBSP_PACKAGE_RENDER ${EXBSP_BUILD_RENDER})
string(REPLACE ";" " " EXBSP_PACKAGE_COMPONENTS "${EXBSP_COMPONENTS}")
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exbspConfig.cmake.in
  ${PROJECT_BINARY_DIR}/exbspConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/exbspConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/exbspConfig.cmake ${PROJECT_BINARY_DIR}/exbspConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/gmp.cmake ${PROJECT_SOURCE_DIR}/cmake/cairo.cmake ${PROJECT_SOURCE_DIR}/cmake/dxflib.cmake
  ${PROJECT_SOURCE_DIR}/cmake/polyclipping.cmake ${PROJECT_SOURCE_DIR}/cmake/imported_dependency.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
