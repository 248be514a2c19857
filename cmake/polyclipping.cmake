# SPDX-License-Identifier: LGPL-3.0-or-later
# Clipper (Angus Johnson's polygon clipper; Debian 12: libpolyclipping-dev): the 2D polygon
# Booleans on integer coordinates behind the visible-region SVG/PDF (src/view/vector_regions.cpp).
# Debian ships no CMake package for it, so find_path/find_library first, with pkg-config's
# polyclipping.pc as a hint.
#
# Defines the imported target exbsp::polyclipping. Installed with the package and included by
# exbspConfig.cmake (the static libexbsp.a needs it at link time); in a consumer's
# find_package(exbsp) a missing Clipper sets exbsp_FOUND to FALSE instead of failing.
if(TARGET exbsp::polyclipping)
  return()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/imported_dependency.cmake)
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(EXBSP_PC_POLYCLIPPING QUIET polyclipping)
endif()
find_path(EXBSP_POLYCLIPPING_INCLUDE_DIR polyclipping/clipper.hpp HINTS ${EXBSP_PC_POLYCLIPPING_INCLUDEDIR})
find_library(EXBSP_POLYCLIPPING_LIBRARY NAMES polyclipping HINTS ${EXBSP_PC_POLYCLIPPING_LIBRARY_DIRS})
if(NOT EXBSP_POLYCLIPPING_INCLUDE_DIR OR NOT EXBSP_POLYCLIPPING_LIBRARY)
  exbsp_missing_dependency("Clipper (polyclipping/clipper.hpp, libpolyclipping) not found: apt-get install libpolyclipping-dev (exbsp's scripts/setup does)")
endif()
exbsp_imported_library(exbsp::polyclipping "${EXBSP_POLYCLIPPING_LIBRARY}" "${EXBSP_POLYCLIPPING_INCLUDE_DIR}")
