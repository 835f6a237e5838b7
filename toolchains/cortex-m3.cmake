# SPDX-License-Identifier: BSD-3-Clause
# Bare-metal build for a microcontroller without an FPU: Cortex-M3 (ARMv7-M, Thumb-2), Debian's
# gcc-arm-none-eabi with newlib and libstdc++-arm-none-eabi-newlib, no operating system. Every
# executable is a firmware image for QEMU's mps2-an385 board (toolchains/mcu: linker script,
# startup code, semihosting for files and the console), run by toolchains/mcu/run-firmware.sh.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR cortex-m3)
# Read by the top CMakeLists.txt: builds the portable libraries, the firmware and the tests that fit.
set(EDGETRACK_BARE_METAL ON)

set(EDGETRACK_MCU_TRIPLE arm-none-eabi)
set(CMAKE_C_COMPILER ${EDGETRACK_MCU_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${EDGETRACK_MCU_TRIPLE}-g++)
# A hosted test program cannot link without the board's startup code: CMake's checks compile only.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# No FPU, soft-float ABI; sections per function so that the linker drops what no image calls.
# newlib-nano (its headers when compiling, libc_nano and libstdc++_nano when linking): its stdio and
# allocator are a fraction of full newlib's flash; it has no 64-bit printf conversions, which
# mcu/c99_formats.c supplies.
set(EDGETRACK_MCU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft -ffunction-sections -fdata-sections --specs=nano.specs")
set(CMAKE_C_FLAGS_INIT "${EDGETRACK_MCU_FLAGS}")
# -Wno-psabi: as in cross-linux.cmake (GCC's note on 8-byte-aligned vector elements).
# -D_GNU_SOURCE: what g++ defines on Linux; newlib hides M_PI, strnlen, ... without it under -std=c++17.
set(CMAKE_CXX_FLAGS_INIT "${EDGETRACK_MCU_FLAGS} -D_GNU_SOURCE -fno-exceptions -fno-rtti -Wno-psabi")
# Flash is the budget (issue #29: 256 KB): Release is built for size, and the sources a frame spends
# its instructions in for speed (toolchains/mcu/hot_sources.cmake). Cached here, before CMake's own
# initialisation would append its -O3 to a *_RELEASE_INIT.
set(CMAKE_C_FLAGS_RELEASE "-Os -DNDEBUG" CACHE STRING "Flags of the Release build (size)")
set(CMAKE_CXX_FLAGS_RELEASE "-Os -DNDEBUG" CACHE STRING "Flags of the Release build (size)")
# Our own startup (toolchains/mcu/startup.c), not newlib's crt0. nano's printf of a double (the
# poses CSV) is linked only when asked for (its scanf's likewise: app/CMakeLists.txt).
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "-u _printf_float -nostartfiles -Wl,--gc-sections -T${CMAKE_CURRENT_LIST_DIR}/mcu/mps2-an385.ld")

set(CMAKE_FIND_ROOT_PATH /usr/lib/${EDGETRACK_MCU_TRIPLE} ${CMAKE_PREFIX_PATH})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# ctest and add_custom_command run each image on the emulated board, its arguments by semihosting.
set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/mcu/run-firmware.sh)
