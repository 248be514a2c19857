# SPDX-License-Identifier: LGPL-3.0-or-later
# OpenMesh (Debian ships a CMake config): optional. When found, exbsp builds the adapter target
# exbsp_openmesh (include/exbsp/adapters/openmesh.h: OpenMesh meshes to and from exbsp) and installs it as
# the package component `openmesh` (find_package(exbsp COMPONENTS openmesh) -> exbsp::openmesh).
# The tests use OpenMesh as an oracle and test the adapter, so EXBSP_BUILD_TESTS requires it.
# Sets EXBSP_HAVE_OPENMESH and EXBSP_OPENMESH_TARGET.
find_package(OpenMesh CONFIG QUIET)
set(EXBSP_HAVE_OPENMESH OFF)
if(TARGET OpenMeshCore)
  set(EXBSP_HAVE_OPENMESH ON)
  set(EXBSP_OPENMESH_TARGET OpenMeshCore)
elseif(OPENMESH_LIBRARIES)
  set(EXBSP_HAVE_OPENMESH ON)
  set(EXBSP_OPENMESH_TARGET ${OPENMESH_LIBRARIES})
endif()
if(EXBSP_HAVE_OPENMESH)
  message(STATUS "OpenMesh: ${OpenMesh_DIR} (component exbsp::openmesh)")
elseif(EXBSP_BUILD_TESTS)
  message(FATAL_ERROR "OpenMesh not found; the tests need it (run scripts/setup: apt-get install "
                      "libopenmesh-dev), or configure with -DEXBSP_BUILD_TESTS=OFF")
else()
  message(STATUS "OpenMesh not found: the exbsp::openmesh component is not built")
endif()
