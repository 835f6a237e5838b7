// SPDX-License-Identifier: BSD-3-Clause
/// How well a frame's matches pin the solved pose down: the standard deviation of the model's
/// image displacement that the residual noise leaves in the pose (docs/ARCHITECTURE.md,
/// "Tracking status").
#pragma once

#include <vector>

#include "edgetrack/edge_match.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/pose_solver.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// Returned, and the most returned, when the matches leave a pose direction unconstrained.
constexpr int kUnconstrainedPx = 1000;

/// The pose's covariance to first order, sigma^2 (J^T W J)^-1, from the point-to-line Jacobian J
/// of the matches at `pose`, Tukey's weights W of their distances there (cut at
/// max(tukey_c sigma, tukey_floor) px, as the pose step's last round) and the residual scale
/// sigma (px), propagated to the image: the largest over the model's vertices (cylinder axis
/// ends and circle centres for curved primitives) in front of the camera of the RMS length of
/// its projection's displacement, px. It is what the overlay may be off by where no match holds
/// it: with part of the model in view, directions the remaining edges barely see (depth along
/// one edge, a turn about it) give the unseen corners large values. Matches are taken as
/// independent and sigma as given, so it is a lower bound where an edge is off as a whole, or
/// where a few matches fit by chance more closely than edges are located. At most
/// kUnconstrainedPx, which it also is when the information matrix is singular.
real pose_uncertainty_px(const std::vector<EdgeMatch>& matches, const EdgeModel& model, const PinholeCamera& camera,
                         const Se3& pose, const real& sigma, const real& tukey_c, const real& tukey_floor);

/// How far the pose the matches not excluded give from `start` lies from `solved` (the pose
/// all of them gave from there), to first order, in that pose's standard deviations: the
/// Gauss-Newton step Delta_2 = -H^-1 g from `start` of their squared distances to their
/// strongest edges, weighted as the pose step's first solve weighed them there (H = J^T W J,
/// g = J^T W delta, summed from that solve's own rows at the start, `rows`), against the move
/// Delta_1 from `start` to `solved`, measured by the covariance sigma^2 H^-1:
/// |L^T (Delta_2 - Delta_1)| / sigma, in the coordinates pose_uncertainty_px takes (a move of
/// the model's centre and a turn about it). sigma is the residual scale the kept matches are
/// predicted to have after Delta_2 (a MAD of their rows' residuals moved by it), at least
/// `sigma_floor`; it is written to `scale_px` where given (`sigma_floor` when no step was
/// taken, or where the bound at `sigma_floor` is already at most `decided_within`: a caller
/// that only asks whether it passes that many deviations need not predict the scale). By
/// Cauchy-Schwarz no overlay point of the two poses then parts, to first order, by more than
/// this many times the RMS displacement pose_uncertainty_px bounds at sigma. `rows` are spent
/// (the kept rows moved to the front, their residuals overwritten). At most kUnconstrainedPx,
/// which it also is when H is singular or `rows` were not kept. Where the scale was predicted,
/// `stepped` (where given) becomes `start` moved by Delta_2: the kept rows' own pose to first
/// order, from which a solve of them needs fewer steps; otherwise it is left as it was.
real excluded_pull_sigmas(const std::vector<EdgeMatch>& matches, StartRows& rows, const EdgeModel& model,
                          const Se3& start, const Se3& solved, const real& sigma_floor, real* scale_px = nullptr,
                          const real& decided_within = real(0), Se3* stepped = nullptr);

}  // namespace edgetrack
