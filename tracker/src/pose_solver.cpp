// SPDX-License-Identifier: BSD-3-Clause
/// Point-to-line pose refinement with MINPACK's lmder (as vnl_levenberg_marquardt drives it) and
/// an analytic Jacobian.
#include "edgetrack/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "edgetrack/millimetres.h"
#include "edgetrack/normal_equations_lm.h"
#include "edgetrack/order_statistic.h"
#include "edgetrack/tracker_memory.h"
#include "netlib/minpack.h"
#include "real/divisor.h"
#include "real/sum_of_products.h"
#include "real/vector_kernels.h"
#include "vnl/algo/vnl_levenberg_marquardt.h"
#include "vnl/vnl_rotation_matrix.h"

namespace edgetrack {
namespace {

/// r y with each row's sum of products rounded once (sum_of_products.h): each solve's start
/// rotation for every match.
__attribute__((always_inline)) inline Vec3 rotate(const Mat33& r, const Vec3& y) {
  return {sum_of_products(r.m[0][0], y.x, r.m[0][1], y.y, r.m[0][2], y.z),
          sum_of_products(r.m[1][0], y.x, r.m[1][1], y.y, r.m[1][2], y.z),
          sum_of_products(r.m[2][0], y.x, r.m[2][1], y.y, r.m[2][2], y.z)};
}

/// out_i = turn(in_i) for each point of a structure of arrays (x, y, z arrays), on restrict
/// parameters, so that the host compiler vectorises it as distances_to_lines.
template <class Turn>
__attribute__((always_inline)) inline void turn_points(size_t n, const Turn& turn, const real* __restrict x, const real* __restrict y,
                 const real* __restrict z, real* __restrict out_x, real* __restrict out_y, real* __restrict out_z) {
  for (size_t i = 0; i < n; ++i) {
    const Vec3 v = turn(Vec3{x[i], y[i], z[i]});
    out_x[i] = v.x;
    out_y[i] = v.y;
    out_z[i] = v.z;
  }
}

/// out_i = w_i a_i, as restrict parameters (see turn_points).
__attribute__((always_inline)) inline void weigh(size_t n, const real* __restrict w, const real* __restrict a, real* __restrict out) {
  for (size_t i = 0; i < n; ++i) out[i] = w[i] * a[i];
}

/// One evaluation's loop over the matches: the camera-frame point (X, Y, Z) = z + t, its 1 / Z,
/// and delta = (a X + b Y + c Z) / Z, times the weight when there are weights (`weight`
/// not null); false (the arrays then partly written) when a point is not in front of the camera.
/// The arrays are restrict parameters (none overlaps another) and, in floating point, the depth
/// test is a pass of its own, so that the host compiler takes two matches per vector
/// instruction, each lane the operations of one match. Inlined where vector_kernels::run builds
/// it for the chosen vectors (as turn_points and weigh).
__attribute__((always_inline)) inline bool distances_to_lines(size_t n, const Vec3& t, const real* __restrict zx, const real* __restrict zy,
                        const real* __restrict zz, const real* __restrict a, const real* __restrict b,
                        const real* __restrict c, const real* __restrict weight, real* __restrict inv_z,
                        real* __restrict delta, real* __restrict fx) {
  constexpr bool kFloating = std::is_floating_point<real>::value;
  if constexpr (kFloating)
    for (size_t i = 0; i < n; ++i)
      if (zz[i] + t.z <= real(0)) return false;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 p{zx[i] + t.x, zy[i] + t.y, zz[i] + t.z};
    if (!kFloating && p.z <= real(0)) return false;
    // One divisor for both quotients: the depth's reciprocal is the Jacobian's.
    const Divisor<real> by_z(p.z);
    inv_z[i] = by_z.divide(real(1));
    const real d = by_z.divide(sum_of_products(a[i], p.x, b[i], p.y, c[i], p.z));
    delta[i] = d;
    fx[i] = weight ? weight[i] * d : d;
  }
  return true;
}

/// distances_to_lines through a lens: delta = a x_d + b y_d + c with (x_d, y_d) the distorted
/// (x, y) = (X / Z, Y / Z), whose undistorted (x, y) are kept for gradf (lens_gradients).
/// ViSP's radial model, (x_d, y_d) = f (x, y) with f = 1 + kud r^2: delta = f s + c with
/// s = (a X + b Y) / Z, divided as the pinhole's distance is (two quotients by Z, as there);
/// (x, y) = (X, Y) / Z enter only f and the Jacobian, as X and Y times 1 / Z (in S40.23 1 / Z of
/// millimetres keeps 16 significant bits, which moves f s by under 1e-3 px). f and s are kept:
/// the Jacobian follows from them without the lens again (radial_lens_gradients). Not inlined:
/// the pinhole's loop in f keeps its own registers.
__attribute__((noinline)) bool distances_through_lens(size_t n, const PinholeCamera& camera, const Vec3& t, const real* zx, const real* zy,
                            const real* zz, const real* a, const real* b, const real* c, const real* weight,
                            real* inv_z, real* delta, real* fx, real* normalised_x, real* normalised_y,
                            real* radial_factor, real* radial_sum) {
  const bool radial = camera.lens.model == LensModel::kVisp;
  const real kud = camera.lens.kud;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 p{zx[i] + t.x, zy[i] + t.y, zz[i] + t.z};
    if (!(p.z > real(0))) return false;
    const Divisor<real> by_z(p.z);
    const real w = by_z.divide(real(1));
    inv_z[i] = w;
    real distance;
    if (radial) {
      const Vec2 normalised{p.x * w, p.y * w};
      normalised_x[i] = normalised.x;
      normalised_y[i] = normalised.y;
      const real factor = real(1) + kud * sum_of_products(normalised.x, normalised.x, normalised.y, normalised.y);
      const real sum = by_z.divide(sum_of_products(a[i], p.x, b[i], p.y));
      radial_factor[i] = factor;
      radial_sum[i] = sum;
      distance = factor * sum + c[i];
    } else {
      // X / Z and Y / Z to the scalar's resolution: the whole distance goes through the lens.
      const Vec2 normalised{by_z.divide(p.x), by_z.divide(p.y)};
      normalised_x[i] = normalised.x;
      normalised_y[i] = normalised.y;
      const Vec2 d = camera.distort(normalised);
      distance = sum_of_products(a[i], d.x, b[i], d.y, c[i], real(1));
    }
    delta[i] = distance;
    fx[i] = weight ? weight[i] * distance : distance;
  }
  return true;
}

