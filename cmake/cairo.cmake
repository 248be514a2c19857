# cairo (Debian 12: libcairo2-dev): PDF output of `exbsp render ... -o OUT.pdf`
# (src/view/vector_pdf.cpp). cairo ships a pkg-config file and no CMake package, so
# pkg-config finds it (find_path/find_library as a fallback).
#
# Defines the INTERFACE target exbsp_cairo (installed with exbsp's export set).
if(TARGET exbsp_cairo)
  return()
endif()
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(EXBSP_PC_CAIRO QUIET cairo)
endif()
find_path(EXBSP_CAIRO_INCLUDE_DIR cairo-pdf.h HINTS ${EXBSP_PC_CAIRO_INCLUDE_DIRS} PATH_SUFFIXES cairo)
find_library(EXBSP_CAIRO_LIBRARY NAMES cairo HINTS ${EXBSP_PC_CAIRO_LIBRARY_DIRS})
if(NOT EXBSP_CAIRO_INCLUDE_DIR OR NOT EXBSP_CAIRO_LIBRARY)
  message(FATAL_ERROR "cairo (cairo-pdf.h, libcairo) not found: run scripts/setup (apt-get install libcairo2-dev)")
endif()
message(STATUS "cairo: ${EXBSP_CAIRO_LIBRARY} (${EXBSP_PC_CAIRO_VERSION})")
add_library(exbsp_cairo INTERFACE)
target_include_directories(exbsp_cairo SYSTEM INTERFACE ${EXBSP_CAIRO_INCLUDE_DIR})
target_link_libraries(exbsp_cairo INTERFACE ${EXBSP_CAIRO_LIBRARY})
