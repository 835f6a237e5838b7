// SPDX-License-Identifier: BSD-3-Clause
/// Point-to-line pose refinement with vnl_levenberg_marquardt and an analytic Jacobian.
#include "edgetrack/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "vnl/algo/vnl_levenberg_marquardt.h"
#include "vnl/vnl_least_squares_function.h"
#include "vnl/vnl_rotation_matrix.h"

namespace edgetrack {
namespace {

/// The solve works in millimetres (the translation parameters and the camera-frame points). In
/// metres the Jacobian's translation columns are px / Z ~ 1500 px/m, past the 512 below which
/// S40.23's multiply is one 32 x 32-bit product (real/fixed64.h), both in the Jacobian and in
/// MINPACK's QR of it; in millimetres they are ~1.5 px/mm. MINPACK scales each column by its
/// norm, so in exact arithmetic the steps do not depend on the unit.
constexpr int kMillimetresPerMetre = 1000;

/// The left Jacobian of SO(3), J(w) = I + b hat(w) + c hat(w)^2: d(exp(hat(w)) y)/dw is
/// -hat(exp(hat(w)) y) J(w).
Mat33 so3_left_jacobian(const Vec3& w) {
  const vnl_rotation_coefficients<real> k = vnl_rotation_exp_coefficients(vnl_vector_fixed<real, 3>(w.x, w.y, w.z));
  const Mat33 h = hat(w);
  const Mat33 h2 = h * h;
  Mat33 j = Mat33::identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) j.m[r][c] = j.m[r][c] + k.b * h.m[r][c] + k.c * h2.m[r][c];
  return j;
}

class PointToLineResiduals : public vnl_least_squares_function {
 public:
  /// `weights` (one per match, or empty for all 1) multiply each residual: they are the square
  /// roots of the least-squares weights.
  PointToLineResiduals(const std::vector<EdgeMatch>& matches, const std::vector<real>& weights,
                       const PinholeCamera& camera, const Se3& start)
      : vnl_least_squares_function(6, static_cast<unsigned>(matches.size()), use_gradient),
        start_(start),
        start_translation_mm_(real(kMillimetresPerMetre) * start.translation()),
        rotated_(matches.size()),
        coefficients_(matches.size()),
        unweighted_(matches.size()),
        turned_(matches.size()),
        moved_(matches.size()) {
    for (size_t i = 0; i < matches.size(); ++i) {
      const EdgeMatch& m = matches[i];
      rotated_[i] = start.rotation() * (real(kMillimetresPerMetre) * m.point.point_in_model);
      // delta = n . (project(p) - q) = (a X + b Y + c Z) / Z, times the match's weight.
      const Vec2& n = m.point.normal;
      unweighted_[i] = {n.x * camera.px, n.y * camera.py,
                        n.x * (camera.u0 - m.used().x) + n.y * (camera.v0 - m.used().y)};
      coefficients_[i] = weights.empty() ? unweighted_[i] : weights[i] * unweighted_[i];
    }
  }

  void f(const vnl_vector<real>& x, vnl_vector<real>& fx) override {
    const Vec3 v{x[0], x[1], x[2]}, w{x[3], x[4], x[5]};
    const Mat33 r = rotation_exp(w);
    const Vec3 t = start_translation_mm_ + v;
    evaluated_ = false;
    for (size_t i = 0; i < rotated_.size(); ++i) {
      const Vec3 z = r * rotated_[i];
      const Vec3 p = z + t;
      if (p.z <= real(0)) {
        throw_failure();
        return;
      }
      turned_[i] = z;
      moved_[i] = p;
      fx[static_cast<unsigned>(i)] = dot(coefficients_[i], p) / p.z;
    }
    for (unsigned k = 0; k < 6; ++k) evaluated_at_[k] = x[k];
    evaluated_ = true;
  }

  void gradf(const vnl_vector<real>& x, vnl_matrix<real>& jacobian) override {
    // MINPACK asks for the Jacobian where it evaluated last (the start, then each accepted
    // step), so the rotation and the moved points come from that evaluation.
    if (!evaluated_at(x)) {
      vnl_vector<real> fx(get_number_of_residuals());
      f(x, fx);
      if (failure) return;
    }
    const Mat33 jl = so3_left_jacobian(Vec3{x[3], x[4], x[5]});
    for (size_t i = 0; i < rotated_.size(); ++i) {
      const Vec3& z = turned_[i];
      const Vec3& p = moved_[i];
      const real inv_z = real(1) / p.z;
      // d delta / d p = (a, b, -(a X + b Y) / Z) / Z, with the weight inside a and b.
      const Vec3& k = coefficients_[i];
      const real gx = k.x * inv_z;
      const real gy = k.y * inv_z;
      const real gz = -(gx * p.x + gy * p.y) * inv_z;
      const unsigned row = static_cast<unsigned>(i);
      jacobian(row, 0) = gx;
      jacobian(row, 1) = gy;
      jacobian(row, 2) = gz;
      // d delta / d w = g^T (-hat(z)) J(w) = (z x g)^T J(w).
      const Vec3 zg = cross(z, Vec3{gx, gy, gz});
      for (int c = 0; c < 3; ++c)
        jacobian(row, 3 + static_cast<unsigned>(c)) = zg.x * jl.m[0][c] + zg.y * jl.m[1][c] + zg.z * jl.m[2][c];
    }
  }