/// The Jacobian's (a, b) J_lens (times the weight) at the undistorted points of the last
/// evaluation: only where MINPACK asks for the Jacobian, fewer times than it evaluates.
void lens_gradients(size_t n, const PinholeCamera& camera, const real* normalised_x, const real* normalised_y,
                    const real* a, const real* b, const real* weight, real* grad_a, real* grad_b) {
  for (size_t i = 0; i < n; ++i) {
    LensJacobian j;
    camera.distort(Vec2{normalised_x[i], normalised_y[i]}, j);
    const real w = weight ? weight[i] : real(1);
    grad_a[i] = w * sum_of_products(a[i], j.xx, b[i], j.yx);
    grad_b[i] = w * sum_of_products(a[i], j.xy, b[i], j.yy);
  }
}

/// lens_gradients for ViSP's radial model from the last evaluation's f = 1 + kud r^2 and
/// s = a x + b y: (a, b) J_lens = f (a, b) + 2 kud s (x, y). `weighted_a` and `weighted_b` are a
/// and b times the weight.
void radial_lens_gradients(size_t n, const real& kud, const real* normalised_x, const real* normalised_y,
                           const real* factor, const real* sum, const real* weighted_a, const real* weighted_b,
                           const real* weight, real* grad_a, real* grad_b) {
  const real twice_k = real(2) * kud;
  for (size_t i = 0; i < n; ++i) {
    const real bend = weight ? weight[i] * (twice_k * sum[i]) : twice_k * sum[i];
    grad_a[i] = sum_of_products(weighted_a[i], factor[i], bend, normalised_x[i]);
    grad_b[i] = sum_of_products(weighted_b[i], factor[i], bend, normalised_y[i]);
  }
}

/// The Jacobian's six columns (MINPACK's layout, column c at out_c) at the last evaluation: per
/// match, from (a, b) times the weight (`ka`, `kb`; through a lens (a, b) J_lens), the turned
/// point (`zx`, `zy`, `zz`), the moved point's X and Y (z + t, as the evaluation added them) and
/// 1 / Z; kLeft false when J(w) is the identity. Restrict parameters and no branch in the loop, inlined where
/// vector_kernels::run builds it, each lane one match's columns (as distances_to_lines).
template <bool kLeft>
__attribute__((always_inline)) inline void jacobian_columns(
    size_t n, const real* __restrict ka, const real* __restrict kb, const Vec3& t, const real* __restrict zx,
    const real* __restrict zy, const real* __restrict zz,
    const real* __restrict inverse_depth, const Mat33 jl, real* __restrict out_0, real* __restrict out_1,
    real* __restrict out_2, real* __restrict out_3, real* __restrict out_4, real* __restrict out_5) {
  for (size_t i = 0; i < n; ++i) {
    const real inv_z = inverse_depth[i];
    // d delta / d p = (a, b, -(a X + b Y) / Z) / Z, with the weight inside a and b (through a
    // lens the chain rule's (a, b) J_lens, d(x, y) / d p being the same).
    const real gx = ka[i] * inv_z;
    const real gy = kb[i] * inv_z;
    const real gz = -sum_of_products(gx, zx[i] + t.x, gy, zy[i] + t.y) * inv_z;
    out_0[i] = gx;
    out_1[i] = gy;
    out_2[i] = gz;
    // d delta / d w = g^T (-hat(z)) J(w) = (z x g)^T J(w).
    const Vec3 zg{difference_of_products(zy[i], gz, zz[i], gy), difference_of_products(zz[i], gx, zx[i], gz),
                  difference_of_products(zx[i], gy, zy[i], gx)};
    if constexpr (kLeft) {
      out_3[i] = sum_of_products(zg.x, jl.m[0][0], zg.y, jl.m[1][0], zg.z, jl.m[2][0]);
      out_4[i] = sum_of_products(zg.x, jl.m[0][1], zg.y, jl.m[1][1], zg.z, jl.m[2][1]);
      out_5[i] = sum_of_products(zg.x, jl.m[0][2], zg.y, jl.m[1][2], zg.z, jl.m[2][2]);
    } else {
      out_3[i] = zg.x;
      out_4[i] = zg.y;
      out_5[i] = zg.z;
    }
  }
}

