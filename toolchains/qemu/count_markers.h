// SPDX-License-Identifier: BSD-3-Clause
/// Count windows for the instruction counter (toolchains/qemu/count-insns.sh): a program calls
/// edgetrack_count_begin() and edgetrack_count_end() around the work it wants counted, and the
/// QEMU plugin sums the guest instructions executed between each pair. Natively, and under QEMU
/// without the plugin, both calls do nothing.
#ifndef EDGETRACK_COUNT_MARKERS_H
#define EDGETRACK_COUNT_MARKERS_H

#ifdef __cplusplus
extern "C" {
#endif

/// Opens a count window (nested pairs count once, for the outermost pair).
void edgetrack_count_begin(void);
/// Closes the window opened by the matching edgetrack_count_begin().
void edgetrack_count_end(void);

#ifdef __cplusplus
}
#endif

#endif  // EDGETRACK_COUNT_MARKERS_H
