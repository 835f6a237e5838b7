// SPDX-License-Identifier: BSD-3-Clause
/// The read box of one control point's moving-edge search.
#include "edgetrack/me_search_box.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/moving_edges.h"

namespace edgetrack {

PixelBox me_search_box(const ControlPoint& point, const vpMe& me) {
  using std::fabs;
  // The site (moving_edges.cpp) steps from pixel - range * (sin a, cos a) to pixel + range *
  // (sin a, cos a) with a = atan2(normal.y, normal.x) and truncates each candidate to whole
  // pixels; the candidates' extremes are the truncated end points. Here sin a and cos a are
  // replaced by the unit normal itself, which skips an atan2, a sine and a cosine per point
  // (about 1900 guest instructions in S40.23). They differ by rounding only, range times that
  // is far below a pixel, so each truncated end moves by at most one pixel: kSlack adds that
  // pixel. The sub-pixel refinement then reads around the found pixel, kRefinementReachAlong
  // pixels along the image axis nearest to the normal and kRefinementReachAcross across it
  // (moving_edges.h; the same axis test as moving_edges.cpp).
  constexpr int kSlack = 1;
  const bool along_x = fabs(point.normal.x) >= fabs(point.normal.y);
  const int reach_x = kSlack + (along_x ? kRefinementReachAlong : kRefinementReachAcross);
  const int reach_y = kSlack + (along_x ? kRefinementReachAcross : kRefinementReachAlong);
  const int range = static_cast<int>(me.getRange());
  const int size = static_cast<int>(me.getMaskSize());
  const int half = (size - 1) >> 1;
  const real di = range * point.normal.y, dj = range * point.normal.x;
  const int i_a = static_cast<int>(point.pixel.y - di), i_b = static_cast<int>(point.pixel.y + di);
  const int j_a = static_cast<int>(point.pixel.x - dj), j_b = static_cast<int>(point.pixel.x + dj);
  PixelBox box;
  box.top = std::min(i_a, i_b) - half - reach_y;
  box.bottom = std::max(i_a, i_b) - half + size + reach_y;
  box.left = std::min(j_a, j_b) - half - reach_x;
  box.right = std::max(j_a, j_b) - half + size + reach_x;
  return box;
}

}  // namespace edgetrack
