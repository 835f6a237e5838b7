// SPDX-License-Identifier: BSD-3-Clause
/// Whether the image supports a pose along the whole of its projected edges, not only at the
/// matches the pose was solved from: the image gradient at every visible control point,
/// projected with the pose, against the projected edge's normal (docs/ARCHITECTURE.md,
/// "Tracking status"). Integer and `real` arithmetic only, no arctangent from libm.
#pragma once

#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/me_search_box.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"
#include "real/real.h"
#include "visp3/core/vpImage.h"

namespace edgetrack {

struct EdgeSupport {
  int visible = 0;    ///< control points looked at
  int measured = 0;   ///< of those, the ones with a gradient over the floor where the pose projects them
  int supported = 0;  ///< of those, the ones whose gradient lies within `support_angle_deg` of the normal
  /// Mean angle between the gradient and the projected normal over the measured points, degrees
  /// (0 to 90; 0 when none is measured): about 45 for orientations at chance.
  real mean_angle_deg{0};
};

/// The angle between (gx, gy) and the unit `normal`, folded into [0, 90] degrees (an edge's
/// gradient points either way along its normal): atan(min / max) of the gradient's components
/// across and along the normal, by a polynomial within 0.1 degree of the arctangent.
real gradient_normal_angle_deg(const real& gx, const real& gy, const Vec2& normal);

/// The support test of an angle bound, computed once per setting (support_bound): a gradient
/// whose magnitudes along and across the normal are along and across is within the bound when
/// across <= tangent along (a bound of at most 45 degrees), else when along >= tangent across
/// (tangent that of the bound's complement). The tangent is the one whose polynomial arctangent
/// is the angle, so the test is the angle's own verdict without its division.
struct SupportBound {
  real tangent{0};
  bool within_45 = true;
};
SupportBound support_bound(const real& support_angle_deg);

/// The support of `pose` along `points` (sampled at another pose, with their normals): the
/// Sobel gradient where each point's normal crosses its edge projected with `pose` (the
/// projected point moved back along the edge onto the normal), only inside the pixels the
/// moving edges read for it (`read_boxes`, one per point: the search's own me_search_box, where
/// the grey image is up to date); a point projected elsewhere, or into the image border, is not
/// measured. A point is measured where the Sobel gradient's magnitude reaches `gradient_floor`
/// and supported within `bound` (support_bound of StatusParams::support_angle_deg; StatusParams
/// says what the settings stand for).
/// `projected`, when given, holds project_points(points, camera, pose), which the frame's status
/// computes once (through a lens a projection is dear).
EdgeSupport edge_support(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                         const std::vector<PixelBox>& read_boxes, const PinholeCamera& camera, const Se3& pose,
                         const real& gradient_floor, const SupportBound& bound,
                         const ProjectedPoints* projected = nullptr);

}  // namespace edgetrack
