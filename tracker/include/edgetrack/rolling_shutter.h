// SPDX-License-Identifier: BSD-3-Clause
/// A rolling shutter's rows, each seen at its own time. A sensor that reads its rows one after
/// another, top first, over `readout` frame intervals sees image row v at
/// t(v) = readout ((v + 0.5) / H - 0.5) frame intervals from the frame's time (the middle row's
/// read, where the frame's pose belongs; H rows, pixel centres at whole coordinates): the pose
/// of row v is the frame's pose moved on by t(v) times the camera's velocity. The model assumes
/// that velocity constant over the frame.
#pragma once

#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_match.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The largest readout, in frame intervals (the readout time of a datasheet times the frame
/// rate): beyond it a sensor would still be reading a frame when the next begins. A negative
/// readout reads the rows bottom first (a sensor mounted upside down).
constexpr double kMaxReadout = 1.0;

/// The time (frame intervals, from the frame's time) at which a rolling shutter reading its
/// rows over readout frame intervals reads the image row at `row` (pixels): `per_row` is
/// readout / H, H (`height`) the image's rows.
inline real row_time(const real& row, const real& per_row, int height) {
  return per_row * (row + real(0.5) - real(height) * real(0.5));
}

/// Whether a twist is exactly zero (no motion measured).
bool is_zero(const Twist& twist);

/// Moves each control point to where its edge is seen when its row is read, `pose` being the
/// frame's pose (at the middle row's read) and `velocity` the camera's motion per frame
/// (camera frame: the pose a frame later is exp(velocity) * pose). Each point's
/// `point_in_model` becomes the model point that `pose` projects where the moving object puts
/// the edge at its row's time, X' = pose^-1 exp(t velocity) pose X: everything that projects
/// it with the frame's pose (the search, the pose step's residuals and Jacobian, the status
/// measures) projects it with its row's pose. Its `pixel` becomes that projection (the row's
/// time follows the moved row, two passes) and its normal turns with the rows' shear.
/// `readout` 0 or a zero velocity leave the points as they are.
void move_to_row_times(std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& pose,
                       const Twist& velocity, const real& readout);

/// The tracker's rolling-shutter step: the control points moved to their rows' times with the
/// velocity of the last trusted poses, then, once the frame's own pose is solved, their model
/// points moved again with the velocity that pose measures (half a frame old instead of one and
/// a half) for a second solve.
class RowTimes {
 public:
  /// move_to_row_times, keeping the points as sampled for again() (with readout 0 or a zero
  /// velocity, nothing: again() then has no points to move).
  void move(std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& pose, const Twist& velocity,
            const real& readout);
  /// The model points of `points` (those move() moved) and of `matches` (found for them, each
  /// at its EdgeMatch::point_index) moved from where they were sampled with `velocity` instead;
  /// their pixels and normals, where the search looked, stay. False, and nothing changed, when
  /// `points` are not as many as move() kept or a match's point_index names none of them.
  bool again(std::vector<ControlPoint>& points, std::vector<EdgeMatch>& matches, const PinholeCamera& camera,
             const Se3& pose, const Twist& velocity, const real& readout);
  /// The heap its buffers hold, for Tracker::memory.
  size_t heap_bytes() const;
  /// Room for `points` control points, so that move() and again() allocate nothing.
  void reserve(size_t points);

 private:
  std::vector<ControlPoint> sampled_;
  std::vector<ControlPoint> moved_;
};

}  // namespace edgetrack
