// SPDX-License-Identifier: BSD-3-Clause
/// The portable rasteriser behind Edge-ID and the test-image renderer: clipping and projection
/// in `real`, then triangle filling and line drawing in integers only (no FPU, no GL).
/// Screen positions are Q4 fixed point (1/16 pixel, pixel centres at multiples of 16) and depth
/// is carried as inverse depth w = 1/Z in Q20 (1/m), which is affine in screen space, so a
/// larger w is nearer and w = 0 is "nothing drawn".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <type_traits>
#include <utility>

#include "edgetrack/floor_to_int.h"
#include "edgetrack/pinhole_camera.h"

namespace edgetrack {

struct ScreenVertex {
  int32_t x = 0;  ///< Q4 pixels
  int32_t y = 0;
  int32_t w = 0;  ///< 1/Z in Q20
};

constexpr int kSubpixelBits = 4;
constexpr int kInverseDepthBits = 20;
/// The most vertices a triangle can have after the near-plane and screen clips.
constexpr int kMaxClippedVertices = 8;

/// Clips the triangle (camera frame) to Z >= near and to the screen grown by a guard band,
/// projects it, and returns its vertex count (0 when nothing is left).
int clip_and_project_triangle(const PinholeCamera& camera, const Vec3 (&in_camera)[3],
                              ScreenVertex (&out)[kMaxClippedVertices]);

/// Clips the segment (camera frame) to Z >= near and to the screen, and projects it.
bool clip_and_project_segment(const PinholeCamera& camera, const Vec3& a, const Vec3& b, ScreenVertex& sa,
                              ScreenVertex& sb);

/// A point in front of the near plane as the camera (and its lens) shows it: pixel and 1/Z, before
/// the conversion to integers. Through a lens, a polyline's or a grid's points are projected once
/// each and their pieces clipped to the screen from these.
struct ProjectedVertex {
  real x{0};
  real y{0};
  real w{0};
};
/// Whether no point of the segment or polygon with these corners is cut by the near plane.
bool in_front_of_near_plane(const Vec3* corners, int count);
/// `point` (Z at or beyond the near plane) projected.
ProjectedVertex project_vertex(const PinholeCamera& camera, const Vec3& point);
/// clip_and_project_triangle for a triangle wholly in front of the near plane, already projected.
int clip_projected_triangle(const PinholeCamera& camera, const ProjectedVertex (&corners)[3],
                            ScreenVertex (&out)[kMaxClippedVertices]);
/// Triangles are clipped to the screen grown by this many pixels on each side, which keeps
/// every Q4 coordinate under 2^15 for images up to 1920 pixels wide.
constexpr int kGuardPixels = 64;
/// Whether `p` lies on the screen grown by the guard band: a polygon whose corners all do is not
/// clipped, and its corners are to_screen's.
inline bool on_guard_band(const PinholeCamera& camera, const ProjectedVertex& p) {
  const real lo_x = real(-kGuardPixels), hi_x = real(camera.width - 1 + kGuardPixels);
  const real lo_y = real(-kGuardPixels), hi_y = real(camera.height - 1 + kGuardPixels);
  return p.x - lo_x >= real(0) && hi_x - p.x >= real(0) && p.y - lo_y >= real(0) && hi_y - p.y >= real(0);
}
/// `p` rounded to the rasteriser's integers (Q4 pixels, Q20 1/Z).
inline ScreenVertex to_screen(const ProjectedVertex& p) {
  const real half = real(0.5);
  const real sub = real(1 << kSubpixelBits);
  const real wscale = real(1 << kInverseDepthBits);
  return {floor_to_int(p.x * sub + half), floor_to_int(p.y * sub + half), floor_to_int(p.w * wscale + half)};
}
/// clip_and_project_segment for a segment wholly in front of the near plane, already projected.
bool clip_projected_segment(const PinholeCamera& camera, const ProjectedVertex& pa, const ProjectedVertex& pb,
                            ScreenVertex& sa, ScreenVertex& sb);

/// Pixels [x0, x1] x [y0, y1] of an image, inclusive.
struct PixelRect {
  int x0 = 0;
  int y0 = 0;
  int x1 = -1;
  int y1 = -1;
};

/// A triangle as fill_triangle rasterises it: corners in counter-clockwise order (positive
/// doubled area), the gradient of w per Q4 step scaled by 2^8 (w(p) = a.w + (gx * (p.x - a.x) +
/// gy * (p.y - a.y)) >> 8), its pixel box within the clip rectangle, and whether its edge
/// functions fit in 32 bits there.
struct PixelTriangle {
  ScreenVertex a, b, c;
  int64_t gx = 0;
  int64_t gy = 0;
  PixelRect box;
  bool narrow = false;
};

/// The pixels draw_line visits, one per step along the major axis: pixel k (0 <= k < count) is at
/// major coordinate first + k * dir and at the minor one nearest to the exact line; w is
/// interpolated. minor and w are Q4 and Q20 scaled by 2^16, at pixel 0.
struct LineWalk {
  bool x_major = true;
  int first = 0;
  int dir = 1;
  int count = 0;
  int64_t minor = 0, minor_step = 0;
  int64_t w = 0, w_step = 0;

