// SPDX-License-Identifier: BSD-3-Clause
#include "edgetrack/drift_check.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/pose_uncertainty.h"
#include "edgetrack/thin_lines.h"
#include "edgetrack/tracker_memory.h"

namespace edgetrack {

real largest_overlay_distance_px(const EdgeModel& model, const PinholeCamera& camera, const Se3& a, const Se3& b) {
  real worst(0);  // squared: one square root at the end
  auto visit = [&](const Vec3& v) {
    const Vec3 in_a = a * v, in_b = b * v;
    if (in_a.z <= real(0) || in_b.z <= real(0)) return;
    const Vec2 d = camera.project(in_a) - camera.project(in_b);
    worst = std::max(worst, dot(d, d));
  };
  for (const Vec3& v : model.vertices) visit(v);
  for (const Cylinder& c : model.cylinders) {
    visit(c.axis_a);
    visit(c.axis_b);
  }
  for (const Circle& c : model.circles) visit(c.centre);
  using std::sqrt;
  return sqrt(worst);
}

int mark_outliers_at(std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& pose, const real& sigma,
                     const PoseParams& pose_params) {
  using std::fabs;
  const real cut = std::max(pose_params.tukey_c * sigma, pose_params.tukey_floor);
  int outliers = 0;
  for (EdgeMatch& match : matches) {
    const Vec3 in_camera = pose * match.point.point_in_model;
    match.outlier = in_camera.z <= real(0) || !(fabs(dot(match.point.normal, camera.project(in_camera) - match.used())) < cut);
    outliers += match.outlier;
  }
  return outliers;
}

namespace {

/// The relative standard deviation of a median absolute deviation of n normal residuals, times
/// sqrt(n), for large n: the MAD's efficiency against the standard deviation is 0.37, so
/// 1 / sqrt(2 * 0.37) (Rousseeuw and Croux, 1993).
constexpr double kMadRelativeError = 1.16;

/// Masks out the matches whose used() hypothesis, or strongest one (where a second solve starts),
/// lies on a thin line; returns how many.
int exclude_thin_lines(const vpImage<unsigned char>& grey, std::vector<EdgeMatch>& matches, const ThinLineParams& lines) {
  int count = 0;
  for (EdgeMatch& match : matches) {
    const bool brighter_along_normal = match.contrast < real(0);  // as reject_thin_line_matches reads it
    match.excluded = on_thin_line(grey, match.used(), match.point.normal, brighter_along_normal, lines) ||
                     (match.chosen != 0 && on_thin_line(grey, match.found, match.point.normal, brighter_along_normal, lines));
    count += match.excluded;
  }
  return count;
}

/// The first solve's marks, held while the second solve overwrites them, and given back.
void hold_marks(const std::vector<EdgeMatch>& matches, std::vector<DriftWorkspace::HeldMarks>& held) {
  held.resize(matches.size());
  for (size_t i = 0; i < matches.size(); ++i) held[i] = {matches[i].outlier, static_cast<signed char>(matches[i].chosen)};
}
void give_back_marks(const std::vector<DriftWorkspace::HeldMarks>& held, std::vector<EdgeMatch>& matches) {
  for (size_t i = 0; i < matches.size(); ++i) {
    matches[i].outlier = held[i].outlier;
    matches[i].chosen = held[i].chosen;
    matches[i].excluded = false;
  }
}

}  // namespace

DriftVerdict check_drift(const vpImage<unsigned char>& grey, std::vector<EdgeMatch>& matches, const PoseSolution& solved,
                         const EdgeModel& model, const PinholeCamera& camera, const Se3& start,
                         const PoseParams& pose_params, const ThinLineParams& lines, const real& sigma_floor,
                         PoseWorkspace& workspace, DriftWorkspace& drift_workspace) {
  DriftVerdict verdict;
  // Room for the held marks on every frame, not only where a second solve runs: the buffer
  // grows with the largest frame seen, as the tracker's others do.
  drift_workspace.reserve(matches.size());
  verdict.lines = exclude_thin_lines(grey, matches, lines);
  if (verdict.lines == 0) return verdict;
  // Matches on the object's own edges that the test calls lines (texture, a real scene's
  // approximate model) give, without the rest, the pose the first solve found, within its noise:
  // only where their step from the start would end as far away as the check could report is the
  // second solve run, in deviations at the scale the rest are predicted to fit at after that step.
  Se3 warm_start = start;
  verdict.pull_sigmas = excluded_pull_sigmas(matches, drift_workspace.start_rows, model, start,
                                             solved.camera_from_model, sigma_floor, &verdict.gate_scale_px,
                                             lines.check_sigmas, &warm_start);
  if (!(verdict.pull_sigmas > lines.check_sigmas)) {
    for (EdgeMatch& match : matches) match.excluded = false;
    return verdict;
  }
  hold_marks(matches, drift_workspace.held);
  // The 6 x 6 normal equations' LM: lmder's poses within the golden tolerances
  // (test_normal_equations.cxx) in fewer instructions; a check needs no more.
  PoseParams second = pose_params;
  second.solver = PoseSolver::kNormalEquations;
  StartRows* const first_rows = workspace.start_rows;  // the first solve's, which the gate has read
  workspace.start_rows = nullptr;
  // From the gate's Gauss-Newton step of the same rows: LM's first step from `start` would land
  // near it. The weights are the same from either start (the first solve weighs the distances
  // at the control points' pixels, which `start` projected), so the solve has the same optimum.
  verdict.second = solve_pose(matches, camera, warm_start, second, workspace);
  workspace.start_rows = first_rows;
  if (verdict.second.solved) {
    verdict.checked = true;
    verdict.parted_px = largest_overlay_distance_px(model, camera, solved.camera_from_model,
                                                    verdict.second.camera_from_model);
    const real sigma = std::max(verdict.second.residual_scale, sigma_floor);
    verdict.allowed_px = lines.check_sigmas * pose_uncertainty_px(matches, model, camera, verdict.second.camera_from_model,
                                                                  sigma, pose_params.tukey_c, pose_params.tukey_floor);
    // Leaving out matches that pulled the pose off the rest lets the rest fit their own pose
    // more closely than all of them fitted the first; leaving out matches that agreed with the
    // rest (true edges the test calls lines) does not, and a pose the rest then fit worse is no
    // correction. Worse: beyond two standard errors of the second scale, a median absolute
    // deviation of the n matches off the lines (kMadRelativeError / sqrt(n) of it, for normal
    // residuals).
    using std::sqrt;
    const size_t kept = matches.size() - static_cast<size_t>(verdict.lines);
    const real noise = real(2 * kMadRelativeError) / sqrt(real(static_cast<int>(kept)));
    verdict.fits_as_closely = !(verdict.second.residual_scale > (real(1) + noise) * solved.residual_scale);
    // The lines' pull bounds the parting to first order (the gate's bound times the uncertainty
    // at the gate's scale); a second pose far beyond it (twice: the robust rounds move on from the lines)
    // is another basin the rest fell into from a start they do not hold (a turn the prediction
    // missed), not the pose the lines pulled the frame from.
    const real explained =
        real(2) * verdict.pull_sigmas * verdict.allowed_px / lines.check_sigmas * verdict.gate_scale_px / sigma;
    verdict.drifted =
        verdict.parted_px > verdict.allowed_px && verdict.fits_as_closely && !(verdict.parted_px > explained);
  }
  give_back_marks(drift_workspace.held, matches);
  return verdict;
}

void DriftWorkspace::reserve(size_t matches) {
  held.reserve(matches);
  start_rows.jacobian.reserve(matches * 6);
  start_rows.residuals.reserve(matches);
}

size_t DriftWorkspace::heap_bytes() const {
  return capacity_bytes(held) + capacity_bytes(start_rows.jacobian) + capacity_bytes(start_rows.residuals);
}

}  // namespace edgetrack
