// SPDX-License-Identifier: BSD-3-Clause
/// The drift check's first-order gate: how far the pose the matches off the thin lines give lies
/// from the first solve's, in its standard deviations (excluded_pull_sigmas). Once a frame, and
/// only with the check on: apart from the pose's covariance (pose_uncertainty.cpp), whose loops
/// run over every match, so that the microcontroller builds it for size.
#include <algorithm>
#include <cmath>

#include "edgetrack/millimetres.h"
#include "edgetrack/order_statistic.h"
#include "edgetrack/pose_solver.h"
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

/// The residual scale the kept rows are predicted to have after their Gauss-Newton step x from
/// the start (solver coordinates), 1.4826 times the median |r_i + J_i x| over the `count` rows, as
/// PoseSolution::residual_scale is over the matches off the lines; 0 where over half the rows
/// weigh nothing. The rows carry the first solve's start weights (1 - u^2, u a distance over the
/// Tukey cut, several scales out): about the median a weighted residual is the match's own within
/// a few percent, and a row of weight 0 (beyond the cut at the start) is counted above the median,
/// as the second solve's scale counts such a match. What is left is at most the residual: a scale
/// no larger than the second's, so the gate errs towards running the second solve. The predicted
/// magnitudes are written over the residuals, which the gate has summed.
real predicted_scale(size_t count, real* residual, real* const (&column)[kDof], const real (&x)[kDof]) {
  using std::fabs;
  size_t weighed = 0;
  for (size_t i = 0; i < count; ++i) {
    if (column[0][i] == real(0) && column[1][i] == real(0)) continue;  // weight 0: no row
    real predicted = residual[i];
    for (int k = 0; k < kDof; ++k) predicted += column[k][i] * x[k];
    residual[weighed++] = fabs(predicted);
  }
  const size_t middle = count / 2;
  if (weighed <= middle) return real(0);
  return real(kMadToSigma) * kth_of_values(residual, weighed, middle);
}

}  // namespace

real excluded_pull_sigmas(const std::vector<EdgeMatch>& matches, StartRows& rows, const EdgeModel& model,
                          const Se3& start, const Se3& solved, const real& sigma_floor, real* scale_px,
                          const real& decided_within, Se3* stepped) {
  using std::sqrt;
  if (scale_px) *scale_px = sigma_floor;
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
  const real distance = sqrt(square);
  const real at_floor = distance / sigma_floor;
  // A larger scale only lowers the bound: within `decided_within` at the floor it is decided.
  if (!(at_floor > decided_within)) return at_floor;
  // The kept rows' own step, Delta_2 = -L^-T z, back in the solver's coordinates: x = T Delta_2.
  real step[kDof];
  for (int j = kDof - 1; j >= 0; --j) {
    real s = -z[j];
    for (int k = j + 1; k < kDof; ++k) s -= h[k][j] * step[k];
    step[j] = s * inv_diagonal[j];
  }
  const Vec3 d = centre_mm - to_millimetres(start.translation());
  const Vec3 turn_by = inv_radius * Vec3{step[3], step[4], step[5]};
  const Vec3 shift = Vec3{step[0], step[1], step[2]} + cross(d, turn_by);
  const real x[kDof] = {shift.x, shift.y, shift.z, turn_by.x, turn_by.y, turn_by.z};
  if (stepped) {  // as the pose step's x moves the pose (PointToLineProblem::pose)
    const real mm(kMillimetresPerMetre);
    *stepped = start.retract(Vec3{shift.x / mm, shift.y / mm, shift.z / mm}, turn_by);
  }
  // The check allows the second pose's deviations at that pose's own scale: the gate takes the
  // scale the kept matches are predicted to fit at there, not the first's (which matches on
  // lines inflate, the frames the lines pull most) nor the floor alone (on a loosely fitting
  // model the rest fit no closer than all of them did, and the check could not act).
  const real scale = std::max(predicted_scale(kept, residual, column, x), sigma_floor);
  if (scale_px) *scale_px = scale;
  const real sigmas = distance / scale;
  return sigmas > unconstrained ? unconstrained : sigmas;
}

}  // namespace edgetrack
