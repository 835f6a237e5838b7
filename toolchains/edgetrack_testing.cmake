# SPDX-License-Identifier: BSD-3-Clause
# edgetrack_add_test_driver(<driver> SOURCES <files> TESTS <test_x>... [LIBS <libs>] [PREFIX <p>])
# Builds one testlib driver (its test_driver.cxx REGISTERs each test_x) and adds one CTest test
# per test_x, named <prefix>_<test_x>, exactly as VXL's ADD_TEST(name driver test_x) does.
# Under the ARM toolchain CTest runs the driver through CMAKE_CROSSCOMPILING_EMULATOR.
function(edgetrack_add_test_driver driver)
  cmake_parse_arguments(ARG "" "PREFIX" "SOURCES;TESTS;LIBS" ${ARGN})
  if(NOT ARG_PREFIX)
    set(ARG_PREFIX ${driver})
  endif()
  add_executable(${driver} ${ARG_SOURCES})
  target_link_libraries(${driver} PRIVATE testlib ${ARG_LIBS})
  foreach(test ${ARG_TESTS})
    add_test(NAME ${ARG_PREFIX}_${test} COMMAND ${driver} ${test})
  endforeach()
endfunction()
