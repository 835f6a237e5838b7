# SPDX-License-Identifier: BSD-3-Clause
# What identifies the installed package, each set here once: the shared libraries' version and
# SONAME (from the one version number of the top CMakeLists.txt), the Debian package names and
# maintainer, and the licence, installed as each package's Debian copyright file. Included by
# edgetrack_install.cmake after the library targets are named; edgetrack_cpack.cmake reads the
# names.

# 0.x: a minor version may change the ABI, so the SONAME carries major.minor
# (libedgetrack_tracker.so.0.1).
foreach(target IN LISTS edgetrack_port_targets ITEMS tracker)
  get_target_property(type ${target} TYPE)
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    # $ORIGIN: a shared library finds the others beside it (a RUNPATH serves direct needs only).
    set_target_properties(${target} PROPERTIES VERSION ${PROJECT_VERSION}
                                               SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
                                               INSTALL_RPATH "$ORIGIN")
  endif()
endforeach()
# The installed command line finds shared libraries installed beside it. Only with shared
# libraries: a static ARM executable has no RUNPATH entry for the install to rewrite.
if(BUILD_SHARED_LIBS)
  set_target_properties(edgetrack PROPERTIES INSTALL_RPATH "$ORIGIN/${EDGETRACK_INSTALL_LIBDIR_FROM_BINDIR}")
  if(TARGET edgetrack-host)
    set_target_properties(edgetrack-host PROPERTIES INSTALL_RPATH "$ORIGIN/${EDGETRACK_INSTALL_LIBDIR_FROM_LIBEXECDIR}")
  endif()
endif()

set(EDGETRACK_MAINTAINER "edgetrack developers <edgetrack-dev@users.noreply.github.com>")
set(EDGETRACK_TOOLS_PACKAGE edgetrack)
# The headers and libraries differ with `real`: its name is in the package's (Debian names
# allow no underscore), and every such package provides and conflicts with libedgetrack-dev,
# so that installing a second `real` removes the first in the open instead of over it.
string(REPLACE "_" "-" edgetrack_real_in_name ${EDGETRACK_REAL})
set(EDGETRACK_DEV_PACKAGE libedgetrack-${edgetrack_real_in_name}-dev)
set(EDGETRACK_DEV_VIRTUAL_PACKAGE libedgetrack-dev)

# LICENSE in Debian's machine-readable copyright format: the text under its License field,
# each line indented by a space, an empty line as " .".
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/LICENSE)
file(READ ${PROJECT_SOURCE_DIR}/LICENSE edgetrack_license)
string(REGEX REPLACE "\n+$" "" edgetrack_license "${edgetrack_license}")
string(REPLACE "\n" ";" edgetrack_license_lines "${edgetrack_license}")
set(edgetrack_copyright "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n"
                        "Upstream-Name: edgetrack\n\nFiles: *\nCopyright: the edgetrack authors\nLicense: BSD-3-Clause\n")
foreach(line IN LISTS edgetrack_license_lines)
  if(line STREQUAL "")
    list(APPEND edgetrack_copyright " .\n")
  else()
    list(APPEND edgetrack_copyright " ${line}\n")
  endif()
endforeach()
string(JOIN "" edgetrack_copyright ${edgetrack_copyright})
file(WRITE ${PROJECT_BINARY_DIR}/package/copyright "${edgetrack_copyright}")
install(FILES ${PROJECT_BINARY_DIR}/package/copyright DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${EDGETRACK_TOOLS_PACKAGE}
        COMPONENT tools)
install(FILES ${PROJECT_BINARY_DIR}/package/copyright DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${EDGETRACK_DEV_PACKAGE}
        COMPONENT dev)
