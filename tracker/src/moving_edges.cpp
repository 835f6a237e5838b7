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
      : response_(site.response(grey, &me)), along_x_(along_x) {}
  int at(int u, int v) const {
    const int value = along_x_ ? response_.at(v, u) : response_.at(u, v);
    return value < 0 ? -value : value;
  }

 private:
  const vpMeResponse response_;
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

/// The sub-pixel edge point near the site's pixel (site.i, site.j), which the caller has set.
/// The site keeps a whole pixel of its path, and which pixel that is (which row, for a mostly
/// vertical edge) flips with a rounding-size move of the control point. So the edge is located
/// on the three lines of the axis nearest to the normal around that pixel (a ridge each), and
/// the match is where the control point's normal line crosses the polyline through those
/// ridges: a continuous function of the control point.
Vec2 refined_edge_point(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, const ControlPoint& point) {
  using std::fabs;
  const bool along_x = fabs(point.normal.x) >= fabs(point.normal.y);
  const int u_site = along_x ? site.get_j() : site.get_i(), v_site = along_x ? site.get_i() : site.get_j();
  const AxisLikelihood likelihood(site, grey, me, along_x);
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
  return along_x ? Vec2{u, v} : Vec2{v, u};
}

/// A local maximum of the likelihood on a site's search path, at a whole pixel.
struct PathPeak {
  int likelihood = 0;
  int i = 0;
  int j = 0;
};

/// Calls visit(conv, i, j) at each local maximum, in path order, of the likelihood |2 conv| above
/// the threshold on the site's search path: the 2 range + 1 candidates pixel + k normal,
/// |k| <= range, truncated to whole pixels, as vpMeSite::track visits them but with the unit
/// normal in place of (cos alpha, sin alpha), which saves a sine and a cosine per point and
/// differs by rounding only. conv is the signed mask response; a path end counts as a maximum
/// when its one neighbour is lower, as the site's search keeps an end.
template <class Visit>
void for_each_path_peak(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, const ControlPoint& point,
                        Visit visit) {
  const int range = static_cast<int>(me.getRange());
  const real threshold = me.getThreshold();
  const vpMeResponse response = site.response(grey, &me);
  auto conv_at = [&](int k, int& i, int& j) {
    i = static_cast<int>(point.pixel.y + k * point.normal.y);
    j = static_cast<int>(point.pixel.x + k * point.normal.x);
    return response.at(i, j);
  };
  int i = 0, j = 0, next_i = 0, next_j = 0;
  int current_conv = conv_at(-range, i, j);
  int before = -1, current = current_conv < 0 ? -2 * current_conv : 2 * current_conv;
  for (int k = -range; k <= range; ++k) {
    const int after_conv = k < range ? conv_at(k + 1, next_i, next_j) : 0;
    const int after = k < range ? (after_conv < 0 ? -2 * after_conv : 2 * after_conv) : -1;
    if (current > before && current >= after && real(current) > threshold) visit(current_conv, i, j);
    before = current;
    current = after;
    current_conv = after_conv;
    i = next_i;
    j = next_j;
  }
}

/// The strongest local maxima of for_each_path_peak (at most `capacity`, strongest first, ties
/// in path order). Returns the count.
int path_peaks(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, const ControlPoint& point,
               PathPeak* peaks, int capacity) {
  int count = 0;
  for_each_path_peak(site, grey, me, point, [&](int conv, int i, int j) {
    const int likelihood = conv < 0 ? -2 * conv : 2 * conv;
    int at = count < capacity ? count++ : capacity;  // insertion into the sorted list
    while (at > 0 && peaks[at - 1].likelihood < likelihood) {
      if (at < capacity) peaks[at] = peaks[at - 1];
      --at;
    }
    if (at < capacity) peaks[at] = {likelihood, i, j};
  });
  return count;
}

/// Adds the weaker local maxima of the site's path as alternatives of `match` (up to
/// hypotheses - 1), each refined as the strongest is. Only maxima of at least half the
/// strongest likelihood compete (weaker ones are mostly noise and background texture, which
/// the pose step would otherwise fit), and a maximum whose refined point lies within a pixel
/// (along the normal) of one already kept is the same edge reached again.
void add_alternatives(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, int hypotheses,
                      EdgeMatch& match) {
  using std::fabs;
  PathPeak peaks[kMaxHypotheses + 1];
  const int strongest_i = site.get_i(), strongest_j = site.get_j();
  const int count = path_peaks(site, grey, me, match.point, peaks, hypotheses + 1);
  for (int p = 0; p < count && match.alternative_count < hypotheses - 1; ++p) {
    if (2 * peaks[p].likelihood < peaks[0].likelihood) break;  // too weak to compete
    if (peaks[p].i == strongest_i && peaks[p].j == strongest_j) continue;
    site.i = peaks[p].i;
    site.j = peaks[p].j;
    const Vec2 q = refined_edge_point(site, grey, me, match.point);
    bool known = fabs(dot(match.point.normal, q - match.found)) < real(1);
    for (int a = 0; a < match.alternative_count && !known; ++a)
      known = fabs(dot(match.point.normal, q - match.alternatives[a])) < real(1);
    if (!known) match.alternatives[match.alternative_count++] = q;
  }
}

