# SPDX-License-Identifier: BSD-3-Clause
# What the Linux cross toolchain files share (armv5te-pxa270.cmake, aarch64-linux.cmake,
# armv7a-hf.cmake): set EDGETRACK_ARM_TRIPLE, EDGETRACK_ARM_FLAGS, EDGETRACK_QEMU
# (program;-cpu;model) and EDGETRACK_DEB_ARCHITECTURE, then include this file.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_C_COMPILER ${EDGETRACK_ARM_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${EDGETRACK_ARM_TRIPLE}-g++)
set(EDGETRACK_ARM_SYSROOT /usr/${EDGETRACK_ARM_TRIPLE})

# -ffp-contract=off: GCC fuses a*b+c into one multiply-add where the target has one (AArch64's
# fmadd) unless told not to, and a fused result is rounded once where the host's is rounded
# twice; with it off the double poses are the host's bit for bit (docs/ANDROID.md has the measure).
# The soft-float PXA270 has no multiply-add to fuse into: the flag changes none of its code.
# -Wno-psabi: GCC notes on every std::vector of 8-byte-aligned elements that GCC 7.1 changed how
# they are passed on ARM; only code built by an older GCC would disagree, and none is linked here.
set(CMAKE_C_FLAGS_INIT "${EDGETRACK_ARM_FLAGS} -ffp-contract=off")
set(CMAKE_CXX_FLAGS_INIT "${EDGETRACK_ARM_FLAGS} -ffp-contract=off -Wno-psabi")
# Static and non-PIE: QEMU needs no guest libraries at run time and the instruction counter finds
# functions (libgcc's soft-float routines on the PXA270 among them) at their link addresses.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -no-pie")

# Prefixes on CMAKE_PREFIX_PATH (an edgetrack installed for this target) are roots too, so a
# program built with this file finds them without re-rooting them under the sysroot.
set(CMAKE_FIND_ROOT_PATH ${EDGETRACK_ARM_SYSROOT} ${CMAKE_PREFIX_PATH})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# CMake's emulator hook: ctest and add_custom_command run target binaries through this.
set(CMAKE_CROSSCOMPILING_EMULATOR ${EDGETRACK_QEMU};-L;${EDGETRACK_ARM_SYSROOT})
