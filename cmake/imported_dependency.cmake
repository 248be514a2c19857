# SPDX-License-Identifier: LGPL-3.0-or-later
# Helpers of the dependency lookups that are installed with the package (gmp.cmake, cairo.cmake,
# dxflib.cmake, polyclipping.cmake: each is a guard, this include and one call, alike by design) and so run both in exbsp's own build and in a consumer's
# find_package(exbsp) (where exbspConfig.cmake sets exbsp_FIND_PACKAGE_CONTEXT).

# exbsp_missing_dependency(MESSAGE): in exbsp's build a FATAL_ERROR; in a consumer's
# find_package(exbsp), exbsp_FOUND becomes FALSE with the message. A macro, so its return()
# leaves the lookup file.
macro(exbsp_missing_dependency message)
  if(exbsp_FIND_PACKAGE_CONTEXT)
    set(exbsp_FOUND FALSE)
    set(exbsp_NOT_FOUND_MESSAGE "${message}")
    return()
  endif()
  message(FATAL_ERROR "${message}")
endmacro()

# exbsp_imported_library(TARGET LIBRARY INCLUDE_DIR [LINKED...]): the imported target TARGET for
# the library file LIBRARY with its headers in INCLUDE_DIR, linking LINKED. Exported exbsp
# targets name TARGET, so no absolute path of the build machine reaches the package.
function(exbsp_imported_library target library include_dir)
  add_library(${target} UNKNOWN IMPORTED)
  set_target_properties(${target} PROPERTIES IMPORTED_LOCATION "${library}"
    INTERFACE_INCLUDE_DIRECTORIES "${include_dir}" INTERFACE_LINK_LIBRARIES "${ARGN}")
  if(NOT exbsp_FIND_PACKAGE_CONTEXT)
    message(STATUS "${target}: ${library}")
  endif()
endfunction()

# exbsp_pkg_config_library(TARGET MODULE HEADER LIBRARY_NAME MESSAGE [PATH_SUFFIX]): the imported
# target TARGET for a library that ships a pkg-config file MODULE and no CMake package: its
# header HEADER (found under pkg-config's include directories, their parent or PATH_SUFFIX) and
# its library LIBRARY_NAME, pkg-config's answers as hints for find_path/find_library; MESSAGE
# (exbsp_missing_dependency) when either is missing. A macro, so that the missing-dependency
# return() leaves the lookup file. (cairo.cmake, dxflib.cmake, polyclipping.cmake.)
macro(exbsp_pkg_config_library target module header library_name message)
  if(TARGET ${target})  # looked up already (the package's config includes every lookup)
    return()
  endif()
  string(TOUPPER "${module}" _exbsp_pc)
  find_package(PkgConfig QUIET)
  if(PKG_CONFIG_FOUND)
    pkg_check_modules(EXBSP_PC_${_exbsp_pc} QUIET ${module})
  endif()
  find_path(EXBSP_${_exbsp_pc}_INCLUDE_DIR ${header}
    HINTS ${EXBSP_PC_${_exbsp_pc}_INCLUDE_DIRS} ${EXBSP_PC_${_exbsp_pc}_INCLUDEDIR}
          ${EXBSP_PC_${_exbsp_pc}_INCLUDEDIR}/..
    PATH_SUFFIXES ${ARGN})
  find_library(EXBSP_${_exbsp_pc}_LIBRARY NAMES ${library_name}
    HINTS ${EXBSP_PC_${_exbsp_pc}_LIBRARY_DIRS})
  if(NOT EXBSP_${_exbsp_pc}_INCLUDE_DIR OR NOT EXBSP_${_exbsp_pc}_LIBRARY)
    exbsp_missing_dependency("${message}")
  endif()
  exbsp_imported_library(${target} "${EXBSP_${_exbsp_pc}_LIBRARY}"
    "${EXBSP_${_exbsp_pc}_INCLUDE_DIR}")
endmacro()
