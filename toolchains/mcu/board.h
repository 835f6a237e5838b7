// SPDX-License-Identifier: BSD-3-Clause
/// What a firmware image may ask the board's runtime (startup.c, syscalls.c): the memory it has
/// used so far, for the RAM budget (docs/MCU.md).
#pragma once

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/// The highest the heap (sbrk over the PSRAM) has reached since reset, in bytes.
size_t edgetrack_heap_high_water(void);
/// Deepest stack use since reset, in bytes: the part of the painted stack that is no longer paint.
size_t edgetrack_stack_high_water(void);
/// Bytes of initialised data and zeroed data (.data, .bss) the image holds for its whole run.
size_t edgetrack_static_ram(void);

#ifdef __cplusplus
}
#endif
