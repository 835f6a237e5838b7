# SPDX-License-Identifier: BSD-3-Clause
# `cmake --install`: the libraries of ports/ and tracker/ as the CMake package `edgetrack`
# (exported targets edgetrack::<name>, a config file that reports and checks the build's
# `real`, a version file) and a pkg-config file; the command line; the shipped models.
# Drop-in headers (vnl/, vcl/, visp3/, real/ ...) go under include/edgetrack/ports/<port>, one
# folder per ports/ directory, and each exported target puts only its own folder on the include
# path: edgetrack::tracker carries include/ and the `real` folder its public headers need, so a
# real VXL or ViSP in the same program keeps its own headers. Library files get an edgetrack_
# prefix for the same reason.
# The folders are set in edgetrack_install_dirs.cmake.
include(CMakePackageConfigHelpers)

# Exported name = build target without its edgetrack_ prefix. A new ports/ library is added here.
set(edgetrack_port_targets edgetrack_real vcl testlib vnl vnl_algo netlib visp_me)

# One target for everything, as VXL's and ViSP's packages offer.
add_library(edgetrack_all INTERFACE)
target_link_libraries(edgetrack_all INTERFACE ${edgetrack_port_targets} tracker)

# The same edgetrack:: names inside this tree, for a project that adds it as a subdirectory.
foreach(target IN LISTS edgetrack_port_targets ITEMS tracker)
  string(REGEX REPLACE "^edgetrack_" "" name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME edgetrack_${name})
  add_library(edgetrack::${name} ALIAS ${target})
endforeach()
set_target_properties(edgetrack_all PROPERTIES EXPORT_NAME edgetrack)
add_library(edgetrack::edgetrack ALIAS edgetrack_all)

foreach(target IN LISTS edgetrack_port_targets)
  get_target_property(edgetrack_port_dir ${target} SOURCE_DIR)
  get_filename_component(edgetrack_port ${edgetrack_port_dir} NAME)
  install(TARGETS ${target} EXPORT edgetrack-targets COMPONENT dev
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${EDGETRACK_INSTALL_PORTS_INCLUDEDIR}/${edgetrack_port})
endforeach()
install(TARGETS tracker edgetrack_all EXPORT edgetrack-targets COMPONENT dev
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# Headers by folder (every ports/*/include), so headers added to ports/ are installed without
# a list to update.
file(GLOB edgetrack_port_include_dirs LIST_DIRECTORIES true ${PROJECT_SOURCE_DIR}/ports/*/include)
foreach(dir IN LISTS edgetrack_port_include_dirs)
  get_filename_component(edgetrack_port_dir ${dir} DIRECTORY)
  get_filename_component(edgetrack_port ${edgetrack_port_dir} NAME)
  # Not the templates CMake fills in (*.in): their filled copies are what a build uses.
  install(DIRECTORY ${dir}/ DESTINATION ${EDGETRACK_INSTALL_PORTS_INCLUDEDIR}/${edgetrack_port} COMPONENT dev
          PATTERN "*.in" EXCLUDE)
endforeach()
install(DIRECTORY ${PROJECT_BINARY_DIR}/ports/real/include/ DESTINATION ${EDGETRACK_INSTALL_PORTS_INCLUDEDIR}/real
        COMPONENT dev)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tracker/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)

install(EXPORT edgetrack-targets NAMESPACE edgetrack:: DESTINATION ${EDGETRACK_INSTALL_CMAKEDIR} COMPONENT dev)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/edgetrack-config.cmake.in
                              ${PROJECT_BINARY_DIR}/package/edgetrack-config.cmake
                              INSTALL_DESTINATION ${EDGETRACK_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/edgetrack-config-version.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/edgetrack-config.cmake
              ${PROJECT_BINARY_DIR}/package/edgetrack-config-version.cmake
        DESTINATION ${EDGETRACK_INSTALL_CMAKEDIR} COMPONENT dev)

# pkg-config: relative to the .pc file, so an unpacked or moved tree works as installed.
file(RELATIVE_PATH edgetrack_pc_prefix /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" edgetrack_pc_prefix "${edgetrack_pc_prefix}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/edgetrack.pc.in ${PROJECT_BINARY_DIR}/package/edgetrack.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/edgetrack.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

install(TARGETS edgetrack RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)
if(TARGET edgetrack-visp-mbt)
  install(TARGETS edgetrack-visp-mbt RUNTIME DESTINATION ${EDGETRACK_INSTALL_LIBEXECDIR} COMPONENT tools)
endif()
if(TARGET edgetrack-host)
  install(TARGETS edgetrack-host LIBRARY DESTINATION ${EDGETRACK_INSTALL_LIBEXECDIR} COMPONENT tools)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/models DESTINATION ${EDGETRACK_INSTALL_DATADIR} COMPONENT tools)
include(${CMAKE_CURRENT_LIST_DIR}/edgetrack_package_identity.cmake)
