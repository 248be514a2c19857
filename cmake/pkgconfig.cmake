# SPDX-License-Identifier: LGPL-3.0-or-later
# pkg-config modules, one per library component, installed into <libdir>/pkgconfig:
#   exbsp-core    -lexbsp_core    Requires gmpxx; private: gmp, mpfr, the OpenMP flags
#   exbsp-render  -lexbsp_render  Requires exbsp-core; private: libpng, cairo, polyclipping
#   exbsp-gpl     -lexbsp_gpl     Requires exbsp-core; private: dxflib (GPL-3.0-or-later, docs/licence.md)
# `pkg-config --cflags --libs exbsp-core` links the shared library; with EXBSP_BUILD_SHARED=OFF
# use `pkg-config --static` for the private dependencies. Checked by tests/check_pkgconfig.sh.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(EXBSP_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  set(EXBSP_PC_LIBDIR "${CMAKE_INSTALL_FULL_LIBDIR}")
  set(EXBSP_PC_INCLUDEDIR "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
else()
  file(RELATIVE_PATH relative_prefix "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  set(EXBSP_PC_PREFIX "\${pcfiledir}/${relative_prefix}")
  set(EXBSP_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
  set(EXBSP_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
set(EXBSP_PC_core_DESCRIPTION "exbsp core: exact BSP trees, orders, clipping and sections (LGPL-3.0-or-later)")
set(EXBSP_PC_core_REQUIRES "gmpxx")
set(EXBSP_PC_core_REQUIRES_PRIVATE "gmp mpfr")
set(EXBSP_PC_core_LIBS_PRIVATE "${OpenMP_CXX_FLAGS}")
set(EXBSP_PC_render_DESCRIPTION "exbsp render: viewing pipeline, raster, PNG/SVG/PDF (LGPL-3.0-or-later)")
set(EXBSP_PC_render_REQUIRES "exbsp-core")
set(EXBSP_PC_render_REQUIRES_PRIVATE "libpng cairo polyclipping")
set(EXBSP_PC_render_LIBS_PRIVATE "")
set(EXBSP_PC_gpl_DESCRIPTION "exbsp gpl: section caps, 3D convex hulls and the DXF writer (GPL-3.0-or-later)")
set(EXBSP_PC_gpl_REQUIRES "exbsp-core")
set(EXBSP_PC_gpl_REQUIRES_PRIVATE "gmp mpfr dxflib")
if(NOT EXBSP_BUILD_RENDER)  # no DXF writer in the gpl library
  set(EXBSP_PC_gpl_DESCRIPTION "exbsp gpl: section caps and 3D convex hulls (GPL-3.0-or-later)")
  set(EXBSP_PC_gpl_REQUIRES_PRIVATE "gmp mpfr")
endif()
set(EXBSP_PC_gpl_LIBS_PRIVATE "")
foreach(component ${EXBSP_COMPONENTS})
  set(EXBSP_PC_COMPONENT ${component})
  foreach(field DESCRIPTION REQUIRES REQUIRES_PRIVATE LIBS_PRIVATE)
    set(EXBSP_PC_${field} "${EXBSP_PC_${component}_${field}}")
  endforeach()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/exbsp.pc.in ${PROJECT_BINARY_DIR}/pkgconfig/exbsp-${component}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/pkgconfig/exbsp-${component}.pc
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()
