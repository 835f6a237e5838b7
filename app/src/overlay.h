// SPDX-License-Identifier: BSD-3-Clause
/// The AR overlay of `edgetrack track` (the paper's Fig. 6): the tracked wireframe with hidden
/// lines removed and a solid shaded cone standing on the object's top face. The host draws it
/// with OSMesa; builds without OSMesa draw it with the tracker's portable rasteriser.
#pragma once

#include <memory>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"
#include "image_io.h"

namespace edgetrack_app {

/// A cone standing on a model face: base circle centred on the face, axis along its normal.
struct Cone {
  edgetrack::Vec3 base_centre;  ///< model frame, metres
  edgetrack::Vec3 axis;         ///< unit outward normal of the face
  double radius = 0;
  double height = 0;
};

/// The cone on the face whose outward normal points most upwards in the image (camera -y) at
/// `camera_from_model`: radius 0.6 times the distance from the face centre to its nearest side,
/// height 2.2 times the radius.
Cone cone_on_top_face(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model);

/// The cone as triangles (model frame), with one outward normal per triangle, for renderers.
struct ConeMesh {
  std::vector<edgetrack::Vec3> corners;  ///< 3 per triangle
  std::vector<edgetrack::Vec3> normals;  ///< 3 per triangle (smooth sides, flat base)
};
ConeMesh cone_mesh(const Cone& cone, int sides);

/// Two unit vectors u, v with (u, v, n) right-handed, for the unit vector n.
void plane_axes(const edgetrack::Vec3& n, edgetrack::Vec3& u, edgetrack::Vec3& v);

class Overlay {
 public:
  virtual ~Overlay() = default;
  /// The frame with the wireframe and the cone drawn for camera_from_model.
  virtual RgbImage draw(const RgbImage& frame, const edgetrack::EdgeModel& model,
                        const edgetrack::Se3& camera_from_model, const Cone& cone) = 0;
};

/// The portable overlay (integer rasteriser, Edge-ID hidden-line removal).
std::unique_ptr<Overlay> make_soft_overlay(const edgetrack::PinholeCamera& camera);
/// The best overlay this build has: OSMesa on the host, the portable one elsewhere.
edgetrack::Result<std::unique_ptr<Overlay>> make_overlay(const edgetrack::PinholeCamera& camera);

}  // namespace edgetrack_app
