// SPDX-License-Identifier: BSD-3-Clause
/// The camera and the settings of a downscaled frame.
#include "downscaled_tracking.h"

#include <algorithm>

namespace edgetrack_app {

void downscale_settings(edgetrack::TrackerParams& params, int factor) {
  if (factor <= 1) return;
  const real f(factor);
  params.me.sample_step = params.me.sample_step / f;
  params.me.range = std::max(1u, params.me.range / static_cast<unsigned>(factor));
  params.faces.min_line_length = params.faces.min_line_length / f;
  params.faces.min_polygon_area = params.faces.min_polygon_area / (f * f);
}

edgetrack::FrameView tracked_frame(const FramePixels& pixels, int factor, FramePixels& small) {
  if (factor <= 1) return pixels.view();
  const edgetrack::FrameView full = pixels.view();
  small.width = full.width / factor;
  small.height = full.height / factor;
  small.offset = 0;
  if (full.layout == edgetrack::PixelLayout::kGrey8) {
    // Grey stays grey: the RGB24 way gives every channel these averages, which grey scaling
    // turns back into the same values (the luma weights sum to 1).
    small.layout = edgetrack::PixelLayout::kGrey8;
    small.bytes.resize(static_cast<size_t>(small.width) * small.height);
    average_blocks(full.row(0), full.width, full.height, 1, factor, small.bytes.data());
  } else {
    small = frame_pixels(downscale(to_rgb_image(full), factor));
  }
  return small.view();
}

}  // namespace edgetrack_app
