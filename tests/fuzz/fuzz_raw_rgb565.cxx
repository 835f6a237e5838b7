// SPDX-License-Identifier: BSD-3-Clause
// Raw RGB565 frames: the first two bytes choose the --raw-size (1..256 each), the rest is the file.
#include "fuzz_input.h"
#include "image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const int width = data[0] + 1, height = data[1] + 1;
  const std::string path = edgetrack_fuzz::scratch_file(data + 2, size - 2, "rgb565");
  edgetrack_fuzz::check_result(edgetrack_app::read_raw_rgb565(path, width, height));
  return 0;
}
