// SPDX-License-Identifier: BSD-3-Clause
/// Prints the markdown rows of tracking_eval's status table: each case of status_cases.h (noise,
/// flat, fully covered, leaving the view) tracked from the true first pose with the defaults:
/// the frames lost and uncertain, the first frame without a trackable object against the first
/// lost one, the frames lost outside the bad ones, the largest overlay offset of a frame
/// reported tracked, and how many frames after the object is visible again a frame is tracked within
/// 1 mm of the truth.
#include <cstdio>

#include "run_sequence.h"
#include "status_cases.h"

using namespace edgetrack;
using namespace edgetrack_test;

int main() {
  for (const StatusCase& c : status_cases()) {
    const SequenceRun run = run_sequence(Scene::kCube, c.frames, false, TrackerParams{}, c.spec);
    if (!run.loaded) {
      std::fprintf(stderr, "bench_status_cases: %s: the sequence did not run\n", c.name.c_str());
      return 1;
    }
    const StatusOutcome o = status_outcome(c, run);
    int retried = 0;
    for (const FrameResult& f : run.frames) retried += f.retried;
    const bool returns = c.visible_again < c.frames;
    char bad[32], back[48];
    std::snprintf(bad, sizeof bad, returns ? "%d-%d" : "%d-", c.first_bad, c.visible_again - 1);
    if (!returns) std::snprintf(back, sizeof back, "-");
    else if (o.back < 0) std::snprintf(back, sizeof back, "never");
    else std::snprintf(back, sizeof back, "%d (%d), %.2f mm", o.back - c.visible_again, o.back, o.worst_after_back_mm);
    std::printf("| %s | %d | %s | %d | %d | %d | %d | %d | %.2f | %s | %d |\n", c.name.c_str(), c.frames, bad, o.first_lost,
                o.lost, o.uncertain, o.missed, o.wrongly_lost, o.worst_tracked_px, back, retried);
  }
  return 0;
}
