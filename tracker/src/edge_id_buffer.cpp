// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID rendering with the portable rasteriser, and the per-point visibility test.
#include "edgetrack/edge_id_buffer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "edgetrack/contours.h"
#include "edgetrack/cylinder_windows.h"
#include "edgetrack/edge_id.h"
#include "edgetrack/floor_to_int.h"
#include "edgetrack/raster.h"
#include "edgetrack/tracker_memory.h"
#include "real/vector_kernels.h"

namespace edgetrack {

EdgeIdBuffer::EdgeIdBuffer(const PinholeCamera& camera, int primitives)
    : camera_(camera),
      screen_{0, 0, camera.width - 1, camera.height - 1},
      pixels_(static_cast<size_t>(camera.width) * camera.height),
      bits_(image_bits(static_cast<size_t>(primitives < 0 ? 0 : primitives))) {
  if (bits_ == 16) colours_.assign(pixels_, 0);
  else narrow_ids_.assign(bits_ == 4 ? (pixels_ + 1) / 2 : pixels_, NarrowId{0});
}

int EdgeIdBuffer::image_bits(size_t primitives) {
  if (primitives <= static_cast<size_t>(kNibblePrimitives)) return 4;
  return primitives <= static_cast<size_t>(kNarrowPrimitives) ? 8 : 16;
}

namespace {

/// An image of one value per pixel (RGB565 colours or primitive numbers), for the drawing loops.
template <class Pixel>
struct WholePixels {
  Pixel* image;
  void set(size_t i, uint16_t value) const { image[i] = static_cast<Pixel>(value); }
};

/// An image of 4-bit primitive numbers, two per byte, the even pixel in the low half.
template <class Byte>
struct NibblePixels {
  Byte* image;
  void set(size_t i, uint16_t value) const {
    const unsigned shift = (i & 1u) * 4u;
    Byte& byte = image[i >> 1];
    byte = static_cast<Byte>((static_cast<unsigned>(byte) & ~(0xFu << shift)) | (unsigned{value} << shift));
  }
};

/// A 4-bit image being cleared: a pixel's whole byte is set to 0, its neighbour's half too, which
/// is either background already or a pixel of the lines being cleared.
template <class Byte>
struct ClearedNibblePairs {
  Byte* image;
  void set(size_t i, uint16_t) const { image[i >> 1] = Byte{0}; }
};

/// Sets the pixels of `lines` in `image` to 0. Each line is walked from a local copy: a byte
/// store may alias anything but a local, so the walk's steps stay in registers.
template <class Image, class Segments>
void clear_line_pixels(const Image& image, const Segments& lines, int width, int height) {
  for (const auto& s : lines) {
    const LineWalk line = s.line;
    draw_line(line, width, height, [image, width](int x, int y, int32_t) { image.set(static_cast<size_t>(y) * width + x, 0); });
  }
}

}  // namespace

void EdgeIdBuffer::clear_lines() {
  if (clear_all_) {
    std::fill(narrow_ids_.begin(), narrow_ids_.end(), NarrowId{0});
    std::fill(colours_.begin(), colours_.end(), uint16_t(0));
    clear_all_ = false;
  } else if (bits_ == 4) {
    clear_line_pixels(ClearedNibblePairs<NarrowId>{narrow_ids_.data()}, segments_, camera_.width, camera_.height);
  } else if (bits_ == 8) {
    clear_line_pixels(WholePixels<NarrowId>{narrow_ids_.data()}, segments_, camera_.width, camera_.height);
  } else {
    clear_line_pixels(WholePixels<uint16_t>{colours_.data()}, segments_, camera_.width, camera_.height);
  }
  segments_.clear();
  occluders_.clear();
}

void EdgeIdBuffer::use_image(int bits) {
  const size_t bytes = bits == 4 ? (pixels_ + 1) / 2 : pixels_;
  const bool sized = bits == 16 ? colours_.size() == pixels_ : narrow_ids_.size() == bytes;
  if (bits == bits_ && sized) return;
  if (bits != 16) {
    std::vector<uint16_t>().swap(colours_);
    std::vector<NarrowId>(bytes, NarrowId{0}).swap(narrow_ids_);
  } else {
    std::vector<NarrowId>().swap(narrow_ids_);
    colours_.assign(pixels_, 0);
  }
  bits_ = bits;
  edge_colours_.clear();  // their values are the other image's
  segments_.clear();      // the new image has none of their pixels
  occluders_.clear();
  clear_all_ = false;
}

void EdgeIdBuffer::assign(const uint16_t* rgb565) {
  use_image(16);
  std::copy(rgb565, rgb565 + pixels_, colours_.begin());
  segments_.clear();
  occluders_.clear();
  clear_all_ = true;
}

void EdgeIdBuffer::reserve_for(const EdgeModel& model) {
  const size_t primitives = static_cast<size_t>(primitive_count(model));
  // An image only widens: a model of more primitives than the last needs more bits.
  use_image(std::max(bits_, image_bits(primitives)));
  if (edge_colours_.size() != primitives) {
    edge_colours_.resize(primitives);
    for (size_t e = 0; e < primitives; ++e)
      edge_colours_[e] = bits_ != 16 ? static_cast<uint16_t>(e + 1) : pack_rgb565(encode_edge_id(static_cast<int>(e)));
  }
  // At most one line per primitive; a clipped polygon fans into kMaxClippedVertices - 2
  // triangles, a windowed back facet (never clipped) into one per rim box.
  segments_.reserve(primitives);
  const size_t most_occluders = (model.triangles.size() + 2 * model.cylinder_surface.size()) * (kMaxClippedVertices - 2);
  occluders_.reserve(most_occluders);
  occluder_runs_.reserve((most_occluders + kOccluderRun - 1) / kOccluderRun);
  // One line at a time (draw_segments): a line clipped to the screen has at most one pixel per
  // column or row, and one more for rounding. Owners only under the lines a side may not hide:
  // cylinder silhouettes and circles.
  const size_t line_pixels = static_cast<size_t>(std::max(camera_.width, camera_.height) + 1);
  line_depth_.reserve(line_pixels);
  if (primitives > model.edges.size()) line_owner_.reserve(line_pixels);
  points_in_camera_.reserve(model.vertices.size());
  front_.reserve(model.faces.size());
  rim_boxes_.reserve(model.cylinders.size());
  facets_.reserve(model.cylinder_surface.size());
}

void EdgeIdBuffer::render(const EdgeModel& model, const Se3& camera_from_model) {
  reserve_for(model);
  clear_lines();
  points_in_camera_.resize(model.vertices.size());
  for (size_t v = 0; v < model.vertices.size(); ++v) points_in_camera_[v] = camera_from_model * model.vertices[v];
  collect_segments(model, camera_from_model);
  collect_faces(model, camera_from_model);
  collect_cylinder_sides(model, camera_from_model);
  draw_segments();
}

namespace {

/// Through a lens, a line is cut into pieces whose curve stays within half a pixel of their
/// chords: a chord's pixels are drawn within half a pixel of it, so a point of the curve rounds
/// to a pixel at most one pixel across the line from a drawn one, which shows() looks at. A
/// face's triangles are cut so that their outline stays within a pixel of the curve: a face
/// only hides lines, and shows() takes a line's colour one pixel either side of a point, so an
/// outline a pixel off moves no point further than that test already reaches across the line
/// (half a pixel cut twice as many triangles out of a large face, and every line is tested
/// against each). The tolerances are given where
/// they are used, as literals: a `real` made from a variable float would be soft-float
/// arithmetic on the ARM target.
constexpr int kMostLinePieces = 32, kMostFacePieces = 8;

}  // namespace

int EdgeIdBuffer::lens_pieces(const Vec3* corners, int count, const real& bend_pixels, int most) const {
  if (!camera_.distorted()) return 1;
  if (!in_front_of_near_plane(corners, count)) return most;  // clipped: cut it as finely as allowed
  Vec2 normalised[3];
  for (int i = 0; i < count; ++i) {
    const real w = real(1) / corners[i].z;
    normalised[i] = Vec2{corners[i].x * w, corners[i].y * w};
  }
  int pieces = 1;
  const int sides = count == 2 ? 1 : count;
  for (int i = 0; i < sides; ++i)
    pieces = std::max(pieces, camera_.chord_pieces(normalised[i], normalised[(i + 1) % count], bend_pixels, most));
  return pieces;
}

void EdgeIdBuffer::add_line(const ScreenVertex& a, const ScreenVertex& b, uint16_t code, int exempt_owner) {
  const LineWalk line = walk_line(a, b);
  segments_.push_back({line, line_box(line), code, exempt_owner});
}

void EdgeIdBuffer::add_segment(const Vec3& a_in_camera, const Vec3& b_in_camera, uint16_t code, int exempt_owner) {
  // Through a lens the line is a curve: drawn as a polyline of pieces short enough that each
  // lies within half a pixel of it.
  const Vec3 ends[2] = {a_in_camera, b_in_camera};
  const int pieces = lens_pieces(ends, 2, real(0.5), kMostLinePieces);
  ScreenVertex a, b;
  if (pieces == 1) {
    if (clip_and_project_segment(camera_, a_in_camera, b_in_camera, a, b)) add_line(a, b, code, exempt_owner);
    return;
  }
  const real step = real(1) / real(pieces);
  const auto at = [&](int k) { return a_in_camera + (real(k) * step) * (b_in_camera - a_in_camera); };
  if (!in_front_of_near_plane(ends, 2)) {
    for (int k = 0; k < pieces; ++k)
      if (clip_and_project_segment(camera_, at(k), at(k + 1), a, b)) add_line(a, b, code, exempt_owner);
    return;
  }
  // In front of the near plane: each point of the polyline through the lens once.
  ProjectedVertex previous = project_vertex(camera_, a_in_camera);
  for (int k = 1; k <= pieces; ++k) {
    const ProjectedVertex next = project_vertex(camera_, k == pieces ? b_in_camera : at(k));
    if (clip_projected_segment(camera_, previous, next, a, b)) add_line(a, b, code, exempt_owner);
    previous = next;
  }
}

void EdgeIdBuffer::add_face_triangle(const Vec3 (&corners)[3]) {
  const int n = lens_pieces(corners, 3, real(1), kMostFacePieces);
  ScreenVertex polygon[kMaxClippedVertices];
  if (n == 1) {
    add_occluders(polygon, clip_and_project_triangle(camera_, corners, polygon), screen_, 0);
    return;
  }
  // Through a lens: n^2 smaller triangles on a barycentric grid, each with its corners through
  // the lens, so that the surface's curved outline is followed to a fraction of a pixel.
  const real step = real(1) / real(n);
  const auto at = [&](int i, int j) {
    const real s = real(i) * step, t = real(j) * step;
    return corners[0] + s * (corners[1] - corners[0]) + t * (corners[2] - corners[0]);
  };
  if (!in_front_of_near_plane(corners, 3)) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        const Vec3 up[3] = {at(i, j), at(i + 1, j), at(i, j + 1)};
        add_occluders(polygon, clip_and_project_triangle(camera_, up, polygon), screen_, 0);
        if (i + j + 1 < n) {
          const Vec3 down[3] = {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
          add_occluders(polygon, clip_and_project_triangle(camera_, down, polygon), screen_, 0);
        }
      }
    return;
  }
  // In front of the near plane: each grid point through the lens once.
  ProjectedVertex grid[kMostFacePieces + 1][kMostFacePieces + 1];
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) grid[i][j] = project_vertex(camera_, at(i, j));
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      const ProjectedVertex up[3] = {grid[i][j], grid[i + 1][j], grid[i][j + 1]};
      add_occluders(polygon, clip_projected_triangle(camera_, up, polygon), screen_, 0);
      if (i + j + 1 < n) {
        const ProjectedVertex down[3] = {grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]};
        add_occluders(polygon, clip_projected_triangle(camera_, down, polygon), screen_, 0);
      }
    }
}

