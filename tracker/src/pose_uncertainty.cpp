// SPDX-License-Identifier: BSD-3-Clause
/// The pose's first-order covariance propagated to the model's image displacement.
#include "edgetrack/pose_uncertainty.h"

#include <cmath>
#include <limits>
#include <type_traits>

#include "edgetrack/millimetres.h"
#include "edgetrack/small_cholesky.h"
#include "pose_perturbation.h"
#include "real/sum_of_products.h"
#include "real/vector_kernels.h"

namespace edgetrack {
using namespace pose_perturbation;
namespace {

template <typename Visit>
void for_each_overlay_point(const EdgeModel& model, Visit visit) {
  for (const Vec3& v : model.vertices) visit(v);
  for (const Cylinder& c : model.cylinders) {
    visit(c.axis_a);
    visit(c.axis_b);
  }
  for (const Circle& c : model.circles) visit(c.centre);
}


/// d(n . pixel)/d(v, w) from (nu, nv) = n^T d(pixel)/d(x/Z, y/Z) / Z, the image covector of the
/// normal at the camera-frame point `in_camera_mm` (inline_pixel_gradient's second half).
__attribute__((always_inline)) inline void gradient_of_covector(const real& nu, const real& nv, const Vec3& in_camera_mm,
                                                                const real& inv_z, const Vec3& offset_mm, real g[kDof]) {
  const Vec3 a{nu, nv, -(nu * (in_camera_mm.x * inv_z) + nv * (in_camera_mm.y * inv_z))};
  // d(point)/dw = -hat(offset), so a . d(point)/dw = -(a x offset).
  const Vec3 turn = -cross(a, offset_mm);
  g[0] = a.x;
  g[1] = a.y;
  g[2] = a.z;
  g[3] = turn.x;
  g[4] = turn.y;
  g[5] = turn.z;
}

/// d(n . pixel)/d(v, w) for the camera-frame point `in_camera_mm` with 1 / Z `inv_z` (one
/// division per point: they are dear without a divider), `offset_mm` its offset from the
/// model's centre in the camera frame, w in radians (scale_turns scales it by the radius).
/// Inlined in floating point's per-match loop (sum_information); pixel_gradient elsewhere.
__attribute__((always_inline)) inline void inline_pixel_gradient(const PinholeCamera& camera, const Vec3& in_camera_mm,
                                                                 const real& inv_z, const Vec3& offset_mm, const Vec2& n,
                                                                 real g[kDof]) {
  real nu, nv;
  if (camera.distorted()) {  // the chain rule through the lens: n^T diag(px, py) J_lens / Z
    const Vec2 across = camera.lens_covector(Vec2{in_camera_mm.x * inv_z, in_camera_mm.y * inv_z},
                                             Vec2{n.x * camera.px, n.y * camera.py});
    nu = across.x * inv_z;
    nv = across.y * inv_z;
  } else {
    nu = n.x * camera.px * inv_z;
    nv = n.y * camera.py * inv_z;
  }
  gradient_of_covector(nu, nv, in_camera_mm, inv_z, offset_mm, g);
}

/// inline_pixel_gradient, out of line: one copy for the per-vertex loop and fixed point.
void pixel_gradient(const PinholeCamera& camera, const Vec3& in_camera_mm, const real& inv_z, const Vec3& offset_mm,
                    const Vec2& n, real g[kDof]) {
  inline_pixel_gradient(camera, in_camera_mm, inv_z, offset_mm, n, g);
}

/// The lower triangle of the information matrix, sum of r r^T over rows r of W^(1/2) J, summed
/// a block of rows at a time, each entry's block sum in order and then added to the entry.
/// Floating point: the rows stored as they come, and a row's six sums taken together over the
/// block (kept in vector registers, each lane one entry's sum in the same order); fixed point:
/// column sums of products (sum_of_products.h: dot_product's exact sum, rounded once).
class InformationSum {
 public:
  explicit InformationSum(real (&information)[kDof][kDof]) : information_(information) {}
  void add(const real row[kDof]) {
    if constexpr (kByRow) {
      for (int k = 0; k < kDof; ++k) rows_[count_][k] = row[k];
    } else {
      for (int k = 0; k < kDof; ++k) rows_[k][count_] = row[k];
    }
    if (++count_ == kBlock) flush();
  }
  void flush() {
    if constexpr (kByRow) {
      vector_kernels::run([&]() __attribute__((always_inline)) { add_block_by_rows(); });
    } else {
      for (int i = 0; i < kDof; ++i)
        for (int j = 0; j <= i; ++j) information_[i][j] += sum_of_products(count_, rows_[i], rows_[j]);
    }
    count_ = 0;
  }

