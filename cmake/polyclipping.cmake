# SPDX-License-Identifier: LGPL-3.0-or-later
# Clipper (Angus Johnson's polygon clipper; Debian 12: libpolyclipping-dev): the 2D polygon
# Booleans on integer coordinates behind the visible-region SVG/PDF (src/view/vector_regions.cpp).
# Debian ships no CMake package for it, so find_path/find_library first, with pkg-config's
# polyclipping.pc as a hint.
#
# Defines the imported target exbsp::polyclipping. Installed with the package and included by
# exbspConfig.cmake (the static libexbsp.a needs it at link time); in a consumer's
# find_package(exbsp) a missing Clipper sets exbsp_FOUND to FALSE instead of failing.
include(${CMAKE_CURRENT_LIST_DIR}/imported_dependency.cmake)
exbsp_pkg_config_library(exbsp::polyclipping polyclipping polyclipping/clipper.hpp polyclipping
  "Clipper (polyclipping/clipper.hpp, libpolyclipping) not found: apt-get install libpolyclipping-dev (exbsp's scripts/setup does)")