void EdgeIdBuffer::collect_segments(const EdgeModel& model, const Se3& camera_from_model) {
  for (size_t e = 0; e < model.edges.size(); ++e)
    add_segment(points_in_camera_[model.edges[e].a], points_in_camera_[model.edges[e].b], edge_colours_[e], -1);
  curved_contours(model, camera_from_model, curved_);
  const int first_circle = circle_primitive(model, 0);
  const Vec3 camera_centre = camera_centre_in_model(camera_from_model);
  for (const ContourSegment& segment : curved_) {
    // A cylinder's own side never hides its silhouette, nor the parts of a circle closing it
    // that the side cannot hide: near the limb the side is seen edge-on, where its depth runs
    // away from the line's.
    int owner = -1;
    if (segment.primitive < first_circle) {
      owner = (segment.primitive - cylinder_primitive(model, 0, 0)) / 2 + 1;
    } else {
      const Circle& circle = model.circles[segment.primitive - first_circle];
      if (circle.cap_of >= 0 && cap_rim_clear_of_side(model.cylinders[circle.cap_of], circle.centre,
                                                      real(0.5) * (segment.a + segment.b), camera_centre))
        owner = circle.cap_of + 1;
    }
    add_segment(camera_from_model * segment.a, camera_from_model * segment.b, edge_colours_[segment.primitive], owner);
  }
}