  int minor_at(int k) const { return minor_pixel(minor + int64_t(k) * minor_step); }
  static int minor_pixel(int64_t minor_q16) {
    return static_cast<int>((minor_q16 + (int64_t(1) << (15 + kSubpixelBits))) >> (16 + kSubpixelBits));
  }
};

LineWalk walk_line(const ScreenVertex& a, const ScreenVertex& b);

/// The box of the pixels draw_line visits for `line` (off the screen too). Always inlined: a
/// call per line drawn costs the PXA270 more than the few instructions it holds.
[[gnu::always_inline]] inline PixelRect line_box(const LineWalk& line) {
  const int m0 = line.first, m1 = line.first + (line.count - 1) * line.dir;
  const int n0 = line.minor_at(0), n1 = line.minor_at(line.count - 1);  // monotonic along the line
  const int major_lo = std::min(m0, m1), major_hi = std::max(m0, m1);
  const int minor_lo = std::min(n0, n1), minor_hi = std::max(n0, n1);
  return line.x_major ? PixelRect{major_lo, minor_lo, major_hi, minor_hi} : PixelRect{minor_lo, major_lo, minor_hi, major_hi};
}

namespace raster_detail {

/// One edge function e + (x - x0) * step of a triangle, row by row (e grows by `row_step` per
/// row), narrowing each row's [lo, hi] to the pixels x where it is >= 0, so the inner loop visits
/// covered pixels only: exactly the pixels of the per-pixel test e_ab >= 0, e_bc >= 0, e_ca >= 0.
/// The row's first (step > 0) or last (step < 0) covered pixel is x0 + ceil(-e / step) or
/// x0 + floor(e / -step); the quotient and remainder are carried from row to row by additions,
/// so a triangle costs two divisions per edge instead of one per edge and row (ARMv5TE divides
/// in software).
template <class Int>
class EdgeSpan {
 public:
  EdgeSpan(Int e, Int step, Int row_step) : e_(e), row_step_(row_step), step_(step) {
    if (step == 0) return;
    size_ = step > 0 ? step : -step;
    const Int n = step > 0 ? -e : e, dn = step > 0 ? -row_step : row_step;
    floor_divide(n, quotient_, remainder_);
    floor_divide(dn, quotient_step_, remainder_step_);
  }

  void clip(int x0, int& lo, int& hi) const {
    if (step_ > 0) {
      if (e_ < 0) {
        const Int first = x0 + quotient_ + (remainder_ != 0 ? 1 : 0);
        if (first > lo) lo = first > Int(hi) + 1 ? hi + 1 : static_cast<int>(first);
      }
    } else if (step_ < 0) {
      if (e_ < 0) {
        hi = lo - 1;
      } else {
        const Int last = x0 + quotient_;
        if (last < hi) hi = last < Int(lo) - 1 ? lo - 1 : static_cast<int>(last);
      }
    } else if (e_ < 0) {
      hi = lo - 1;
    }
  }

