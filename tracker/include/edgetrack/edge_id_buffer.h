// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID visibility (paper, section 3.4): the model's faces and tessellated cylinder sides go
/// into an inverse-depth buffer, then its edges, cylinder silhouettes and circle polygons, with
/// hidden-line removal, into a 16-bit RGB565 colour buffer, each in the colour that encodes its
/// primitive number (EdgeModel). A control point of primitive i is visible when the colour at
/// its pixel decodes to i.
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/contours.h"
#include "edgetrack/cylinder_windows.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/raster.h"
#include "edgetrack/se3.h"

namespace edgetrack {

class EdgeIdBuffer {
 public:
  /// Buffers for images of the camera's size; they are allocated here, once.
  explicit EdgeIdBuffer(const PinholeCamera& camera);

  /// Redraws the buffers for the model seen from camera_from_model. On a closed model
  /// (EdgeModel::closed) back faces are skipped. An edge pixel is kept when
  /// its inverse depth is within 1/128 (0.8 %) of the nearest surface there, so edges lying on
  /// their own faces pass and edges behind other faces do not; a cylinder's silhouette (and the
  /// part of a circle closing it that the side cannot hide) also passes over that cylinder's side.
  void render(const EdgeModel& model, const Se3& camera_from_model);

  /// Takes an Edge-ID image drawn elsewhere (GL): width * height RGB565 pixels, row 0 at the
  /// top, in the paper's 8-level code. The depth buffer is cleared: it stays this renderer's.
  void assign(const uint16_t* rgb565);

  /// The edge index drawn at pixel (x, y), or -1 for the background or outside the image.
  int edge_at(int x, int y) const;
  /// True when edge `edge` is drawn at the pixel nearest to `pixel`, or at one of the two
  /// pixels beside it across the line (a drawn line has one pixel per column, or per row when
  /// steep: `along` is the edge direction and picks which).
  bool shows(int edge, const Vec2& pixel, const Vec2& along) const;

  int width() const { return camera_.width; }
  int height() const { return camera_.height; }
  const std::vector<uint16_t>& colours() const { return colours_; }
  const std::vector<int32_t>& inverse_depth() const { return inverse_depth_; }

 private:
  void clear_dirty();
  void grow_dirty(int x0, int y0, int x1, int y1);
  void draw_surfaces(const EdgeModel& model, const Se3& camera_from_model);
  /// The cylinders' sides into the depth buffer, back facets only where they can show
  /// (cylinder_windows.h).
  void draw_cylinder_sides(const EdgeModel& model, const Se3& camera_from_model);
  /// Draws the segment where it is not hidden; pixels whose nearest surface is `exempt_owner`
  /// (a cylinder number + 1, or -1 for none) never hide it.
  void draw_edge(const Vec3& a_in_camera, const Vec3& b_in_camera, uint16_t code, int exempt_owner);

  PinholeCamera camera_;
  std::vector<uint16_t> colours_;       ///< RGB565 Edge-ID colours, 0 = background
  std::vector<int32_t> inverse_depth_;  ///< Q20 1/Z of the nearest face, 0 = none
  std::vector<int16_t> surface_owner_;  ///< the cylinder number + 1 whose side is nearest, 0 = a face or none
  bool owners_written_ = false;         ///< surface_owner_ has non-zero pixels in the dirty area (cylinders drawn)
  std::vector<Vec3> points_in_camera_;  ///< per model vertex, reused every frame
  std::vector<uint16_t> edge_colours_;  ///< the RGB565 code of each primitive
  std::vector<ContourSegment> curved_;  ///< this frame's cylinder silhouettes and circle sides
  std::vector<uint8_t> front_;          ///< per face: drawn this frame (front-facing or not closed)
  /// Per cylinder, this frame: its rim boxes, whether they apply, and the projected orientation
  /// of its front facets (+1 or -1; that of the facet facing the camera most).
  struct RimBoxes {
    PixelRect boxes[2];
    bool valid = false;
    int front_sign = 0;
    real nearest_facing{0};
  };
  /// A cylinder facet projected this frame, with its signed area's sign where rim boxes apply.
  struct ProjectedFacet {
    ScreenVertex polygon[kMaxClippedVertices];
    int count = 0;
    int sign = 0;
  };
  std::vector<RimBoxes> rim_boxes_;
  std::vector<ProjectedFacet> facets_;  ///< per model.cylinder_surface triangle
  int dirty_x0_ = 0, dirty_y0_ = 0, dirty_x1_ = -1, dirty_y1_ = -1;  ///< area drawn last time
};

}  // namespace edgetrack
