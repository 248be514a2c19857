# Clipper (Angus Johnson's polygon clipper; Debian 12: libpolyclipping-dev): the 2D polygon
# Booleans on integer coordinates behind the visible-region SVG/PDF (src/view/vector_regions.cpp).
# Debian ships no CMake package for it, so find_path/find_library first, with pkg-config's
# polyclipping.pc as a hint.
#
# Defines the INTERFACE target exbsp_polyclipping (installed with exbsp's export set).
if(TARGET exbsp_polyclipping)
  return()
endif()
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(EXBSP_PC_POLYCLIPPING QUIET polyclipping)
endif()
find_path(EXBSP_POLYCLIPPING_INCLUDE_DIR polyclipping/clipper.hpp HINTS ${EXBSP_PC_POLYCLIPPING_INCLUDEDIR})
find_library(EXBSP_POLYCLIPPING_LIBRARY NAMES polyclipping HINTS ${EXBSP_PC_POLYCLIPPING_LIBRARY_DIRS})
if(NOT EXBSP_POLYCLIPPING_INCLUDE_DIR OR NOT EXBSP_POLYCLIPPING_LIBRARY)
  message(FATAL_ERROR "Clipper (polyclipping/clipper.hpp, libpolyclipping) not found: "
                      "run scripts/setup (apt-get install libpolyclipping-dev)")
endif()
message(STATUS "Clipper: ${EXBSP_POLYCLIPPING_LIBRARY}")
add_library(exbsp_polyclipping INTERFACE)
target_include_directories(exbsp_polyclipping SYSTEM INTERFACE ${EXBSP_POLYCLIPPING_INCLUDE_DIR})
target_link_libraries(exbsp_polyclipping INTERFACE ${EXBSP_POLYCLIPPING_LIBRARY})