  void next_row() {
    e_ += row_step_;
    if (step_ == 0) return;
    quotient_ += quotient_step_;
    remainder_ += remainder_step_;
    if (remainder_ >= size_) {
      remainder_ -= size_;
      ++quotient_;
    }
  }

 private:
  /// n = q * size_ + r with 0 <= r < size_.
  void floor_divide(Int n, Int& q, Int& r) const {
    q = n / size_;
    r = n - q * size_;
    if (r < 0) {
      r += size_;
      --q;
    }
  }

  Int e_, row_step_, step_;
  Int size_ = 1, quotient_ = 0, remainder_ = 0, quotient_step_ = 0, remainder_step_ = 0;
};

/// The scan of fill_triangle, with edge functions in `Int`: int32_t when the triangle's bounding
/// box is small enough for every product to fit, int64_t otherwise. `plot` is a copy, so that
/// what it captured stays in registers while the loop stores pixels.
template <class Int, class Plot>
void scan_triangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int x0, int x1, int y0,
                   int y1, int64_t gx, int64_t gy, Plot plot) {
  auto edge_at = [](const ScreenVertex& u, const ScreenVertex& v, Int px, Int py) {
    return Int(v.x - u.x) * (py - Int(u.y)) - Int(v.y - u.y) * (px - Int(u.x));
  };
  const Int step = 1 << kSubpixelBits;
  const Int py0 = Int(y0) << kSubpixelBits, px = Int(x0) << kSubpixelBits;
  EdgeSpan<Int> ab(edge_at(a, b, px, py0), -Int(b.y - a.y) * step, Int(b.x - a.x) * step);
  EdgeSpan<Int> bc(edge_at(b, c, px, py0), -Int(c.y - b.y) * step, Int(c.x - b.x) * step);
  EdgeSpan<Int> ca(edge_at(c, a, px, py0), -Int(a.y - c.y) * step, Int(a.x - c.x) * step);
  const int64_t acc_step = gx * step;
  for (int y = y0; y <= y1; ++y, ab.next_row(), bc.next_row(), ca.next_row()) {
    const Int py = Int(y) << kSubpixelBits;
    int lo = x0, hi = x1;
    ab.clip(x0, lo, hi);
    bc.clip(x0, lo, hi);
    ca.clip(x0, lo, hi);
    int64_t acc = gx * ((int64_t(lo) << kSubpixelBits) - a.x) + gy * (int64_t(py) - a.y);
    for (int x = lo; x <= hi; ++x) {
      plot(x, y, static_cast<int32_t>(a.w + (acc >> 8)));
      acc += acc_step;
    }
  }
}

/// The per-pixel test: the centre of (x, y) on the inner side of t's three edges.
template <class Int>
bool inside(const PixelTriangle& t, int x, int y) {
  const Int px = Int(x) * (1 << kSubpixelBits), py = Int(y) * (1 << kSubpixelBits);
  auto edge = [px, py](const ScreenVertex& u, const ScreenVertex& v) {
    return Int(v.x - u.x) * (py - Int(u.y)) - Int(v.y - u.y) * (px - Int(u.x));
  };
  return edge(t.a, t.b) >= 0 && edge(t.b, t.c) >= 0 && edge(t.c, t.a) >= 0;
}

/// The state of a walk along a line inside a triangle at one step: the pixel, the three edge
/// functions and w's accumulator (that of scan_triangle) there.
template <class Int>
struct TriangleWalk {
  int k = 0, m = 0, n = 0;
  int64_t minor_q16 = 0;
  Int e[3] = {0, 0, 0};
  int64_t acc = 0;

