// SPDX-License-Identifier: BSD-3-Clause
// PGM/PPM frames (P2, P3, P5, P6), our own reader.
#include "fuzz_input.h"
#include "image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgetrack_fuzz::check_result(edgetrack_app::read_netpbm(edgetrack_fuzz::scratch_file(data, size, "pgm")));
  return 0;
}
