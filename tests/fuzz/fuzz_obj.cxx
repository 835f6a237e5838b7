// SPDX-License-Identifier: BSD-3-Clause
// Wavefront .obj models, through load_model.
#include "edgetrack/model_io.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgetrack_fuzz::check_result(edgetrack::load_model(edgetrack_fuzz::scratch_file(data, size, "obj")));
  return 0;
}
