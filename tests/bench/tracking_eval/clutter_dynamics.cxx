// SPDX-License-Identifier: BSD-3-Clause
/// How a generated sequence's tracking error builds up from frame to frame, against what one
/// frame alone allows (docs/ME.md, "Next to parallel lines"). Per frame, the camera position
/// error (mm, as `edgetrack eval`) of:
///   tracked  the tracker from the true first pose through every frame (as `edgetrack track`);
///   alone    one frame solved from its own true pose, the contrasts taken there (the floor the
///            moving edges leave at that frame);
///   one_step one frame solved after the previous one was solved from its true pose: the
///            previous frame's contrasts, and its solved pose as the start;
///   near     alone's matches that lie within a pixel of their edge (along the normal from the
///            control point, sampled at the true pose) solved again from the true pose: what is
///            left if every match farther off were known to be wrong, so what the edges' own
///            localisation beside the lines allows.
/// The last three search the configured range (no start widening: the true pose needs none).
///   tracking_eval_clutter_dynamics MODEL.cao SEQUENCE_DIR   (synth's camera.xml, truth.csv, frames/)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "edgetrack/pose_solver.h"
#include "generated_sequence.h"

using namespace edgetrack;

namespace {

/// The distance between the camera positions in the object frame, mm.
double camera_position_error_mm(const Se3& pose, const Se3& truth) {
  return 1000.0 * static_cast<double>(norm(pose.inverse().translation() - truth.inverse().translation()));
}

/// The matches within a pixel of their control point along its normal, as the pose step takes
/// them (no outlier marks), into `near`.
void matches_near_points(const std::vector<EdgeMatch>& matches, std::vector<EdgeMatch>& near) {
  near.clear();
  for (EdgeMatch m : matches) {
    using std::fabs;
    if (!(fabs(dot(m.point.normal, m.found - m.point.pixel)) < real(1))) continue;
    m.outlier = false;
    near.push_back(m);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s MODEL.cao SEQUENCE_DIR\n", argv[0]);
    return 2;
  }
  GeneratedSequence sequence;
  if (!sequence.load(argv[0], argv[1], argv[2])) return 1;
  const std::vector<Se3>& truth = sequence.truth;
  const TrackerConfig& config = sequence.config;
  const EdgeModel& model = sequence.model;
  TrackerParams from_truth = config.params;
  from_truth.motion.start_frames = 0;
  // What the frame's own matches give from its true pose: the pose step alone, without the
  // drift check's second solve (#27's reference for the tracked error).
  from_truth.thin_lines.check = DriftAction::kNone;
  Result<Tracker> tracked = Tracker::create(model, config.camera, truth[0], config.params);
  Result<Tracker> alone = Tracker::create(model, config.camera, truth[0], from_truth);
  Result<Tracker> one_step = Tracker::create(model, config.camera, truth[0], from_truth);
  if (!tracked.ok() || !alone.ok() || !one_step.ok()) return 1;
  std::printf("frame tracked_mm alone_mm one_step_mm near_mm\n");
  double sums[4] = {0, 0, 0, 0};
  std::vector<EdgeMatch> near;
  int frames = 0, steps = 0;
  Result<edgetrack_app::FramePixels> previous = Error{"", 0, "no frame before the first"};
  for (size_t k = 0; k < truth.size(); ++k) {
    Result<edgetrack_app::FramePixels> pixels = sequence.frame(k);
    if (!pixels.ok()) break;
    const FrameView frame = pixels.value().view();
    const Result<FrameResult> t = tracked.value().track(frame);
    alone.value().reset(truth[k]);
    const Result<FrameResult> a = alone.value().track(frame);
    if (!t.ok() || !a.ok()) break;
    const double errors[2] = {camera_position_error_mm(t.value().camera_from_model, truth[k]),
                              camera_position_error_mm(a.value().camera_from_model, truth[k])};
    matches_near_points(alone.value().matches(), near);
    const PoseSolution near_pose = solve_pose(near, config.camera, truth[k], config.params.pose);
    const double near_error = camera_position_error_mm(near_pose.camera_from_model, truth[k]);
    sums[0] += errors[0];
    sums[1] += errors[1];
    sums[3] += near_error;
    ++frames;
    if (previous.ok()) {
      one_step.value().reset(truth[k - 1]);
      const Result<FrameResult> before = one_step.value().track(previous.value().view());
      const Result<FrameResult> s = one_step.value().track(frame);
      if (!before.ok() || !s.ok()) break;
      const double error = camera_position_error_mm(s.value().camera_from_model, truth[k]);
      sums[2] += error;
      ++steps;
      std::printf("%zu %.3f %.3f %.3f %.3f\n", k, errors[0], errors[1], error, near_error);
    } else {
      std::printf("%zu %.3f %.3f - %.3f\n", k, errors[0], errors[1], near_error);
    }
    previous = std::move(pixels);
  }
  if (frames == 0) return 1;
  std::printf("mean %.3f %.3f %.3f %.3f\n", sums[0] / frames, sums[1] / frames, steps ? sums[2] / steps : 0.0,
              sums[3] / frames);
  return 0;
}
