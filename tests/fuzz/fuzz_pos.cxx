// SPDX-License-Identifier: BSD-3-Clause
// ViSP .pos pose files.
#include "edgetrack/pose_io.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgetrack_fuzz::check_result(edgetrack::read_pos(edgetrack_fuzz::scratch_file(data, size, "pos")));
  return 0;
}
