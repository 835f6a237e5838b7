// SPDX-License-Identifier: BSD-3-Clause
/// Synthetic frames for tests and benchmarks, and ray-cast ground-truth visibility.
#include "edgetrack/scene_renderer.h"

#include <algorithm>
#include <cstdlib>
#include <cmath>

#include "edgetrack/lens_resampling.h"
#include "edgetrack/raster.h"

namespace edgetrack {
namespace {

/// xorshift32: a small generator whose sequence is the same on every platform.
uint32_t next_random(uint32_t& state) {
  state ^= state << 13;
  state ^= state >> 17;
  state ^= state << 5;
  return state;
}

/// The face index of clutter lines in the supersampled buffer (-1 is the background).
constexpr int16_t kClutterFace = -2;

uint16_t grey_to_rgb565(int grey) {
  if (grey < 0) grey = 0;
  if (grey > 255) grey = 255;
  return static_cast<uint16_t>(((grey >> 3) << 11) | ((grey >> 2) << 5) | (grey >> 3));
}

/// True when the ray s q from the origin meets the side of the cylinder a-b of radius r for some
/// s in (0, limit): a root of |m + s q|^2 - r^2 = 0 across the axis, within the axis' length.
bool ray_meets_cylinder(const Vec3& a, const Vec3& b, const real& r, const Vec3& q, const real& limit) {
  using std::sqrt;
  const Vec3 axis = b - a;
  const real length = norm(axis);
  const Vec3 d = (real(1) / length) * axis;
  const Vec3 m = -a;
  const Vec3 m_across = m - dot(m, d) * d, q_across = q - dot(q, d) * d;
  const real qa = dot(q_across, q_across), qb = real(2) * dot(m_across, q_across);
  const real qc = dot(m_across, m_across) - r * r;
  const real discriminant = qb * qb - real(4) * qa * qc;
  if (qa == real(0) || discriminant < real(0)) return false;
  const real root = sqrt(discriminant);
  for (const real s : {(-qb - root) / (real(2) * qa), (-qb + root) / (real(2) * qa)}) {
    const real along = dot(m + s * q, d);
    if (s > real(0) && s < limit && along >= real(0) && along <= length) return true;
  }
  return false;
}

}  // namespace

SceneRenderer::SceneRenderer(const PinholeCamera& camera, const SceneStyle& style)
    : camera_(camera), fine_camera_(camera.pinhole().scaled(style.supersample)), style_(style) {
  if (camera.distorted()) {
    lens_.emplace(camera, style.supersample, style.supersample);
    fine_camera_ = lens_->pinhole_camera();
  }
  // Value noise: random greys on a coarse grid, bilinearly interpolated in integers.
  const int cell = style.texture_cell;
  const int grid_w = camera.width / cell + 2, grid_h = camera.height / cell + 2;
  std::vector<int> grid(static_cast<size_t>(grid_w) * grid_h);
  uint32_t state = style.texture_seed ? style.texture_seed : 1;
  const int range = style.background_high - style.background_low + 1;
  for (int& g : grid) g = style.background_low + static_cast<int>(next_random(state) % static_cast<uint32_t>(range));
  background_.resize(static_cast<size_t>(camera.width) * camera.height);
  for (int y = 0; y < camera.height; ++y) {
    const int gy = y / cell, fy = y % cell;
    for (int x = 0; x < camera.width; ++x) {
      const int gx = x / cell, fx = x % cell;
      const int g00 = grid[gy * grid_w + gx], g10 = grid[gy * grid_w + gx + 1];
      const int g01 = grid[(gy + 1) * grid_w + gx], g11 = grid[(gy + 1) * grid_w + gx + 1];
      const int top = g00 * (cell - fx) + g10 * fx, bottom = g01 * (cell - fx) + g11 * fx;
      background_[static_cast<size_t>(y) * camera.width + x] =
          static_cast<uint8_t>((top * (cell - fy) + bottom * fy) / (cell * cell));
    }
  }
  depth_.resize(static_cast<size_t>(fine_camera_.width) * fine_camera_.height);
  face_.resize(depth_.size());
}

void SceneRenderer::render(const EdgeModel& model, const Se3& camera_from_model, uint32_t noise_seed,
                           Rgb565Frame& frame) {
  render(model, camera_from_model, noise_seed, SceneAdditions{}, frame);
}

void SceneRenderer::draw_clutter(const std::vector<Segment3>& clutter, const Se3& camera_from_model) {
  const int fw = fine_camera_.width, fh = fine_camera_.height, one = 1 << kSubpixelBits;
  const int half_width = (3 * style_.supersample * one) / 4;  // 1.5 image pixels wide, in Q4 fine pixels
  for (const Segment3& line : clutter) {
    ScreenVertex a, b;
    if (!clip_and_project_segment(fine_camera_, camera_from_model * line.a, camera_from_model * line.b, a, b)) continue;
    const int64_t dx = b.x - a.x, dy = b.y - a.y;
    const int steps = static_cast<int>(std::max(std::abs(dx), std::abs(dy)) / one) + 1;
    for (int i = 0; i <= steps; ++i) {
      // Inverse depth is linear in screen space, so it interpolates like x and y.
      const int32_t x = static_cast<int32_t>(a.x + dx * i / steps), y = static_cast<int32_t>(a.y + dy * i / steps);
      const int32_t w = static_cast<int32_t>(a.w + (static_cast<int64_t>(b.w) - a.w) * i / steps);
      for (int py = (y - half_width) >> kSubpixelBits; py <= (y + half_width) >> kSubpixelBits; ++py)
        for (int px = (x - half_width) >> kSubpixelBits; px <= (x + half_width) >> kSubpixelBits; ++px) {
          if (px < 0 || py < 0 || px >= fw || py >= fh) continue;
          const size_t k = static_cast<size_t>(py) * fw + px;
          if (w > depth_[k]) {
            depth_[k] = w;
            face_[k] = kClutterFace;
          }
        }
    }
  }
}

void SceneRenderer::render(const EdgeModel& model, const Se3& camera_from_model, uint32_t noise_seed,
                           const SceneAdditions& additions, Rgb565Frame& frame) {
  using std::fabs;
  std::fill(depth_.begin(), depth_.end(), 0);
  std::fill(face_.begin(), face_.end(), int16_t(-1));
  std::vector<Vec3> in_camera(model.vertices.size());
  for (size_t v = 0; v < model.vertices.size(); ++v) in_camera[v] = camera_from_model * model.vertices[v];

  // Flat shading from a light above and left of the camera.
  const Vec3 light = normalized({real(-0.3), real(-0.5), real(-1)});
  auto lit = [&](const Vec3& normal_in_camera) {
    const real lambert = fabs(dot(normal_in_camera, light));
    return style_.face_low + static_cast<int>(lambert * (style_.face_high - style_.face_low));
  };
  std::vector<int> shade(model.faces.size());
  for (size_t f = 0; f < model.faces.size(); ++f) shade[f] = lit(camera_from_model.rotation() * model.faces[f].normal);

  // Cylinder facets and circle discs get shade entries after the faces'.
  const int fw = fine_camera_.width, fh = fine_camera_.height;
  auto draw = [&](const Vec3 (&corners)[3], int shade_index, int32_t in_front) {
    ScreenVertex polygon[kMaxClippedVertices];
    const int n = clip_and_project_triangle(fine_camera_, corners, polygon);
    const int16_t id = static_cast<int16_t>(shade_index);
    for (int i = 1; i + 1 < n; ++i)
      fill_triangle(polygon[0], polygon[i], polygon[i + 1], fw, fh, [&](int x, int y, int32_t w) {
        const size_t k = static_cast<size_t>(y) * fw + x;
        if (w + ((w >> 12) & -in_front) > depth_[k]) {
          depth_[k] = w;
          face_[k] = id;
        }
      });
  };
  for (const Triangle& t : model.triangles) {
    const Vec3 corners[3] = {in_camera[t.a], in_camera[t.b], in_camera[t.c]};
    draw(corners, t.face, 0);
  }
  for (const SurfaceTriangle& t : model.cylinder_surface) {
    const Vec3 corners[3] = {camera_from_model * t.corners[0], camera_from_model * t.corners[1],
                             camera_from_model * t.corners[2]};
    shade.push_back(lit(camera_from_model.rotation() * t.normal));
    draw(corners, static_cast<int>(shade.size()) - 1, 0);
  }
  // A circle is drawn as a darker disc, just in front of a face it lies on (a marking, or a
  // cylinder's cap), so that its rim is an image edge.
  for (const Circle& circle : model.circles) {
    shade.push_back(std::max(0, lit(camera_from_model.rotation() * circle.normal) - style_.disc_darker));
    const Vec3 centre = camera_from_model * circle.centre;
    for (size_t s = 0; s + 1 < circle.rim.size(); ++s) {
      const Vec3 corners[3] = {centre, camera_from_model * circle.rim[s], camera_from_model * circle.rim[s + 1]};
      draw(corners, static_cast<int>(shade.size()) - 1, -1);
    }
  }

  if (additions.clutter) draw_clutter(*additions.clutter, camera_from_model);

  frame.width = camera_.width;
  frame.height = camera_.height;
  frame.pixels.resize(static_cast<size_t>(frame.width) * frame.height);
  const int s = style_.supersample, samples = s * s;
  const int noise_range = 2 * style_.noise + 1;
  uint32_t state = noise_seed ? noise_seed : 1;
  for (int y = 0; y < camera_.height; ++y) {
    for (int x = 0; x < camera_.width; ++x) {
      const int bg = background_[static_cast<size_t>(y) * camera_.width + x];
      const auto grey = [&](int id) { return id >= 0 ? shade[id] : id == kClutterFace ? additions.clutter_grey : bg; };
      int sum = 0;
      if (lens_) {
        const int16_t* faces = face_.data();
        const int64_t one = LensResampling::kWeightOne;
        sum = static_cast<int>(lens_->weighted_sum(x, y, [&](int32_t i) { return grey(faces[i]); }, bg) / (one * one));
      } else {
        for (int sy = 0; sy < s; ++sy)
          for (int sx = 0; sx < s; ++sx) sum += grey(face_[static_cast<size_t>(y * s + sy) * fw + (x * s + sx)]);
      }
      if (x >= additions.band.x_begin && x < additions.band.x_end) sum = additions.occluder_grey * samples;
      const int noise = static_cast<int>(next_random(state) % static_cast<uint32_t>(noise_range)) - style_.noise;
      frame.pixels[static_cast<size_t>(y) * camera_.width + x] = grey_to_rgb565((sum + samples / 2) / samples + noise);
    }
  }
}

bool point_visible(const EdgeModel& model, const Se3& camera_from_model, const Vec3& point_in_model,
                   const real& margin) {
  // The ray is cast in the model frame from the camera centre c, and everything is divided by
  // the point's depth, so the numbers stay near 1 for every `real`.
  const Vec3 c = camera_from_model.inverse().translation();
  const real scale = real(1) / (camera_from_model * point_in_model).z;
  const Vec3 p = scale * (point_in_model - c);
  const real limit = real(1) - margin;
  const real tiny = real(1e-6);
  for (const Triangle& t : model.triangles) {
    const Vec3 a = scale * (model.vertices[t.a] - c);
    const Vec3 b = scale * (model.vertices[t.b] - c);
    const Vec3 c2 = scale * (model.vertices[t.c] - c);
    // Moller-Trumbore for the ray O + s p, s in (0, limit).
    const Vec3 e1 = b - a, e2 = c2 - a;
    const Vec3 h = cross(p, e2);
    const real det = dot(e1, h);
    if (det > -tiny && det < tiny) continue;  // ray parallel to the triangle
    const Vec3 to_a = -a;
    const real u = dot(to_a, h) / det;
    if (u < real(0) || u > real(1)) continue;
    const Vec3 q = cross(to_a, e1);
    const real v = dot(p, q) / det;
    if (v < real(0) || u + v > real(1)) continue;
    const real s = dot(e2, q) / det;
    if (s > real(0) && s < limit) return false;
  }
  for (const Cylinder& cylinder : model.cylinders)
    if (ray_meets_cylinder(scale * (cylinder.axis_a - c), scale * (cylinder.axis_b - c), scale * cylinder.radius, p,
                           limit))
      return false;
  return true;
}

}  // namespace edgetrack
