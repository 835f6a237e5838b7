// SPDX-License-Identifier: BSD-3-Clause
/// The moving-edge search per control point, on the ported vpMeSite, with a sub-pixel
/// refinement that varies continuously with the control point.
#include "edgetrack/moving_edges.h"

#include <cmath>

namespace edgetrack {

namespace {

/// Pixels a ridge search may climb from its start to reach the likelihood's local maximum; it
/// then reads one more for the parabola (kRefinementReachAlong in the header).
constexpr int kMaxClimb = kRefinementReachAlong - 1;

/// Reads |mask response| with the site's orientation in "axis" coordinates: u along the image
/// axis nearest to the normal, v along the other one. 0 near the border.
class AxisLikelihood {
 public:
  AxisLikelihood(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, bool along_x)
      : site_(site), grey_(grey), me_(me), along_x_(along_x) {}
  int at(int u, int v) const {
    site_.i = along_x_ ? v : u;
    site_.j = along_x_ ? u : v;
    const int value = static_cast<int>(site_.convolution(grey_, &me_));
    return value < 0 ? -value : value;
  }

 private:
  vpMeSite& site_;
  const vpImage<unsigned char>& grey_;
  const vpMe& me_;
  bool along_x_;
};

/// The edge's position on line v: from u, climbs (at most kMaxClimb pixels, ties towards lower
/// u, the same in every build) to a local maximum of the likelihood, then fits a parabola
/// through it and its two neighbours. `peak` receives the maximum's likelihood.
real ridge_on_line(const AxisLikelihood& likelihood, int u, int v, int& peak) {
  int centre = likelihood.at(u, v), before = likelihood.at(u - 1, v), after = likelihood.at(u + 1, v);
  for (int climb = 0; climb < kMaxClimb && (before > centre || after > centre); ++climb) {
    if (before >= after) {
      --u;
      after = centre;
      centre = before;
      before = likelihood.at(u - 1, v);
    } else {
      ++u;
      before = centre;
      centre = after;
      after = likelihood.at(u + 1, v);
    }
  }
  peak = centre;
  const int curvature = before - 2 * centre + after;
  if (curvature < 0 && centre >= before && centre >= after)
    return real(u) + real(before - after) / (2 * curvature);  // within half a pixel of u
  return real(u);
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
    // The site keeps a whole pixel of its path, and which pixel that is (which row, for a
    // mostly vertical edge) flips with a rounding-size move of the control point. So the edge
    // is located on the three lines of the axis nearest to the normal around that pixel (a
    // ridge each), and the match is where the control point's normal line crosses the
    // polyline through those ridges: a continuous function of the control point.
    const bool along_x = fabs(point.normal.x) >= fabs(point.normal.y);
    const AxisLikelihood likelihood(site, grey, me, along_x);
    const int u_site = along_x ? site.get_j() : site.get_i(), v_site = along_x ? site.get_i() : site.get_j();
    const real u0 = along_x ? point.pixel.x : point.pixel.y, v0 = along_x ? point.pixel.y : point.pixel.x;
    const real nu = along_x ? point.normal.x : point.normal.y, nv = along_x ? point.normal.y : point.normal.x;
    static_assert(kRefinementReachAcross == 1, "three lines: the site's and one either side");
    real ridge[3], side[3];  // side: (edge point - control point) . edge direction, 0 on the normal line
    int peak[3];
    for (int k = 0; k < 3; ++k) {
      ridge[k] = ridge_on_line(likelihood, u_site, v_site + k - 1, peak[k]);
      side[k] = nu * (real(v_site + k - 1) - v0) - nv * (ridge[k] - u0);
    }
    real u = ridge[1], v = real(v_site);
    // Both neighbours must show the same edge (at least half the peak) for the polyline.
    if (2 * peak[0] >= peak[1] && 2 * peak[2] >= peak[1]) {
      // side grows with v along a straight edge (d side / dv = 1 / nu): take the segment on
      // the side of the middle line where side changes sign. Where it does not (lines that
      // show different edges), the crossing is clamped to the segment's ends, which keeps the
      // match next to the site's pixel and still continuous.
      const int k = (side[1] > real(0)) == (nu > real(0)) ? 0 : 1;
      const real span = side[k] - side[k + 1];
      if (span != real(0)) {
        real t = side[k] / span;
        if (t < real(0)) t = real(0);
        if (t > real(1)) t = real(1);
        u = ridge[k] + t * (ridge[k + 1] - ridge[k]);
        v = real(v_site + k - 1) + t;
      }
    }
    const Vec2 found = along_x ? Vec2{u, v} : Vec2{v, u};
    matches.push_back({point, found, false});
  }
  return matches;
}

}  // namespace edgetrack
