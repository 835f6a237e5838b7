// SPDX-License-Identifier: BSD-3-Clause
/// Control points: the model edges projected with the current pose and sampled evenly in the
/// image, n = edge length / sampling step (the paper's equation (1)), keeping the points the
/// Edge-ID buffer shows as visible.
#pragma once

#include <vector>

#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/face_visibility.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

struct ControlPoint {
  int edge = 0;          ///< the primitive's number (EdgeModel): an edge, a cylinder silhouette or a circle
  Vec3 point_in_model;   ///< the 3D point on the edge
  Vec2 pixel;            ///< where it projects with the sampling pose
  Vec2 direction;        ///< unit direction of the projected edge
  Vec2 normal;           ///< unit normal of the projected edge: direction turned by +90 degrees
};

/// The sampling step's inputs. The tracker builds them from its settings (TrackerParams); they
/// are not settings of their own.
struct SamplingParams {
  real step = real(10);    ///< pixels between control points (the paper's 10)
  int border = 10;         ///< points nearer the image border than this (pixels) are dropped
  ViewClipping clipping;   ///< the part of each edge that is sampled
  /// The most points one call keeps (0: no maximum); the points past it are counted, not kept.
  size_t max_points = 0;
};

/// Samples the part of every edge that params.clipping keeps (at least the part 1 cm in front
/// of the camera): n = floor(projected length / step) points at the
/// centres of n equal parts of the projected segment, each lifted back to the 3D edge with the
/// perspective-correct parameter. Each cylinder's two silhouette generator lines at this pose
/// (contours.h) are sampled the same way: a fixed point on the current generator is right to
/// first order for the moving silhouette, since the surface there is tangent to the viewing
/// ray, so a small move of the touching point along the surface leaves its image unchanged.
/// Circles are sampled every step pixels along their projected rim (ViSP steps by degrees
/// instead), each point on the true circle with the normal of the projected ellipse there.
/// Points within params.border of the image border are dropped. Visibility is not checked here.
std::vector<ControlPoint> sample_control_points(const EdgeModel& model, const PinholeCamera& camera,
                                                const Se3& camera_from_model, const SamplingParams& params);
/// The same into `points` (emptied first; its memory is reused, so a caller that keeps it
/// allocates only while the point count grows). Returns the points params.max_points left out.
size_t sample_control_points(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                             const SamplingParams& params, std::vector<ControlPoint>& points);
/// The same for only the primitives `faces` tracks (FaceVisibility::edge_tracked); the others
/// are not sampled at all.
size_t sample_control_points(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                             const SamplingParams& params, const FaceVisibility& faces,
                             std::vector<ControlPoint>& points);

/// Each of some points (control points) in the camera frame at a pose, whether it is in front of
/// the camera, and where it projects then (else (0, 0)): the frame's status measures and the
/// contrast memory share one transform per point, and through a lens one projection.
struct ProjectedPoints {
  std::vector<Vec3> in_camera;
  std::vector<Vec2> pixel;
  std::vector<unsigned char> in_front;
};
void project_points(const std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& camera_from_model,
                    ProjectedPoints& out);

/// Keeps the points whose own edge the Edge-ID buffer shows at their pixel.
std::vector<ControlPoint> keep_visible(const std::vector<ControlPoint>& points, const EdgeIdBuffer& edge_ids);
/// The same into `visible` (emptied first, memory reused).
void keep_visible(const std::vector<ControlPoint>& points, const EdgeIdBuffer& edge_ids,
                  std::vector<ControlPoint>& visible);
/// The same in place, in the same order: one buffer for the sampled and the visible points.
void keep_visible(std::vector<ControlPoint>& points, const EdgeIdBuffer& edge_ids);

}  // namespace edgetrack
