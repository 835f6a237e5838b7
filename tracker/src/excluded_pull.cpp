// SPDX-License-Identifier: BSD-3-Clause
/// The drift check's first-order gate: how far the pose the matches off the thin lines give lies
/// from the first solve's, in its standard deviations (excluded_pull_sigmas). Once a frame, and
/// only with the check on: apart from the pose's covariance (pose_uncertainty.cpp), whose loops
/// run over every match, so that the microcontroller builds it for size.
#include <cmath>

#include "edgetrack/millimetres.h"
#include "edgetrack/pose_uncertainty.h"
#include "pose_perturbation.h"
#include "real/sum_of_products.h"

namespace edgetrack {
using namespace pose_perturbation;
namespace {

/// The pose step's rows at `start` (a move v of the model's origin, mm, and a turn w about it,
/// radians) in the perturbation's coordinates, a move v' of the model's centre and the turn
/// times the radius, w' = r w: v = v' + d x w (d the centre's offset from the origin in the
/// camera frame, mm), so H' = T^T H T and g' = T^T g with T = [[I, hat(d) / r], [0, I / r]], on
/// the lower triangle `h` and `g` in place. Summed at the origin the turns' columns are as
/// large as the model is far from it; about the centre they are balanced as factor_information
/// needs.
void to_perturbation(const Vec3& d, const real& inv_radius, real (&h)[kDof][kDof], real (&g)[kDof]) {
  real full[kDof][kDof];
  for (int i = 0; i < kDof; ++i)
    for (int j = 0; j <= i; ++j) full[i][j] = full[j][i] = h[i][j];
  // S = hat(d) / r; the columns of T's upper right block.
  const real s[3][3] = {{real(0), -d.z * inv_radius, d.y * inv_radius},
                        {d.z * inv_radius, real(0), -d.x * inv_radius},
                        {-d.y * inv_radius, d.x * inv_radius, real(0)}};
  // P = A S + B / r (the vv-w' block); C' = S^T P + (B^T S + C / r) / r.
  real p[3][3], q[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      p[i][j] = sum_of_products(full[i][0], s[0][j], full[i][1], s[1][j], full[i][2], s[2][j]) + full[i][3 + j] * inv_radius;
      q[i][j] = sum_of_products(full[3 + i][0], s[0][j], full[3 + i][1], s[1][j], full[3 + i][2], s[2][j]) +
                full[3 + i][3 + j] * inv_radius;
    }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) h[3 + i][j] = p[j][i];
    for (int j = 0; j <= i; ++j)
      h[3 + i][3 + j] = sum_of_products(s[0][i], p[0][j], s[1][i], p[1][j], s[2][i], p[2][j]) + q[i][j] * inv_radius;
  }
  real turned[3];
  for (int i = 0; i < 3; ++i)
    turned[i] = sum_of_products(s[0][i], g[0], s[1][i], g[1], s[2][i], g[2]) + g[3 + i] * inv_radius;
  for (int i = 0; i < 3; ++i) g[3 + i] = turned[i];
}

}  // namespace

real excluded_pull_sigmas(const std::vector<EdgeMatch>& matches, StartRows& rows, const EdgeModel& model,
                          const Se3& start, const Se3& solved, const real& sigma) {
  using std::sqrt;
  const real unconstrained = real(kUnconstrainedPx);
  const size_t m = matches.size();
  if (!rows.kept || rows.residuals.size() != m || rows.jacobian.size() != m * kDof) return unconstrained;
  real* const residual = rows.residuals.data();
  real* column[kDof];
  for (int k = 0; k < kDof; ++k) column[k] = rows.jacobian.data() + static_cast<size_t>(k) * m;
  // The rows of the matches not excluded, moved to the front of each column: the sums below
  // skip the excluded rows rather than add their zeros (the same sums, a fifth fewer products
  // where the test calls a fifth of the matches lines).
  size_t kept = 0;
  for (size_t i = 0; i < m; ++i) {
    if (matches[i].excluded) continue;
    if (kept != i) {
      residual[kept] = residual[i];
      for (int k = 0; k < kDof; ++k) column[k][kept] = column[k][i];
    }
    ++kept;
  }
  const int count = static_cast<int>(kept);
  real h[kDof][kDof] = {}, pull[kDof];
  for (int i = 0; i < kDof; ++i) {
    for (int j = 0; j <= i; ++j) h[i][j] = sum_of_products(count, column[i], column[j]);
    pull[i] = sum_of_products(count, column[i], residual);
  }
  const Perturbation perturbation = perturbation_of(model);
  const real inv_radius = real(1) / perturbation.radius_mm;
  const Vec3 centre_mm = to_millimetres(start * perturbation.centre);
  to_perturbation(centre_mm - to_millimetres(start.translation()), inv_radius, h, pull);
  real inv_diagonal[kDof];
  if (!factor_information(h, inv_diagonal)) return unconstrained;
  // The first solve's move from the start in the same coordinates: the model centre's
  // displacement (mm) and the turn about it times the radius.
  const Vec3 moved = to_millimetres(solved * perturbation.centre) - centre_mm;
  const Vec3 turn = perturbation.radius_mm * rotation_log(solved.rotation() * start.rotation().transpose());
  const real first[kDof] = {moved.x, moved.y, moved.z, turn.x, turn.y, turn.z};
  // |L^T (Delta_2 - Delta_1)| with L L^T Delta_2 = -g: |L^-1 g + L^T Delta_1|.
  real z[kDof];
  forward_substitute(h, inv_diagonal, pull, z);
  real square(0);
  for (int j = 0; j < kDof; ++j) {
    real y(0);
    for (int k = j; k < kDof; ++k) y += h[k][j] * first[k];
    const real component = z[j] + y;
    if (!(component < kWhitenedCap && component > -kWhitenedCap)) return unconstrained;
    square += component * component;
  }
  const real sigmas = sqrt(square) / sigma;
  return sigmas > unconstrained ? unconstrained : sigmas;
}

}  // namespace edgetrack
