// SPDX-License-Identifier: BSD-3-Clause
// ViSP .init files and --init-points files (the same bytes read as both).
#include "fuzz_input.h"
#include "pose_from_points.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = edgetrack_fuzz::scratch_file(data, size, "init");
  edgetrack_fuzz::check_result(edgetrack_app::read_init_points(path));
  edgetrack_fuzz::check_result(edgetrack_app::read_image_points(path));
  return 0;
}
