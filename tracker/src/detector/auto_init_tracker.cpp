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

AutoFrame AutoInitTracker::track(const uint16_t* rgb565) {
  AutoFrame out;
  if (detect_next_) {
    out.detected = true;
    const Detection detection = detector_.detect(rgb565);
    out.found = detection.found && tracker_.reset(detection.camera_from_model);
    if (!out.found) {
      out.frame.camera_from_model = tracker_.camera_from_model();
      out.frame.status = TrackingStatus::kLost;
      out.frame.reason = StatusReason::kPoseFailed;
      return out;
    }
  }
  out.frame = tracker_.track(rgb565);
  detect_next_ = out.frame.status == TrackingStatus::kLost;
  return out;
}

}  // namespace edgetrack
