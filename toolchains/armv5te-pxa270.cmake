# SPDX-License-Identifier: BSD-3-Clause
# Cross build for the paper's target: Intel PXA270 (XScale, ARMv5TE, no FPU, soft-float ABI),
# with Debian's armel compilers (g++-arm-linux-gnueabi). Every test runs on qemu-arm -cpu pxa270,
# where a stray VFP instruction traps instead of passing unnoticed.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR armv5te)

set(EDGETRACK_ARM_TRIPLE arm-linux-gnueabi)
set(CMAKE_C_COMPILER ${EDGETRACK_ARM_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${EDGETRACK_ARM_TRIPLE}-g++)
set(EDGETRACK_ARM_SYSROOT /usr/${EDGETRACK_ARM_TRIPLE})

# Pinned here rather than trusted from the compiler's defaults. Static, non-PIE binaries keep
# libgcc's soft-float routines at fixed addresses for the instruction counter.
set(EDGETRACK_ARM_FLAGS "-march=armv5te -mtune=xscale -marm -mfloat-abi=soft")
set(CMAKE_C_FLAGS_INIT "${EDGETRACK_ARM_FLAGS}")
# -Wno-psabi: GCC notes on every std::vector of 8-byte-aligned elements that GCC 7.1 changed how
# they are passed on ARM; only code built by an older GCC would disagree, and none is linked here.
set(CMAKE_CXX_FLAGS_INIT "${EDGETRACK_ARM_FLAGS} -Wno-psabi")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -no-pie")

# Prefixes on CMAKE_PREFIX_PATH (an edgetrack installed for this target) are roots too, so a
# program built with this file finds them without re-rooting them under the sysroot.
set(CMAKE_FIND_ROOT_PATH ${EDGETRACK_ARM_SYSROOT} ${CMAKE_PREFIX_PATH})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# CMake's emulator hook: ctest and add_custom_command run target binaries through this.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-arm;-cpu;pxa270;-L;${EDGETRACK_ARM_SYSROOT})
