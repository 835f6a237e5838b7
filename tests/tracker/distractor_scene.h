// SPDX-License-Identifier: BSD-3-Clause
/// Generated sequences with parallel edges close to the tracked ones: the scene is the tracked
/// model plus a thin bar beside each of its edges, rendered together by the test-image renderer,
/// while the tracker follows the plain model.
#pragma once

#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"

namespace edgetrack_test {

/// The model plus, beside each tracked edge, a flat bar `width` metres wide and as long as the
/// edge, in the plane of the edge's first face, parallel to the edge at `offset` metres beyond
/// it: a second and a third edge parallel to the tracked one a few pixels away, outside the
/// silhouette or over the neighbouring face, which hide none of the model's own edges.
edgetrack::EdgeModel with_distractor_bars(const edgetrack::EdgeModel& model, real offset,
                                          real width);

struct DistractorRun {
  bool loaded = false;
  std::vector<edgetrack::Se3> poses;    ///< tracked camera_from_model per frame
  std::vector<double> position_error_mm;  ///< |camera position - true camera position| per frame
  double mean_position_error_mm = 0;
  double largest_position_error_mm = 0;
  double mean_alternatives = 0;  ///< alternatives per match, mean over the frames
};

/// Tracks `frames` frames of the scene rendered with distractor bars, from the true first pose.
DistractorRun run_with_distractors(Scene scene, int frames, const edgetrack::TrackerParams& params,
                                   real offset, real width);

}  // namespace edgetrack_test