/// The residuals and their Jacobian for MINPACK's lmder, over one solve's matches and weights,
/// in the workspace's memory.
class PointToLineProblem {
 public:
  /// `weights` (one per match, or empty for all 1) multiply each residual: they are the square
  /// roots of the least-squares weights.
  /// The workspace's model_mm and unweighted hold `matches`' terms (prepare_matches).
  PointToLineProblem(const std::vector<EdgeMatch>& matches, const std::vector<real>& weights, const Se3& start,
                     const PinholeCamera& camera, PoseWorkspace& w)
      : camera_(camera),
        start_(start),
        start_translation_mm_(to_millimetres(start.translation())),
        count_(matches.size()),
        weighted_(!weights.empty()),
        weights_(weights.data()),
        w_(w) {
    for (int k = 0; k < 3; ++k) {
      w.rotated[k].resize(count_);
      w.turned[k].resize(count_);
    }
    for (int k = 0; k < 2; ++k) w.gradient[k].resize(count_);
    w.inverse_depth.resize(count_);
    if (camera.distorted())
      for (int k = 0; k < 2; ++k) {
        w.lens_point[k].resize(count_);
        w.lens_gradient[k].resize(count_);
        w.lens_radial[k].resize(count_);
      }
    w.evaluated.resize(count_);
    // The points in millimetres and the distances' coefficients are the solve_pose call's
    // (prepare_matches): only the rotation and the weights differ between its solves.
    const Mat33& r = start.rotation();
    vector_kernels::run([&]() __attribute__((always_inline)) {
      turn_points(count_, [&r](const Vec3& y) { return rotate(r, y); }, w.model_mm[0].data(), w.model_mm[1].data(),
                  w.model_mm[2].data(), w.rotated[0].data(), w.rotated[1].data(), w.rotated[2].data());
    });
    for (int k = 0; k < 2; ++k) {
      if (weighted_)
        vector_kernels::run([&]() __attribute__((always_inline)) {
          weigh(count_, weights.data(), w.unweighted[k].data(), w.gradient[k].data());
        });
      else std::copy(w.unweighted[k].begin(), w.unweighted[k].begin() + static_cast<std::ptrdiff_t>(count_),
                     w.gradient[k].begin());
    }
  }

  /// Fills the workspace's per-match terms that stay the same over one solve_pose call's solves:
  /// each point in millimetres and, for the hypothesis each match uses, the coefficients of
  /// delta = n . (project(p) - q) = (a X + b Y + c Z) / Z. `all` false refreshes only the
  /// coefficients of matches with alternatives (their choice may have changed).
  static void prepare_matches(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera, bool all,
                              PoseWorkspace& w) {
    const size_t count = matches.size();
    if (all)
      for (int k = 0; k < 3; ++k) {
        w.model_mm[k].resize(count);
        w.unweighted[k].resize(count);
      }
    for (size_t i = 0; i < count; ++i) {
      const EdgeMatch& m = matches[i];
      if (!all && m.alternatives_held() == 0) continue;
      if (all) set(w.model_mm, i, to_millimetres(m.point.point_in_model));
      const Vec2& n = m.point.normal;
      set(w.unweighted, i,
          Vec3{n.x * camera.px, n.y * camera.py, n.x * (camera.u0 - m.used().x) + n.y * (camera.v0 - m.used().y)});
    }
  }

  /// lmder's callback: iflag 1 evaluates the residuals, 2 the Jacobian; -1 stops the solve.
  static int evaluate(void* self, int, int, const real* x, real* fx, real* fjac, int ldfjac, int iflag) {
    auto* problem = static_cast<PointToLineProblem*>(self);
    if (iflag == 1) {
      ++problem->evaluations_;
      if (!problem->f(x, fx)) return -1;
      if (problem->evaluations_ == 1 && problem->measure_start_) problem->start_rms_ = rms(fx, problem->count_);
      if (problem->evaluations_ == 1 && problem->keep_) problem->keep_->residuals.assign(fx, fx + problem->count_);
    } else if (iflag == 2) {
      if (!problem->gradf(x, fjac, static_cast<size_t>(ldfjac))) return -1;
      if (problem->keep_ && !problem->keep_->kept && is_start(x)) problem->keep_start_jacobian(fjac, ldfjac);
    }
    return iflag;
  }

