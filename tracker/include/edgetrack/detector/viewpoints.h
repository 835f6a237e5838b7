// SPDX-License-Identifier: BSD-3-Clause
/// The viewpoints templates are made from: directions on a sphere around the model (the vertices
/// of a subdivided icosahedron, nearly even), optionally inside a cone, times in-plane rotations
/// about the optical axis, times distances spaced by a constant ratio.
#pragma once

#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/input_file.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The range of views templates cover.
struct ViewRange {
  /// Icosahedron subdivisions: 0 gives 12 directions (63 degrees apart), 1 gives 42 (about 32),
  /// 2 gives 162 (about 16), 3 gives 642 (about 8).
  int subdivisions = 2;
  /// The directions kept: within max_angle (radians) of `axis` (model frame, from the model's
  /// centre towards the camera). pi keeps the whole sphere.
  Vec3 axis{real(0), real(0), real(1)};
  real max_angle = real(3.141592653589793);
  /// Rotations about the optical axis per direction, evenly over the full turn (18: 20 degrees
  /// apart, so the nearest is at most 10 degrees off, as the directions are).
  int in_plane_steps = 18;
  /// Camera distances to the model's centre (metres); 0 and 0: from the camera and the model's
  /// size (model_distances).
  real distance_min{0};
  real distance_max{0};
  /// Successive distances differ by this factor (1.1: the image scale of the nearest template is
  /// at most 5 % off, a few pixels at the object's outline, which the refinement's search
  /// reaches; at 1.2, 10 %, the refinement failed twice as often on the generated cube).
  real distance_ratio = real(1.1);
};

/// The centre of the model's bounding box and the largest distance from it to a vertex.
struct ModelExtent {
  Vec3 centre;
  real radius{0};
};
ModelExtent model_extent(const EdgeModel& model);

/// Unit directions: the vertices of the icosahedron subdivided `subdivisions` times.
std::vector<Vec3> sphere_directions(int subdivisions);

/// The camera distances to the model's centre (metres) at which the model's bounding sphere
/// spans `largest_share` of the image's shorter side (`nearest`) and `smallest_share` of it
/// (`farthest`).
void span_distances(const PinholeCamera& camera, const ModelExtent& extent, const real& largest_share,
                    const real& smallest_share, real& nearest, real& farthest);

/// The views automatic initialisation searches when it is told nothing of the distance (a user's
/// files as shipped): the default directions and in-plane steps, at every camera distance at which
/// the model's bounding sphere spans between the whole of the image's shorter side and a tenth
/// of it. Wider than the templates' own default (80 % to 40 %), which assumes a framed object.
ViewRange auto_init_views(const PinholeCamera& camera, const ModelExtent& extent);

/// Distances from min to max (each ratio times the last, the last one not past max by more than
/// the ratio's half); when range.distance_min is 0, min and max are where the model's bounding
/// sphere spans 80 % and 40 % of the image's shorter side.
std::vector<real> view_distances(const ViewRange& range, const PinholeCamera& camera, const ModelExtent& extent);

/// The most bytes one template takes in a template file: at most 63 features.
constexpr long long kMaxTemplateFileLineBytes = 900;
/// The most views a template range may ask for (distances x directions x in-plane steps): each
/// gives at most one template, so the largest file `templates` writes stays within what
/// `detect --templates` reads (kMaxTextFileBytes, 64 MiB, less 4 KiB for the header): 74560,
/// above the 72900 of the default range `--init-auto` derives from the camera and the model.
constexpr long long kMaxTemplateViews =
    (static_cast<long long>(kMaxTextFileBytes) - 4096) / kMaxTemplateFileLineBytes;
/// The model's image (its bounding sphere's diameter) at the farthest distance, at least.
constexpr int kMinModelPixels = 16;

/// The number of views of the range, counted before any is made; an Error when the camera would
/// be inside the model's bounding sphere at the nearest distance, the model would span fewer
/// than kMinModelPixels at the farthest, or the views are more than kMaxTemplateViews.
Result<long long> checked_view_count(const ViewRange& range, const PinholeCamera& camera, const ModelExtent& extent);

/// camera_from_model looking at the model's centre from `direction` (unit, model frame) at
/// `distance`, turned by `in_plane` radians about the optical axis: the centre is on the
/// optical axis at depth `distance`.
Se3 view_pose(const Vec3& direction, const real& in_plane, const real& distance, const Vec3& centre);

struct ViewPose {
  Se3 camera_from_model;
  int distance_index = 0;  ///< into view_distances
};

/// Every pose of the range, distances outermost, then directions, then in-plane rotations.
std::vector<ViewPose> view_poses(const ViewRange& range, const PinholeCamera& camera, const ModelExtent& extent);

}  // namespace edgetrack
