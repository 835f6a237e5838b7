// SPDX-License-Identifier: BSD-3-Clause
/// The tracker's frame loop, one line per step, timed per step like the paper's Table 1.
#include "edgetrack/tracker.h"

#include <chrono>

#include "edgetrack/me_search_box.h"
#include "edgetrack/tracker_params.h"
#include "visp3/core/vpImageConvert.h"

namespace edgetrack {
namespace {

/// One lap per step on the host's monotonic clock.
class StepClock {
 public:
  StepClock() : last_(std::chrono::steady_clock::now()) {}
  void lap(Step step, FrameResult& result) {
    const auto now = std::chrono::steady_clock::now();
    result.step_ns[static_cast<int>(step)] = std::chrono::duration_cast<std::chrono::nanoseconds>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_;
};

}  // namespace

const char* step_name(Step step) {
  switch (step) {
    case Step::kVisibleEdges: return "visible edges detection";
    case Step::kGreyScaling: return "image grey scaling";
    case Step::kMovingEdges: return "ME";
    case Step::kPose: return "pose calculation";
  }
  return "?";
}

Result<Tracker> Tracker::create(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial,
                                const TrackerParams& params) {
  if (camera.width <= 0 || camera.height <= 0) return Error{"", 0, "the camera has no image size"};
  if (model.edges.empty()) return Error{"", 0, "the model has no edge to track"};
  if (static_cast<int>(model.edges.size()) > kMaxEdges) return Error{"", 0, "the model has too many edges for Edge-ID"};
  const auto problem = check_tracker_params(params);
  if (problem) return Error{"", 0, problem->message};
  if (initial.translation().z <= real(0)) return Error{"", 0, "the initial pose puts the model behind the camera"};
  return Tracker(model, camera, initial, params);
}

Tracker::Tracker(const EdgeModel& model, const PinholeCamera& camera, const Se3& initial, const TrackerParams& params)
    : model_(model),
      camera_(camera),
      params_(params),
      sampling_(sampling_params(params)),
      face_visibility_(model),
      camera_from_model_(initial),
      edge_ids_(camera),
      grey_(static_cast<unsigned>(camera.height), static_cast<unsigned>(camera.width)) {}

const vpImage<unsigned char>& Tracker::grey_scale(const uint16_t* rgb565, unsigned int& converted) {
  if (params_.grey == GreyScaling::kWholeFrame) {
    vpImageConvert::RGB565ToGrey(rgb565, grey_.bitmap, grey_.getSize());
    converted = grey_.getSize();
    return grey_;
  }
  // Box by box: boxes of neighbouring points overlap little, so converting an overlap twice
  // costs less than tracking what is done (measured on the cube sequence: vpGreyOnDemand's 8x8
  // tiles converted twice the pixels, at twice the guest instructions).
  converted = 0;
  for (const ControlPoint& point : visible_) {
    const PixelBox box = me_search_box(point, params_.me);
    converted += vpImageConvert::RGB565ToGrey(rgb565, grey_, box.top, box.left, box.bottom, box.right);
  }
  return grey_;
}

bool Tracker::reset(const Se3& camera_from_model) {
  if (camera_from_model.translation().z <= real(0)) return false;
  camera_from_model_ = camera_from_model;
  face_visibility_.reset();
  return true;
}

FrameResult Tracker::track(const uint16_t* rgb565) {
  FrameResult result;
  StepClock clock;
  begin(Step::kVisibleEdges);
  if (edge_id_source_) edge_id_source_->draw(model_, camera_from_model_, edge_ids_);
  else edge_ids_.render(model_, camera_from_model_);
  face_visibility_.update(model_, camera_, camera_from_model_, params_.faces);
  std::vector<ControlPoint> sampled = sample_control_points(model_, camera_, camera_from_model_, sampling_);
  face_visibility_.keep_tracked(sampled);
  visible_ = keep_visible(sampled, edge_ids_);
  end(Step::kVisibleEdges);
  clock.lap(Step::kVisibleEdges, result);
  begin(Step::kGreyScaling);
  const vpImage<unsigned char>& grey = grey_scale(rgb565, result.grey_pixels);
  end(Step::kGreyScaling);
  clock.lap(Step::kGreyScaling, result);
  begin(Step::kMovingEdges);
  matches_ = search_moving_edges(grey, visible_, params_.me);
  end(Step::kMovingEdges);
  clock.lap(Step::kMovingEdges, result);
  begin(Step::kPose);
  result.pose = solve_pose(matches_, camera_, camera_from_model_, params_.pose);
  end(Step::kPose);
  clock.lap(Step::kPose, result);
  camera_from_model_ = result.pose.camera_from_model;
  result.camera_from_model = camera_from_model_;
  result.points_sampled = static_cast<int>(visible_.size());
  result.points_matched = static_cast<int>(matches_.size()) - result.pose.outliers;
  return result;
}

}  // namespace edgetrack