  void start(const LineWalk& line, const PixelTriangle& t, int at) {
    k = at;
    m = line.first + at * line.dir;
    minor_q16 = line.minor + int64_t(at) * line.minor_step;
    n = LineWalk::minor_pixel(minor_q16);
    const Int unit = 1 << kSubpixelBits;
    const Int px = Int(line.x_major ? m : n) * unit, py = Int(line.x_major ? n : m) * unit;
    const ScreenVertex* corner[3] = {&t.a, &t.b, &t.c};
    for (int i = 0; i < 3; ++i) {
      const ScreenVertex &u = *corner[i], &v = *corner[(i + 1) % 3];
      e[i] = Int(v.x - u.x) * (py - Int(u.y)) - Int(v.y - u.y) * (px - Int(u.x));
    }
    acc = t.gx * (int64_t(px) - t.a.x) + t.gy * (int64_t(py) - t.a.y);
  }
};

/// Narrows [k0, k1] to the steps where the line's pixels can lie inside the triangle: along the
/// exact line each edge function is affine in k, and a pixel is off it by at most half a pixel
/// across, which moves the function by at most half its change per pixel across (`across`).
/// Conservative, so no covered pixel is dropped; one division per edge.
template <class Int>
void narrow_steps(const LineWalk& line, const TriangleWalk<Int>& at, const Int (&along)[3], const Int (&across)[3],
                  int& k0, int& k1) {
  const int64_t one = int64_t(1) << (16 + kSubpixelBits);  // a pixel, in minor_q16 units
  for (int i = 0; i < 3 && k0 <= k1; ++i) {
    const int64_t c = across[i], slack = (c < 0 ? -c : c) * (one / 2);
    // one * e along the exact line at step at.k + j: offset + j * slope.
    const int64_t offset = one * int64_t(at.e[i]) + c * (at.minor_q16 - int64_t(at.n) * one) + slack;
    const int64_t slope = one * int64_t(along[i]) + c * line.minor_step;
    if (slope == 0) {
      if (offset < 0) k1 = k0 - 1;
    } else if (slope > 0) {
      if (offset < 0) k0 = std::max(k0, at.k + static_cast<int>((-offset + slope - 1) / slope));
    } else if (offset < 0) {
      k1 = k0 - 1;
    } else {
      k1 = std::min(k1, at.k + static_cast<int>(offset / -slope));
    }
  }
}

}  // namespace raster_detail

/// Narrows [k0, k1] to the steps of `line` whose major coordinate lies in `box`; false when none.
inline bool steps_in_box(const LineWalk& line, const PixelRect& box, int& k0, int& k1) {
  const int major_lo = line.x_major ? box.x0 : box.y0, major_hi = line.x_major ? box.x1 : box.y1;
  int lo = (major_lo - line.first) * line.dir, hi = (major_hi - line.first) * line.dir;
  if (lo > hi) std::swap(lo, hi);
  k0 = std::max(k0, lo);
  k1 = std::min(k1, hi);
  return k0 <= k1;
}

/// A bound on how far t's w (as line_in_triangle plots it) rises above the line's own w
/// (draw_line's) at any of the line's pixels k0..k1: both are affine along the exact line and a
/// pixel is within half a pixel of it across, so the bound at the two ends, with t's w taken half
/// a pixel across on its rising side, holds between them; +1 for the lines' rounding down.
inline int64_t most_above_line(const LineWalk& line, const PixelTriangle& t, int k0, int k1) {
  const bool xm = line.x_major;
  const int64_t g_major = xm ? t.gx : t.gy, g_minor = xm ? t.gy : t.gx;
  const int32_t a_major = xm ? t.a.x : t.a.y, a_minor = xm ? t.a.y : t.a.x;
  const int64_t half_pixel = 1 << (kSubpixelBits - 1);
  int64_t most = INT64_MIN;
  for (const int k : {k0, k1}) {
    const int64_t major = int64_t(line.first + k * line.dir) * (1 << kSubpixelBits);
    const int64_t minor_q16 = line.minor + int64_t(k) * line.minor_step;  // Q4 scaled by 2^16
    const int64_t minor = g_minor >= 0 ? ((minor_q16 + 65535) >> 16) + half_pixel : (minor_q16 >> 16) - half_pixel;
    const int64_t acc = g_major * (major - a_major) + g_minor * (minor - a_minor);
    const int64_t w_line = (line.w + int64_t(k) * line.w_step) >> 16;
    most = std::max(most, t.a.w + (acc >> 8) - w_line);
  }
  return most + 1;
}