void EdgeIdBuffer::add_occluders(const ScreenVertex* polygon, int count, const PixelRect& clip, int16_t owner) {
  // Set up in place (reserve_for made room): a triangle kept is not copied.
  for (int i = 1; i + 1 < count; ++i) {
    Occluder& o = occluders_.emplace_back();
    o.owner = owner;
    if (!setup_triangle(polygon[0], polygon[i], polygon[i + 1], clip, o.triangle)) occluders_.pop_back();
  }
}

void EdgeIdBuffer::collect_faces(const EdgeModel& model, const Se3& camera_from_model) {
  // Faces facing away from the camera cannot hide anything on a closed surface.
  front_.assign(model.faces.size(), 1);
  if (model.closed)
    for (size_t f = 0; f < model.faces.size(); ++f)
      front_[f] = dot(camera_from_model.rotation() * model.faces[f].normal,
                      points_in_camera_[model.faces[f].vertices[0]]) < real(0);
  for (const Triangle& t : model.triangles) {
    if (!front_[t.face]) continue;
    const Vec3 corners[3] = {points_in_camera_[t.a], points_in_camera_[t.b], points_in_camera_[t.c]};
    add_face_triangle(corners);
  }
}

namespace {

/// collect_cylinder_sides' rim points in floating point through a pinhole camera, a batch at a
/// time: each moved, projected (project_vertex) and tested against the guard band in a vector
/// lane with the one-by-one loop's expressions (the same bits), then stored, and rounded
/// (to_screen) on the guard band, as the loop does.
template <class CylinderPoint>
void move_rim_points_in_lanes(const std::vector<Vec3>& rim, const Se3& camera_from_model, const PinholeCamera& camera,
                              std::vector<CylinderPoint>& out) {
  constexpr int kBatch = 32;
  vector_kernels::run([&]() __attribute__((always_inline)) {
    const Se3 pose = camera_from_model;
    const real u0 = camera.u0, v0 = camera.v0, px = camera.px, py = camera.py;
    // on_guard_band's bounds; its test without branches.
    const real lo_x = real(-kGuardPixels), hi_x = real(camera.width - 1 + kGuardPixels);
    const real lo_y = real(-kGuardPixels), hi_y = real(camera.height - 1 + kGuardPixels);
    real x[kBatch], y[kBatch], z[kBatch], projected_x[kBatch], projected_y[kBatch], w[kBatch], band[kBatch];
    const size_t count = rim.size();
    for (size_t first = 0; first < count; first += kBatch) {
      const int n = count - first < size_t(kBatch) ? static_cast<int>(count - first) : kBatch;
      for (int k = 0; k < n; ++k) {
        const Vec3 p = pose * rim[first + static_cast<size_t>(k)];
        x[k] = p.x;
        y[k] = p.y;
        z[k] = p.z;
      }
      for (int k = 0; k < n; ++k) {
        w[k] = real(1) / z[k];
        projected_x[k] = u0 + px * x[k] * w[k];
        projected_y[k] = v0 + py * y[k] * w[k];
        const real &sx = projected_x[k], &sy = projected_y[k];
        band[k] = (sx - lo_x >= real(0)) & (hi_x - sx >= real(0)) & (sy - lo_y >= real(0)) & (hi_y - sy >= real(0))
                      ? real(1)
                      : real(0);
      }
      for (int k = 0; k < n; ++k) {
        CylinderPoint& p = out[first + static_cast<size_t>(k)];
        p.in_camera = Vec3{x[k], y[k], z[k]};
        p.in_front = in_front_of_near_plane(&p.in_camera, 1);
        p.on_band = false;
        if (!p.in_front) continue;
        p.projected = ProjectedVertex{projected_x[k], projected_y[k], w[k]};
        p.on_band = band[k] != real(0);
        if (p.on_band) p.screen = to_screen(p.projected);
      }
    }
  });
}

}  // namespace

