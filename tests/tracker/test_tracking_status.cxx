// SPDX-License-Identifier: BSD-3-Clause
/// The tracking status on generated QVGA cube sequences (status_cases.h): frames of noise, flat
/// frames and frames where the object is fully covered are lost from the first such frame and
/// tracking is back (tracked, within 1 mm of the truth) within 5 frames of the object being
/// visible again; an object leaving the view is lost once too little of it is left to track,
/// and tracked while wholly in view; no frame reported tracked draws the cube more than 1 px off.
#include <cstdio>
#include <string>

#include "run_sequence.h"
#include "status_cases.h"
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

void print_run(const std::string& name, const SequenceRun& run) {
  std::printf("%s %s: %s\n", real_name(), name.c_str(), status_letters(run).c_str());
  for (size_t k = 0; k < run.frames.size(); ++k) {
    const FrameResult& f = run.frames[k];
    if (f.status == TrackingStatus::kTracked) continue;
    const FrameMeasures& m = f.measures;
    std::printf("  frame %zu %s (%s): visible %d matched %d kept %d scale %.2f px range %u correction %.1f px "
                "error %.2f mm%s\n",
                k, status_name(f.status), reason_name(f.reason), m.visible, m.matched, m.kept,
                static_cast<double>(m.residual_scale), m.range, static_cast<double>(m.correction_px),
                run.position_error_mm[k], f.retried ? ", retried" : "");
  }
}

/// Runs the case; checks the frames that must and must not be lost and, when the object comes
/// back, that a frame is tracked within 1 mm of the truth within kRecoveryFrames, as are all
/// after it.
void check_case(const StatusCase& c) {
  const SequenceRun run = run_sequence(Scene::kCube, c.frames, false, TrackerParams{}, c.spec);
  TEST((c.name + ": the sequence runs").c_str(), run.loaded, true);
  if (!run.loaded) return;
  print_run(c.name, run);
  const StatusOutcome o = status_outcome(c, run);
  TEST_EQUAL((c.name + ": every frame from the first bad one is lost").c_str(), o.missed, 0);
  TEST_EQUAL((c.name + ": no frame with the object wholly in view is lost").c_str(), o.wrongly_lost, 0);
  std::printf("largest overlay offset of a frame reported tracked: %.2f px\n", o.worst_tracked_px);
  TEST_NEAR((c.name + ": a frame reported tracked draws the cube within 1 px of the truth").c_str(), o.worst_tracked_px, 0,
            1.0);
  if (c.visible_again >= c.frames) return;
  std::printf("back to tracked within 1 mm at frame %d (object visible again at %d)\n", o.back, c.visible_again);
  TEST((c.name + ": tracking is back within 5 frames of the object being visible again").c_str(),
       o.back >= c.visible_again && o.back < c.visible_again + kRecoveryFrames, true);
  TEST_NEAR((c.name + ": and stays within 1 mm of the truth").c_str(), o.worst_after_back_mm, 0, 1.0);
}

StatusCase find_case(const char* name) {
  for (const StatusCase& c : status_cases())
    if (c.name == name) return c;
  return StatusCase{};
}

}  // namespace

static void test_status_noise_and_flat() {
  check_case(find_case("noise at 10-11"));
  check_case(find_case("flat at 10-11"));
}

static void test_status_covered() { check_case(find_case("covered at 12-14")); }

static void test_status_leaving_view() {
  const StatusCase c = find_case("leaving the view");
  std::printf("wholly in view: %d frames; too little left to track from frame %d\n", c.wholly_in_view, c.first_bad);
  TEST("the cube is wholly in view for a while, then leaves", c.wholly_in_view >= 10 && c.first_bad < c.frames, true);
  check_case(c);
}

TESTMAIN(test_status_noise_and_flat)
TESTMAIN(test_status_covered)
TESTMAIN(test_status_leaving_view)
