// SPDX-License-Identifier: BSD-3-Clause
/// The portable rasteriser behind Edge-ID and the test-image renderer: clipping and projection
/// in `real`, then triangle filling and line drawing in integers only (no FPU, no GL).
/// Screen positions are Q4 fixed point (1/16 pixel, pixel centres at multiples of 16) and depth
/// is carried as inverse depth w = 1/Z in Q20 (1/m), which is affine in screen space, so a
/// larger w is nearer and w = 0 is "nothing drawn".
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <utility>

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

}  // namespace raster_detail

/// Calls plot(x, y, w) for every pixel centre inside the triangle; w is interpolated exactly
/// (affine in screen space). Triangles under 1/16 pixel^2 are skipped. Returns false when
/// nothing of the triangle lies on the screen; otherwise its pixel bounding box is in box.
template <class Plot>
bool fill_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, int width, int height, Plot&& plot,
                   int (*box)[4] = nullptr) {
  int64_t area = int64_t(b.x - a.x) * (c.y - a.y) - int64_t(b.y - a.y) * (c.x - a.x);
  if (area < 0) {
    std::swap(b, c);
    area = -area;
  }
  if (area < 16) return false;
  const int32_t min_x = std::min(a.x, std::min(b.x, c.x)), max_x = std::max(a.x, std::max(b.x, c.x));
  const int32_t min_y = std::min(a.y, std::min(b.y, c.y)), max_y = std::max(a.y, std::max(b.y, c.y));
  const int x0 = std::max(0, (min_x + 15) >> kSubpixelBits), x1 = std::min(width - 1, max_x >> kSubpixelBits);
  const int y0 = std::max(0, (min_y + 15) >> kSubpixelBits), y1 = std::min(height - 1, max_y >> kSubpixelBits);
  if (x0 > x1 || y0 > y1) return false;
  if (box) {
    (*box)[0] = x0;
    (*box)[1] = y0;
    (*box)[2] = x1;
    (*box)[3] = y1;
  }
  // Gradient of w per Q4 step, scaled by 2^8: w(p) = a.w + (gx * (p.x - a.x) + gy * (p.y - a.y)) >> 8.
  const int64_t dxb = b.x - a.x, dyb = b.y - a.y, dwb = b.w - a.w;
  const int64_t dxc = c.x - a.x, dyc = c.y - a.y, dwc = c.w - a.w;
  const int64_t gx = ((dwb * dyc - dwc * dyb) * 256) / area;
  const int64_t gy = ((dxb * dwc - dxc * dwb) * 256) / area;
  // Edge functions are products of two coordinate differences plus one more: under 2^14 Q4
  // units (1024 pixels) on both axes they fit in 32 bits, which halves the inner loop on ARM.
  const int32_t span = std::max(max_x - min_x, max_y - min_y);
  const int32_t reach = std::max(std::max(std::abs(min_x), std::abs(max_x)), std::max(std::abs(min_y), std::abs(max_y)));
  if (span < (1 << 14) && reach < (1 << 14))
    raster_detail::scan_triangle<int32_t>(a, b, c, x0, x1, y0, y1, gx, gy, plot);
  else
    raster_detail::scan_triangle<int64_t>(a, b, c, x0, x1, y0, y1, gx, gy, plot);
  return true;
}

/// Calls plot(x, y, w) for the pixels of the segment: one pixel per column (or per row, when
/// the segment is steeper than 45 degrees), the nearest to the exact line; w is interpolated.
template <class Plot>
void draw_line(const ScreenVertex& a, const ScreenVertex& b, int width, int height, Plot&& plot) {
  const int32_t dx = b.x - a.x, dy = b.y - a.y;
  const bool x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const int32_t major_a = x_major ? a.x : a.y, major_b = x_major ? b.x : b.y;
  const int32_t minor_a = x_major ? a.y : a.x;
  const int32_t d_major = major_b - major_a, d_minor = x_major ? dy : dx;
  const int half = 1 << (kSubpixelBits - 1);
  const int first = (major_a + half) >> kSubpixelBits, last = (major_b + half) >> kSubpixelBits;
  const int dir = first <= last ? 1 : -1;
  // Minor coordinate and w at a major position m: value_a + slope * (m - major_a), slopes in Q16
  // (scaled by multiplying: the values may be negative, where a left shift is undefined).
  const int64_t q16 = 65536;
  const int64_t minor_slope = d_major != 0 ? int64_t(d_minor) * q16 / d_major : 0;
  const int64_t w_slope = d_major != 0 ? int64_t(b.w - a.w) * q16 / d_major : 0;
  const int64_t offset = int64_t(first) * (1 << kSubpixelBits) - major_a;
  int64_t minor = int64_t(minor_a) * q16 + minor_slope * offset;
  int64_t w = int64_t(a.w) * q16 + w_slope * offset;
  const int64_t minor_step = minor_slope * dir * (1 << kSubpixelBits);
  const int64_t w_step = w_slope * dir * (1 << kSubpixelBits);
  for (int m = first;; m += dir) {
    const int n = static_cast<int>((minor + half * q16) >> (16 + kSubpixelBits));
    const int x = x_major ? m : n, y = x_major ? n : m;
    if (x >= 0 && x < width && y >= 0 && y < height) plot(x, y, static_cast<int32_t>(w >> 16));
    if (m == last) break;
    minor += minor_step;
    w += w_step;
  }
}

}  // namespace edgetrack