void EdgeIdBuffer::collect_cylinder_sides(const EdgeModel& model, const Se3& camera_from_model) {
  // Where a cylinder's rim boxes apply (cylinder_windows.h), no facet is clipped: each projects to
  // one triangle, whose signed area (as fill_triangle rounds it) says which way it faces.
  const size_t cylinders = model.cylinders.size();
  rim_boxes_.resize(cylinders);
  for (size_t c = 0; c < cylinders; ++c) {
    RimBoxes& r = rim_boxes_[c];
    r.valid = cylinder_rim_boxes(model, static_cast<int>(c), camera_, camera_from_model, r.boxes);
    r.front_sign = 0;
    r.nearest_facing = real(0);
  }
  const Vec3 camera_centre = camera_centre_in_model(camera_from_model);
  // Each rim point moved, projected and rounded once for the facets that share it: the numbers
  // clip_and_project_triangle gives each facet corner. A facet whose corners are in front of the
  // near plane and on the guard band is not clipped: its corners are theirs as they are.
  const size_t points = model.cylinder_points.size();
  cylinder_points_.resize(points);
  if (std::numeric_limits<real>::is_iec559 && points > 0 && !camera_.distorted()) {
    move_rim_points_in_lanes(model.cylinder_points, camera_from_model, camera_, cylinder_points_);
  } else {
    for (size_t i = 0; i < points; ++i) {
      CylinderPoint& p = cylinder_points_[i];
      p.in_camera = camera_from_model * model.cylinder_points[i];
      p.in_front = in_front_of_near_plane(&p.in_camera, 1);
      p.on_band = false;
      if (!p.in_front) continue;
      p.projected = project_vertex(camera_, p.in_camera);
      p.on_band = on_guard_band(camera_, p.projected);
      if (p.on_band) p.screen = to_screen(p.projected);
    }
  }
  facets_.resize(model.cylinder_surface.size());
  for (size_t k = 0; k < model.cylinder_surface.size(); ++k) {
    const SurfaceTriangle& t = model.cylinder_surface[k];
    ProjectedFacet& f = facets_[k];
    const CylinderPoint* corner[3] = {&cylinder_points_[static_cast<size_t>(t.points[0])],
                                      &cylinder_points_[static_cast<size_t>(t.points[1])],
                                      &cylinder_points_[static_cast<size_t>(t.points[2])]};
    if (corner[0]->on_band && corner[1]->on_band && corner[2]->on_band) {
      for (int i = 0; i < 3; ++i) f.polygon[i] = corner[i]->screen;
      f.count = 3;
    } else if (corner[0]->in_front && corner[1]->in_front && corner[2]->in_front) {
      const ProjectedVertex projected[3] = {corner[0]->projected, corner[1]->projected, corner[2]->projected};
      f.count = clip_projected_triangle(camera_, projected, f.polygon);
    } else {
      const Vec3 corners[3] = {corner[0]->in_camera, corner[1]->in_camera, corner[2]->in_camera};
      f.count = clip_and_project_triangle(camera_, corners, f.polygon);
    }
    RimBoxes& r = rim_boxes_[static_cast<size_t>(t.cylinder)];
    if (!r.valid) continue;
    const ScreenVertex &a = f.polygon[0], &b = f.polygon[1], &c = f.polygon[2];
    const int64_t area = int64_t(b.x - a.x) * (c.y - a.y) - int64_t(b.y - a.y) * (c.x - a.x);
    f.sign = area > 0 ? 1 : area < 0 ? -1 : 0;
    // setup_triangle skips triangles under 16: a skipped front sliver would leave a hole in the
    // front layer, so that cylinder's back facets all count this frame.
    if (f.count != 3 || (area < 16 && area > -16)) r.valid = false;
    const real facing = dot(t.normal, t.corners[0] - camera_centre);
    if (facing < r.nearest_facing) {
      r.nearest_facing = facing;
      r.front_sign = f.sign;
    }
  }
  // Each pixel off the rims is covered by as many front-oriented as back-oriented facets (the
  // projected closed prism has degree 0, caps inside the rim boxes), so a back one never shows
  // alone there, and a front one there is nearer.
  for (size_t k = 0; k < model.cylinder_surface.size(); ++k) {
    const SurfaceTriangle& t = model.cylinder_surface[k];
    const ProjectedFacet& f = facets_[k];
    const RimBoxes& r = rim_boxes_[static_cast<size_t>(t.cylinder)];
    const int16_t owner = static_cast<int16_t>(t.cylinder + 1);
    if (!r.valid || r.front_sign == 0 || f.sign == r.front_sign) add_occluders(f.polygon, f.count, screen_, owner);
    else add_windowed_occluders(f.polygon, r.boxes, owner);  // valid boxes: every facet a triangle
  }
}