 private:
  static constexpr int kBlock = 32;
  static constexpr bool kByRow = std::numeric_limits<real>::is_iec559;
  /// Every row's six sums at once, all 36 in vector registers over the block (the upper
  /// triangle's are the lower's and thrown away: whole vectors cost less than a triangle).
  __attribute__((always_inline)) void add_block_by_rows() {
    real sums[kDof][kDof] = {};
    for (int k = 0; k < count_; ++k) {
      const real* row = rows_[k];
#pragma GCC unroll 6
      for (int i = 0; i < kDof; ++i)
#pragma GCC unroll 6
        for (int j = 0; j < kDof; ++j) sums[i][j] += row[i] * row[j];
    }
    for (int i = 0; i < kDof; ++i)
      for (int j = 0; j <= i; ++j) information_[i][j] += sums[i][j];
  }
  real (&information_)[kDof][kDof];
  std::conditional_t<kByRow, real[kBlock][kDof], real[kDof][kBlock]> rows_;
  int count_ = 0;
};

/// Rescales the lower triangle of the information matrix from w in radians to w times the radius
/// (mm at the farthest vertex), once per frame rather than per match.
void scale_turns(real a[kDof][kDof], const real& inv_radius) {
  for (int i = 3; i < kDof; ++i)
    for (int j = 0; j <= i; ++j) {
      a[i][j] = inv_radius * a[i][j];
      if (j >= 3) a[i][j] = inv_radius * a[i][j];  // not inv_radius^2: S40.23 keeps 1/r to 1e-5, not its square
    }
}

/// |L^-1 g|^2 (`inv_diagonal`: 1 / L's diagonal), or a negative value when a component passes
/// `cap` (the variance is then off scale).
real whitened_square(const real (&l)[kDof][kDof], const real (&inv_diagonal)[kDof], const real (&g)[kDof],
                     const real& cap) {
  real z[kDof];
  if (!forward_substitute(l, inv_diagonal, g, z, cap)) return real(-1);
  real sum(0);
  for (int k = 0; k < kDof; ++k) sum += z[k] * z[k];
  return sum;
}

/// sum_information's rows through a pinhole camera in floating point, a batch of matches at a
/// time: the kept matches' values gathered into arrays, each match's row computed in a vector
/// lane with the one-by-one loop's expressions in its order (the same bits), and the rows within
/// the cut added in match order (the same sums).
void sum_information_in_lanes(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& pose,
                              const Vec3& centre_mm, const real& inv_cut, InformationSum& sum) {
  using std::fabs;
  constexpr int kBatch = 32;
  vector_kernels::run([&]() __attribute__((always_inline)) {
    // In locals: the stores to the arrays could otherwise alias them.
    const Se3 at = pose;
    const Vec3 centre = centre_mm;
    const real u0 = camera.u0, v0 = camera.v0, px = camera.px, py = camera.py, cut = inv_cut;
    real x[kBatch], y[kBatch], z[kBatch], nx[kBatch], ny[kBatch], ux[kBatch], uy[kBatch];
    real rows[kDof][kBatch];
    real kept[kBatch];  // 1 where the match's row is summed
    const size_t count = matches.size();
    for (size_t m = 0; m < count;) {
      int n = 0;
      for (; m < count && n < kBatch; ++m) {
        const EdgeMatch& match = matches[m];
        if (match.excluded || match.outlier) continue;
        x[n] = match.point.point_in_model.x;
        y[n] = match.point.point_in_model.y;
        z[n] = match.point.point_in_model.z;
        nx[n] = match.point.normal.x;
        ny[n] = match.point.normal.y;
        ux[n] = match.used().x;
        uy[n] = match.used().y;
        ++n;
      }
      for (int k = 0; k < n; ++k) {
        const Vec3 in_camera = to_millimetres(at * Vec3{x[k], y[k], z[k]});
        const real inv_z = real(1) / in_camera.z;
        const real delta =
            nx[k] * (u0 + px * (in_camera.x * inv_z) - ux[k]) + ny[k] * (v0 + py * (in_camera.y * inv_z) - uy[k]);
        const real u = fabs(delta) * cut;
        kept[k] = !(in_camera.z <= real(0)) && !(u >= real(1)) ? real(1) : real(0);
        const real root_weight = real(1) - u * u;
        real g[kDof];
        gradient_of_covector(nx[k] * px * inv_z, ny[k] * py * inv_z, in_camera, inv_z, in_camera - centre, g);
        for (int i = 0; i < kDof; ++i) rows[i][k] = root_weight * g[i];
      }
      for (int k = 0; k < n; ++k) {
        if (kept[k] == real(0)) continue;
        real row[kDof];
        for (int i = 0; i < kDof; ++i) row[i] = rows[i][k];
        sum.add(row);
      }
    }
  });
}

/// Sums the lower triangle of the information matrix over `matches` at `pose` (each row of
/// W^(1/2) J with Tukey's weights cut at `cut` px, of the distances to each match's used()
/// hypothesis; excluded matches and outliers left out). Turns in radians.
void sum_information(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& pose,
                     const Vec3& centre_mm, const real& cut, real (&information)[kDof][kDof]) {
  using std::fabs;
  const bool through_lens = camera.distorted();
  const real inv_cut = real(1) / cut;
  InformationSum sum(information);
  if constexpr (std::numeric_limits<real>::is_iec559) {
    if (!through_lens) {
      sum_information_in_lanes(matches, camera, pose, centre_mm, inv_cut, sum);
      sum.flush();
      return;
    }
  }
  real g[kDof];
  for (const EdgeMatch& match : matches) {
    if (match.excluded || match.outlier) continue;
    const Vec3 in_camera = to_millimetres(pose * match.point.point_in_model);
    if (in_camera.z <= real(0)) continue;
    const real inv_z = real(1) / in_camera.z;
    const Vec2 pixel = through_lens
                           ? camera.project_through_lens(in_camera)
                           : Vec2{camera.u0 + camera.px * (in_camera.x * inv_z), camera.v0 + camera.py * (in_camera.y * inv_z)};
    const real delta = dot(match.point.normal, pixel - match.used());
    const real u = fabs(delta) * inv_cut;
    if (u >= real(1)) continue;
    const real root_weight = real(1) - u * u;  // Tukey's weight is its square
    // Per match, floating point keeps the gradient in registers; fixed point's is long, and the
    // firmware's flash holds it once.
    if constexpr (std::numeric_limits<real>::is_iec559)
      inline_pixel_gradient(camera, in_camera, inv_z, in_camera - centre_mm, match.point.normal, g);
    else pixel_gradient(camera, in_camera, inv_z, in_camera - centre_mm, match.point.normal, g);
    for (int k = 0; k < kDof; ++k) g[k] = root_weight * g[k];
    sum.add(g);
  }
  sum.flush();
}



/// The information matrix of matches at a pose, factored, in the perturbation's coordinates.
struct FactoredInformation {
  Perturbation perturbation;
  real inv_radius{1};
  Vec3 centre_mm;  ///< the model's centre in the camera frame at the pose, mm
  real l[kDof][kDof] = {};  ///< L of L L^T, turns scaled by the radius
  real inv_diagonal[kDof] = {};
};

/// `matches`' information at `pose` (sum_information's): false where a direction is one they
/// do not see.
bool factor_at(const std::vector<EdgeMatch>& matches, const EdgeModel& model, const PinholeCamera& camera,
               const Se3& pose, const real& cut, FactoredInformation& f) {
  f.perturbation = perturbation_of(model);
  f.inv_radius = real(1) / f.perturbation.radius_mm;
  f.centre_mm = to_millimetres(pose * f.perturbation.centre);
  sum_information(matches, camera, pose, f.centre_mm, cut, f.l);
  scale_turns(f.l, f.inv_radius);
  return factor_information(f.l, f.inv_diagonal);
}

}  // namespace

real pose_uncertainty_px(const std::vector<EdgeMatch>& matches, const EdgeModel& model, const PinholeCamera& camera,
                         const Se3& pose, const real& sigma, const real& tukey_c, const real& tukey_floor) {
  using std::sqrt;
  const real unconstrained = real(kUnconstrainedPx);
  real cut = tukey_c * sigma;
  if (cut < tukey_floor) cut = tukey_floor;
  FactoredInformation f;
  if (!factor_at(matches, model, camera, pose, cut, f)) return unconstrained;
  const real(&information)[kDof][kDof] = f.l;
  const real(&inv_diagonal)[kDof] = f.inv_diagonal;
  const real& inv_radius = f.inv_radius;
  const Vec3& centre_mm = f.centre_mm;
  const real& cap = kWhitenedCap;
  real g[kDof];
  real worst(0);  // the largest |L^-1 g_u|^2 + |L^-1 g_v|^2
  bool off_scale = false;
  for_each_overlay_point(model, [&](const Vec3& v) {
    const Vec3 in_camera = to_millimetres(pose * v);
    if (off_scale || in_camera.z <= real(0)) return;
    const real inv_z = real(1) / in_camera.z;
    const Vec3 offset = in_camera - centre_mm;
    pixel_gradient(camera, in_camera, inv_z, offset, Vec2{real(1), real(0)}, g);
    for (int k = 3; k < kDof; ++k) g[k] = inv_radius * g[k];
    const real along_u = whitened_square(information, inv_diagonal, g, cap);
    pixel_gradient(camera, in_camera, inv_z, offset, Vec2{real(0), real(1)}, g);
    for (int k = 3; k < kDof; ++k) g[k] = inv_radius * g[k];
    const real along_v = whitened_square(information, inv_diagonal, g, cap);
    if (along_u < real(0) || along_v < real(0)) {
      off_scale = true;
      return;
    }
    if (along_u + along_v > worst) worst = along_u + along_v;
  });
  if (off_scale) return unconstrained;
  const real deviation = sigma * sqrt(worst);
  return deviation > unconstrained ? unconstrained : deviation;
}

namespace pose_perturbation {

Perturbation perturbation_of(const EdgeModel& model) {
  using std::sqrt;
  Perturbation p;
  Vec3 sum;
  int count = 0;
  for_each_overlay_point(model, [&](const Vec3& v) {
    sum = sum + v;
    ++count;
  });
  if (count == 0) return p;
  p.centre = (real(1) / real(count)) * sum;
  real farthest(0);  // mm^2: one square root at the end
  for_each_overlay_point(model, [&](const Vec3& v) {
    const Vec3 d = to_millimetres(v - p.centre);
    const real r2 = dot(d, d);
    if (r2 > farthest) farthest = r2;
  });
  if (farthest > real(0)) p.radius_mm = sqrt(farthest);
  return p;
}

bool factor_information(real (&information)[kDof][kDof], real (&inv_diagonal)[kDof]) {
  real largest(0);
  for (int k = 0; k < kDof; ++k)
    if (information[k][k] > largest) largest = information[k][k];
  // A pivot below a millionth of the largest is a direction the matches do not see.
  if (!(largest > real(0)) || !cholesky_in_place(information, kDof, real(1e-6) * largest)) return false;
  for (int k = 0; k < kDof; ++k) inv_diagonal[k] = real(1) / information[k][k];
  return true;
}

bool forward_substitute(const real (&l)[kDof][kDof], const real (&inv_diagonal)[kDof], const real (&g)[kDof],
                        real (&z)[kDof], const real& cap) {
  using std::fabs;
  for (int k = 0; k < kDof; ++k) {
    real s = g[k];
    for (int j = 0; j < k; ++j) s -= l[k][j] * z[j];
    z[k] = s * inv_diagonal[k];
    if (fabs(z[k]) > cap) return false;
  }
  return true;
}

}  // namespace pose_perturbation
}  // namespace edgetrack
