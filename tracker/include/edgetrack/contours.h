// SPDX-License-Identifier: BSD-3-Clause
/// The pose-dependent outline of the curved primitives: a cylinder's two silhouette generator
/// lines (where the viewing rays from the camera centre graze its side, ViSP's limbs in
/// vpMbtDistanceCylinder) and a circle's polygon, as 3D segments in the model frame.
#pragma once

#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// A straight piece of a tracked primitive's outline, model frame.
struct ContourSegment {
  Vec3 a;
  Vec3 b;
  int primitive = 0;  ///< see EdgeModel: the Edge-ID code and ControlPoint::edge
};

/// The two lines along which the planes through `camera_centre` (model frame) touch the
/// cylinder's side, each from the rim at axis_a to the rim at axis_b: with d the unit axis, w the
/// part of camera_centre - axis_a across the axis and D = |w|, the touching points on the rim
/// are axis_a + r (r/D w/D +- sqrt(1 - r^2/D^2) d x w/D). False, and nothing is set, when the
/// camera is inside or on the cylinder's surface (D <= r): then no silhouette exists.
bool cylinder_generators(const Cylinder& cylinder, const Vec3& camera_centre, Vec3 (&lines)[2][2]);

/// True when the side of `cylinder` cannot hide `rim_point`, a point of the circle closing its
/// end at `cap_centre`: the cap faces the camera, or the side next to the point does (the
/// outward radius u there has u . (camera_centre - cap_centre) > r).
bool cap_rim_clear_of_side(const Cylinder& cylinder, const Vec3& cap_centre, const Vec3& rim_point,
                           const Vec3& camera_centre);

/// The camera centre in the model frame, -R^T t.
Vec3 camera_centre_in_model(const Se3& camera_from_model);

/// Replaces `out` with the segments of the curved primitives seen from camera_from_model: the two
/// silhouette lines of each cylinder (skipped when the camera is inside it) and the kCircleSides
/// sides of each circle's polygon. The model's straight edges are not included.
void curved_contours(const EdgeModel& model, const Se3& camera_from_model, std::vector<ContourSegment>& out);

}  // namespace edgetrack
