// SPDX-License-Identifier: BSD-3-Clause
/// When a camera's pixels collect light, for `edgetrack synth`: motion blur (the shutter stays
/// open while the object moves) and rolling shutter (each row is read at its own time). Both
/// compose one frame from renders of the scene at times around the frame's own, so the truth
/// stays the pose at the frame's time: the middle of the exposure and of the readout.
#pragma once

#include <functional>
#include <vector>

#include "edgetrack/se3.h"
#include "image_io.h"

namespace edgetrack_app {

/// Times in frame intervals. A frame's rows are exposed for `shutter`, centred on their read
/// time; row y (of H) is read `readout` ((y + 0.5) / H - 0.5) after the frame's time, so the
/// top row is read first and the middle row at the frame's time.
struct SensorTiming {
  double shutter = 0;  ///< exposure time (0: an instant, no motion blur)
  double readout = 0;  ///< time from the top row's read to the bottom row's (0: global shutter)
};

/// The pose at time t (frame numbers, fractional) on the screw motion between the two frames
/// around it; before the first frame or after the last, the first or last step carried on.
edgetrack::Se3 pose_at_time(const std::vector<edgetrack::Se3>& poses, double t);

/// The renders one frame is made of: their times (frame intervals from the frame's own) and, per
/// image row, each render's weight. Renders are evenly spaced, no farther apart than
/// kMaxRenderStepPx of image motion (or kMaxRenders of them over a longer motion); a row's weights average the renders over its exposure,
/// each render standing for its time by linear interpolation between neighbours, so that with
/// no shutter time a row is the scene at its read time interpolated between the two nearest.
struct ExposurePlan {
  static constexpr double kMaxRenderStepPx = 1.0;
  static constexpr int kMaxRenders = 129;
  std::vector<double> times;
  std::vector<double> weights;  ///< row y, render j at [y * times.size() + j]; each row sums to 1
  double weight(int row, size_t render) const { return weights[static_cast<size_t>(row) * times.size() + render]; }
};

/// The plan for an image `height` rows high whose content moves up to `motion_px` pixels per
/// frame interval. A zero timing gives one render at the frame's time.
ExposurePlan plan_exposure(const SensorTiming& timing, int height, double motion_px);

/// The frame: row y is the sum over the plan's renders of weight(y, j) times render j's row y.
/// `render_at(offset)` draws the scene `offset` frame intervals from the frame's time; each
/// render is asked for once, and with one render it is returned as it is.
RgbImage expose(const ExposurePlan& plan, const std::function<RgbImage(double offset)>& render_at);

}  // namespace edgetrack_app
