// SPDX-License-Identifier: BSD-3-Clause
/// Near-plane and screen clipping in `real`, then conversion to the rasteriser's integers.
#include "edgetrack/raster.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace edgetrack {
namespace {

/// Nothing nearer than 1 cm is drawn.
const real kNear = real(0.01);
using Projected = ProjectedVertex;

Vec3 lerp(const Vec3& a, const Vec3& b, const real& t) { return a + t * (b - a); }
Projected lerp(const Projected& a, const Projected& b, const real& t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.w + t * (b.w - a.w)};
}

/// One Sutherland-Hodgman pass against the half-plane distance(v) >= 0.
template <class V, class Distance>
int clip_pass(const V* in, int count, V* out, Distance distance) {
  int n = 0;
  for (int i = 0; i < count; ++i) {
    const V& p = in[i];
    const V& q = in[(i + 1) % count];
    const real dp = distance(p), dq = distance(q);
    if (dp >= real(0)) out[n++] = p;
    if ((dp >= real(0)) != (dq >= real(0))) out[n++] = lerp(p, q, dp / (dp - dq));
  }
  return n;
}

/// The projected polygon a (n3 corners) clipped to the screen grown by the guard band, into out.
int clip_to_guard_band(const PinholeCamera& camera, ProjectedVertex (&a)[kMaxClippedVertices], int n3,
                       ScreenVertex (&out)[kMaxClippedVertices]) {
  Projected b[kMaxClippedVertices];
  const real lo_x = real(-kGuardPixels), hi_x = real(camera.width - 1 + kGuardPixels);
  const real lo_y = real(-kGuardPixels), hi_y = real(camera.height - 1 + kGuardPixels);
  bool on_screen = true;
  for (int i = 0; i < n3 && on_screen; ++i) on_screen = on_guard_band(camera, a[i]);
  int n = n3;
  if (!on_screen) {
    n = clip_pass(a, n, b, [&](const Projected& v) { return v.x - lo_x; });
    n = clip_pass(b, n, a, [&](const Projected& v) { return hi_x - v.x; });
    n = clip_pass(a, n, b, [&](const Projected& v) { return v.y - lo_y; });
    n = clip_pass(b, n, a, [&](const Projected& v) { return hi_y - v.y; });
  }
  for (int i = 0; i < n; ++i) out[i] = to_screen(a[i]);
  return n >= 3 ? n : 0;
}

}  // namespace

bool in_front_of_near_plane(const Vec3* corners, int count) {
  for (int i = 0; i < count; ++i)
    if (corners[i].z - kNear < real(0)) return false;
  return true;
}

ProjectedVertex project_vertex(const PinholeCamera& camera, const Vec3& p) {
  const real w = real(1) / p.z;
  if (camera.distorted()) {
    // Through the lens at the vertices; callers cut what is long into pieces (edge_id_buffer.h).
    const Vec2 pixel = camera.to_pixel(camera.distort(Vec2{p.x * w, p.y * w}));
    return {pixel.x, pixel.y, w};
  }
  return {camera.u0 + camera.px * p.x * w, camera.v0 + camera.py * p.y * w, w};
}

bool setup_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, const PixelRect& clip, PixelTriangle& t) {
  int64_t area = int64_t(b.x - a.x) * (c.y - a.y) - int64_t(b.y - a.y) * (c.x - a.x);
  if (area < 0) {
    std::swap(b, c);
    area = -area;
  }
  if (area < 16) return false;
  const int32_t min_x = std::min(a.x, std::min(b.x, c.x)), max_x = std::max(a.x, std::max(b.x, c.x));
  const int32_t min_y = std::min(a.y, std::min(b.y, c.y)), max_y = std::max(a.y, std::max(b.y, c.y));
  t.box.x0 = std::max<int>(clip.x0, (min_x + 15) >> kSubpixelBits);
  t.box.x1 = std::min<int>(clip.x1, max_x >> kSubpixelBits);
  t.box.y0 = std::max<int>(clip.y0, (min_y + 15) >> kSubpixelBits);
  t.box.y1 = std::min<int>(clip.y1, max_y >> kSubpixelBits);
  if (t.box.x0 > t.box.x1 || t.box.y0 > t.box.y1) return false;
  t.a = a;
  t.b = b;
  t.c = c;
  const int64_t dxb = b.x - a.x, dyb = b.y - a.y, dwb = b.w - a.w;
  const int64_t dxc = c.x - a.x, dyc = c.y - a.y, dwc = c.w - a.w;
  t.gx = ((dwb * dyc - dwc * dyb) * 256) / area;
  t.gy = ((dxb * dwc - dxc * dwb) * 256) / area;
  // Edge functions are products of two coordinate differences plus one more: under 2^14 Q4
  // units (1024 pixels) on both axes they fit in 32 bits, which halves the inner loop on ARM.
  const int32_t span = std::max(max_x - min_x, max_y - min_y);
  const int32_t reach = std::max(std::max(std::abs(min_x), std::abs(max_x)), std::max(std::abs(min_y), std::abs(max_y)));
  t.narrow = span < (1 << 14) && reach < (1 << 14);
  return true;
}

