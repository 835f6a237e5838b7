// SPDX-License-Identifier: BSD-3-Clause
/// The tracking-status cases of issue 10 on the generated QVGA cube: frames of noise, flat frames,
/// the object fully covered for a few frames, and the object leaving the view; shared by
/// test_tracking_status.cxx (which checks them) and tests/bench/tracking_eval (which tables them).
#pragma once

#include <string>
#include <vector>

#include "run_sequence.h"

namespace edgetrack_test {

struct StatusCase {
  std::string name;
  int frames = 0;
  SequenceSpec spec;
  /// Frames [first_bad, visible_again) show no trackable object; visible_again = frames when it
  /// does not come back (the leaving view: first_bad is the first frame with too few control
  /// points left at the true pose).
  int first_bad = 0;
  int visible_again = 0;
  /// Frames before first_bad in which the whole object is in view (the leaving view); the
  /// others are interrupted, and every frame before first_bad shows the whole object.
  int wholly_in_view = 0;
};

/// Noise at 10-11, flat at 10-11 and covered at 12-14 in 30 frames; leaving the view in 40.
std::vector<StatusCase> status_cases();

/// What a run of a case did.
struct StatusOutcome {
  int lost = 0;             ///< frames reported lost
  int uncertain = 0;        ///< frames reported uncertain
  /// The largest overlay offset of a frame reported tracked: the farthest a model vertex in the
  /// image is drawn from its true projection, pixels.
  double worst_tracked_px = 0;
  int first_lost = -1;      ///< the first lost frame (-1: none)
  int missed = 0;           ///< frames in [first_bad, visible_again) not reported lost
  int wrongly_lost = 0;     ///< lost frames outside it (the leaving view: among the wholly-in-view frames)
  /// The first frame from visible_again on that is tracked within 1 mm of the truth (-1: none,
  /// or the object does not come back).
  int back = -1;
  double worst_after_back_mm = 0;  ///< the largest position error from `back` on
};

StatusOutcome status_outcome(const StatusCase& c, const SequenceRun& run);

}  // namespace edgetrack_test
