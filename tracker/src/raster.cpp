// SPDX-License-Identifier: BSD-3-Clause
/// Near-plane and screen clipping in `real`, then conversion to the rasteriser's integers.
#include "edgetrack/raster.h"

#include <cmath>

namespace edgetrack {
namespace {

/// Nothing nearer than 1 cm is drawn.
const real kNear = real(0.01);
/// Triangles are clipped to the screen grown by this many pixels on each side, which keeps
/// every Q4 coordinate under 2^15 for images up to 1920 pixels wide.
constexpr int kGuardPixels = 64;

/// A vertex projected to the screen, before conversion to integers.
struct Projected {
  real x{0};
  real y{0};
  real w{0};
};

Projected project(const PinholeCamera& camera, const Vec3& p) {
  const real w = real(1) / p.z;
  return {camera.u0 + camera.px * p.x * w, camera.v0 + camera.py * p.y * w, w};
}

ScreenVertex to_screen(const Projected& p) {
  using std::floor;
  const real half = real(0.5);
  const real sub = real(1 << kSubpixelBits);
  const real wscale = real(1 << kInverseDepthBits);
  return {static_cast<int32_t>(floor(p.x * sub + half)), static_cast<int32_t>(floor(p.y * sub + half)),
          static_cast<int32_t>(floor(p.w * wscale + half))};
}

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

}  // namespace

int clip_and_project_triangle(const PinholeCamera& camera, const Vec3 (&in_camera)[3],
                              ScreenVertex (&out)[kMaxClippedVertices]) {
  Vec3 near_clipped[4];
  const int n3 = clip_pass(in_camera, 3, near_clipped, [](const Vec3& v) { return v.z - kNear; });
  if (n3 < 3) return 0;
  Projected a[kMaxClippedVertices], b[kMaxClippedVertices];
  for (int i = 0; i < n3; ++i) a[i] = project(camera, near_clipped[i]);
  const real lo_x = real(-kGuardPixels), hi_x = real(camera.width - 1 + kGuardPixels);
  const real lo_y = real(-kGuardPixels), hi_y = real(camera.height - 1 + kGuardPixels);
  int n = clip_pass(a, n3, b, [&](const Projected& v) { return v.x - lo_x; });
  n = clip_pass(b, n, a, [&](const Projected& v) { return hi_x - v.x; });
  n = clip_pass(a, n, b, [&](const Projected& v) { return v.y - lo_y; });
  n = clip_pass(b, n, a, [&](const Projected& v) { return hi_y - v.y; });
  for (int i = 0; i < n; ++i) out[i] = to_screen(a[i]);
  return n >= 3 ? n : 0;
}

bool clip_and_project_segment(const PinholeCamera& camera, const Vec3& a, const Vec3& b, ScreenVertex& sa,
                              ScreenVertex& sb) {
  Vec3 p = a, q = b;
  if (p.z < kNear && q.z < kNear) return false;
  if (p.z < kNear) p = lerp(p, q, (kNear - p.z) / (q.z - p.z));
  if (q.z < kNear) q = lerp(q, p, (kNear - q.z) / (p.z - q.z));
  Projected pa = project(camera, p), pb = project(camera, q);
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
