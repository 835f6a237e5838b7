# SPDX-License-Identifier: BSD-3-Clause
# What the hard-float Linux cross toolchain files share (aarch64-linux.cmake, armv7a-hf.cmake):
# set EDGETRACK_ARM_TRIPLE, EDGETRACK_ARM_FLAGS, EDGETRACK_QEMU (program;-cpu;model) and
# EDGETRACK_DEB_ARCHITECTURE, then include this file.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_C_COMPILER ${EDGETRACK_ARM_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${EDGETRACK_ARM_TRIPLE}-g++)
set(EDGETRACK_ARM_SYSROOT /usr/${EDGETRACK_ARM_TRIPLE})

# -ffp-contract=off: GCC fuses a*b+c into one multiply-add where the target has one (AArch64's
# fmadd) unless told not to, and a fused result is rounded once where the host's is rounded
# twice; with it off the double poses are the host's bit for bit (docs/ANDROID.md has the measure).
set(CMAKE_C_FLAGS_INIT "${EDGETRACK_ARM_FLAGS} -ffp-contract=off")
set(CMAKE_CXX_FLAGS_INIT "${EDGETRACK_ARM_FLAGS} -ffp-contract=off -Wno-psabi")
# Static and non-PIE, as on the PXA270: QEMU needs no guest libraries at run time and the
# instruction counter finds functions at their link addresses.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -no-pie")

set(CMAKE_FIND_ROOT_PATH ${EDGETRACK_ARM_SYSROOT} ${CMAKE_PREFIX_PATH})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

set(CMAKE_CROSSCOMPILING_EMULATOR ${EDGETRACK_QEMU};-L;${EDGETRACK_ARM_SYSROOT})
