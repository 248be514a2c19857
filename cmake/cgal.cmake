# SPDX-License-Identifier: LGPL-3.0-or-later
# CGAL (header-only in Debian 12; brings GMP and MPFR). find_package first.
find_package(CGAL 5.5 REQUIRED)
# Exact kernels need the FPU rounding mode respected: never let the compiler fold it away.
add_library(exbsp_cgal_flags INTERFACE)
target_link_libraries(exbsp_cgal_flags INTERFACE CGAL::CGAL)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(exbsp_cgal_flags INTERFACE -frounding-math)
endif()

# exbsp_lgpl_module(TARGET): TARGET goes into the LGPL libraries (exbsp::core, exbsp::render),
# so it must not compile in any CGAL package that CGAL licenses under the GPL. Every header of
# such a package includes CGAL/license/<Package>.h, which stops the compilation when
# CGAL_LICENSE_ERROR is defined (and no commercial licence macro is): the check is CGAL's own
# and sees transitive includes (docs/licence.md).
function(exbsp_lgpl_module target)
  target_compile_definitions(${target} PRIVATE CGAL_LICENSE_ERROR)
endfunction()