void EdgeIdBuffer::add_windowed_occluders(const ScreenVertex (&corners)[kMaxClippedVertices],
                                          const PixelRect (&windows)[2], int16_t owner) {
  // A non-empty rim box lies on the screen (cylinder_rim_boxes clamps it there), so the
  // triangle's box on the screen cut to the window is the box setup_triangle gives with the
  // window, and the rest of the setup does not depend on the clip.
  Occluder o;
  o.owner = owner;
  if (!setup_triangle(corners[0], corners[1], corners[2], screen_, o.triangle)) return;
  const PixelRect on_screen = o.triangle.box;
  for (const PixelRect& window : windows) {
    if (window.x0 > window.x1 || window.y0 > window.y1) continue;
    PixelRect& box = o.triangle.box;
    box.x0 = std::max(on_screen.x0, window.x0);
    box.y0 = std::max(on_screen.y0, window.y0);
    box.x1 = std::min(on_screen.x1, window.x1);
    box.y1 = std::min(on_screen.y1, window.y1);
    if (box.x0 <= box.x1 && box.y0 <= box.y1) occluders_.push_back(o);
  }
}

void EdgeIdBuffer::gather_occluder_runs() {
  occluder_runs_.clear();
  for (size_t first = 0; first < occluders_.size(); first += kOccluderRun) {
    const size_t end = std::min(occluders_.size(), first + kOccluderRun);
    OccluderRun run{occluders_[first].triangle.box, occluders_[first].owner};
    for (size_t k = first + 1; k < end; ++k) {
      const PixelRect& box = occluders_[k].triangle.box;
      run.box.x0 = std::min(run.box.x0, box.x0);
      run.box.y0 = std::min(run.box.y0, box.y0);
      run.box.x1 = std::max(run.box.x1, box.x1);
      run.box.y1 = std::max(run.box.y1, box.y1);
      if (occluders_[k].owner != run.owner) run.owner = kMixedOwners;
    }
    occluder_runs_.push_back(run);
  }
}

