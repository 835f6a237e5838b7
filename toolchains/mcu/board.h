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

/// Where the heap ends: edgetrack_heap_start plus the image's arena size when its link states one
/// (--defsym=edgetrack_arena_size=BYTES, heap_guard.c), else the end of the board's PSRAM.
char* edgetrack_arena_end(void);
/// Calls of the C library's allocator since reset (malloc, calloc, realloc, operator new and the
/// C library's own buffers all go through them; heap_guard.c). A realloc that moves its block
/// counts twice.
size_t edgetrack_allocation_calls(void);
/// From now on every allocation fails and is counted here, the first with one line on stderr: a
/// firmware locks its heap once it holds everything it keeps (no heap after the tracker is created).
void edgetrack_heap_lock(void);
size_t edgetrack_refused_allocations(void);

#ifdef __cplusplus
}
#endif
