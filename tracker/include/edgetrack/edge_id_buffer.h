// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID visibility (paper, section 3.4): the model's edges, cylinder silhouettes and circle
/// polygons are drawn with hidden-line removal into a 16-bit RGB565 colour buffer, each in the
/// colour that encodes its primitive number (EdgeModel). A control point of primitive i is
/// visible when the colour at its pixel decodes to i. Hidden-line removal needs the nearest
/// surface only under the lines, so the faces and tessellated cylinder sides are rasterised at the
/// lines' pixels alone (raster.h, line_in_triangle): the same depths there as filling them whole,
/// for a cost that follows the lines' length instead of the surfaces' area.
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
  /// Buffers for images of the camera's size, allocated at the first render or assign. Up to
  /// kNarrowPrimitives primitives (`primitives`, the models it will draw: primitive_count) the
  /// image holds the primitive's number + 1 instead of the RGB565 colour, in half a byte per
  /// pixel up to kNibblePrimitives, else a byte: the same edge at every pixel, in a quarter or
  /// half the memory.
  explicit EdgeIdBuffer(const PinholeCamera& camera, int primitives = kMaxEdges);
  static constexpr int kNarrowPrimitives = 255;
  static constexpr int kNibblePrimitives = 15;

  /// Redraws the colours for the model seen from camera_from_model. On a closed model
  /// (EdgeModel::closed) back faces are skipped. An edge pixel is kept when its inverse depth is
  /// within 1/128 (0.8 %) of the nearest surface there, so edges lying on their own faces pass
  /// and edges behind other faces do not; a cylinder's silhouette (and the part of a circle
  /// closing it that the side cannot hide) also passes over that cylinder's side.
  void render(const EdgeModel& model, const Se3& camera_from_model);
  /// Allocates every buffer render needs for `model` (render does it too): a tracker that calls
  /// it at create renders without allocating.
  void reserve_for(const EdgeModel& model);

  /// Takes an Edge-ID image drawn elsewhere (GL): width * height RGB565 pixels, row 0 at the
  /// top, in the paper's 8-level code, kept as RGB565. The surfaces are forgotten: they stay this
  /// renderer's.
  void assign(const uint16_t* rgb565);

  /// The edge index drawn at pixel (x, y), or -1 for the background or outside the image.
  int edge_at(int x, int y) const;
  /// True when edge `edge` is drawn at the pixel nearest to `pixel`, or at one of the two
  /// pixels beside it across the line (a drawn line has one pixel per column, or per row when
  /// steep: `along` is the edge direction and picks which).
  bool shows(int edge, const Vec2& pixel, const Vec2& along) const;

  int width() const { return camera_.width; }
  int height() const { return camera_.height; }
  /// The Q20 1/Z of the nearest surface of the last render() at every pixel (0 = none), filled
  /// whole into `depth` (width * height) for whoever needs more than the lines' pixels.
  void surface_depth(std::vector<int32_t>& depth) const;
  /// Heap bytes (tracker_memory.h): the colour image, and what the lines and surfaces keep.
  size_t image_bytes() const;
  size_t line_bytes() const;

 private:
  /// A line to draw this frame, the box of its pixels, and the owner whose side never hides it
  /// (a cylinder number + 1, or -1 for none).
  struct Segment {
    LineWalk line;
    PixelRect box;
    uint16_t code = 0;
    int exempt_owner = -1;
  };
  /// A triangle of a surface as this frame projects it, and its owner (a cylinder number + 1, or
  /// 0 for a face).
  struct Occluder {
    PixelTriangle triangle;
    int16_t owner = 0;
  };
  /// Clears the colours the last render drew, at its lines' pixels (or everywhere after assign),
  /// so that they are 0 everywhere.
  void clear_lines();
  /// Bits per pixel of the image for `primitives` primitives: 4, 8, or 16 (RGB565).
  static int image_bits(size_t primitives);
  /// Sizes the image for `bits` per pixel (an image of another kind is freed).
  void use_image(int bits);
  /// Through a lens, how many pieces each side of a segment (count 2) or triangle (count 3) is
  /// cut into so that its curve stays within `bend_pixels` of the pieces, at most `most`; 1 for
  /// a pinhole.
  int lens_pieces(const Vec3* corners, int count, const real& bend_pixels, int most) const;
  void add_segment(const Vec3& a_in_camera, const Vec3& b_in_camera, uint16_t code, int exempt_owner);
  /// One projected, clipped piece of a segment to draw.
  void add_line(const ScreenVertex& a, const ScreenVertex& b, uint16_t code, int exempt_owner);
  /// A face's triangle as occluders (through a lens, cut into smaller ones).
  void add_face_triangle(const Vec3 (&corners)[3]);
  void collect_segments(const EdgeModel& model, const Se3& camera_from_model);
  void add_occluders(const ScreenVertex* polygon, int count, const PixelRect& clip, int16_t owner);
  void collect_faces(const EdgeModel& model, const Se3& camera_from_model);
  /// The cylinders' sides, back facets only where they can show (cylinder_windows.h).
  void collect_cylinder_sides(const EdgeModel& model, const Se3& camera_from_model);
  /// A back facet (a triangle) as one occluder per non-empty rim box: one setup for all, since
  /// only the box changes with the window.
  void add_windowed_occluders(const ScreenVertex (&corners)[kMaxClippedVertices], const PixelRect (&windows)[2],
                              int16_t owner);
  /// occluder_runs_ for this frame's occluders.
  void gather_occluder_runs();
  /// What the drawing of a line must test at each pixel: nothing (no surface can hide any of
  /// it), line_depth_, or line_depth_ and line_owner_.
  enum class Cover { kNone, kDepths, kDepthsAndOwners };
  /// The nearest surface and its owner at every pixel of line `s` that one may hide, into
  /// line_depth_ and line_owner_.
  Cover find_nearest_surfaces(const Segment& s);
  /// Keeps at each pixel of `s` the nearest w of the occluders whose owner is not `left_out` (-1:
  /// none left out) and, with kOwners, whose it is in line_owner_; false when no such occluder
  /// can hide a pixel of `s` (line_depth_ is then left as it was).
  template <bool kOwners>
  bool nearest_under(const Segment& s, int left_out);
  /// Whether every pixel of `s` passes the drawing's depth test against the depths found.
  bool drawn_whole(const Segment& s) const;
  /// Each of this frame's lines, after its nearest surfaces.
  void draw_segments();
  /// Line `s`'s pixels where it is nearer than the surface (find_nearest_surfaces), into
  /// `image` (a pixel store of edge_id_buffer.cpp).
  template <class Image>
  void draw_segment_into(const Segment& s, Cover cover, const Image& image) const;

  PinholeCamera camera_;
  PixelRect screen_;
  /// A pixel of the one-byte image: its own type, so that a store to it may not alias
  /// everything as an unsigned char's may (the drawing loops keep their state in registers).
  enum class NarrowId : uint8_t {};
  size_t pixels_ = 0;                   ///< width * height
  /// Bits per pixel: 4 or 8, narrow_ids_ is the image; 16, colours_ is.
  int bits_ = 16;
  /// Primitive number + 1, 0 = background (up to kNarrowPrimitives): a byte per pixel, or with
  /// 4 bits two pixels per byte, the even pixel in the low half.
  std::vector<NarrowId> narrow_ids_;
  std::vector<uint16_t> colours_;       ///< RGB565 Edge-ID colours, 0 = background (more primitives, or assign)
  /// Per pixel of the line being drawn (in the line's order): the Q20 1/Z of the nearest surface
  /// there (0: none) and, for a line with an exempt owner that another surface hides, its
  /// Occluder::owner; as find_nearest_surfaces's Cover says which the drawing reads. Only a
  /// line's pixels need them: a few bytes per pixel of the longest line, not six per image pixel.
  std::vector<int32_t> line_depth_;
  std::vector<int16_t> line_owner_;
  bool clear_all_ = false;  ///< the image holds more than segments_ drew (assign)
  std::vector<Vec3> points_in_camera_;  ///< per model vertex, reused every frame
  std::vector<uint16_t> edge_colours_;  ///< each primitive's pixel value in the image in use
  std::vector<ContourSegment> curved_;  ///< this frame's cylinder silhouettes and circle sides
  std::vector<uint8_t> front_;          ///< per face: drawn this frame (front-facing or not closed)
  std::vector<Segment> segments_;       ///< this frame's lines (the last frame's until render clears them)
  std::vector<Occluder> occluders_;     ///< this frame's surface triangles, faces first
  /// occluders_ in runs of kOccluderRun (a cylinder's neighbouring facets, a face's triangles),
  /// each with the box around its occluders' boxes and their owner (kMixedOwners when they
  /// differ), so that a line skips the runs it cannot meet; gathered when there is more than one.
  struct OccluderRun {
    PixelRect box;
    int owner = 0;
  };
  static constexpr size_t kOccluderRun = 8;
  static constexpr int kMixedOwners = -2;
  std::vector<OccluderRun> occluder_runs_;
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
  /// A point of EdgeModel::cylinder_points this frame: in the camera frame, projected when in front
  /// of the near plane, and rounded when on the guard band (raster.h).
  struct CylinderPoint {
    Vec3 in_camera;
    ProjectedVertex projected;
    ScreenVertex screen;
    bool in_front = false;
    bool on_band = false;
  };
  std::vector<CylinderPoint> cylinder_points_;
};

}  // namespace edgetrack
