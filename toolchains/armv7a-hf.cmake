# SPDX-License-Identifier: BSD-3-Clause
# Cross build for 32-bit ARMv7-A hard-float (Android's armeabi-v7a, Raspberry Pi 2, camera
# boards): Thumb-2 with VFPv3 and NEON, Debian's armhf compilers (g++-arm-linux-gnueabihf);
# tests run on qemu-arm -cpu cortex-a7.
set(CMAKE_SYSTEM_PROCESSOR armv7-a)
set(EDGETRACK_ARM_TRIPLE arm-linux-gnueabihf)
set(EDGETRACK_ARM_FLAGS "-march=armv7-a -mfpu=neon -mfloat-abi=hard -mthumb")
set(EDGETRACK_QEMU qemu-arm;-cpu;cortex-a7)
set(EDGETRACK_DEB_ARCHITECTURE armhf)
include(${CMAKE_CURRENT_LIST_DIR}/cross-linux.cmake)
