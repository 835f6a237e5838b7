// SPDX-License-Identifier: BSD-3-Clause
/// The C library's allocator, counted and lockable (board.h): newlib's _malloc_r and _realloc_r
/// (which malloc, calloc, realloc, operator new and the C library's own buffers all go through)
/// are wrapped by the linker (CMakeLists.txt). Once a firmware has allocated what it keeps, it
/// locks the heap; any allocation after that fails and is counted, the first with one line on
/// stderr, so that a test of the firmware sees it.
#include <errno.h>
#include <reent.h>
#include <stddef.h>
#include <string.h>
#include <unistd.h>

#include "board.h"

void* __real__malloc_r(struct _reent* reent, size_t bytes);
void* __real__realloc_r(struct _reent* reent, void* block, size_t bytes);

static size_t allocation_calls;
static size_t refused_calls;
static int locked;

/// One line on stderr, written straight to the descriptor: stdio could allocate.
static void say_refused(void) {
  static const char line[] = "heap: an allocation after the heap was locked (edgetrack_heap_lock): refused\n";
  write(2, line, sizeof line - 1);
}

/// Counts the call; false, with the refusal counted, when the heap is locked.
static int admit(struct _reent* reent) {
  ++allocation_calls;
  if (!locked) return 1;
  if (refused_calls++ == 0) say_refused();
  reent->_errno = ENOMEM;
  return 0;
}

void* __wrap__malloc_r(struct _reent* reent, size_t bytes) {
  return admit(reent) ? __real__malloc_r(reent, bytes) : NULL;
}

void* __wrap__realloc_r(struct _reent* reent, void* block, size_t bytes) {
  if (block == NULL || bytes > 0) {
    if (!admit(reent)) return NULL;
  }
  return __real__realloc_r(reent, block, bytes);
}

/// An image's arena size, from its link (absolute; 0, undefined, when none is stated).
extern char edgetrack_arena_size[] __attribute__((weak));
extern char edgetrack_heap_start[], edgetrack_heap_end[];

char* edgetrack_arena_end(void) {
  const size_t stated = (size_t)edgetrack_arena_size;
  if (stated == 0 || stated > (size_t)(edgetrack_heap_end - edgetrack_heap_start)) return edgetrack_heap_end;
  return edgetrack_heap_start + stated;
}

size_t edgetrack_allocation_calls(void) { return allocation_calls; }
size_t edgetrack_refused_allocations(void) { return refused_calls; }
void edgetrack_heap_lock(void) { locked = 1; }