namespace {

/// Where a pixel of a line is along it: k of LineWalk's pixel k, from its major coordinate.
struct StepAlong {
  explicit StepAlong(const LineWalk& line) : x_major(line.x_major), first(line.first), dir(line.dir) {}
  int operator()(int x, int y) const { return ((x_major ? x : y) - first) * dir; }
  bool x_major;
  int first, dir;
};

/// Whether no pixel of `line` can fail the drawing's depth test against triangle t: t's w rises
/// above the line's by at most the tolerance of the line's least w wherever they overlap. Such a
/// triangle (the faces a line lies on, those behind it) changes no pixel drawn, nor which owner
/// is nearest where one hides the line.
/// Whether boxes a and b share a pixel.
bool boxes_meet(const PixelRect& a, const PixelRect& b) {
  return !(a.x1 < b.x0 || a.x0 > b.x1 || a.y1 < b.y0 || a.y0 > b.y1);
}

bool hides_nothing(const LineWalk& line, const PixelTriangle& t) {
  int k0 = 0, k1 = line.count - 1;
  if (!steps_in_box(line, t.box, k0, k1)) return true;
  const int64_t w0 = (line.w + int64_t(k0) * line.w_step) >> 16, w1 = (line.w + int64_t(k1) * line.w_step) >> 16;
  return most_above_line(line, t, k0, k1) <= (std::min(w0, w1) >> 7);
}

}  // namespace