  /// Keeps the solve's weighted residuals and Jacobian at its start in `rows` (StartRows).
  void keep_start_rows(StartRows* rows) { keep_ = rows; }

  /// The unweighted signed distances delta_i at x, for the next round's choice and weights.
  bool signed_distances(const real* x, std::vector<real>& out) {
    if (!evaluated_at(x) && !f(x, scratch())) return false;
    std::copy(w_.evaluated.begin(), w_.evaluated.begin() + static_cast<std::ptrdiff_t>(count_), out.begin());
    return true;
  }

  Se3 pose(const real* x) const {
    const real mm(kMillimetresPerMetre);
    return start_.retract(Vec3{x[0] / mm, x[1] / mm, x[2] / mm}, Vec3{x[3], x[4], x[5]});
  }

  int evaluations() const { return evaluations_; }
  /// The RMS at the start is measured only when asked (measure_start): the solution reports
  /// its first solve's alone.
  void measure_start() { measure_start_ = true; }
  real start_rms() const { return start_rms_; }

  /// What vnl_vector::rms computes: sqrt(sum of squares / n) (in fixed point the sum rounded once).
  static real rms(const real* v, size_t n) {
    using std::sqrt;
    if (n == 0) return real(0);
    const int count = static_cast<int>(n);
    return sqrt(sum_of_products(count, v, v) / real(count));
  }

