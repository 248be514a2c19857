# SPDX-License-Identifier: LGPL-3.0-or-later
# dxflib (RibbonSoft; Debian 12: libdxflib-dev, GPL-2.0-or-later): the DXF writer of
# `exbsp drawing` (src/drawing/sheet_dxf.cpp), part of the GPL component exbsp::gpl
# (docs/licence.md). dxflib ships a pkg-config file and no CMake package, so pkg-config finds
# it (find_path/find_library as a fallback).
#
# Defines the imported target exbsp::dxflib. Installed with the package and included by
# exbspConfig.cmake (the static libexbsp_gpl.a needs it at link time); in a consumer's
# find_package(exbsp) a missing dxflib sets exbsp_FOUND to FALSE instead of failing.
include(${CMAKE_CURRENT_LIST_DIR}/imported_dependency.cmake)
exbsp_pkg_config_library(exbsp::dxflib dxflib dxflib/dl_dxf.h dxflib
  "dxflib (dxflib/dl_dxf.h, libdxflib) not found: apt-get install libdxflib-dev (exbsp's scripts/setup does)")
