// SPDX-License-Identifier: BSD-3-Clause
/// Runs the tracker over a synthetic sequence rendered in-process, from the true first pose,
/// and collects per-frame poses, errors, counts and ground-truth visibility checks.
#pragma once

#include <vector>

#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"

namespace edgetrack_test {

/// What a frame of a sequence shows instead of the scene, for the status tests.
enum class FrameContent {
  kScene,     ///< the model over the textured background
  kNoise,     ///< uniform noise over the whole frame
  kFlat,      ///< one flat grey
  kNoObject   ///< the background alone, as if the object were fully covered by the same texture
};

/// A sequence: the scene's trajectory sped up `subsample` times (true_poses), and per frame
/// what it shows (empty: the scene in every frame). `poses`, when not empty, replaces the
/// trajectory (one pose per frame).
struct SequenceSpec {
  int subsample = 1;
  std::vector<FrameContent> content;
  std::vector<edgetrack::Se3> poses;
  /// As `edgetrack synth --cover` and `--clutter` (scene_extras.h): a dark board in front
  /// covering this share of the object's image, sweeping across it (0: none), and dark lines
  /// this many metres beside every model edge (0: none).
  double cover = 0;
  double clutter = 0;
  /// The lens the frames are seen through (none: the pinhole), and whether the tracker is given
  /// it (or tracks with the pinhole alone, as a user who leaves the distortion out).
  edgetrack::LensDistortion lens;
  bool lens_given = true;
  /// As `edgetrack synth --readout`: the rows read over this many frame intervals, top first
  /// (0: a global shutter), from `readout_renders` renders a frame (rolling_shutter_render.h);
  /// the scene alone: not with `content`, `cover` or `clutter`.
  double readout = 0;
  int readout_renders = 13;
};

struct SequenceRun {
  bool loaded = false;
  std::vector<edgetrack::Se3> truth;
  std::vector<edgetrack::FrameResult> frames;
  std::vector<double> position_error_mm;  ///< |camera position - true camera position| per frame
  double mean_position_error_mm = 0;
  double mean_points_sampled = 0;
  /// Sampled points that ray casting finds hidden by more than a pixel: hidden along the rays
  /// through the point and through the points one pixel left, right, above and below it. Must
  /// be 0. (Within a pixel of an occluding contour the raster and the exact ray may disagree.)
  int hidden_points_sampled = 0;
  int hidden_points_dropped = 0;  ///< candidates hidden in the same sense (every 4th frame), all dropped
  int outliers = 0;               ///< matches the pose step left out
  /// Per frame, per primitive (EdgeModel numbering): the matches the pose step kept.
  std::vector<std::vector<int>> matched_per_primitive;
};

/// Tracks `frames` frames of the scene; `visibility_check` adds the ray-casting checks.
SequenceRun run_sequence(Scene scene, int frames, bool visibility_check,
                         const edgetrack::TrackerParams& params = edgetrack::TrackerParams{},
                         const SequenceSpec& spec = SequenceSpec{});

/// Frames of the run with the given status.
int count_status(const SequenceRun& run, edgetrack::TrackingStatus status);

}  // namespace edgetrack_test
