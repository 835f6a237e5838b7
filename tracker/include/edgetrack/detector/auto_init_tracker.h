// SPDX-License-Identifier: BSD-3-Clause
/// Tracking with no pose given: the detector (detector.h) finds the model on the first frame and
/// again on each frame after one the tracker reports lost; the tracker follows it in between.
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

  /// Detects when there is no pose yet or the last frame was lost, then tracks the frame (any
  /// layout, frame_view.h). On a frame where the detector ran and found nothing: a lost frame
  /// (kPoseFailed) carrying the last pose. An Error when check_frame refuses the frame.
  Result<FrameResult> track(const FrameView& frame);

  /// Whether the detector ran on the last frame, and found the model there.
  bool detected() const { return detected_; }
  bool found() const { return found_; }
  Tracker& tracker() { return tracker_; }

 private:
  AutoInitTracker(Detector detector, Tracker tracker) : detector_(std::move(detector)), tracker_(std::move(tracker)) {}

  Detector detector_;
  Tracker tracker_;
  bool detect_next_ = true;
  bool detected_ = false;
  bool found_ = false;
};

}  // namespace edgetrack