LineWalk walk_line(const ScreenVertex& a, const ScreenVertex& b) {
  const int32_t dx = b.x - a.x, dy = b.y - a.y;
  LineWalk line;
  line.x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const int32_t major_a = line.x_major ? a.x : a.y, major_b = line.x_major ? b.x : b.y;
  const int32_t minor_a = line.x_major ? a.y : a.x;
  const int32_t d_major = major_b - major_a, d_minor = line.x_major ? dy : dx;
  const int half = 1 << (kSubpixelBits - 1);
  line.first = (major_a + half) >> kSubpixelBits;
  const int last = (major_b + half) >> kSubpixelBits;
  line.dir = line.first <= last ? 1 : -1;
  line.count = (last - line.first) * line.dir + 1;
  // Minor coordinate and w at a major position m: value_a + slope * (m - major_a), slopes in Q16
  // (scaled by multiplying: the values may be negative, where a left shift is undefined).
  const int64_t q16 = 65536;
  const int64_t minor_slope = d_major != 0 ? int64_t(d_minor) * q16 / d_major : 0;
  const int64_t w_slope = d_major != 0 ? int64_t(b.w - a.w) * q16 / d_major : 0;
  const int64_t offset = int64_t(line.first) * (1 << kSubpixelBits) - major_a;
  line.minor = int64_t(minor_a) * q16 + minor_slope * offset;
  line.w = int64_t(a.w) * q16 + w_slope * offset;
  line.minor_step = minor_slope * line.dir * (1 << kSubpixelBits);
  line.w_step = w_slope * line.dir * (1 << kSubpixelBits);
  return line;
}

int clip_and_project_triangle(const PinholeCamera& camera, const Vec3 (&in_camera)[3],
                              ScreenVertex (&out)[kMaxClippedVertices]) {
  auto near_distance = [](const Vec3& v) { return v.z - kNear; };
  Vec3 near_clipped[4];
  const Vec3* in_front = in_camera;
  int n3 = 3;
  // A pass that keeps every vertex returns them as they were: skipped when none is cut.
  if (!(near_distance(in_camera[0]) >= real(0) && near_distance(in_camera[1]) >= real(0) &&
        near_distance(in_camera[2]) >= real(0))) {
    n3 = clip_pass(in_camera, 3, near_clipped, near_distance);
    if (n3 < 3) return 0;
    in_front = near_clipped;
  }
  Projected a[kMaxClippedVertices];
  for (int i = 0; i < n3; ++i) a[i] = project_vertex(camera, in_front[i]);
  return clip_to_guard_band(camera, a, n3, out);
}

int clip_projected_triangle(const PinholeCamera& camera, const ProjectedVertex (&corners)[3],
                            ScreenVertex (&out)[kMaxClippedVertices]) {
  Projected a[kMaxClippedVertices] = {corners[0], corners[1], corners[2]};
  return clip_to_guard_band(camera, a, 3, out);
}

bool clip_and_project_segment(const PinholeCamera& camera, const Vec3& a, const Vec3& b, ScreenVertex& sa,
                              ScreenVertex& sb) {
  Vec3 p = a, q = b;
  if (p.z < kNear && q.z < kNear) return false;
  if (p.z < kNear) p = lerp(p, q, (kNear - p.z) / (q.z - p.z));
  if (q.z < kNear) q = lerp(q, p, (kNear - q.z) / (p.z - q.z));
  return clip_projected_segment(camera, project_vertex(camera, p), project_vertex(camera, q), sa, sb);
}

bool clip_projected_segment(const PinholeCamera& camera, const ProjectedVertex& pa, const ProjectedVertex& pb,
                            ScreenVertex& sa, ScreenVertex& sb) {
  // Liang-Barsky against the screen rectangle [-0.5, size - 0.5].
  real t0(0), t1(1);
  const real dx = pb.x - pa.x, dy = pb.y - pa.y;
  const real half = real(0.5);
  const real limits[4][2] = {{-dx, pa.x + half},
                             {dx, real(camera.width) - half - pa.x},
                             {-dy, pa.y + half},
                             {dy, real(camera.height) - half - pa.y}};
  for (const auto& limit : limits) {
    const real& p_coef = limit[0];
    const real& q_coef = limit[1];
    if (p_coef == real(0)) {
      if (q_coef < real(0)) return false;
      continue;
    }
    const real r = q_coef / p_coef;
    if (p_coef < real(0)) {
      if (r > t1) return false;
      if (r > t0) t0 = r;
    } else {
      if (r < t0) return false;
      if (r < t1) t1 = r;
    }
  }
  const Projected ca = lerp(pa, pb, t0), cb = lerp(pa, pb, t1);
  sa = to_screen(ca);
  sb = to_screen(cb);
  return true;
}

}  // namespace edgetrack
