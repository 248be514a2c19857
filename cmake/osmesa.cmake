# SPDX-License-Identifier: LGPL-3.0-or-later
# OSMesa, Mesa's off-screen OpenGL (Debian 12: libosmesa6-dev, which pulls libgl-dev for
# GL/gl.h): the independent z-buffer renderer of tests/test_oracle_gl.cpp.
#
# Defines the INTERFACE target exbsp_osmesa. libOSMesa exports the GL entry points itself, so
# only it is linked (never libGL: the glvnd dispatcher would not reach an OSMesa context).
# When OSMesa or the GL headers are missing, configuring still succeeds with a warning and
# exbsp_osmesa defines EXBSP_HAVE_OSMESA=0: the oracle test then FAILS with a message naming
# the package, it does not silently skip.
if(TARGET exbsp_osmesa)
  return()
endif()

find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(EXBSP_PC_OSMESA QUIET osmesa)
endif()
find_path(EXBSP_OSMESA_INCLUDE_DIR GL/osmesa.h HINTS ${EXBSP_PC_OSMESA_INCLUDE_DIRS})
find_path(EXBSP_GL_INCLUDE_DIR GL/gl.h HINTS ${EXBSP_PC_OSMESA_INCLUDE_DIRS})
find_library(EXBSP_OSMESA_LIBRARY NAMES OSMesa osmesa HINTS ${EXBSP_PC_OSMESA_LIBRARY_DIRS})

add_library(exbsp_osmesa INTERFACE)
if(EXBSP_OSMESA_INCLUDE_DIR AND EXBSP_GL_INCLUDE_DIR AND EXBSP_OSMESA_LIBRARY)
  message(STATUS "OSMesa: ${EXBSP_OSMESA_LIBRARY}")
  target_include_directories(exbsp_osmesa INTERFACE ${EXBSP_OSMESA_INCLUDE_DIR} ${EXBSP_GL_INCLUDE_DIR})
  target_link_libraries(exbsp_osmesa INTERFACE ${EXBSP_OSMESA_LIBRARY})
  target_compile_definitions(exbsp_osmesa INTERFACE EXBSP_HAVE_OSMESA=1)
else()
  message(WARNING "OSMesa not found (GL/osmesa.h, GL/gl.h, libOSMesa): test_oracle_gl will fail; "
                  "run scripts/setup (apt-get install libosmesa6-dev)")
  target_compile_definitions(exbsp_osmesa INTERFACE EXBSP_HAVE_OSMESA=0)
endif()