  /// The unweighted signed distances delta_i at x, for the next round's choice and weights.
  void signed_distances(const vnl_vector<real>& x, std::vector<real>& out) {
    if (!evaluated_at(x)) {
      vnl_vector<real> fx(get_number_of_residuals());
      f(x, fx);
    }
    for (size_t i = 0; i < rotated_.size(); ++i) out[i] = dot(unweighted_[i], moved_[i]) / moved_[i].z;
  }

  Se3 pose(const vnl_vector<real>& x) const {
    const Vec3 w{x[3], x[4], x[5]};
    const real mm(kMillimetresPerMetre);
    return Se3(rotation_exp(w) * start_.rotation(), start_.translation() + Vec3{x[0] / mm, x[1] / mm, x[2] / mm});
  }

 private:
  bool evaluated_at(const vnl_vector<real>& x) const {
    if (!evaluated_) return false;
    for (unsigned k = 0; k < 6; ++k)
      if (!(x[k] == evaluated_at_[k])) return false;
    return true;
  }

  Se3 start_;
  Vec3 start_translation_mm_;
  std::vector<Vec3> rotated_;       ///< R0 * point_in_model in millimetres, fixed during the minimisation
  std::vector<Vec3> coefficients_;  ///< (a, b, c) of each residual, see the constructor
  std::vector<Vec3> unweighted_;    ///< the same before the weights
  /// At the last evaluation (x = evaluated_at_): R(w) R0 * point_in_model and the camera-frame
  /// point, millimetres, for the Jacobian.
  std::vector<Vec3> turned_, moved_;
  real evaluated_at_[6] = {};
  bool evaluated_ = false;
};

/// MINPACK's endings that still leave the best estimate LM found: the evaluation limit, and
/// tolerances reached at the scalar's resolution (info 6, 7, 8: no further reduction, step or
/// gradient test is possible at this precision). A fixed-point solve whose tolerances lie near
/// its resolution ends this way at its optimum: in millimetres S47.16 often does (frames were
/// lost in the app tests when these counted as failures). Other codes are failures.
bool keeps_best_estimate(int code) {
  return code == vnl_levenberg_marquardt::FAILED_TOO_MANY_ITERATIONS ||
         code == vnl_levenberg_marquardt::FAILED_FTOL_TOO_SMALL ||
         code == vnl_levenberg_marquardt::FAILED_XTOL_TOO_SMALL ||
         code == vnl_levenberg_marquardt::FAILED_GTOL_TOO_SMALL;
}

/// One Levenberg-Marquardt solve over `matches` from `start`, stopped after `max_evaluations`
/// residual evaluations; adds its counts to `solution`. With `distances`, also the unweighted
/// signed point-to-line distances at the new pose.
bool solve_once(const std::vector<EdgeMatch>& matches, const std::vector<real>& weights, const PinholeCamera& camera,
                const Se3& start, const PoseParams& params, int max_evaluations, PoseSolution& solution, Se3& pose,
                std::vector<real>* distances) {
  PointToLineResiduals residuals(matches, weights, camera, start);
  vnl_levenberg_marquardt lm(residuals);
  lm.set_max_function_evals(max_evaluations);
  lm.set_x_tolerance(params.x_tolerance);
  lm.set_f_tolerance(params.f_tolerance);
  lm.set_g_tolerance(params.g_tolerance);
  vnl_vector<real> x(6, real(0));
  const bool ok = lm.minimize_using_gradient(x);
  solution.evaluations += lm.get_num_evaluations();
  solution.iterations += lm.get_num_jacobian_evaluations();
  if (solution.evaluations == lm.get_num_evaluations()) solution.start_rms = lm.get_start_error();
  solution.end_rms = lm.get_end_error();
  if (!(ok || keeps_best_estimate(lm.get_failure_code())) || residuals.failure) return false;
  pose = residuals.pose(x);
  if (distances) residuals.signed_distances(x, *distances);
  return !residuals.failure;
}

/// The median of |values| (the distances may be signed).
real median_of(std::vector<real> values) {
  using std::fabs;
  for (real& v : values) v = fabs(v);
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  return values[mid];
}

/// Each match uses its hypothesis nearest to the pose where `distances` (signed, to each
/// match's used() point) were measured; `distances` become the signed distances to the chosen
/// ones. The lines through the hypotheses are parallel (one normal), so
/// delta_h = delta + n . (used - h): no projection per hypothesis.
void choose_nearest_hypotheses(std::vector<EdgeMatch>& matches, std::vector<real>& distances) {
  using std::fabs;
  for (size_t i = 0; i < matches.size(); ++i) {
    EdgeMatch& m = matches[i];
    if (m.alternative_count == 0) continue;
    const Vec2 used = m.used();
    const real delta = distances[i];
    real nearest = delta;
    for (int h = 0; h <= m.alternative_count; ++h) {
      const real d = delta + dot(m.point.normal, used - (h == 0 ? m.found : m.alternatives[h - 1]));
      if (fabs(d) < fabs(nearest)) {
        nearest = d;
        m.chosen = h;
      }
    }
    distances[i] = nearest;
  }
}

/// The signed distances to each match's strongest edge (`found`), from those to its used() one.
void to_strongest(const std::vector<EdgeMatch>& matches, std::vector<real>& distances) {
  for (size_t i = 0; i < matches.size(); ++i)
    if (matches[i].chosen != 0) distances[i] = distances[i] + dot(matches[i].point.normal, matches[i].used() - matches[i].found);
}

/// The square roots of Tukey's weights, 1 - (d / c)^2, of the signed distances, with
/// c = max(tukey_c * 1.4826 * median |d|, tukey_floor); marks and counts the outliers (weight 0).
int tukey_weights(std::vector<EdgeMatch>& matches, const std::vector<real>& distances, const PoseParams& params,
                  std::vector<real>& weights) {
  using std::fabs;
  real c = params.tukey_c * real(1.4826) * median_of(distances);
  if (c < params.tukey_floor) c = params.tukey_floor;
  int outliers = 0;
  for (size_t i = 0; i < matches.size(); ++i) {
    const real u = fabs(distances[i]) / c;
    matches[i].outlier = u >= real(1);
    weights[i] = matches[i].outlier ? real(0) : real(1) - u * u;
    outliers += matches[i].outlier;
  }
  return outliers;
}

}  // namespace

