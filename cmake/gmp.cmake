# SPDX-License-Identifier: LGPL-3.0-or-later
# GMP, GMP's C++ classes (gmpxx) and MPFR as imported targets: CGAL uses them, and exbsp also
# calls them directly (exact rationals, correctly rounded output, bsp/exact_gmp.h).
#
# Defines exbsp::gmp, exbsp::gmpxx (links exbsp::gmp) and exbsp::mpfr (links exbsp::gmp), and
# the INTERFACE target exbsp_gmp (all three) for exbsp's own modules. Debian ships neither a
# CMake package nor (for gmpxx) a reliable pkg-config file, so find_path/find_library look them
# up. The same file is installed with the package and included by exbspConfig.cmake, so the
# exported link interface names these targets, never the absolute paths of this machine.
# When a library is missing: a FATAL_ERROR in exbsp's own build; in a consumer's
# find_package(exbsp), exbsp_FOUND is set to FALSE with a message.
if(TARGET exbsp::gmp)
  return()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/imported_dependency.cmake)
find_path(EXBSP_GMP_INCLUDE_DIR gmp.h)
find_path(EXBSP_GMPXX_INCLUDE_DIR gmpxx.h)
find_path(EXBSP_MPFR_INCLUDE_DIR mpfr.h)
find_library(EXBSP_GMP_LIBRARY gmp)
find_library(EXBSP_GMPXX_LIBRARY gmpxx)
find_library(EXBSP_MPFR_LIBRARY mpfr)
foreach(var EXBSP_GMP_INCLUDE_DIR EXBSP_GMPXX_INCLUDE_DIR EXBSP_MPFR_INCLUDE_DIR
            EXBSP_GMP_LIBRARY EXBSP_GMPXX_LIBRARY EXBSP_MPFR_LIBRARY)
  if(NOT ${var})
    exbsp_missing_dependency("GMP/gmpxx/MPFR not found (${var}): apt-get install libgmp-dev libmpfr-dev (exbsp's scripts/setup does)")
  endif()
endforeach()
exbsp_imported_library(exbsp::gmp "${EXBSP_GMP_LIBRARY}" "${EXBSP_GMP_INCLUDE_DIR}")
exbsp_imported_library(exbsp::gmpxx "${EXBSP_GMPXX_LIBRARY}" "${EXBSP_GMPXX_INCLUDE_DIR}" exbsp::gmp)
exbsp_imported_library(exbsp::mpfr "${EXBSP_MPFR_LIBRARY}" "${EXBSP_MPFR_INCLUDE_DIR}" exbsp::gmp)
if(NOT exbsp_FIND_PACKAGE_CONTEXT)
  add_library(exbsp_gmp INTERFACE)
  target_link_libraries(exbsp_gmp INTERFACE exbsp::mpfr exbsp::gmpxx exbsp::gmp)
endif()
