// SPDX-License-Identifier: BSD-3-Clause
/// The count-window markers: empty functions the plugin recognises by address. They live in
/// their own translation unit and are kept out of inlining, cloning and identical-code folding,
/// so every call in the source stays a call to its own address in the binary.
#include "count_markers.h"

#if defined(__GNUC__) && !defined(__clang__)
#define EDGETRACK_MARKER __attribute__((noipa))
#else
#define EDGETRACK_MARKER __attribute__((noinline))
#endif

// The empty asm with a memory clobber is also a compiler barrier: stores before the call are not
// moved into the window, nor stores inside it out of the window.
EDGETRACK_MARKER void edgetrack_count_begin(void) { __asm__ volatile("" ::: "memory"); }

EDGETRACK_MARKER void edgetrack_count_end(void) { __asm__ volatile("" ::: "memory"); }
