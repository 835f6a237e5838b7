# SPDX-License-Identifier: BSD-3-Clause
# A death test: runs COMMAND (a list, the emulator first when there is one) and passes when it
# ends unsuccessfully (an abort included) with stderr matching EXPECT.
# usage: cmake -DCOMMAND=<list> -DEXPECT=<regex> -P expect_stop.cmake
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(result EQUAL 0)
  message(FATAL_ERROR "'${COMMAND}' succeeded; expected it to stop with '${EXPECT}'. Output: ${out}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "'${COMMAND}' stopped (${result}) without '${EXPECT}' on stderr: ${err}")
endif()
message(STATUS "stopped (${result}): ${err}")