namespace raster_detail {

/// line_in_triangle with edge functions in `Int` (wide enough on screen, as for scan_triangle).
/// The edge functions and w's accumulator follow the line's pixels by additions: a step moves
/// the major coordinate by one pixel, and the minor one by the pixels its rounding moves.
template <class Int, class Plot>
void walk_in_triangle(const LineWalk& line, const PixelTriangle& t, Plot& plot) {
  const bool xm = line.x_major;
  const int minor_lo = xm ? t.box.y0 : t.box.x0, minor_hi = xm ? t.box.y1 : t.box.x1;
  int k0 = 0, k1 = line.count - 1;
  if (!steps_in_box(line, t.box, k0, k1)) return;
  // The minor coordinate is monotonic along the line: its ends over [k0, k1] bound it.
  const int n0 = line.minor_at(k0), n1 = line.minor_at(k1);
  if (std::max(n0, n1) < minor_lo || std::min(n0, n1) > minor_hi) return;
  const Int unit = 1 << kSubpixelBits;
  const int minor_sign = line.minor_step < 0 ? -1 : 1;
  const ScreenVertex* corner[3] = {&t.a, &t.b, &t.c};
  Int along[3], across[3];  // each edge function's change per step, and per pixel across (+1 minor)
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex &u = *corner[i], &v = *corner[(i + 1) % 3];
    const Int ex = Int(v.x - u.x), ey = Int(v.y - u.y);
    along[i] = (xm ? -ey : ex) * unit * line.dir;
    across[i] = (xm ? ex : -ey) * unit;
  }
  TriangleWalk<Int> walk;
  walk.start(line, t, k0);
  // Long walks first skip the steps that cannot be inside.
  constexpr int kNarrowFrom = 16;
  if (k1 - k0 >= kNarrowFrom) {
    narrow_steps(line, walk, along, across, k0, k1);
    if (k0 > k1) return;
    if (k0 != walk.k) walk.start(line, t, k0);
  }
  Int minor_step[3];
  for (int i = 0; i < 3; ++i) minor_step[i] = across[i] * minor_sign;
  const int64_t acc_major = (xm ? t.gx : t.gy) * unit * line.dir;
  const int64_t acc_minor = (xm ? t.gy : t.gx) * unit * minor_sign;
  int m = walk.m, n = walk.n;
  int64_t minor_q16 = walk.minor_q16, acc = walk.acc;
  Int e0 = walk.e[0], e1 = walk.e[1], e2 = walk.e[2];
  for (int k = k0;;) {
    if (n >= minor_lo && n <= minor_hi) {
      if ((e0 | e1 | e2) >= 0) plot(xm ? m : n, xm ? n : m, static_cast<int32_t>(t.a.w + (acc >> 8)));
    } else if ((minor_sign > 0) == (n > minor_hi)) {
      break;  // past the box: the minor coordinate only moves on
    }
    if (++k > k1) break;
    m += line.dir;
    minor_q16 += line.minor_step;
    e0 += along[0];
    e1 += along[1];
    e2 += along[2];
    acc += acc_major;
    for (const int next = LineWalk::minor_pixel(minor_q16); n != next; n += minor_sign) {
      e0 += minor_step[0];
      e1 += minor_step[1];
      e2 += minor_step[2];
      acc += acc_minor;
    }
  }
}

}  // namespace raster_detail

/// Sets t up for filling the triangle abc inside `clip` (fill_triangle); false when nothing is
/// drawn: under 1/16 pixel^2, or no pixel of its box inside clip.
bool setup_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, const PixelRect& clip, PixelTriangle& t);

