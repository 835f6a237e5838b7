// SPDX-License-Identifier: BSD-3-Clause
/// Pose calculation (paper, equations (2)-(3)): Levenberg-Marquardt (MINPACK's lmder, the solver
/// under our vnl_levenberg_marquardt, with the same arguments) over six parameters, minimising
/// the distances between the projected control points and the lines through their matches
/// along the projected edge normals, with an analytic Jacobian.
#pragma once

#include <vector>

#include "edgetrack/edge_match.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The least-squares solver of each pose solve. Both minimise the same residuals with the same
/// tolerances, evaluation budgets and robust rounds.
enum class PoseSolver {
  kLmder,            ///< MINPACK's lmder (QR of the Jacobian, trust region): the faithful default
  kNormalEquations,  ///< LM on the 6 x 6 normal equations (normal_equations_lm.h): fewer instructions
};

/// The median absolute deviation of normal residuals times this is their standard deviation.
constexpr double kMadToSigma = 1.4826;

struct PoseParams {
  PoseSolver solver = PoseSolver::kLmder;
  int max_evaluations = 30;  ///< residual evaluations in the first (unweighted) solve, at most
  /// Residual evaluations per robust solve, at most. 2 is one LM step from the previous
  /// round's pose (MINPACK counts the start as the first evaluation): iteratively re-weighted
  /// least squares with one step per re-weighting, as ViSP's edge tracker does; running each
  /// round to convergence only adds a Jacobian and a QR factorisation that confirm the pose.
  int robust_evaluations = 2;
  /// LM's relative tolerance on the step. VXL's default (1e-8) lies below S40.23's resolution
  /// (1.2e-7), where LM would run to max_evaluations; a pose step of 1e-6 relative is far below
  /// a pixel and reachable by every `real`.
  real x_tolerance = real(1e-6);
  /// LM's relative tolerance on the sum of squares: a solve ends once a step reduced it, and
  /// predicts it can reduce it, by at most 1 %, i.e. the RMS point-to-line distance is within
  /// 0.5 % of what LM can still reach, well under a thousandth of a pixel at matched edges' RMS.
  real f_tolerance = real(1e-2);
  /// LM's gradient test: the largest cosine between the residual vector and a Jacobian column
  /// (0 at the optimum). S40.23's rounding keeps the cosine above VXL's 1e-5, where LM would
  /// spend its evaluations on rejected steps; 3e-3 moves the double poses by less than the
  /// tests resolve (0.01 mm) on the generated sequences (docs/results/lm.md, tracker.md).
  real g_tolerance = real(3e-3);
  int min_points = 6;        ///< fewer matches than this: the pose is kept as it was
  /// Not in the paper (its section 5 leaves robust estimation to future work): after the first
  /// solve, robust_rounds more solves (one LM step each, see robust_evaluations) each weight
  /// every distance with Tukey's biweight at the previous solve's pose,
  /// w = (1 - (delta / c)^2)^2 for |delta| < c and 0 beyond, c = max(tukey_c * 1.4826 *
  /// median |delta|, tukey_floor) pixels; matches with weight 0 in the last round are marked as
  /// outliers. The weights vary continuously with the distances, so nearby inputs give nearby
  /// poses; three rounds keep a gross mismatch present in one `real` build and not in another
  /// from pulling their poses apart (docs/ARCHITECTURE.md). A round that left the pose as it was
  /// ends the rounds when the next would weigh the same distances with the same hypotheses: it
  /// would repeat that round exactly, as would every round after it. tukey_c = 0 or
  /// robust_rounds = 0 is the paper's tracker.
  int robust_rounds = 3;
  /// The robust rounds end early once one moved no match farther than this along its normal
  /// (pixels): the weights at the next round's start would be those of this one's, and so its
  /// step as small. 0 runs every round (the tracker's default: its frames need few rounds).
  real rounds_settled_px{0};
  /// With robust rounds, the first solve too is weighted by Tukey's biweight (as below) of the
  /// distances at `start`, which the matches' control points were sampled at: where the start is
  /// a good prediction, a whole edge matched to a line a few pixels beside it stands out there,
  /// where unweighted the first solve would follow it in depth (docs/ARCHITECTURE.md). Where the
  /// start's error is larger, the median and so c grow with it. The tracker turns it off after a
  /// lost frame, whose start is a guess.
  bool weigh_at_start = true;
  real tukey_c = real(4.685);
  real tukey_floor = real(1.5);
};

