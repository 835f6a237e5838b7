// SPDX-License-Identifier: BSD-3-Clause
/// The tracking status on generated QVGA cube sequences: frames of noise, flat frames and frames
/// where the object is fully covered are lost from the first such frame and tracking is back
/// (tracked, within 1 mm of the truth) within 5 frames of the object being visible again; an
/// object leaving the view is lost once too little of it is left to track, and tracked while
/// wholly in view.
#include <cmath>
#include <cstdio>
#include <string>

#include "edgetrack/model_io.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kRecoveryFrames = 5;  ///< the issue's bound: tracked again within 5 frames

/// The frames' statuses as one letter each: t tracked, u uncertain, l lost.
std::string status_letters(const SequenceRun& run) {
  std::string letters;
  for (const FrameResult& f : run.frames)
    letters += f.status == TrackingStatus::kTracked ? 't' : f.status == TrackingStatus::kUncertain ? 'u' : 'l';
  return letters;
}

void print_run(const char* name, const SequenceRun& run) {
  std::printf("%s %s: %s\n", real_name(), name, status_letters(run).c_str());
  for (size_t k = 0; k < run.frames.size(); ++k) {
    const FrameResult& f = run.frames[k];
    if (f.status == TrackingStatus::kTracked) continue;
    const FrameMeasures& m = f.measures;
    std::printf("  frame %zu %s (%s): visible %d matched %d kept %d scale %.2f px range %u correction %.1f px "
                "error %.2f mm\n",
                k, status_name(f.status), reason_name(f.reason), m.visible, m.matched, m.kept,
                static_cast<double>(m.residual_scale), m.range, static_cast<double>(m.correction_px),
                run.position_error_mm[k]);
  }
}

/// Frames [first, end) of `content` are lost, every other frame is not, and within
/// kRecoveryFrames of `end` a frame is tracked within 1 mm of the truth, as are all after it.
void check_interruption(const SequenceRun& run, int first, int end) {
  int wrong_lost = 0, missed = 0;
  for (int k = 0; k < static_cast<int>(run.frames.size()); ++k) {
    const bool lost = run.frames[k].status == TrackingStatus::kLost;
    if (k >= first && k < end) missed += !lost;
    else wrong_lost += lost;
  }
  TEST_EQUAL("every interrupted frame is lost, from the first one", missed, 0);
  TEST_EQUAL("no other frame is lost", wrong_lost, 0);
  int back = -1;
  for (int k = end; k < static_cast<int>(run.frames.size()) && back < 0; ++k)
    if (run.frames[k].status == TrackingStatus::kTracked && run.position_error_mm[k] < 1.0) back = k;
  std::printf("back to tracked within 1 mm at frame %d (object visible again at %d)\n", back, end);
  TEST("tracking is back within 5 frames of the object being visible again", back >= end && back < end + kRecoveryFrames,
       true);
  double worst_after = 0;
  for (int k = back < 0 ? end : back; k < static_cast<int>(run.frames.size()); ++k)
    worst_after = std::fmax(worst_after, run.position_error_mm[k]);
  TEST_NEAR("and stays within 1 mm of the truth", worst_after, 0, 1.0);
}

}  // namespace

static void test_status_noise_and_flat() {
  for (FrameContent content : {FrameContent::kNoise, FrameContent::kFlat}) {
    SequenceSpec spec;
    spec.content.assign(30, FrameContent::kScene);
    for (int k = 10; k < 12; ++k) spec.content[k] = content;
    const SequenceRun run = run_sequence(Scene::kCube, 30, false, TrackerParams{}, spec);
    TEST("the sequence runs", run.loaded, true);
    if (!run.loaded) return;
    print_run(content == FrameContent::kNoise ? "noise at 10-11" : "flat at 10-11", run);
    check_interruption(run, 10, 12);
  }
}

static void test_status_covered() {
  SequenceSpec spec;
  spec.content.assign(30, FrameContent::kScene);
  for (int k = 12; k < 15; ++k) spec.content[k] = FrameContent::kNoObject;
  const SequenceRun run = run_sequence(Scene::kCube, 30, false, TrackerParams{}, spec);
  TEST("the sequence runs", run.loaded, true);
  if (!run.loaded) return;
  print_run("covered at 12-14", run);
  check_interruption(run, 12, 15);
}

static void test_status_leaving_view() {
  // From the cube's first pose, the camera accelerates sideways to 6 mm (about 9 px) per frame
  // until the cube has left the image.
  const int frames = 40;
  const Se3 start = true_poses(Scene::kCube, 1)[0];
  SequenceSpec spec;
  double x = 0;
  for (int k = 0; k < frames; ++k) {
    x += 0.0005 * std::fmin(k, 12);
    spec.poses.push_back(Se3(start.rotation(), start.translation() + Vec3{real(x), real(0), real(0)}));
  }
  const SequenceRun run = run_sequence(Scene::kCube, frames, false, TrackerParams{}, spec);
  TEST("the sequence runs", run.loaded, true);
  if (!run.loaded) return;
  print_run("leaving the view", run);
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  const PinholeCamera camera = qvga_camera();
  const SamplingParams sampling;
  int first_gone = -1, wrong_in_view = 0, wrong_gone = 0, in_view = 0;
  for (int k = 0; k < frames; ++k) {
    bool whole = true;
    for (const Vec3& v : model.value().vertices) {
      const Vec2 p = camera.project(spec.poses[k] * v);
      whole = whole && p.x >= real(sampling.border) && p.x <= real(camera.width - 1 - sampling.border);
    }
    const int left = static_cast<int>(sample_control_points(model.value(), camera, spec.poses[k], sampling).size());
    if (left < PoseParams{}.min_points && first_gone < 0) first_gone = k;
    const bool lost = run.frames[k].status == TrackingStatus::kLost;
    if (whole) {
      ++in_view;
      wrong_in_view += lost;
    }
    if (first_gone >= 0) wrong_gone += !lost;
  }
  std::printf("wholly in view: %d frames; too little left to track from frame %d\n", in_view, first_gone);
  TEST("the cube is wholly in view for a while, then leaves", in_view >= 10 && first_gone > 0, true);
  TEST_EQUAL("no frame with the cube wholly in view is lost", wrong_in_view, 0);
  TEST_EQUAL("every frame from the first with too little left to track is lost", wrong_gone, 0);
}

TESTMAIN(test_status_noise_and_flat)
TESTMAIN(test_status_covered)
TESTMAIN(test_status_leaving_view)