// Flattened: the walks inlined with their plots, whose captures then stay in registers.
__attribute__((flatten)) EdgeIdBuffer::Cover EdgeIdBuffer::find_nearest_surfaces(const Segment& s) {
  // A line with an exempt owner first leaves its owner's surfaces out: where the others leave
  // it in front, it is drawn whatever its owner's are (nearer ones are its owner's, farther
  // ones hide nothing), and the walks along a cylinder's facets beside its silhouette are
  // most of this step. Where another surface is nearer, the owner's may be nearer still: that
  // line is walked again through all of them, in their order, with who is nearest.
  if (!nearest_under<false>(s, s.exempt_owner)) return Cover::kNone;
  if (s.exempt_owner < 0) return Cover::kDepths;
  if (drawn_whole(s)) return Cover::kNone;
  line_owner_.assign(static_cast<size_t>(s.line.count), 0);
  nearest_under<true>(s, -1);
  return Cover::kDepthsAndOwners;
}

template <bool kOwners>
bool EdgeIdBuffer::nearest_under(const Segment& s, int left_out) {
  // In the order a whole-surface fill would take, keeping the first of equal depths: the same
  // nearest surface at every pixel as that fill's. A triangle whose box misses the line's box has
  // none of its pixels (most of a tessellated side's facets, for each line). The depths start at
  // 0 (no surface) at the first triangle that may hide a pixel. A pixel two lines share gets the
  // same nearest surface from each (line_in_triangle gives a triangle's own depth there, whatever
  // the line).
  int32_t* depth = nullptr;
  const LineWalk& line = s.line;
  const StepAlong step_along(line);
  const auto walk = [&](const Occluder& o) {
    if (!boxes_meet(o.triangle.box, s.box) || o.owner == left_out || hides_nothing(line, o.triangle)) return;
    if (!depth) {
      line_depth_.assign(static_cast<size_t>(line.count), 0);
      depth = line_depth_.data();
    }
    if constexpr (!kOwners) {
      line_in_triangle(line, o.triangle, [depth, step_along](int x, int y, int32_t w) {
        int32_t& nearest = depth[step_along(x, y)];
        if (w > nearest) nearest = w;
      });
    } else {
      int16_t* owner = line_owner_.data();
      const int16_t id = o.owner;
      line_in_triangle(line, o.triangle, [depth, owner, step_along, id](int x, int y, int32_t w) {
        const int k = step_along(x, y);
        if (w > depth[k]) {
          depth[k] = w;
          owner[k] = id;
        }
      });
    }
  };
  // A run whose box misses the line's, or whose occluders are all left out, is skipped whole; a
  // single run has no box (gather_occluder_runs leaves it out). One loop: the walk, inlined with
  // its plots, is the most of this function's code.
  const size_t n = occluders_.size();
  const bool runs = n > kOccluderRun;
  for (size_t first = 0; first < n; first += kOccluderRun) {
    if (runs) {
      const OccluderRun& run = occluder_runs_[first / kOccluderRun];
      if (!boxes_meet(run.box, s.box) || run.owner == left_out) continue;
    }
    const Occluder* const end = occluders_.data() + std::min(n, first + kOccluderRun);
    for (const Occluder* o = occluders_.data() + first; o != end; ++o) walk(*o);
  }
  return depth != nullptr;
}

bool EdgeIdBuffer::drawn_whole(const Segment& s) const {
  // draw_line's w at each pixel, tested as draw_segment_into tests it.
  const int32_t* depth = line_depth_.data();
  int64_t w_q16 = s.line.w;
  for (int k = 0; k < s.line.count; ++k, w_q16 += s.line.w_step) {
    const int32_t w = static_cast<int32_t>(w_q16 >> 16);
    if (!(w + (w >> 7) >= depth[k])) return false;
  }
  return true;
}