/// +1 or -1: the sign that orients vpMe's mask for the normal angle `alpha` along the normal.
/// vpMe::maskIndex folds the tangent angle alpha + pi/2 into [0, pi) (180 degrees is mask 0),
/// and each fold by pi turns the mask, and so the response's sign, over.
int normal_sign(const real& alpha) {
  using std::round;
  real theta = alpha + real(M_PI_2);
  int sign = 1;
  if (theta < real(0)) {
    theta += real(M_PI);
    sign = -sign;
  }
  if (theta > real(M_PI)) {
    theta -= real(M_PI);
    sign = -sign;
  }
  if (static_cast<int>(round(theta * real(180 / M_PI))) == 180) sign = -sign;
  return sign;
}

/// The site's pixel by upstream's contrast test against `reference`, the oriented contrast
/// (EdgeMatch::contrast) the same model point showed in the last trusted frame: of the local
/// maxima of for_each_path_peak, those
/// whose conv has the reference's sign and lies within (1 - mu1, 1 + mu2) times it, and of
/// those the strongest. (Upstream takes the pixel whose contrast is nearest to the reference:
/// where a face turns into view beside a silhouette, its far edge has the silhouette's old
/// contrast, and on the generated frames that rule followed it off the cube.) False when none
/// passes (the site's pixel is then left anywhere on the path).
bool track_by_contrast(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, const ControlPoint& point,
                       const real& reference) {
  using std::fabs;
  const real least = (real(1) - me.getMu1()) * fabs(reference), most = (real(1) + me.getMu2()) * fabs(reference);
  const bool positive = reference > real(0);
  int best = 0, best_i = 0, best_j = 0, best_conv = 0;
  for_each_path_peak(site, grey, me, point, [&](int conv, int i, int j) {
    const int magnitude = conv < 0 ? -conv : conv;
    if ((conv > 0) != positive || !(real(magnitude) > least && real(magnitude) < most) || magnitude <= best) return;
    best = magnitude;
    best_i = i;
    best_j = j;
    best_conv = conv;
  });
  if (best == 0) return false;
  site.i = best_i;
  site.j = best_j;
  site.convlt = real(best_conv);
  site.setState(vpMeSite::NO_SUPPRESSION);
  return true;
}

/// The site's search: the contrast test with a reference (track_by_contrast), else, or when no
/// edge passes it (the edge's look changed: a new background behind a silhouette, a shadow), the
/// strongest edge within the range, as the paper's tracker takes; a strict reference (borrowed
/// from the primitive for a point not seen last time) leaves the site unmatched instead.
void track_site(vpMeSite& site, const vpImage<unsigned char>& grey, const vpMe& me, const ControlPoint& point,
                const real& alpha, int sign, const real& reference, bool strict) {
  site.init(point.pixel.y, point.pixel.x, alpha, real(0), sign);
  if (reference != real(0) && track_by_contrast(site, grey, me, point, reference)) return;
  if (reference != real(0) && strict) {
    site.setState(vpMeSite::CONSTRAST);
    return;
  }
  site.track(grey, &me, false);
}

}  // namespace

void contrasts_at_points(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points, const vpMe& me,
                         std::vector<real>& out) {
  using std::atan2;
  out.assign(points.size(), real(0));
  for (size_t p = 0; p < points.size(); ++p) {
    const ControlPoint& point = points[p];
    const real alpha = atan2(point.normal.y, point.normal.x);
    vpMeSite site;
    site.init(point.pixel.y, point.pixel.x, alpha, real(0), normal_sign(alpha));
    out[p] = site.convolution(grey, &me);
  }
}

std::vector<EdgeMatch> search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                                           const vpMe& me, int hypotheses, const std::vector<real>* references,
                                           const std::vector<unsigned char>* strict) {
  std::vector<EdgeMatch> matches;
  search_moving_edges(grey, points, me, hypotheses, matches, references, strict);
  return matches;
}

void search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points, const vpMe& me,
                         int hypotheses, std::vector<EdgeMatch>& matches, const std::vector<real>* references,
                         const std::vector<unsigned char>* strict) {
  using std::atan2;
  matches.clear();
  matches.reserve(points.size());
  for (size_t p = 0; p < points.size(); ++p) {
    const ControlPoint& point = points[p];
    vpMeSite site;
    const real alpha = atan2(point.normal.y, point.normal.x);
    const int sign = normal_sign(alpha);
    track_site(site, grey, me, point, alpha, sign, references ? (*references)[p] : real(0),
               strict && (*strict)[p] != 0);
    if (site.getState() != vpMeSite::NO_SUPPRESSION) continue;
    const int strongest_i = site.get_i(), strongest_j = site.get_j();
    matches.emplace_back();
    EdgeMatch& match = matches.back();
    match.point = point;
    match.contrast = site.convlt;
    match.found = refined_edge_point(site, grey, me, point);
    if (hypotheses > 1) {
      site.i = strongest_i;
      site.j = strongest_j;
      add_alternatives(site, grey, me, hypotheses, match);
    }
  }
}

}  // namespace edgetrack
