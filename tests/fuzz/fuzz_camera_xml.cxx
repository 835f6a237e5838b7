// SPDX-License-Identifier: BSD-3-Clause
// ViSP XML configuration files: the <camera> block and the moving-edge settings.
#include "edgetrack/pinhole_camera.h"
#include "fuzz_input.h"
#include "me_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = edgetrack_fuzz::scratch_file(data, size, "xml");
  edgetrack_fuzz::check_result(edgetrack::read_visp_camera_xml(path, 640, 480));
  auto ecm = edgetrack_app::read_ecm_config(path);
  edgetrack_fuzz::check_result(ecm);
  if (ecm.ok()) {
    edgetrack::TrackerParams params;
    edgetrack_fuzz::check_result(edgetrack_app::apply_ecm_config(ecm.value(), path, params));
  }
  return 0;
}
