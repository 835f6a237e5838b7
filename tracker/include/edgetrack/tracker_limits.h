// SPDX-License-Identifier: BSD-3-Clause
/// The most a tracker will hold, stated at Tracker::create so that it allocates every buffer
/// there and nothing while it tracks: a microcontroller's static arena is sized from these
/// (docs/MCU.md). The default states none, and the buffers grow to the largest frame seen.
#pragma once

#include <optional>
#include <string>

namespace edgetrack {

struct TrackerLimits {
  /// The model's primitives: edges, cylinder silhouettes and circles (EdgeModel). create
  /// refuses a larger model.
  int primitives = 0;
  /// Control points one frame samples (before the visibility test). It bounds every per-frame
  /// buffer: the visible points and their read boxes, the matches, the pose solver's arrays and
  /// the remembered contrasts. A frame that would sample more is lost with
  /// StatusReason::kOverLimit, without a search or a solve.
  int control_points = 0;
  /// The largest image, pixels: create refuses a camera without a size or a larger one.
  int image_width = 0;
  int image_height = 0;
  /// Frames whose bytes are not the grey image (RGB565, RGBA, ...) need a grey image of the
  /// camera's size: allocated at create when true; such a frame is refused with an Error when
  /// false (grey8 frames, and the Y plane of NV21/I420/NV12 with packed rows, need none).
  bool colour_frames = false;

  /// Whether any maximum is stated; then every one must be.
  bool stated() const { return primitives > 0 || control_points > 0 || image_width > 0 || image_height > 0; }
};

/// Why `limits` cannot be used (a maximum stated and another not, or one negative), or nothing.
std::optional<std::string> check_tracker_limits(const TrackerLimits& limits);

}  // namespace edgetrack