template <class Image>
void EdgeIdBuffer::draw_segment_into(const Segment& s, Cover cover, const Image& image) const {
  const int width = camera_.width, height = camera_.height;
  const int32_t* depth = line_depth_.data();
  const LineWalk line = s.line;  // a local copy, as in clear_line_pixels
  const StepAlong step_along(line);
  const uint16_t code = s.code;
  if (cover == Cover::kNone) {  // the test against no surface (depth 0)
    draw_line(line, width, height, [image, width, code](int x, int y, int32_t w) {
      if (w + (w >> 7) >= 0) image.set(static_cast<size_t>(y) * width + x, code);
    });
    return;
  }
  if (cover == Cover::kDepths) {  // only the depth decides
    draw_line(line, width, height, [depth, image, width, step_along, code](int x, int y, int32_t w) {
      if (w + (w >> 7) >= depth[step_along(x, y)]) image.set(static_cast<size_t>(y) * width + x, code);
    });
    return;
  }
  const int16_t* owner = line_owner_.data();
  const int exempt = s.exempt_owner;
  draw_line(line, width, height, [depth, owner, image, width, step_along, code, exempt](int x, int y, int32_t w) {
    const int k = step_along(x, y);
    if (w + (w >> 7) >= depth[k] || owner[k] == exempt) image.set(static_cast<size_t>(y) * width + x, code);
  });
}

void EdgeIdBuffer::draw_segments() {
  // Each line's nearest surfaces, then the line: a line reads only its own, so one line's room
  // serves them all.
  if (occluders_.size() > kOccluderRun) gather_occluder_runs();
  for (const Segment& s : segments_) {
    const Cover cover = find_nearest_surfaces(s);
    if (bits_ == 4) draw_segment_into(s, cover, NibblePixels<NarrowId>{narrow_ids_.data()});
    else if (bits_ == 8) draw_segment_into(s, cover, WholePixels<NarrowId>{narrow_ids_.data()});
    else draw_segment_into(s, cover, WholePixels<uint16_t>{colours_.data()});
  }
}

void EdgeIdBuffer::surface_depth(std::vector<int32_t>& depth) const {
  depth.assign(pixels_, 0);
  int32_t* d = depth.data();
  const int width = camera_.width;
  for (const Occluder& o : occluders_)
    fill_triangle(o.triangle, [d, width](int x, int y, int32_t w) {
      int32_t& at = d[static_cast<size_t>(y) * width + x];
      if (w > at) at = w;
    });
}

size_t EdgeIdBuffer::image_bytes() const { return capacity_bytes(narrow_ids_) + capacity_bytes(colours_); }

size_t EdgeIdBuffer::line_bytes() const {
  return capacity_bytes(line_depth_) + capacity_bytes(line_owner_) + capacity_bytes(points_in_camera_) +
         capacity_bytes(edge_colours_) + capacity_bytes(curved_) + capacity_bytes(front_) + capacity_bytes(segments_) +
         capacity_bytes(occluders_) + capacity_bytes(rim_boxes_) + capacity_bytes(facets_) +
         capacity_bytes(cylinder_points_) + capacity_bytes(occluder_runs_);
}

int EdgeIdBuffer::edge_at(int x, int y) const {
  if (x < 0 || y < 0 || x >= camera_.width || y >= camera_.height) return -1;
  const size_t i = static_cast<size_t>(y) * camera_.width + x;
  if (bits_ == 4) {
    if (narrow_ids_.empty()) return -1;
    return static_cast<int>((static_cast<unsigned>(narrow_ids_[i >> 1]) >> ((i & 1u) * 4u)) & 0xFu) - 1;
  }
  if (bits_ == 8) return narrow_ids_.empty() ? -1 : static_cast<int>(narrow_ids_[i]) - 1;
  return colours_.empty() ? -1 : decode_edge_id_rgb565(colours_[i]);
}

bool EdgeIdBuffer::shows(int edge, const Vec2& pixel, const Vec2& along) const {
  using std::fabs;
  const real half = real(0.5);
  const int x = floor_to_int(pixel.x + half), y = floor_to_int(pixel.y + half);
  const bool x_major = fabs(along.x) >= fabs(along.y);
  const int dx = x_major ? 0 : 1, dy = x_major ? 1 : 0;
  return edge_at(x, y) == edge || edge_at(x - dx, y - dy) == edge || edge_at(x + dx, y + dy) == edge;
}

}  // namespace edgetrack
