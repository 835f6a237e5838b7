// SPDX-License-Identifier: BSD-3-Clause
// Template files (`edgetrack templates`), through read_templates against the model and camera
// the seeds were made for (data/models/cube60.cao, px 220 at 320 x 240), so that the fuzzer gets
// past the header's identity checks into the parameters and the template lines.
#include "edgetrack/detector/template_io.h"
#include "edgetrack/model_io.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const edgetrack::Result<edgetrack::EdgeModel> model =
      edgetrack::load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  if (!model.ok()) __builtin_trap();  // the seed model itself is missing
  const edgetrack::PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  edgetrack_fuzz::check_result(
      edgetrack::read_templates(edgetrack_fuzz::scratch_file(data, size, "txt"), model.value(), camera));
  return 0;
}
