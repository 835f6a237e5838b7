// SPDX-License-Identifier: BSD-3-Clause
/// Detection on the first frame and after each lost one, tracking in between.
#include "edgetrack/detector/auto_init_tracker.h"

#include <utility>

namespace edgetrack {

Result<AutoInitTracker> AutoInitTracker::create(const EdgeModel& model, const PinholeCamera& camera,
                                                TemplateSet templates, const DetectorParams& detection,
                                                const TrackerParams& tracking) {
  const ModelExtent extent = templates.extent;
  Result<Detector> detector = Detector::create(model, camera, std::move(templates), detection, tracking);
  if (!detector.ok()) return detector.error();
  // Until the first detection the tracker's pose is a placeholder in front of the camera.
  const Se3 start(Mat33::identity(), Vec3{real(0), real(0), real(4) * extent.radius + real(0.1)} - extent.centre);
  Result<Tracker> tracker = Tracker::create(model, camera, start, tracking);
  if (!tracker.ok()) return tracker.error();
  return AutoInitTracker(std::move(detector).value(), std::move(tracker).value());
}

Result<FrameResult> AutoInitTracker::track(const FrameView& frame) {
  detected_ = detect_next_;
  found_ = false;
  if (detect_next_) {
    const Result<Detection> detection = detector_.detect(frame);
    if (!detection.ok()) return detection.error();
    found_ = detection.value().found && tracker_.reset(detection.value().camera_from_model);
    if (!found_) {
      FrameResult lost;
      lost.camera_from_model = tracker_.camera_from_model();
      lost.status = TrackingStatus::kLost;
      lost.reason = StatusReason::kPoseFailed;
      return lost;
    }
  }
  Result<FrameResult> result = tracker_.track(frame);
  if (result.ok()) detect_next_ = result.value().status == TrackingStatus::kLost;
  return result;
}

}  // namespace edgetrack
