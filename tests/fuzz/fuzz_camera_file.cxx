// SPDX-License-Identifier: BSD-3-Clause
// Calibration files (camera_file.h): ViSP's camera XML and OpenCV's YAML or XML, the format told
// by the content as read_camera_file tells it. A camera read must be one the tracker accepts.
#include <cmath>

#include "edgetrack/camera_file.h"
#include "edgetrack/tracker_inputs.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto camera = edgetrack::read_camera_file(edgetrack_fuzz::scratch_file(data, size, "xml"));
  edgetrack_fuzz::check_result(camera);
  if (camera.ok() && edgetrack::check_intrinsics(camera.value())) __builtin_trap();  // read past its own limits
  return 0;
}
