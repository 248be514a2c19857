# SPDX-License-Identifier: LGPL-3.0-or-later
# cairo (Debian 12: libcairo2-dev): PDF output of `exbsp render ... -o OUT.pdf`
# (src/view/vector_pdf.cpp). cairo ships a pkg-config file and no CMake package, so
# pkg-config finds it (find_path/find_library as a fallback).
#
# Defines the imported target exbsp::cairo. Installed with the package and included by
# exbspConfig.cmake (the static libexbsp.a needs it at link time); in a consumer's
# find_package(exbsp) a missing cairo sets exbsp_FOUND to FALSE instead of failing.
if(TARGET exbsp::cairo)
  return()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/imported_dependency.cmake)
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(EXBSP_PC_CAIRO QUIET cairo)
endif()
find_path(EXBSP_CAIRO_INCLUDE_DIR cairo-pdf.h HINTS ${EXBSP_PC_CAIRO_INCLUDE_DIRS} PATH_SUFFIXES cairo)
find_library(EXBSP_CAIRO_LIBRARY NAMES cairo HINTS ${EXBSP_PC_CAIRO_LIBRARY_DIRS})
if(NOT EXBSP_CAIRO_INCLUDE_DIR OR NOT EXBSP_CAIRO_LIBRARY)
  exbsp_missing_dependency("cairo (cairo-pdf.h, libcairo) not found: apt-get install libcairo2-dev (exbsp's scripts/setup does)")
endif()
exbsp_imported_library(exbsp::cairo "${EXBSP_CAIRO_LIBRARY}" "${EXBSP_CAIRO_INCLUDE_DIR}")
