# SPDX-License-Identifier: LGPL-3.0-or-later
# cmake --install: the public headers, the component libraries libexbsp_core, libexbsp_render
# and libexbsp_gpl (static, and shared with EXBSP_BUILD_SHARED), the exbsp command line, a CMake
# package (find_package(exbsp [COMPONENTS core render gpl openmesh])) and pkg-config files.
#
# Only the headers listed here are installed, under <prefix>/include/exbsp/<module>/; they
# include each other by relative paths ("../mesh/soup.h"), so a consumer's include path holds
# <prefix>/include alone and #include <exbsp/bsp/engine.h> (or <exbsp/exbsp.h>) works. No
# installed header includes CGAL, Boost, OpenMP, nlohmann-json or a private exbsp header
# (tests/install_consumer.sh compiles each one alone against the installed tree). The others
# (bsp_tree_impl.h, kernel_*.h, geometry_*.h, reader_util.h, ...) stay in src/.
include(CMakePackageConfigHelpers)
set(EXBSP_PUBLIC_HEADERS
  core/errors.h
  mesh/soup.h mesh/mesh_io.h mesh/gmp_memory.h
  bsp/engine.h bsp/traversal.h bsp/exact_gmp.h
  clip/clip_types.h clip/bbox.h clip/cohen_sutherland.h clip/liang_barsky.h
  clip/sutherland_hodgman.h clip/convex_region.h clip/homogeneous.h clip/homogeneous_segment.h
  clip/section.h clip/section_cap.h clip/convex_hull.h
  view/matrix.h view/camera.h view/phigs.h view/projection.h view/viewport.h view/transforms.h
  view/image.h view/png_io.h view/effect_settings.h view/screen_line.h view/screen_polygon.h
  view/vector_drawing.h view/sample_shader.h view/pipeline.h view/stages.h view/standard_pipeline.h
  view/trackball.h view/bezier.h
  scene/procedural.h
  adapters/triangle_list.h adapters/cgal_face_graph.h
  exbsp.h)
if(EXBSP_HAVE_OPENMESH)
  list(APPEND EXBSP_PUBLIC_HEADERS adapters/openmesh.h)
endif()
foreach(header ${EXBSP_PUBLIC_HEADERS})
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exbsp/${dir})
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/core/version.h ${PROJECT_BINARY_DIR}/include/exbsp/core/export.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exbsp/core)

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
install(TARGETS exbsp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# exbspConfig.cmake re-finds the libraries the requested components link (GMP and MPFR; for
# the static render library also libpng, cairo and Clipper; for the static gpl library dxflib) with the same lookup files exbsp's
# build used, so the exported link interface names imported targets (exbsp::gmp, ...) and
# never this machine's absolute paths.
set(EXBSP_PACKAGE_STATIC ON)
set(EXBSP_PACKAGE_SHARED ${EXBSP_BUILD_SHARED})
set(EXBSP_PACKAGE_OPENMESH ${EXBSP_HAVE_OPENMESH})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exbspConfig.cmake.in
  ${PROJECT_BINARY_DIR}/exbspConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/exbspConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/exbspConfig.cmake ${PROJECT_BINARY_DIR}/exbspConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/gmp.cmake ${PROJECT_SOURCE_DIR}/cmake/cairo.cmake ${PROJECT_SOURCE_DIR}/cmake/dxflib.cmake
  ${PROJECT_SOURCE_DIR}/cmake/polyclipping.cmake ${PROJECT_SOURCE_DIR}/cmake/imported_dependency.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/exbsp)
