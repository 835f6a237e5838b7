// SPDX-License-Identifier: BSD-3-Clause
/// Detection on the first frame and on each frame the tracker does not hold, tracking in between.
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
  detected_ = false;
  found_ = false;
  if (!has_pose_) return detect(frame, nullptr);
  Result<FrameResult> own = tracker_.track(frame);
  if (!own.ok()) return own;
  const TrackingStatus status = own.value().status;
  if (status == TrackingStatus::kTracked) {
    confirmed_ = true;
    doubted_ = 0;
    return own;
  }
  if (status == TrackingStatus::kUncertain && confirmed_ && ++doubted_ % kDoubtFrames != 0) return own;
  return detect(frame, &own.value());
}

Result<FrameResult> AutoInitTracker::detect(const FrameView& frame, const FrameResult* own) {
  detected_ = true;
  const Result<Detection> detection = detector_.detect(frame);
  if (!detection.ok()) return detection.error();
  found_ = detection.value().found && tracker_.reset(detection.value().camera_from_model, Tracker::StartPose::kDetected);
  if (!found_) {
    if (own) return *own;
    FrameResult lost;
    lost.camera_from_model = tracker_.camera_from_model();
    lost.status = TrackingStatus::kLost;
    lost.reason = StatusReason::kNotDetected;
    return lost;
  }
  has_pose_ = true;
  confirmed_ = false;
  doubted_ = 0;
  Result<FrameResult> result = tracker_.track(frame);
  if (result.ok() && result.value().status != TrackingStatus::kLost) {
    result.value().status = TrackingStatus::kUncertain;
    result.value().reason = StatusReason::kUnconfirmed;
  }
  return result;
}

}  // namespace edgetrack
