# OpenMesh (Debian ships a CMake config).
find_package(OpenMesh CONFIG REQUIRED)
if(TARGET OpenMeshCore)
  set(EXBSP_OPENMESH_TARGET OpenMeshCore)
else()
  set(EXBSP_OPENMESH_TARGET ${OPENMESH_LIBRARIES})
endif()
