// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID rendering with the portable rasteriser, and the per-point visibility test.
#include "edgetrack/edge_id_buffer.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/contours.h"
#include "edgetrack/cylinder_windows.h"
#include "edgetrack/edge_id.h"
#include "edgetrack/raster.h"

namespace edgetrack {

EdgeIdBuffer::EdgeIdBuffer(const PinholeCamera& camera)
    : camera_(camera),
      colours_(static_cast<size_t>(camera.width) * camera.height, 0),
      inverse_depth_(static_cast<size_t>(camera.width) * camera.height, 0),
      surface_owner_(static_cast<size_t>(camera.width) * camera.height, 0) {}

void EdgeIdBuffer::clear_dirty() {
  for (int y = dirty_y0_; y <= dirty_y1_; ++y) {
    const size_t row = static_cast<size_t>(y) * camera_.width;
    std::fill(colours_.begin() + row + dirty_x0_, colours_.begin() + row + dirty_x1_ + 1, uint16_t(0));
    std::fill(inverse_depth_.begin() + row + dirty_x0_, inverse_depth_.begin() + row + dirty_x1_ + 1, 0);
    if (owners_written_)
      std::fill(surface_owner_.begin() + row + dirty_x0_, surface_owner_.begin() + row + dirty_x1_ + 1, int16_t(0));
  }
  owners_written_ = false;
  dirty_x0_ = camera_.width;
  dirty_y0_ = camera_.height;
  dirty_x1_ = -1;
  dirty_y1_ = -1;
}

void EdgeIdBuffer::assign(const uint16_t* rgb565) {
  std::copy(rgb565, rgb565 + colours_.size(), colours_.begin());
  std::fill(inverse_depth_.begin(), inverse_depth_.end(), 0);
  std::fill(surface_owner_.begin(), surface_owner_.end(), int16_t(0));
  owners_written_ = false;
  // Everything may be drawn now: the next render() clears the whole image.
  dirty_x0_ = 0;
  dirty_y0_ = 0;
  dirty_x1_ = camera_.width - 1;
  dirty_y1_ = camera_.height - 1;
}

void EdgeIdBuffer::grow_dirty(int x0, int y0, int x1, int y1) {
  dirty_x0_ = std::min(dirty_x0_, x0);
  dirty_y0_ = std::min(dirty_y0_, y0);
  dirty_x1_ = std::max(dirty_x1_, x1);
  dirty_y1_ = std::max(dirty_y1_, y1);
}

void EdgeIdBuffer::render(const EdgeModel& model, const Se3& camera_from_model) {
  clear_dirty();
  const size_t primitives = static_cast<size_t>(primitive_count(model));
  if (edge_colours_.size() != primitives) {
    edge_colours_.resize(primitives);
    for (size_t e = 0; e < primitives; ++e) edge_colours_[e] = pack_rgb565(encode_edge_id(static_cast<int>(e)));
  }
  points_in_camera_.resize(model.vertices.size());
  for (size_t v = 0; v < model.vertices.size(); ++v) points_in_camera_[v] = camera_from_model * model.vertices[v];
  draw_surfaces(model, camera_from_model);
  for (size_t e = 0; e < model.edges.size(); ++e)
    draw_edge(points_in_camera_[model.edges[e].a], points_in_camera_[model.edges[e].b], edge_colours_[e], -1);
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
    draw_edge(camera_from_model * segment.a, camera_from_model * segment.b, edge_colours_[segment.primitive], owner);
  }
}

void EdgeIdBuffer::draw_surfaces(const EdgeModel& model, const Se3& camera_from_model) {
  // Faces facing away from the camera cannot hide anything on a closed surface.
  front_.assign(model.faces.size(), 1);
  if (model.closed)
    for (size_t f = 0; f < model.faces.size(); ++f)
      front_[f] = dot(camera_from_model.rotation() * model.faces[f].normal,
                      points_in_camera_[model.faces[f].vertices[0]]) < real(0);

  const int width = camera_.width, height = camera_.height;
  int32_t* depth = inverse_depth_.data();
  int16_t* owner = surface_owner_.data();
  auto fill = [&](const Vec3 (&corners)[3], auto&& plot) {
    ScreenVertex polygon[kMaxClippedVertices];
    const int n = clip_and_project_triangle(camera_, corners, polygon);
    for (int i = 1; i + 1 < n; ++i) {
      int box[4];
      if (fill_triangle(polygon[0], polygon[i], polygon[i + 1], width, height, plot, &box))
        grow_dirty(box[0], box[1], box[2], box[3]);
    }
  };
  const bool owners = !model.cylinders.empty();
  owners_written_ = owners;
  for (const Triangle& t : model.triangles) {
    if (!front_[t.face]) continue;
    const Vec3 corners[3] = {points_in_camera_[t.a], points_in_camera_[t.b], points_in_camera_[t.c]};
    if (owners)
      fill(corners, [depth, owner, width](int x, int y, int32_t w) {
        const size_t i = static_cast<size_t>(y) * width + x;
        if (w > depth[i]) {
          depth[i] = w;
          owner[i] = 0;
        }
      });
    else
      fill(corners, [depth, width](int x, int y, int32_t w) {
        int32_t& d = depth[static_cast<size_t>(y) * width + x];
        if (w > d) d = w;
      });
  }
  draw_cylinder_sides(model, camera_from_model);
}