struct PoseSolution {
  Se3 camera_from_model;
  real start_rms{0};  ///< RMS point-to-line distance before and after, pixels
  real end_rms{0};
  int evaluations = 0;  ///< residual evaluations of the solves run
  int iterations = 0;  ///< Jacobian evaluations (MINPACK's iterations) of the solves run
  int outliers = 0;    ///< matches given weight 0 in the last robust solve
  /// 1.4826 * median |delta| over all matches at the returned pose, to each match's strongest
  /// edge (`found`), pixels: the robust scale of the residuals (the standard deviation for
  /// normal residuals), for the tracking status.
  real residual_scale{0};
  bool solved = false;  ///< false when there were too few points or LM reported a failure
};

/// The first solve's weighted Jacobian and residuals at its start (x = 0, the first Jacobian LM
/// asks for), kept where a caller asks (PoseWorkspace::start_rows): the drift check's gate
/// (excluded_pull_sigmas) sums its information from these rows rather than computing them again.
struct StartRows {
  std::vector<real> jacobian;   ///< matches x 6, column c from c * matches (MINPACK's layout)
  std::vector<real> residuals;  ///< the residuals times the first solve's weights
  bool kept = false;            ///< the last solve_pose's first solve reached its first Jacobian
};

/// The pose step's scratch memory. A caller that keeps one between solves (the tracker does)
/// makes no heap allocation once its buffers have reached the largest match count seen; what
/// it holds between calls means nothing. Per match, the arrays are structures of arrays (one
/// array per coordinate), the layout of MINPACK's column-major Jacobian. What lives only within
/// one LM solve or only between solves shares memory: the Jacobian's holds the robust weights'
/// median work between solves and an evaluation's residuals LM did not ask for.
struct PoseWorkspace {
  std::vector<real> model_mm[3];      ///< point_in_model, millimetres
  std::vector<real> rotated[3];       ///< R0 * point_in_model, millimetres
  std::vector<real> unweighted[3];    ///< (a, b, c) of each distance (a X + b Y + c Z) / Z
  std::vector<real> gradient[2];      ///< a and b times the match's weight, for the Jacobian
  std::vector<real> evaluated;        ///< the distances at the last evaluation, unweighted
  std::vector<real> turned[3];        ///< R(w) R0 * point at the last evaluation with w != 0
  std::vector<real> inverse_depth;    ///< 1 / Z of the camera-frame point there, for the Jacobian
  std::vector<real> lens_point[2];     ///< through a lens: the undistorted X / Z and Y / Z at the last evaluation
  std::vector<real> lens_gradient[2];  ///< and (a, b) J_lens times the weight there, for the Jacobian
  std::vector<real> lens_radial[2];    ///< ViSP's lens: 1 + kud r^2 and a x + b y there, which the Jacobian reuses
  std::vector<real> residuals, jacobian, work;            ///< lmder's fvec, fjac (m x 6) and wa4
  std::vector<real> distances, weights;
  std::vector<real> before_round;  ///< the distances the last robust round weighed (its weights, rounds_settled_px)
  /// Where set, each solve_pose keeps its first solve's rows at the start there (their room is
  /// the owner's, not counted in heap_bytes).
  StartRows* start_rows = nullptr;

  /// The heap its buffers hold (their capacities), for Tracker::memory.
  size_t heap_bytes() const;
  /// Room for `matches` matches in every buffer (the lens's only when `lens`): solve_pose then
  /// allocates nothing for up to that many.
  void reserve(size_t matches, bool lens);
};

/// Residual i is delta_i = n_i . (p_i(x) - q_i) (equation (3) before the absolute value; LM
/// minimises the sum of their squares). p_i(x) projects point_in_model with the pose
/// R = exp(hat(w)) R0, t = t0 + v for x = (v, w): the exponential map around the start pose
/// `start`, so x = 0 is the start and the rotation needs no constraint. LM sees v and the
/// camera-frame points in millimetres, where S40.23's products stay in their fast range.
/// Matches given weight 0 by the last robust solve are returned with `outlier` set.
/// Matches with alternatives (several edge hypotheses, moving_edges.h): the first solve uses
/// each match's `found` (its strongest edge, so a wrong hypothesis pulls it no more than with
/// one hypothesis); before each robust round, each match takes the hypothesis nearest to the
/// projection at the previous solve's pose, and its weight follows that distance. Choosing per
/// round, not per LM evaluation, keeps the residuals a smooth function within each solve, as
/// MINPACK's trust region assumes; a robust round is one LM step, so the choice follows every
/// step after the first solve. Each match's `chosen` says which hypothesis the last round used.
PoseSolution solve_pose(std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& start,
                        const PoseParams& params);
/// The same in `workspace`'s memory (the same results, bit for bit).
PoseSolution solve_pose(std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& start,
                        const PoseParams& params, PoseWorkspace& workspace);

}  // namespace edgetrack
