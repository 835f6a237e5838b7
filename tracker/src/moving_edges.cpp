// SPDX-License-Identifier: BSD-3-Clause
/// The moving-edge search per control point, on the ported vpMeSite.
#include "edgetrack/moving_edges.h"

#include <cmath>

namespace edgetrack {

namespace {

/// |mask response| at pixel (i, j) for the site's orientation; 0 near the border.
int likelihood_at(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, int i, int j) {
  site.i = i;
  site.j = j;
  const real conv = site.convolution(grey, &me);
  const int value = static_cast<int>(conv);
  return value < 0 ? -value : value;
}

}  // namespace

std::vector<EdgeMatch> search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                                           const vpMe& me) {
  using std::atan2;
  using std::fabs;
  std::vector<EdgeMatch> matches;
  matches.reserve(points.size());
  for (const ControlPoint& point : points) {
    vpMeSite site;
    site.init(point.pixel.y, point.pixel.x, atan2(point.normal.y, point.normal.x));
    site.track(grey, &me, false);
    if (site.getState() != vpMeSite::NO_SUPPRESSION) continue;
    // Sub-pixel refinement: a parabola through the likelihoods at the best pixel and its two
    // neighbours along the image axis nearest to the normal.
    const int i = site.get_i(), j = site.get_j();
    const bool along_x = fabs(point.normal.x) >= fabs(point.normal.y);
    const int di = along_x ? 0 : 1, dj = along_x ? 1 : 0;
    const int centre = likelihood_at(site, grey, me, i, j);
    const int before = likelihood_at(site, grey, me, i - di, j - dj);
    const int after = likelihood_at(site, grey, me, i + di, j + dj);
    real offset(0);
    const int curvature = before - 2 * centre + after;
    if (curvature < 0 && centre >= before && centre >= after)
      offset = real(before - after) / (2 * curvature);  // in [-0.5, 0.5] at a maximum
    Vec2 found{real(j), real(i)};
    if (along_x) found.x = found.x + offset;
    else found.y = found.y + offset;
    matches.push_back({point, found, false});
  }
  return matches;
}

}  // namespace edgetrack
