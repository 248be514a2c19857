# SPDX-License-Identifier: LGPL-3.0-or-later
# CGAL (header-only in Debian 12; brings GMP and MPFR). find_package first.
find_package(CGAL 5.5 REQUIRED)
# Exact kernels need the FPU rounding mode respected: never let the compiler fold it away.
add_library(exbsp_cgal_flags INTERFACE)
target_link_libraries(exbsp_cgal_flags INTERFACE CGAL::CGAL)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(exbsp_cgal_flags INTERFACE -frounding-math)
endif()
