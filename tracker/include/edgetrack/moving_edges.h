// SPDX-License-Identifier: BSD-3-Clause
/// Matching: one moving-edge site (our port of ViSP's vpMeSite) per control point, searching the
/// grey image along the projected edge's normal (paper, section 2).
#pragma once

#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_match.h"
#include "edgetrack/tracker_params.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"

namespace edgetrack {

/// vpMe holding `params` (its range is not read: each search takes its own), with its masks
/// built; the tracker builds it once per settings.
vpMe moving_edge_masks(const MovingEdgeParams& params);

/// How far the sub-pixel refinement reads from the site's pixel, in whole pixels, besides the
/// mask around each read: along the image axis nearest to the normal (a climb of up to 2 pixels
/// and the parabola's neighbour) and across it (the lines either side). me_search_box.h must
/// cover these for the on-demand grey step.
constexpr int kRefinementReachAlong = 3;
constexpr int kRefinementReachAcross = 1;

/// Runs vpMeSite::track's search at every control point: a site at the point's pixel with the
/// normal angle alpha = atan2(n_y, n_x) (its mask from the normal itself, normal_mask.h; its
/// path along the unit normal) keeps the strongest edge within +-range pixels that
/// passes the likelihood threshold, or with a reference contrast (below) the edge that passes
/// the contrast test. The match is then refined to
/// sub-pixel precision (not in ViSP, which keeps whole pixels): on the line of the image axis
/// nearest to the normal through the site's pixel and on the two lines beside it, the edge's
/// position is the likelihood's local maximum (climbing up to 2 pixels from the site's column
/// or row) refined by a parabola through it and its two neighbours; the match is where the
/// control point's normal crosses the polyline through those three positions (the middle one
/// alone when a side line's peak is under half the middle one). Unlike the site's whole pixel,
/// which jumps when a rounding-size move of the control point changes the truncated path, this
/// moves continuously with the control point, so double and fixed-point builds agree. Returns
/// only the matched points.
///
/// With `hypotheses` > 1 (at most kMaxHypotheses; Wuest et al.'s multiple-hypothesis edge
/// tracking, ViSP 3.7's vpMeSite::trackMultipleHypotheses), each match also keeps up to
/// hypotheses - 1 alternatives: the next strongest local maxima of the likelihood along the
/// site's path that pass the threshold and reach half the strongest one's likelihood, each
/// refined as above, a pixel or more apart along the normal. (ViSP keeps the strongest
/// candidates of the path, which are mostly the neighbours of one peak.) The pose step chooses
/// among them (EdgeMatch::chosen); `found` is the strongest, so hypotheses = 1 is the
/// single-hypothesis search.
///
/// `references` (one per point, 0: none) are the contrasts the contrast test compares with
/// (contrast_memory.h); where none passes, the site takes the strongest edge, unless `strict`
/// marks the point (nonzero): its reference is its primitive's, borrowed because the point
/// itself was not seen in the last trusted frame (ContrastMemory::references), and the point
/// then gets no match.
std::vector<EdgeMatch> search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                                           const vpMe& me, unsigned int range, int hypotheses = 1,
                                           const std::vector<real>* references = nullptr,
                                           const std::vector<unsigned char>* strict = nullptr);
/// The same into `matches` (its earlier matches replaced, memory reused).
void search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points, const vpMe& me,
                         unsigned int range, int hypotheses, std::vector<EdgeMatch>& matches, const std::vector<real>* references = nullptr,
                         const std::vector<unsigned char>* strict = nullptr);

/// The mask response at each point's own pixel, oriented along its normal (EdgeMatch::contrast):
/// the contrast of the edge where a trusted pose projects it.
void contrasts_at_points(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points, const vpMe& me,
                         std::vector<real>& out);

}  // namespace edgetrack
