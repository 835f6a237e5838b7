// SPDX-License-Identifier: BSD-3-Clause
/// The pinhole camera and its lens models.
#include "edgetrack/pinhole_camera.h"

#include <cmath>

#include "edgetrack/downscaled_camera.h"
#include "real/divisor.h"
#include "real/sum_of_products.h"

namespace edgetrack {
namespace {

/// Newton steps that invert the forward model: from the distorted point itself, each step
/// squares the error; 6 reach every `real`'s resolution for |k r^2| up to 0.3 and beyond.
constexpr int kInversionSteps = 6;

}  // namespace

Vec2 PinholeCamera::distort_other(const Vec2& n) const {
  const real r2 = n.x * n.x + n.y * n.y;
  if (lens.model == LensModel::kOpenCv) {
    const real radial = real(1) + r2 * (lens.k1 + r2 * (lens.k2 + r2 * lens.k3));
    const real xy2 = real(2) * n.x * n.y;
    return {n.x * radial + lens.p1 * xy2 + lens.p2 * (r2 + real(2) * n.x * n.x),
            n.y * radial + lens.p1 * (r2 + real(2) * n.y * n.y) + lens.p2 * xy2};
  }
  return n;
}

Vec2 PinholeCamera::project_through_lens(const Vec3& p) const {
  // Both quotients over one divisor (bit for bit the two divisions, less work on a core without
  // a divider): the contrast memory and the frame's status project every point.
  const Divisor<real> by_z(p.z);
  return to_pixel(distort(Vec2{by_z.divide(p.x), by_z.divide(p.y)}));
}

LensJacobian PinholeCamera::lens_jacobian(const Vec2& n) const {
  const real r2 = n.x * n.x + n.y * n.y;
  LensJacobian j;
  if (lens.model == LensModel::kVisp) {
    // x (1 + kud r^2): d/dx = 1 + kud r^2 + 2 kud x^2, d/dy = 2 kud x y.
    const real factor = real(1) + lens.kud * r2;
    const real twice_k = real(2) * lens.kud;
    j.xx = factor + twice_k * n.x * n.x;
    j.yy = factor + twice_k * n.y * n.y;
    j.xy = twice_k * n.x * n.y;
    j.yx = j.xy;
  } else if (lens.model == LensModel::kOpenCv) {
    const real radial = real(1) + r2 * (lens.k1 + r2 * (lens.k2 + r2 * lens.k3));
    // d radial / d r^2, times 2 gives d radial / dx = 2 x radial'.
    const real slope = lens.k1 + r2 * (real(2) * lens.k2 + real(3) * lens.k3 * r2);
    const real twice_slope = real(2) * slope;
    j.xx = radial + twice_slope * n.x * n.x + real(2) * lens.p1 * n.y + real(6) * lens.p2 * n.x;
    j.yy = radial + twice_slope * n.y * n.y + real(6) * lens.p1 * n.y + real(2) * lens.p2 * n.x;
    j.xy = twice_slope * n.x * n.y + real(2) * lens.p1 * n.x + real(2) * lens.p2 * n.y;
    j.yx = twice_slope * n.x * n.y + real(2) * lens.p1 * n.x + real(2) * lens.p2 * n.y;
  }
  return j;
}

Vec2 PinholeCamera::lens_covector(const Vec2& n, const Vec2& c) const {
  if (lens.model == LensModel::kVisp) {
    const real factor = real(1) + lens.kud * sum_of_products(n.x, n.x, n.y, n.y);
    const real bend = real(2) * lens.kud * sum_of_products(c.x, n.x, c.y, n.y);
    return {sum_of_products(factor, c.x, bend, n.x), sum_of_products(factor, c.y, bend, n.y)};
  }
  const LensJacobian j = lens_jacobian(n);
  return {sum_of_products(c.x, j.xx, c.y, j.yx), sum_of_products(c.x, j.xy, c.y, j.yy)};
}

Vec2 PinholeCamera::undistort(const Vec2& d) const {
  if (lens.model == LensModel::kVisp) {
    const real factor = real(1) + lens.kdu * (d.x * d.x + d.y * d.y);
    return {d.x * factor, d.y * factor};
  }
  return invert_distortion(d);
}

Vec2 PinholeCamera::invert_distortion(const Vec2& d) const {
  if (!distorted()) return d;
  Vec2 n = d;
  for (int step = 0; step < kInversionSteps; ++step) {
    const Vec2 e = distort(n) - d;
    const LensJacobian j = lens_jacobian(n);
    const real det = j.xx * j.yy - j.xy * j.yx;
    if (!(det > real(0))) break;  // beyond the fold of the lens: no inverse there
    n = n - Vec2{(j.yy * e.x - j.xy * e.y) / det, (j.xx * e.y - j.yx * e.x) / det};
  }
  return n;
}

Vec2 PinholeCamera::distort_direction(const Vec2& pinhole, const Vec2& along) const {
  const LensJacobian j = lens_jacobian(to_normalised(pinhole));
  // In pixels: diag(px, py) J diag(1 / px, 1 / py) along.
  const real ax = along.x / px, ay = along.y / py;
  return {px * (j.xx * ax + j.xy * ay), py * (j.yx * ax + j.yy * ay)};
}

bool PinholeCamera::bend_within(const Vec2& a, const Vec2& b, const real& tolerance) const {
  using std::fabs;
  // With m the middle and u half the segment, x (1 + k |x|^2) puts the middle's image
  // -k (m |u|^2 + 2 u (m . u)) off the middle of the ends' images: at most 3 |k| |m| |u|^2, in
  // pixels times the larger focal length, and the bend is the part of that across the chord.
  // With s = a + b = 2 m and d = b - a = 2 u, that is 3/8 |k| f |d|^2 |s|, squared here.
  const Vec2 s = a + b, d = b - a;
  const real focal = px > py ? px : py;
  const real reach = real(0.375) * fabs(lens.kud) * focal * dot(d, d);  // the bound over |s|, pixels
  return reach * reach * dot(s, s) <= tolerance * tolerance;
}

int PinholeCamera::chord_pieces(const Vec2& a, const Vec2& b, const real& tolerance, int most) const {
  if (!distorted()) return 1;
  if (lens.model == LensModel::kVisp && bend_within(a, b, tolerance)) return 1;
  const Vec2 da = distort(a), db = distort(b), dm = distort(real(0.5) * (a + b));
  // In pixels: the chord of the ends and the middle's offset from its start.
  const Vec2 chord{px * (db.x - da.x), py * (db.y - da.y)};
  const Vec2 middle{px * (dm.x - da.x), py * (dm.y - da.y)};
  // Squared, which needs no square root: bend^2 = cross^2 / length^2 <= (tolerance n^2)^2.
  const real cross = chord.x * middle.y - chord.y * middle.x;
  const real length_squared = dot(chord, chord);
  const real bend_squared = length_squared > real(0) ? cross * cross / length_squared : dot(middle, middle);
  const real tolerance_squared = tolerance * tolerance;
  int pieces = 1;
  while (pieces < most && bend_squared > tolerance_squared * real(pieces * pieces * pieces * pieces)) ++pieces;
  return pieces;
}

PinholeCamera PinholeCamera::scaled(int factor) const {
  // Pixel centres sit at integer coordinates, so pixel (0, 0) covers [-0.5, 0.5): in an image
  // `factor` times larger, the same ray lands at factor * (u + 0.5) - 0.5.
  const real shift = real(factor - 1) / 2;
  return {px * factor, py * factor, u0 * factor + shift, v0 * factor + shift, width * factor, height * factor, lens};
}

PinholeCamera downscaled_camera(const PinholeCamera& camera, int factor) {
  if (factor <= 1) return camera;
  const real f(factor), half(0.5);
  return {camera.px / f, camera.py / f, (camera.u0 + half) / f - half, (camera.v0 + half) / f - half,
          camera.width / factor, camera.height / factor, camera.lens};
}

}  // namespace edgetrack