 private:
  static void set(std::vector<real>* arrays, size_t i, const Vec3& v) {
    arrays[0][i] = v.x;
    arrays[1][i] = v.y;
    arrays[2][i] = v.z;
  }
  static bool is_identity(const Mat33& m) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (!(m.m[r][c] == real(r == c ? 1 : 0))) return false;
    return true;
  }
  /// Where an evaluation the solver did not ask for writes its residuals: the Jacobian's
  /// memory, which only gradf fills (after that evaluation) and which LM leaves free after it.
  real* scratch() { return w_.jacobian.data(); }

  bool f(const real* x, real* fx) {
    const Vec3 v{x[0], x[1], x[2]}, w{x[3], x[4], x[5]};
    const Mat33 r = rotation_exp(w);
    // At x = 0 (each solve's first evaluation) r is exactly the identity: r * y would be y.
    const bool turn = !is_identity(r);
    const Vec3 t = start_translation_mm_ + v;
    const std::vector<real>* q = w_.rotated;
    const std::vector<real>* u = w_.unweighted;
    real* const inv_z = w_.inverse_depth.data();
    real* const delta = w_.evaluated.data();
    evaluated_ = false;
    // The turned points first, in their own loop: fewer values live at once in the next.
    turned_ = turn ? w_.turned : w_.rotated;
    if (turn) {
      std::vector<real>* z = w_.turned;
      vector_kernels::run([&]() __attribute__((always_inline)) {
        turn_points(count_, [&r](const Vec3& y) { return r * y; }, q[0].data(), q[1].data(), q[2].data(), z[0].data(),
                    z[1].data(), z[2].data());
      });
    }
    const std::vector<real>* z = turned_;
    if (camera_.distorted()) {
      if (!distances_through_lens(count_, camera_, t, z[0].data(), z[1].data(), z[2].data(), u[0].data(), u[1].data(),
                                  u[2].data(), weighted_ ? weights_ : nullptr, inv_z, delta, fx,
                                  w_.lens_point[0].data(), w_.lens_point[1].data(),
                                  w_.lens_radial[0].data(), w_.lens_radial[1].data()))
        return false;
    } else if (!vector_kernels::run([&]() __attribute__((always_inline)) {
                 return distances_to_lines(count_, t, z[0].data(), z[1].data(), z[2].data(), u[0].data(), u[1].data(),
                                           u[2].data(), weighted_ ? weights_ : nullptr, inv_z, delta, fx);
               })) {
      return false;
    }
    for (unsigned c = 0; c < 6; ++c) evaluated_at_[c] = x[c];
    evaluated_ = true;
    return true;
  }

  /// Column c of the Jacobian at fjac + c * ld (MINPACK's column-major layout).
  bool gradf(const real* x, real* fjac, size_t ld) {
    // MINPACK asks for the Jacobian where it evaluated last (the start, then each accepted
    // step), so the rotation and the moved points come from that evaluation.
    if (!evaluated_at(x) && !f(x, scratch())) return false;
    const Mat33 jl = so3_left_jacobian(Vec3{x[3], x[4], x[5]});
    const bool left = !is_identity(jl);  // at x = 0, (z x g)^T J is z x g exactly
    // Through a lens, (a, b) J_lens at the last evaluation in place of (a, b).
    if (camera_.lens.model == LensModel::kVisp && camera_.distorted())
      radial_lens_gradients(count_, camera_.lens.kud, w_.lens_point[0].data(), w_.lens_point[1].data(),
                            w_.lens_radial[0].data(), w_.lens_radial[1].data(), w_.gradient[0].data(),
                            w_.gradient[1].data(), weighted_ ? weights_ : nullptr, w_.lens_gradient[0].data(),
                            w_.lens_gradient[1].data());
    else if (camera_.distorted())
      lens_gradients(count_, camera_, w_.lens_point[0].data(), w_.lens_point[1].data(), w_.unweighted[0].data(),
                     w_.unweighted[1].data(), weighted_ ? weights_ : nullptr, w_.lens_gradient[0].data(),
                     w_.lens_gradient[1].data());
    const std::vector<real>* k = camera_.distorted() ? w_.lens_gradient : w_.gradient;
    const std::vector<real>* z = turned_;
    const Vec3 t = start_translation_mm_ + Vec3{x[0], x[1], x[2]};  // the evaluation's own sum
    const real* const inverse_depth = w_.inverse_depth.data();
    real* const column[6] = {fjac, fjac + ld, fjac + 2 * ld, fjac + 3 * ld, fjac + 4 * ld, fjac + 5 * ld};
    vector_kernels::run([&]() __attribute__((always_inline)) {
      if (left)
        jacobian_columns<true>(count_, k[0].data(), k[1].data(), t, z[0].data(), z[1].data(), z[2].data(),
                               inverse_depth, jl, column[0], column[1], column[2], column[3], column[4],
                               column[5]);
      else
        jacobian_columns<false>(count_, k[0].data(), k[1].data(), t, z[0].data(), z[1].data(), z[2].data(),
                                inverse_depth, jl, column[0], column[1], column[2], column[3], column[4],
                                column[5]);
    });
    return true;
  }

  static bool is_start(const real* x) {
    for (unsigned c = 0; c < 6; ++c)
      if (!(x[c] == real(0))) return false;
    return true;
  }

  void keep_start_jacobian(const real* fjac, int ld) {
    keep_->jacobian.resize(count_ * 6);
    for (size_t c = 0; c < 6; ++c)
      std::copy(fjac + c * static_cast<size_t>(ld), fjac + c * static_cast<size_t>(ld) + count_,
                keep_->jacobian.begin() + static_cast<std::ptrdiff_t>(c * count_));
    keep_->kept = keep_->residuals.size() == count_;
  }

  bool evaluated_at(const real* x) const {
    if (!evaluated_) return false;
    for (unsigned c = 0; c < 6; ++c)
      if (!(x[c] == evaluated_at_[c])) return false;
    return true;
  }

  const PinholeCamera& camera_;
  Se3 start_;
  Vec3 start_translation_mm_;
  size_t count_;
  bool weighted_;
  const real* weights_;
  PoseWorkspace& w_;
  const std::vector<real>* turned_ = nullptr;  ///< R(w) y at the last evaluation: w_.turned, or w_.rotated at w = 0
  real evaluated_at_[6] = {};
  bool evaluated_ = false;
  int evaluations_ = 0;
  real start_rms_{0};
  bool measure_start_ = false;
  StartRows* keep_ = nullptr;
};

/// MINPACK's endings that still leave the best estimate LM found: the evaluation limit, and
/// tolerances reached at the scalar's resolution (info 6, 7, 8: no further reduction, step or
/// gradient test is possible at this precision). A fixed-point solve whose tolerances lie near
/// its resolution ends this way at its optimum: in millimetres S47.16 often does (frames were
/// lost in the app tests when these counted as failures). Other codes are failures.
bool keeps_best_estimate(int code) {
  return code == vnl_levenberg_marquardt_of<real>::FAILED_TOO_MANY_ITERATIONS ||
         code == vnl_levenberg_marquardt_of<real>::FAILED_FTOL_TOO_SMALL ||
         code == vnl_levenberg_marquardt_of<real>::FAILED_XTOL_TOO_SMALL ||
         code == vnl_levenberg_marquardt_of<real>::FAILED_GTOL_TOO_SMALL;
}

/// What one solve gives back.
struct SolveResult {
  bool solved = false;  ///< LM ended with an estimate (and the distances at it were measured)
  Se3 pose;             ///< when solved
  int evaluations = 0;
  int iterations = 0;  ///< Jacobian evaluations
  real start_rms{0};  ///< when the solve was the first
};

