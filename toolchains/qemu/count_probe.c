// SPDX-License-Identifier: BSD-3-Clause
/// Guest program for test-count-insns.sh: runs count windows whose instruction counts are known,
/// so the test can check the counter exactly.
///   count_probe spin <iterations> <windows>   each window runs a 2-instruction loop <iterations> times
///   count_probe float <windows>               each window does double and float arithmetic
///   count_probe nested                        one window inside another, then one stray end
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "count_markers.h"

/// Exactly two ARM instructions per iteration (subs, bne); iterations must be at least 1.
static void spin(unsigned iterations) {
#if defined(__arm__)
  __asm__ volatile("1: subs %0, %0, #1\n\tbne 1b" : "+r"(iterations) : : "cc");
#else
  volatile unsigned left = iterations;
  while (left > 0) left = left - 1;
#endif
}

int main(int argc, char** argv) {
  if (argc == 4 && strcmp(argv[1], "spin") == 0) {
    const unsigned iterations = (unsigned)strtoul(argv[2], NULL, 10);
    const int windows = atoi(argv[3]);
    if (iterations == 0) return 2;
    for (int w = 0; w < windows; ++w) {
      edgetrack_count_begin();
      spin(iterations);
      edgetrack_count_end();
    }
    return 0;
  }
  if (argc == 3 && strcmp(argv[1], "float") == 0) {
    const int windows = atoi(argv[2]);
    volatile double d = (double)windows + 0.25;  // volatile: computed at run time, not folded
    volatile float f = (float)windows * 0.5f;
    for (int w = 0; w < windows; ++w) {
      edgetrack_count_begin();
      d = d * 1.5 + d / 3.0;
      f = f * 1.5f - f / 7.0f;
      edgetrack_count_end();
    }
    printf("%d\n", (int)(d + (double)f) != 0);
    return 0;
  }
  if (argc == 2 && strcmp(argv[1], "nested") == 0) {
    edgetrack_count_begin();
    edgetrack_count_begin();
    spin(10);
    edgetrack_count_end();
    spin(10);
    edgetrack_count_end();
    edgetrack_count_end();
    return 0;
  }
  fprintf(stderr, "usage: count_probe spin <iterations> <windows> | float <windows> | nested\n");
  return 2;
}
