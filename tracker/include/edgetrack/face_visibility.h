// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's face rules beside Edge-ID: a face seen almost edge-on stops being tracked (the angle
/// rule of vpMbtPolygon::isVisible with vpMbHiddenFaces' appear/disappear hysteresis), edges are
/// clipped to the near and far planes and to the field of view (vpPolygon3D's clipping), and
/// level of detail drops short free lines and small faces. Edge-ID stays the visibility test
/// for occlusion; these rules only take edges out.
#pragma once

#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The <face> and <lod> settings with ViSP's meanings; the defaults are vpMbTracker's (what
/// ViSP's edge tracker uses when a configuration file has no such block).
struct FaceVisibilityParams {
  /// A hidden face appears when the angle between its normal and the direction from its centre
  /// to the camera is below angle_appear; a visible one stays while that angle is below
  /// angle_disappear (radians; 89 degrees each by default).
  real angle_appear = real(1.5533430342749532);
  real angle_disappear = real(1.5533430342749532);
  bool near_clipping = false;  ///< when set, no part of an edge nearer than near_distance is sampled
  real near_distance = real(0.001);  ///< metres along the camera's z
  bool far_clipping = false;   ///< when set, no part of an edge farther than far_distance is sampled
  real far_distance = real(100);
  bool fov_clipping = false;   ///< edges are clipped to the image's field of view before sampling
  /// Level of detail: the two thresholds below apply. A face's or a free line's own .cao
  /// parameters (PrimitiveAttributes) take precedence over these three, as in ViSP.
  bool use_lod = false;
  real min_line_length = real(50);    ///< a free line shorter than this in the image is not tracked (pixels)
  real min_polygon_area = real(2500);  ///< a face smaller than this in the image is not visible (pixels^2)
};

/// The part of the view edges are sampled in.
struct ViewClipping {
  real near_distance = real(0.01);  ///< metres; always applied, so that every sampled point projects
  bool far_clipping = false;
  real far_distance = real(100);
  bool fov_clipping = false;
};

/// The clipping the sampler applies for `params`: ViSP's near plane when set (else 1 cm), its far
/// plane and its field of view.
ViewClipping view_clipping(const FaceVisibilityParams& params);

/// Clips the segment from a to b (camera frame) to the view: on true, the part kept runs from
/// a + t0 (b - a) to a + t1 (b - a), 0 <= t0 < t1 <= 1; false when nothing is left. The field of
/// view is bounded by the planes through the optical centre and the image borders u = 0,
/// u = width, v = 0, v = height (vpCameraParameters::computeFov).
bool clip_to_view(const Vec3& a, const Vec3& b, const PinholeCamera& camera, const ViewClipping& clipping, real& t0,
                  real& t1);

/// Which faces are visible and which edges are tracked, kept from frame to frame (the rule has
/// hysteresis). Every face starts hidden, as ViSP's polygons do, so the first frame uses
/// angle_appear.
class FaceVisibility {
 public:
  explicit FaceVisibility(const EdgeModel& model);

  /// Updates every face's state for the pose, then the edges: an edge bordering faces is
  /// tracked when at least one of them is visible (vpMbEdgeTracker); a free line always, or with
  /// use_lod when its clipped image is at least min_line_length long; a circle always, or with
  /// use_lod when the image of the square about it in its plane (ViSP's polygon of a circle)
  /// covers at least min_polygon_area; a cylinder always (ViSP: its polygons have no
  /// orientation, and level of detail never hides them).
  void update(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
              const FaceVisibilityParams& params);

  /// Every face hidden again, as in a new tracker.
  void reset();

  bool face_visible(int face) const { return face_visible_[static_cast<size_t>(face)] != 0; }
  /// Whether primitive `edge` (an edge, or a cylinder's generator or a circle, numbered after the
  /// edges: edge_model.h) is tracked, by the rules above.
  bool edge_tracked(int edge) const {
    return static_cast<size_t>(edge) >= edge_tracked_.size() || edge_tracked_[static_cast<size_t>(edge)] != 0;
  }

 private:
  bool face_passes(const EdgeModel& model, int face, const PinholeCamera& camera, const Se3& camera_from_model,
                   const real& cos_limit, const FaceVisibilityParams& params);
  real clipped_area(const EdgeModel& model, int face, const PinholeCamera& camera, const Se3& camera_from_model,
                    const ViewClipping& clipping);
  real clipped_square_area(const Circle& circle, const PinholeCamera& camera, const Se3& camera_from_model,
                           const ViewClipping& clipping);
  /// The image area of polygon_ (camera frame) clipped to the view.
  real clipped_polygon_area(const PinholeCamera& camera, const ViewClipping& clipping);

  std::vector<unsigned char> face_visible_;
  std::vector<unsigned char> edge_tracked_;  ///< per primitive: edges, cylinder sides, circles
  size_t edge_count_ = 0;
  std::vector<Vec3> polygon_;  ///< scratch for the face clipping, sized once
  std::vector<Vec3> clipped_;
};

}  // namespace edgetrack
