// SPDX-License-Identifier: BSD-3-Clause
/// Matching: one moving-edge site (our port of ViSP's vpMeSite) per control point, searching the
/// grey image along the projected edge's normal (paper, section 2).
#pragma once

#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_match.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeSite.h"

namespace edgetrack {

/// Runs vpMeSite::track at every control point: the site starts at the point's pixel with the
/// normal angle alpha = atan2(n_y, n_x) and keeps the strongest edge within +-me.getRange()
/// pixels that passes the likelihood threshold (no contrast test: sites are re-sampled every
/// frame, so there is no previous contrast to compare with). The found pixel is then refined to
/// sub-pixel precision by a parabola through the likelihoods of it and its two neighbours along
/// the image axis nearest to the normal (not in ViSP, which keeps whole pixels). Returns only the
/// matched points (state NO_SUPPRESSION).
std::vector<EdgeMatch> search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                                           const vpMe& me);

}  // namespace edgetrack
