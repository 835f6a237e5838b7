// SPDX-License-Identifier: BSD-3-Clause
/// One program linking our drop-in visp_me and Debian's real visp_core: both vpImage classes
/// exist under one source name in two translation units; each half must get its own.
#include <cstdio>
#include <string>

#include "beside.h"

int main(int argc, char* argv[]) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCRATCH_DIR\n", argv[0]);
    return 2;
  }
  int failures = 0;
  for (int edge : {20, 27}) {
    const int found = ours_track_vertical_step(edge);
    // The site stops on the last column of the dark side, as Debian's ViSP 3.5 vpMeSite does
    // on the same image (19 and 26).
    if (found != edge - 1) {
      std::fprintf(stderr, "drop-in vpMeSite: edge at column %d found at %d\n", edge, found);
      ++failures;
    }
  }
  const unsigned rows = 480, cols = 64;
  long expected = 0;
  for (unsigned i = 0; i < rows; ++i)
    for (unsigned j = 0; j < cols; ++j) expected += static_cast<unsigned char>(i + 2 * j);
  const long sum = upstream_pgm_round_trip(std::string(argv[1]) + "/beside.pgm", rows, cols);
  if (sum != expected) {
    std::fprintf(stderr, "real ViSP vpImageIo round trip: sum %ld, expected %ld\n", sum, expected);
    ++failures;
  }
  if (failures == 0) std::printf("drop-in visp_me and real visp_core ran side by side in one program\n");
  return failures == 0 ? 0 : 1;
}