/// One Levenberg-Marquardt solve (MINPACK's lmder with the arguments vnl_levenberg_marquardt
/// passes it, called directly so that its buffers are the workspace's, or with
/// PoseSolver::kNormalEquations normal_equations_lm) over `matches` weighted by
/// workspace.weights (empty: all 1) from `start`, stopped after `max_evaluations` residual
/// evaluations. When solved, workspace.distances become the unweighted signed point-to-line
/// distances at the new pose; otherwise they are left as they were. The workspace holds the
/// matches' terms (PointToLineProblem::prepare_matches). workspace.residuals are left at LM's
/// last estimate, for the solution's end RMS.
SolveResult solve_once(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& start,
                       const PoseParams& params, int max_evaluations, bool first, PoseWorkspace& workspace) {
  constexpr int n = 6;
  const int m = static_cast<int>(matches.size());
  PointToLineProblem problem(matches, workspace.weights, start, camera, workspace);
  if (first) problem.measure_start();
  if (first && workspace.start_rows) problem.keep_start_rows(workspace.start_rows);
  workspace.residuals.resize(matches.size());
  workspace.jacobian.resize(matches.size() * n);
  workspace.work.resize(matches.size());
  real x[n] = {}, diag[n] = {}, qtf[n] = {}, wa1[n] = {}, wa2[n] = {}, wa3[n] = {};
  int ipvt[n] = {};
  int nfev = 0, njev = 0;
  const int info =
      params.solver == PoseSolver::kNormalEquations
          ? normal_equations_lm(&PointToLineProblem::evaluate, &problem, m, n, x, workspace.residuals.data(),
                                workspace.jacobian.data(), m, params.f_tolerance, params.x_tolerance,
                                params.g_tolerance, max_evaluations, workspace.work.data(), &nfev, &njev)
          : netlib::lmder<real>(&PointToLineProblem::evaluate, &problem, m, n, x, workspace.residuals.data(),
                                workspace.jacobian.data(), m, params.f_tolerance, params.x_tolerance,
                                params.g_tolerance, max_evaluations, diag, 1, real(100), 0, &nfev, &njev, ipvt, qtf,
                                wa1, wa2, wa3, workspace.work.data());
  SolveResult result;
  result.evaluations = problem.evaluations();
  result.iterations = njev;
  result.start_rms = problem.start_rms();
  const bool ok = info >= vnl_levenberg_marquardt::CONVERGED_FTOL && info <= vnl_levenberg_marquardt::CONVERGED_GTOL;
  if (!(ok || keeps_best_estimate(info))) return result;
  result.pose = problem.pose(x);
  result.solved = problem.signed_distances(x, workspace.distances);
  return result;
}

/// Adds one solve's counts to `solution`; the first solve's start RMS is the solution's.
void add_counts(const SolveResult& solve, PoseSolution& solution) {
  if (solution.evaluations == 0) solution.start_rms = solve.start_rms;
  solution.evaluations += solve.evaluations;
  solution.iterations += solve.iterations;
}

/// The solution's end RMS: the last solve's, whose residuals are still in `workspace`.
void measure_end_rms(const PoseWorkspace& workspace, PoseSolution& solution) {
  solution.end_rms = PointToLineProblem::rms(workspace.residuals.data(), workspace.residuals.size());
}

/// Room for median_of's work between solves: the Jacobian's memory, which LM only uses within
/// a solve (matches of its 6 x matches).
struct OrderWork {
  real* values;
};
OrderWork order_work(PoseWorkspace& workspace, size_t matches) {
  workspace.jacobian.resize(matches * 6);
  return {workspace.jacobian.data()};
}

/// The median of |values| (the distances may be signed) over the matches not excluded
/// (`masked`: some are), in `work` (room for as many).
real median_of(const std::vector<EdgeMatch>& matches, const std::vector<real>& signed_values, bool masked,
               const OrderWork& work) {
  using std::fabs;
  real* const values = work.values;
  size_t n = 0;
  if (masked) {
    for (size_t i = 0; i < signed_values.size(); ++i)
      if (!matches[i].excluded) values[n++] = fabs(signed_values[i]);
  } else {
    n = signed_values.size();
    for (size_t i = 0; i < n; ++i) values[i] = fabs(signed_values[i]);
  }
  if (n == 0) return real(0);
  return median_of_values(values, n);
}

/// Each match uses its hypothesis nearest to the pose where `distances` (signed, to each
/// match's used() point) were measured; `distances` become the signed distances to the chosen
/// ones. The lines through the hypotheses are parallel (one normal), so
/// delta_h = delta + n . (used - h): no projection per hypothesis. Returns whether a match
/// changed its choice (if none did, `distances` are as they were).
bool choose_nearest_hypotheses(std::vector<EdgeMatch>& matches, std::vector<real>& distances) {
  using std::fabs;
  bool changed = false;
  for (size_t i = 0; i < matches.size(); ++i) {
    EdgeMatch& m = matches[i];
    const int held = m.alternatives_held();
    if (held == 0) continue;
    const Vec2 used = m.used();
    const real delta = distances[i];
    real nearest = delta;
    for (int h = 0; h <= held; ++h) {
      const real d = delta + dot(m.point.normal, used - (h == 0 ? m.found : m.alternatives[h - 1]));
      if (fabs(d) < fabs(nearest)) {
        nearest = d;
        changed = changed || m.chosen != h;
        m.chosen = h;
      }
    }
    distances[i] = nearest;
  }
  return changed;
}

