# SPDX-License-Identifier: BSD-3-Clause
# `cpack -G DEB` in a build tree: two Debian packages from the install components,
# edgetrack (component tools: the command line and the models) and libedgetrack-<real>-dev
# (component dev: headers, libraries, CMake and pkg-config files), for the build's
# architecture: the host's (dpkg --print-architecture) or the ARM toolchain's (armel, armhf, arm64).
# A cross toolchain file names its own (cross-linux.cmake); a host build asks dpkg.
if(NOT CMAKE_CROSSCOMPILING)
  find_program(EDGETRACK_DPKG dpkg)
  if(EDGETRACK_DPKG)
    execute_process(COMMAND ${EDGETRACK_DPKG} --print-architecture OUTPUT_VARIABLE EDGETRACK_DEB_ARCHITECTURE
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
  endif()
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME edgetrack)
set(CPACK_PACKAGE_VENDOR edgetrack)
set(CPACK_PACKAGE_CONTACT ${EDGETRACK_MAINTAINER})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL tools dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${EDGETRACK_DEB_ARCHITECTURE})

# Each description's first line is the package's synopsis (no CPACK_PACKAGE_DESCRIPTION_SUMMARY,
# which CPack would put in front of it).
set(CPACK_DEBIAN_TOOLS_PACKAGE_NAME ${EDGETRACK_TOOLS_PACKAGE})
set(CPACK_DEBIAN_TOOLS_PACKAGE_SECTION science)
set(CPACK_DEBIAN_TOOLS_DESCRIPTION
    "edge-based 3D object tracker for processors without an FPU (command line)\n The markerless edge-based tracker of Lima, Teichrieb and Kelner, built with real = ${EDGETRACK_REAL}: synthetic sequences, tracking, evaluation; and its sample models.")
# The host tools link OpenCV, OSMesa and X11: dpkg-shlibdeps (dpkg-dev) names their packages.
# The ARM tools are static.
if(NOT CMAKE_CROSSCOMPILING)
  set(CPACK_DEBIAN_TOOLS_PACKAGE_SHLIBDEPS ON)
endif()

set(CPACK_DEBIAN_DEV_PACKAGE_NAME ${EDGETRACK_DEV_PACKAGE})
set(CPACK_DEBIAN_DEV_PACKAGE_PROVIDES ${EDGETRACK_DEV_VIRTUAL_PACKAGE})
set(CPACK_DEBIAN_DEV_PACKAGE_CONFLICTS ${EDGETRACK_DEV_VIRTUAL_PACKAGE})
set(CPACK_DEBIAN_DEV_PACKAGE_REPLACES ${EDGETRACK_DEV_VIRTUAL_PACKAGE})
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_DESCRIPTION
    "edge-based 3D object tracker, vnl and ViSP moving-edge ports (development files, real = ${EDGETRACK_REAL})\n Headers, libraries built with real = ${EDGETRACK_REAL}, the CMake package (find_package(edgetrack)) and edgetrack.pc.")
# python3-edgetrack (component python, python/CMakeLists.txt): the module, for the python3 it
# was built with; dpkg-shlibdeps adds the C++ runtime.
if(EDGETRACK_PYTHON)
  list(APPEND CPACK_COMPONENTS_ALL python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME ${EDGETRACK_PYTHON_PACKAGE})
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SHLIBDEPS ON)
  math(EXPR edgetrack_python_next_minor "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), python3 (<< ${Python_VERSION_MAJOR}.${edgetrack_python_next_minor}), python3-numpy")
  set(CPACK_DEBIAN_PYTHON_DESCRIPTION
      "edge-based 3D object tracker for Python (real = ${EDGETRACK_REAL})\n import edgetrack: models, ViSP configurations, and tracking of numpy frames read in place.")
endif()
include(CPack)
