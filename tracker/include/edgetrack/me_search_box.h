// SPDX-License-Identifier: BSD-3-Clause
/// The pixels the moving-edge step reads around one control point, so the grey step can convert
/// only those (on-demand grey scaling, grey_conversion.h).
#pragma once

#include <vector>

#include "edgetrack/control_points.h"
#include "visp3/me/vpMe.h"

namespace edgetrack {

/// Rows [top, bottom) x columns [left, right); may reach past the image (the caller clips).
struct PixelBox {
  int top = 0;
  int left = 0;
  int bottom = 0;
  int right = 0;
};

/// A box holding every pixel search_moving_edges reads for `point`: the masks of all candidates
/// within +-range along the normal (vpMeSite::getSearchBox's box) and of the sub-pixel
/// refinement's two neighbours of the found pixel. Computed from the unit normal without
/// trigonometry; see the .cpp for why the margin covers the site's own sine and cosine.
PixelBox me_search_box(const ControlPoint& point, const vpMe& me, unsigned int range);
/// me_search_box of each of `points`, in order, into `boxes` (sized to the points): one call per
/// frame, with what the points share taken once.
void me_search_boxes(const std::vector<ControlPoint>& points, const vpMe& me, unsigned int range,
                     std::vector<PixelBox>& boxes);

}  // namespace edgetrack