/// The signed distances to each match's strongest edge (`found`), from those to its used() one.
void to_strongest(const std::vector<EdgeMatch>& matches, std::vector<real>& distances) {
  for (size_t i = 0; i < matches.size(); ++i)
    if (matches[i].chosen != 0) distances[i] = distances[i] + dot(matches[i].point.normal, matches[i].used() - matches[i].found);
}

/// weight_i = 1 - u^2 with u = |d_i| / c (`inv_c` = 1 / c), 0 where u >= 1, as restrict parameters
/// (see turn_points). In floating point 1 - u^2 is below 0 or +0 exactly where u >= 1 (below 1 it
/// is at least the scalar's resolution), so the weight is chosen by its own sign: no operation
/// sits on one path of a condition, which would keep the compiler from taking several matches
/// per instruction.
__attribute__((always_inline)) inline void weigh_by_tukey(size_t n, const real* __restrict distances, const real& inv_c,
                                                          real* __restrict weights) {
  using std::fabs;
  const real scale = inv_c;
  for (size_t i = 0; i < n; ++i) {
    const real u = fabs(distances[i]) * scale;
    const real weight = real(1) - u * u;
    weights[i] = weight < real(0) ? real(0) : weight;
  }
}

/// The square roots of Tukey's weights, 1 - (d / c)^2, of the signed distances, with
/// c = max(tukey_c * 1.4826 * median |d|, tukey_floor); marks and counts the outliers (weight 0).
/// An excluded match (`masked`: some are) weighs 0 and is no outlier.
int tukey_weights(std::vector<EdgeMatch>& matches, const std::vector<real>& distances, bool masked,
                  const PoseParams& params, const OrderWork& work, std::vector<real>& weights) {
  using std::fabs;
  real c = params.tukey_c * real(kMadToSigma) * median_of(matches, distances, masked, work);
  if (c < params.tukey_floor) c = params.tukey_floor;
  const real inv_c = real(1) / c;  // one division: an ARMv5TE has no divider
  int outliers = 0;
  if constexpr (std::is_floating_point<real>::value) {
    // The weights lane by lane, then the outliers from them: a weight is 0 exactly where u >= 1.
    vector_kernels::run([&]() __attribute__((always_inline)) {
      weigh_by_tukey(matches.size(), distances.data(), inv_c, weights.data());
    });
    for (size_t i = 0; i < matches.size(); ++i) {
      const bool outlier = weights[i] == real(0);
      matches[i].outlier = outlier;
      outliers += outlier;
    }
  } else {
    for (size_t i = 0; i < matches.size(); ++i) {
      const real u = fabs(distances[i]) * inv_c;
      const bool outlier = u >= real(1);
      matches[i].outlier = outlier;
      weights[i] = outlier ? real(0) : real(1) - u * u;
      outliers += outlier;
    }
  }
  if (masked)
    for (size_t i = 0; i < matches.size(); ++i)
      if (matches[i].excluded) {
        outliers -= matches[i].outlier;
        matches[i].outlier = false;
        weights[i] = real(0);
      }
  return outliers;
}

/// The largest |after - before| over the matches: how far a round moved a match along its normal
/// (the distances before are to the hypotheses the round chose, as those after are).
real largest_move(const std::vector<real>& before, const std::vector<real>& after) {
  using std::fabs;
  real largest(0);
  for (size_t i = 0; i < after.size(); ++i) {
    const real move = fabs(after[i] - before[i]);
    if (move > largest) largest = move;
  }
  return largest;
}

}  // namespace

PoseSolution solve_pose(std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& start,
                        const PoseParams& params) {
  PoseWorkspace workspace;
  return solve_pose(matches, camera, start, params, workspace);
}

