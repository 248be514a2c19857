# SPDX-License-Identifier: LGPL-3.0-or-later
# cairo (Debian 12: libcairo2-dev): PDF output of `exbsp render ... -o OUT.pdf`
# (src/view/vector_pdf.cpp). cairo ships a pkg-config file and no CMake package, so
# pkg-config finds it (find_path/find_library as a fallback).
#
# Defines the imported target exbsp::cairo. Installed with the package and included by
# exbspConfig.cmake (the static libexbsp.a needs it at link time); in a consumer's
# find_package(exbsp) a missing cairo sets exbsp_FOUND to FALSE instead of failing.
include(${CMAKE_CURRENT_LIST_DIR}/imported_dependency.cmake)
exbsp_pkg_config_library(exbsp::cairo cairo cairo-pdf.h cairo
  "cairo (cairo-pdf.h, libcairo) not found: apt-get install libcairo2-dev (exbsp's scripts/setup does)" cairo)
