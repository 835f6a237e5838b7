// SPDX-License-Identifier: BSD-3-Clause
// ViSP .cao models, through load_model: the reader and the edge derivation (triangulation, creases).
#include "edgetrack/model_io.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgetrack_fuzz::check_result(edgetrack::load_model(edgetrack_fuzz::scratch_file(data, size, "cao")));
  return 0;
}