void EdgeIdBuffer::draw_cylinder_sides(const EdgeModel& model, const Se3& camera_from_model) {
  const int width = camera_.width, height = camera_.height;
  int32_t* depth = inverse_depth_.data();
  int16_t* owner = surface_owner_.data();
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
  facets_.resize(model.cylinder_surface.size());
  for (size_t k = 0; k < model.cylinder_surface.size(); ++k) {
    const SurfaceTriangle& t = model.cylinder_surface[k];
    ProjectedFacet& f = facets_[k];
    const Vec3 corners[3] = {camera_from_model * t.corners[0], camera_from_model * t.corners[1],
                             camera_from_model * t.corners[2]};
    f.count = clip_and_project_triangle(camera_, corners, f.polygon);
    RimBoxes& r = rim_boxes_[static_cast<size_t>(t.cylinder)];
    if (!r.valid) continue;
    const ScreenVertex &a = f.polygon[0], &b = f.polygon[1], &c = f.polygon[2];
    const int64_t area = int64_t(b.x - a.x) * (c.y - a.y) - int64_t(b.y - a.y) * (c.x - a.x);
    f.sign = area > 0 ? 1 : area < 0 ? -1 : 0;
    // fill_triangle skips triangles under 16: a skipped front sliver would leave a hole in the
    // front layer, so that cylinder's back facets are all filled this frame.
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
    const int16_t id = static_cast<int16_t>(t.cylinder + 1);
    auto plot = [depth, owner, width, id](int x, int y, int32_t w) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (w > depth[i]) {
        depth[i] = w;
        owner[i] = id;
      }
    };
    if (!r.valid || r.front_sign == 0 || f.sign == r.front_sign) {
      for (int i = 1; i + 1 < f.count; ++i) {
        int box[4];
        if (fill_triangle(f.polygon[0], f.polygon[i], f.polygon[i + 1], width, height, plot, &box))
          grow_dirty(box[0], box[1], box[2], box[3]);
      }
      continue;
    }
    // The same triangle moved by a whole number of pixels gives the same pixels and depths, so it
    // is filled in a box-sized image at each box's origin.
    for (const PixelRect& window : r.boxes) {
      if (window.x0 > window.x1 || window.y0 > window.y1) continue;
      ScreenVertex moved[3];
      for (int i = 0; i < 3; ++i)
        moved[i] = {f.polygon[i].x - (window.x0 << kSubpixelBits), f.polygon[i].y - (window.y0 << kSubpixelBits),
                    f.polygon[i].w};
      int box[4];
      if (fill_triangle(moved[0], moved[1], moved[2], window.x1 - window.x0 + 1, window.y1 - window.y0 + 1,
                        [&plot, &window](int x, int y, int32_t w) { plot(x + window.x0, y + window.y0, w); }, &box))
        grow_dirty(box[0] + window.x0, box[1] + window.y0, box[2] + window.x0, box[3] + window.y0);
    }
  }
}

void EdgeIdBuffer::draw_edge(const Vec3& a_in_camera, const Vec3& b_in_camera, uint16_t code, int exempt_owner) {
  ScreenVertex a, b;
  if (!clip_and_project_segment(camera_, a_in_camera, b_in_camera, a, b)) return;
  const int width = camera_.width, height = camera_.height;
  const int32_t* depth = inverse_depth_.data();
  const int16_t* owner = surface_owner_.data();
  uint16_t* colour = colours_.data();
  draw_line(a, b, width, height, [&](int x, int y, int32_t w) {
    const size_t i = static_cast<size_t>(y) * width + x;
    if (w + (w >> 7) >= depth[i] || owner[i] == exempt_owner) colour[i] = code;
  });
  // The line's pixels lie within one pixel of its clipped end points' box.
  const int half = 1 << (kSubpixelBits - 1);
  grow_dirty(std::max(0, ((std::min(a.x, b.x) + half) >> kSubpixelBits) - 1),
             std::max(0, ((std::min(a.y, b.y) + half) >> kSubpixelBits) - 1),
             std::min(width - 1, ((std::max(a.x, b.x) + half) >> kSubpixelBits) + 1),
             std::min(height - 1, ((std::max(a.y, b.y) + half) >> kSubpixelBits) + 1));
}

int EdgeIdBuffer::edge_at(int x, int y) const {
  if (x < 0 || y < 0 || x >= camera_.width || y >= camera_.height) return -1;
  return decode_edge_id(unpack_rgb565(colours_[static_cast<size_t>(y) * camera_.width + x]));
}

bool EdgeIdBuffer::shows(int edge, const Vec2& pixel, const Vec2& along) const {
  using std::fabs;
  using std::floor;
  const real half = real(0.5);
  const int x = static_cast<int>(floor(pixel.x + half)), y = static_cast<int>(floor(pixel.y + half));
  const bool x_major = fabs(along.x) >= fabs(along.y);
  const int dx = x_major ? 0 : 1, dy = x_major ? 1 : 0;
  return edge_at(x, y) == edge || edge_at(x - dx, y - dy) == edge || edge_at(x + dx, y + dy) == edge;
}

}  // namespace edgetrack
