// SPDX-License-Identifier: BSD-3-Clause
/// Matches on a thin dark line beside an edge rather than on the edge itself (issue #27, drift
/// in clutter). A line a pixel or two wide has the polarity of the object's boundary on one of
/// its sides, so the contrast test passes it; what an edge between two surfaces does not show is
/// the intensity coming back: a few pixels into the darker side, a line is over and the image
/// is about as bright as on the brighter side again, while behind an object's boundary the darker
/// surface goes on.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/edge_match.h"
#include "edgetrack/thin_line_params.h"
#include "visp3/core/vpImage.h"

namespace edgetrack {

/// Whether the grey profile through `at` along `normal` looks like a thin dark line's side:
/// `brighter_along_normal` says which side the edge's brighter one is. A profile that leaves
/// the image counts as no line.
bool on_thin_line(const vpImage<unsigned char>& grey, const Vec2& at, const Vec2& normal, bool brighter_along_normal,
                  const ThinLineParams& params);

/// Each match whose `found` lies on a thin line takes its first alternative that does not; a
/// match left with none is removed. Returns the number of matches that changed or went.
int reject_thin_line_matches(const vpImage<unsigned char>& grey, std::vector<EdgeMatch>& matches,
                             const ThinLineParams& params);

}  // namespace edgetrack
