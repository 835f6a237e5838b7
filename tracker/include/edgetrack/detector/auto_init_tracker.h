// SPDX-License-Identifier: BSD-3-Clause
/// Tracking with no pose given: the detector (detector.h) finds the model on the first frame and
/// again on each frame the tracker does not hold it; the tracker follows it in between.
/// The recovery decision lives here, so that an application only feeds frames.
#pragma once

#include "edgetrack/detector/detector.h"
#include "edgetrack/result.h"
#include "edgetrack/tracker.h"

namespace edgetrack {

class AutoInitTracker {
 public:
  /// The detector (its templates checked against the model and camera) and the tracker, with
  /// the same tracking settings.
  static Result<AutoInitTracker> create(const EdgeModel& model, const PinholeCamera& camera, TemplateSet templates,
                                        const DetectorParams& detection, const TrackerParams& tracking);

  /// Tracks the frame (any layout, frame_view.h) and detects on it, in this order:
  /// - With no pose found yet: detects only.
  /// - Else the tracker goes first, from its prediction. Its tracked frame confirms the pose. Its
  ///   lost frame, or an uncertain one before any confirmation, is detected on at once, so every
  ///   such frame gets a detection. Its uncertain frame after a confirmation stands (the
  ///   tracker's own doubt, which it recovers from or loses), except every kDoubtFrames-th one in
  ///   a row: a pose doubted that long is mostly held in a wrong minimum beside the object, which
  ///   no further frame corrects, and the detection is the way out.
  /// A detection the tracker then tracks on the frame is reported uncertain (kUnconfirmed): the
  /// detector refined its pose on this very image, so only the next frames, tracked from it,
  /// say it is right. One it does not find leaves the tracker as it was: the tracker's own frame,
  /// or a lost one (kNotDetected) carrying the last pose when there was none. An Error when
  /// check_frame refuses the frame.
  Result<FrameResult> track(const FrameView& frame);

  /// Whether the detector ran on the last frame, and found the model there.
  bool detected() const { return detected_; }
  bool found() const { return found_; }
  /// Whether a tracked frame has followed the last detection.
  bool confirmed() const { return confirmed_; }
  Tracker& tracker() { return tracker_; }
  const Detector& detector() const { return detector_; }

  /// Uncertain frames in a row, after a confirmation, between detections: a handful of frames
  /// (a sixth of a second at 30 Hz) lets the tracker's own recovery outlast a passing cause (fast
  /// motion, a hand across the object), and a detection on a device without an FPU costs about
  /// a hundred tracked frames (docs/results/detection.md), which one in five bounds.
  static constexpr int kDoubtFrames = 5;

 private:
  AutoInitTracker(Detector detector, Tracker tracker) : detector_(std::move(detector)), tracker_(std::move(tracker)) {}
  /// The detection on `frame` and the tracker's frame from its pose; `own` is the tracker's frame
  /// from its prediction, when it ran.
  Result<FrameResult> detect(const FrameView& frame, const FrameResult* own);

  Detector detector_;
  Tracker tracker_;
  bool has_pose_ = false;   ///< the detector found the model once
  bool confirmed_ = false;  ///< a frame was tracked since the last detection
  int doubted_ = 0;         ///< uncertain frames in a row since the last tracked frame or detection
  bool detected_ = false;
  bool found_ = false;
};

}  // namespace edgetrack
