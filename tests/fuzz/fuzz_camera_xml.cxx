// SPDX-License-Identifier: BSD-3-Clause
// ViSP XML configuration files, read as loadConfigFile reads them: camera and tracker settings.
#include "edgetrack/visp_config.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = edgetrack_fuzz::scratch_file(data, size, "xml");
  edgetrack::TrackerConfig config;
  edgetrack_fuzz::check_result(edgetrack::apply_visp_config(path, config));
  return 0;
}