PoseSolution solve_pose(std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& start,
                        const PoseParams& params) {
  using std::fabs;
  PoseSolution solution;
  solution.camera_from_model = start;
  const size_t needed = static_cast<size_t>(params.min_points > 6 ? params.min_points : 6);
  if (matches.size() < needed) return solution;
  for (EdgeMatch& m : matches) m.chosen = 0;  // the first solve uses the strongest edges
  const bool robust = params.tukey_c > real(0) && params.robust_rounds > 0;
  std::vector<real> distances(matches.size()), weights;  // no weights: the first solve is unweighted
  if (robust && params.weigh_at_start) {
    // The control points were sampled at `start`: their pixels are its projections.
    for (size_t i = 0; i < matches.size(); ++i)
      distances[i] = dot(matches[i].point.normal, matches[i].point.pixel - matches[i].found);
    weights.resize(matches.size());
    tukey_weights(matches, distances, params, weights);
    for (EdgeMatch& m : matches) m.outlier = false;  // outliers are the last round's
  }
  Se3 pose;
  if (!solve_once(matches, weights, camera, start, params, params.max_evaluations, solution, pose, &distances))
    return solution;
  solution.camera_from_model = pose;
  solution.solved = true;
  if (!robust) {
    solution.residual_scale = real(1.4826) * median_of(distances);
    return solution;
  }

  weights.resize(matches.size());
  for (int round = 0; round < params.robust_rounds; ++round) {
    choose_nearest_hypotheses(matches, distances);
    solution.outliers = tukey_weights(matches, distances, params, weights);
    if (matches.size() - static_cast<size_t>(solution.outliers) < needed) break;
    if (!solve_once(matches, weights, camera, pose, params, params.robust_evaluations, solution, pose, &distances))
      break;
    solution.camera_from_model = pose;
  }
  // distances are those at solution.camera_from_model: solve_once leaves them alone when it fails.
  // The scale reads the strongest edges: on an image unrelated to the model the nearest of
  // several hypotheses is nearer than chance puts one edge, which would hide a lost frame.
  to_strongest(matches, distances);
  solution.residual_scale = real(1.4826) * median_of(distances);
  return solution;
}

}  // namespace edgetrack
