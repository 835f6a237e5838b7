# SPDX-License-Identifier: BSD-3-Clause
# EDGETRACK_PYTHON: the `edgetrack` Python module (python/). On by default in host trees that find
# pybind11, python3's headers and numpy; off when cross-compiling and in the fuzz and sanitizer
# trees (an ASan-instrumented module loads into a plain python3 only with the ASan runtime
# preloaded: docs/PYTHON.md).
set(EDGETRACK_PYTHON_DEFAULT OFF)
if(NOT CMAKE_CROSSCOMPILING AND NOT EDGETRACK_FUZZ AND NOT EDGETRACK_SANITIZE)
  # Debian's python3, whose numpy and dist-packages the module and its package are for, rather
  # than whichever python3 comes first on PATH (a pyenv or a virtualenv); -DPython_EXECUTABLE=
  # picks another.
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python 3 COMPONENTS Interpreter Development.Module NumPy QUIET)
  if(Python_FOUND AND Python_NumPy_FOUND)
    find_package(pybind11 CONFIG QUIET)
    if(pybind11_FOUND)
      set(EDGETRACK_PYTHON_DEFAULT ON)
    endif()
  endif()
endif()
option(EDGETRACK_PYTHON "Build the edgetrack Python module (needs pybind11, python3-dev, python3-numpy)"
       ${EDGETRACK_PYTHON_DEFAULT})
if(EDGETRACK_PYTHON)
  if(NOT pybind11_FOUND)
    find_package(Python 3 COMPONENTS Interpreter Development.Module NumPy REQUIRED)
    find_package(pybind11 CONFIG REQUIRED)
  endif()
  set(EDGETRACK_PYTHON_PACKAGE python3-edgetrack)  # the .deb (edgetrack_cpack.cmake)
  # The module is a shared object holding the static libraries of ports/ and tracker/.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
endif()
