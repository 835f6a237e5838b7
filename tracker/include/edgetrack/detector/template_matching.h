// SPDX-License-Identifier: BSD-3-Clause
/// Template matching over the response maps (response_maps.h): each template's score at every
/// position of the T-pixel grid, a feature at a time, each feature adding one contiguous run of
/// linearised memory; and the pose a match stands for.
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/detector/response_maps.h"
#include "edgetrack/detector/template_set.h"
#include "edgetrack/se3.h"

namespace edgetrack {

struct MatchParams {
  /// A template's score is the sum of its features' similarities over the best sum, 4 per
  /// feature; positions under this share are not candidates. 0.5 is, for instance, half the
  /// features on their orientation: the nearest template to a view is up to 10 degrees and 10 %
  /// of scale off it, and the light may leave an inner edge without contrast.
  real min_share = real(0.5);
  /// The best matches kept per distance of the range (one per template, at the template's best
  /// position). Per distance, because a small template (a far view) lines up with a part of a
  /// near object's edges as well as a near one with the whole: shares compare within a size.
  /// Three: the nearest template to the view is often not the best-scoring one at its distance
  /// (the light leaves an edge faint, clutter lines up with another view's edges).
  int max_candidates = 3;
};

struct TemplateMatch {
  int template_index = 0;
  int x = 0;  ///< the template's top-left corner, downscaled pixels (a multiple of T)
  int y = 0;
  int score = 0;  ///< sum of the features' similarities
  real share{0};  ///< score / (4 * features)
};

/// Scores every template at every grid position where it fits in the image; `out` gets, for each
/// distance, the best `max_candidates` templates' best positions, all sorted best first (ties:
/// the lower template index). `scores` (a byte per grid position, in words), `runs` and
/// `per_distance` are scratch.
void match_templates(const TemplateSet& set, const ResponseMaps& maps, const MatchParams& params,
                     std::vector<uint32_t>& scores, std::vector<const uint32_t*>& runs,
                     std::vector<std::vector<TemplateMatch>>& per_distance, std::vector<TemplateMatch>& out);

/// camera_from_model at full resolution for a match: the template's view turned so that the
/// model's centre lies on the ray through the matched anchor pixel, at the template's distance.
/// The spreading lets a feature find its edge up to T - 1 pixels right and below, so the anchor is
/// taken (T - 1) / 2 pixels on.
Se3 pose_of_match(const TemplateSet& set, const TemplateMatch& match, int t);

}  // namespace edgetrack
