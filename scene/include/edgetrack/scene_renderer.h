// SPDX-License-Identifier: BSD-3-Clause
/// The test-image renderer: a model drawn flat-shaded over a textured background with noise, as
/// an RGB565 frame (faces, tessellated cylinder sides, circles as discs), through the camera's
/// lens when it has one (lens_resampling.h), with the portable rasteriser, so tracking tests
/// with known ground truth run everywhere (QEMU included). Also the ground-truth visibility of a 3D point, by ray casting.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/frame_view.h"
#include "edgetrack/lens_resampling.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/scene_extras.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// A 16-bit RGB565 image, row-major, as a handheld camera delivers it.
struct Rgb565Frame {
  int width = 0;
  int height = 0;
  std::vector<uint16_t> pixels;
};

/// The frame as the tracker reads it.
inline FrameView rgb565_view(const Rgb565Frame& frame) {
  return packed_frame(frame.pixels.data(), frame.width, frame.height, PixelLayout::kRgb565);
}

struct SceneStyle {
  int supersample = 2;        ///< samples per pixel along each axis (anti-aliased edges)
  int noise = 6;              ///< uniform noise added to each pixel, +-this many grey levels
  int background_low = 40;    ///< the background texture's grey range
  int background_high = 110;
  int texture_cell = 12;      ///< pixels between the texture's random grey values
  int face_low = 150;         ///< face grey: face_low + (face_high - face_low) * |cos(light, normal)|
  int face_high = 240;
  int disc_darker = 70;       ///< a circle's disc is this much darker than a face lit the same way
  uint32_t texture_seed = 1;  ///< the background is the same in every frame
};

class SceneRenderer {
 public:
  SceneRenderer(const PinholeCamera& camera, const SceneStyle& style);

  /// Draws the model at camera_from_model; `noise_seed` picks the frame's noise.
  void render(const EdgeModel& model, const Se3& camera_from_model, uint32_t noise_seed, Rgb565Frame& frame);
  /// The same with `additions` (scene_extras.h): clutter lines hidden where the model is in front
  /// of them, 1.5 pixels wide, and the occluder's columns over everything.
  void render(const EdgeModel& model, const Se3& camera_from_model, uint32_t noise_seed, const SceneAdditions& additions,
              Rgb565Frame& frame);

 private:
  /// Draws the lines into the supersampled depth and face buffers as face kClutterFace.
  void draw_clutter(const std::vector<Segment3>& clutter, const Se3& camera_from_model);
  PinholeCamera camera_;
  PinholeCamera fine_camera_;  ///< the camera at the supersampled size, without the lens (with a margin through one)
  std::optional<LensResampling> lens_;  ///< through a lens: where each sample reads the pinhole buffer
  SceneStyle style_;
  std::vector<uint8_t> background_;  ///< grey texture, one value per pixel
  std::vector<int32_t> depth_;       ///< supersampled inverse depth
  std::vector<int16_t> face_;        ///< supersampled shade index (faces, then facets and discs), -1 for background
};

/// Ground truth: true when no face or cylinder side of the model lies on the segment from the camera centre to
/// the point, except within `margin` (a fraction of the point's distance) in front of it, so a
/// point on its own faces counts as visible. Exact ray casting, independent of the rasteriser.
bool point_visible(const EdgeModel& model, const Se3& camera_from_model, const Vec3& point_in_model,
                   const real& margin);

}  // namespace edgetrack
