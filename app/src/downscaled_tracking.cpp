// SPDX-License-Identifier: BSD-3-Clause
/// The camera and the settings of a downscaled frame.
#include "downscaled_tracking.h"

#include <algorithm>

namespace edgetrack_app {

edgetrack::PinholeCamera downscaled(const edgetrack::PinholeCamera& camera, int factor) {
  if (factor <= 1) return camera;
  const real f(factor), half(0.5);
  return {camera.px / f, camera.py / f, (camera.u0 + half) / f - half, (camera.v0 + half) / f - half,
          camera.width / factor, camera.height / factor};
}

void downscale_settings(edgetrack::TrackerParams& params, int factor) {
  if (factor <= 1) return;
  const real f(factor);
  params.me.setSampleStep(params.me.getSampleStep() / f);
  params.me.setRange(std::max(1u, params.me.getRange() / static_cast<unsigned>(factor)));
  params.faces.min_line_length = params.faces.min_line_length / f;
  params.faces.min_polygon_area = params.faces.min_polygon_area / (f * f);
}

edgetrack::FrameView tracked_frame(const FramePixels& pixels, int factor, RgbImage& small) {
  if (factor <= 1) return pixels.view();
  small = downscale(to_rgb_image(pixels.view()), factor);
  return edgetrack::packed_frame(small.rgb.data(), small.width, small.height, edgetrack::PixelLayout::kRgb24);
}

}  // namespace edgetrack_app
