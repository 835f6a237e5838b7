// SPDX-License-Identifier: BSD-3-Clause
/// The read box of one control point's moving-edge search.
#include "edgetrack/me_search_box.h"

#include <cmath>

#include "edgetrack/moving_edges.h"

namespace edgetrack {

namespace {

/// me_search_box's body, inlined into both calls.
__attribute__((always_inline)) inline PixelBox search_box(const ControlPoint& point, const vpMe& me,
                                                          unsigned int search_range) {
  using std::fabs;
  // The site (moving_edges.cpp) puts its candidates at pixel + k normal, |k| <= range, truncated
  // to whole pixels, and convolves a mask_size mask whose top-left is half a mask before each.
  // The box's ends are computed differently from the candidates (range |n| here, k n there), so
  // they may differ by rounding, a few units in the last place of `real`, far below kRounding:
  // pushing each end out by range * kRounding keeps every candidate inside.
  constexpr real kRounding = real(1.0 / 1024);
  const int range = static_cast<int>(search_range);
  const int size = static_cast<int>(me.getMaskSize());
  const int half = (size - 1) >> 1;
  const real di = range * (fabs(point.normal.y) + kRounding), dj = range * (fabs(point.normal.x) + kRounding);
  PixelBox box;
  box.top = static_cast<int>(point.pixel.y - di) - half;
  box.bottom = static_cast<int>(point.pixel.y + di) - half + size;
  box.left = static_cast<int>(point.pixel.x - dj) - half;
  box.right = static_cast<int>(point.pixel.x + dj) - half + size;
  // The sub-pixel refinement also reads around the found pixel, kRefinementReachAlong pixels
  // along the image axis nearest to the normal and kRefinementReachAcross across it
  // (moving_edges.h; the same axis test as moving_edges.cpp).
  const bool along_x = fabs(point.normal.x) >= fabs(point.normal.y);
  const int reach_x = along_x ? kRefinementReachAlong : kRefinementReachAcross;
  const int reach_y = along_x ? kRefinementReachAcross : kRefinementReachAlong;
  box.left -= reach_x;
  box.right += reach_x;
  box.top -= reach_y;
  box.bottom += reach_y;
  return box;
}

}  // namespace

PixelBox me_search_box(const ControlPoint& point, const vpMe& me, unsigned int range) {
  return search_box(point, me, range);
}

void me_search_boxes(const std::vector<ControlPoint>& points, const vpMe& me, unsigned int range,
                     std::vector<PixelBox>& boxes) {
  boxes.resize(points.size());
  for (size_t p = 0; p < points.size(); ++p) boxes[p] = search_box(points[p], me, range);
}

}  // namespace edgetrack
