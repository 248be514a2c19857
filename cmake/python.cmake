# SPDX-License-Identifier: LGPL-3.0-or-later
# Python module (src/python): pybind11 (Debian's python3-pybind11 / pybind11-dev) for Debian's
# /usr/bin/python3, which has numpy and pytest (the pyenv python3 that may come first on PATH
# has neither). Pass -DPython_EXECUTABLE=... to use another interpreter.
# EXBSP_BUILD_PYTHON defaults to ON when pybind11 and the Python headers are found.
if(NOT Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter for the exbsp module and its tests")
endif()
set(PYBIND11_FINDPYTHON ON)
find_package(Python 3.7 COMPONENTS Interpreter Development.Module QUIET)
if(Python_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(Python_FOUND AND pybind11_FOUND)
  set(EXBSP_PYTHON_DEFAULT ON)
else()
  set(EXBSP_PYTHON_DEFAULT OFF)
endif()
option(EXBSP_BUILD_PYTHON "Build the Python module exbsp (needs pybind11 and the Python headers)" ${EXBSP_PYTHON_DEFAULT})
if(EXBSP_BUILD_PYTHON AND NOT (Python_FOUND AND pybind11_FOUND))
  message(FATAL_ERROR "EXBSP_BUILD_PYTHON is ON but pybind11 or the Python headers were not found "
                      "(Debian: apt-get install python3-pybind11 python3-dev)")
endif()