/// Calls plot(x, y, w) for every pixel centre of t's box inside the triangle; w is interpolated
/// exactly (affine in screen space).
template <class Plot>
void fill_triangle(const PixelTriangle& t, Plot&& plot) {
  if (t.narrow)
    raster_detail::scan_triangle<int32_t>(t.a, t.b, t.c, t.box.x0, t.box.x1, t.box.y0, t.box.y1, t.gx, t.gy, plot);
  else
    raster_detail::scan_triangle<int64_t>(t.a, t.b, t.c, t.box.x0, t.box.x1, t.box.y0, t.box.y1, t.gx, t.gy, plot);
}

/// Calls plot(x, y, w) for every pixel centre inside the triangle on a width x height image.
/// Triangles under 1/16 pixel^2 are skipped. Returns false when nothing of the triangle lies on
/// the screen; otherwise its pixel bounding box is in box.
template <class Plot>
bool fill_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, int width, int height, Plot&& plot,
                   int (*box)[4] = nullptr) {
  PixelTriangle t;
  if (!setup_triangle(a, b, c, PixelRect{0, 0, width - 1, height - 1}, t)) return false;
  if (box) {
    (*box)[0] = t.box.x0;
    (*box)[1] = t.box.y0;
    (*box)[2] = t.box.x1;
    (*box)[3] = t.box.y1;
  }
  fill_triangle(t, plot);
  return true;
}

/// True when fill_triangle(t) plots pixel (x, y): the pixel is in t's box and its centre on the
/// inner side of the three edges, the per-pixel test the row scan narrows its spans to.
inline bool covers(const PixelTriangle& t, int x, int y) {
  if (x < t.box.x0 || x > t.box.x1 || y < t.box.y0 || y > t.box.y1) return false;
  return t.narrow ? raster_detail::inside<int32_t>(t, x, y) : raster_detail::inside<int64_t>(t, x, y);
}

/// The w fill_triangle(t) plots at pixel (x, y).
inline int32_t depth_at(const PixelTriangle& t, int x, int y) {
  const int64_t acc = t.gx * (int64_t(x) * (1 << kSubpixelBits) - t.a.x) + t.gy * (int64_t(y) * (1 << kSubpixelBits) - t.a.y);
  return static_cast<int32_t>(t.a.w + (acc >> 8));
}

/// Calls plot(x, y, w) for the pixels of the segment: one pixel per column (or per row, when
/// the segment is steeper than 45 degrees), the nearest to the exact line; w is interpolated.
template <class Plot>
void draw_line(const LineWalk& line, int width, int height, Plot&& plot) {
  // On the image (a clipped segment is, but for rounding), no pixel needs the test.
  const PixelRect box = line_box(line);
  const bool inside = box.x0 >= 0 && box.x1 < width && box.y0 >= 0 && box.y1 < height;
  auto walk = [&](auto border_test) {
    int64_t minor = line.minor, w = line.w;
    for (int k = 0, m = line.first; k < line.count; ++k, m += line.dir) {
      const int n = LineWalk::minor_pixel(minor);
      const int x = line.x_major ? m : n, y = line.x_major ? n : m;
      if (!border_test || (x >= 0 && x < width && y >= 0 && y < height)) plot(x, y, static_cast<int32_t>(w >> 16));
      minor += line.minor_step;
      w += line.w_step;
    }
  };
  if (inside)
    walk(std::false_type{});
  else
    walk(std::true_type{});
}

template <class Plot>
void draw_line(const ScreenVertex& a, const ScreenVertex& b, int width, int height, Plot&& plot) {
  draw_line(walk_line(a, b), width, height, plot);
}

/// Calls plot(x, y, w) for the pixels of the line that fill_triangle(t) plots too, with w the
/// triangle's there: only the steps whose major coordinate lies in t's box are visited.
template <class Plot>
void line_in_triangle(const LineWalk& line, const PixelTriangle& t, Plot&& plot) {
  if (t.narrow)
    raster_detail::walk_in_triangle<int32_t>(line, t, plot);
  else
    raster_detail::walk_in_triangle<int64_t>(line, t, plot);
}

}  // namespace edgetrack