PoseSolution solve_pose(std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& start,
                        const PoseParams& params, PoseWorkspace& workspace) {
  using std::fabs;
  PoseSolution solution;
  solution.camera_from_model = start;
  if (workspace.start_rows) {
    workspace.start_rows->kept = false;
    workspace.start_rows->residuals.clear();
  }
  const size_t needed = static_cast<size_t>(params.min_points > 6 ? params.min_points : 6);
  size_t excluded = 0;
  for (const EdgeMatch& m : matches) excluded += m.excluded;
  const size_t taken = matches.size() - excluded;
  const bool masked = excluded > 0;  // the drift check excluded some: the median and weights skip them
  // Without alternatives (one hypothesis per match) no choice can change between rounds.
  const bool alternatives = std::any_of(matches.begin(), matches.end(),
                                        [](const EdgeMatch& m) { return m.alternatives_held() > 0; });
  if (taken < needed) return solution;
  for (EdgeMatch& m : matches) m.chosen = 0;  // the first solve uses the strongest edges
  PointToLineProblem::prepare_matches(matches, camera, true, workspace);
  const OrderWork order = order_work(workspace, matches.size());
  const bool robust = params.tukey_c > real(0) && params.robust_rounds > 0;
  std::vector<real>& distances = workspace.distances;
  std::vector<real>& weights = workspace.weights;
  distances.resize(matches.size());
  weights.clear();  // no weights: the first solve is unweighted
  if (robust && params.weigh_at_start) {
    // The control points were sampled at `start`: their pixels are its projections.
    for (size_t i = 0; i < matches.size(); ++i)
      distances[i] = dot(matches[i].point.normal, matches[i].point.pixel - matches[i].found);
    weights.resize(matches.size());
    tukey_weights(matches, distances, masked, params, order, weights);
    for (EdgeMatch& m : matches) m.outlier = false;  // outliers are the last round's
  } else if (masked) {
    weights.resize(matches.size());
    for (size_t i = 0; i < matches.size(); ++i) weights[i] = matches[i].excluded ? real(0) : real(1);
  }
  const SolveResult first = solve_once(matches, camera, start, params, params.max_evaluations, true, workspace);
  add_counts(first, solution);
  if (!first.solved || !robust) measure_end_rms(workspace, solution);
  if (!first.solved) return solution;
  solution.camera_from_model = first.pose;
  solution.solved = true;
  if (!robust) {
    solution.residual_scale = real(kMadToSigma) * median_of(matches, distances, masked, order);
    return solution;
  }

  weights.resize(matches.size());
  bool moved = true;  // whether the last round changed the pose
  for (int round = 0; round < params.robust_rounds; ++round) {
    const bool rechosen = alternatives && choose_nearest_hypotheses(matches, distances);
    // After a round that left the pose as it was, the same choices and distances would give
    // this round the same weights, start and solve, ending where that one did: so would every
    // round after it.
    if (!moved && !rechosen && distances == workspace.before_round) break;
    if (alternatives) PointToLineProblem::prepare_matches(matches, camera, false, workspace);
    solution.outliers = tukey_weights(matches, distances, masked, params, order, weights);
    if (taken - static_cast<size_t>(solution.outliers) < needed) break;
    workspace.before_round = distances;
    const SolveResult robust_solve =
        solve_once(matches, camera, solution.camera_from_model, params, params.robust_evaluations, false, workspace);
    add_counts(robust_solve, solution);
    if (!robust_solve.solved) break;
    moved = !same_bits(robust_solve.pose, solution.camera_from_model);
    solution.camera_from_model = robust_solve.pose;
    const bool watch = params.rounds_settled_px > real(0);
    if (watch && largest_move(workspace.before_round, distances) <= params.rounds_settled_px) break;
  }
  measure_end_rms(workspace, solution);
  // distances are those at solution.camera_from_model: solve_once leaves them alone when it fails.
  // The scale reads the strongest edges: on an image unrelated to the model the nearest of
  // several hypotheses is nearer than chance puts one edge, which would hide a lost frame.
  if (alternatives) to_strongest(matches, distances);
  solution.residual_scale = real(kMadToSigma) * median_of(matches, distances, masked, order);
  return solution;
}

void PoseWorkspace::reserve(size_t matches, bool lens) {
  for (std::vector<real>* arrays : {model_mm, rotated, unweighted, turned})
    for (int i = 0; i < 3; ++i) arrays[i].reserve(matches);
  for (int i = 0; i < 2; ++i) gradient[i].reserve(matches);
  if (lens)
    for (std::vector<real>* arrays : {lens_point, lens_gradient, lens_radial})
      for (int i = 0; i < 2; ++i) arrays[i].reserve(matches);
  for (std::vector<real>* array : {&evaluated, &inverse_depth, &residuals, &work, &distances, &weights, &before_round})
    array->reserve(matches);
  jacobian.reserve(matches * 6);  // m x 6 (solve_once)
}

size_t PoseWorkspace::heap_bytes() const {
  size_t bytes = 0;
  for (const std::vector<real>* arrays : {model_mm, rotated, unweighted, turned})
    for (int i = 0; i < 3; ++i) bytes += capacity_bytes(arrays[i]);
  for (const std::vector<real>* arrays : {gradient, lens_point, lens_gradient, lens_radial})
    for (int i = 0; i < 2; ++i) bytes += capacity_bytes(arrays[i]);
  for (const std::vector<real>* array :
       {&evaluated, &inverse_depth, &residuals, &jacobian, &work, &distances, &weights, &before_round})
    bytes += capacity_bytes(*array);
  return bytes;
}

}  // namespace edgetrack
