# SPDX-License-Identifier: LGPL-3.0-or-later
# Helpers of the dependency lookups that are installed with the package (gmp.cmake, cairo.cmake,
# polyclipping.cmake) and so run both in exbsp's own build and in a consumer's
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
