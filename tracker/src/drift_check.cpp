// SPDX-License-Identifier: BSD-3-Clause
#include "edgetrack/drift_check.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/pose_uncertainty.h"
#include "edgetrack/thin_lines.h"

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

/// The Tukey cut the pose step's first solve weighs the matches not excluded with at the start
/// (solve_pose, PoseParams::weigh_at_start): max(tukey_c * 1.4826 * median |delta|, tukey_floor)
/// px over their distances at the start, in `scratch` (the pose workspace's, which means nothing
/// between solves).
real start_cut(const std::vector<EdgeMatch>& matches, const PoseParams& params, std::vector<real>& scratch) {
  using std::fabs;
  scratch.resize(matches.size());
  size_t n = 0;
  for (const EdgeMatch& match : matches)
    if (!match.excluded) scratch[n++] = fabs(dot(match.point.normal, match.point.pixel - match.found));
  if (n == 0) return params.tukey_floor;
  std::nth_element(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(n / 2),
                   scratch.begin() + static_cast<std::ptrdiff_t>(n));
  return std::max(params.tukey_c * real(kMadToSigma) * scratch[n / 2], params.tukey_floor);
}

/// The first solve's marks, held while the second solve overwrites them, and given back.
void hold_marks(std::vector<EdgeMatch>& matches) {
  for (EdgeMatch& match : matches) {
    match.held_outlier = match.outlier;
    match.held_chosen = static_cast<signed char>(match.chosen);
  }
}
void give_back_marks(std::vector<EdgeMatch>& matches) {
  for (EdgeMatch& match : matches) {
    match.outlier = match.held_outlier;
    match.chosen = match.held_chosen;
    match.excluded = false;
  }
}

}  // namespace

DriftVerdict check_drift(const vpImage<unsigned char>& grey, std::vector<EdgeMatch>& matches, const PoseSolution& solved,
                         const EdgeModel& model, const PinholeCamera& camera, const Se3& start,
                         const PoseParams& pose_params, const ThinLineParams& lines, const real& sigma_floor,
                         PoseWorkspace& workspace) {
  DriftVerdict verdict;
  verdict.lines = exclude_thin_lines(grey, matches, lines);
  if (verdict.lines == 0) return verdict;
  // Matches on the object's own edges that the test calls lines (texture, a real scene's
  // approximate model) give, without the rest, the pose the first solve found, within its noise:
  // only where their step from the start would end as far away as the check could report is the
  // second solve run.
  const real first_sigma = std::max(solved.residual_scale, sigma_floor);
  verdict.pull_sigmas = excluded_pull_sigmas(matches, model, camera, start, solved.camera_from_model, first_sigma,
                                             start_cut(matches, pose_params, workspace.distances));
  if (!(verdict.pull_sigmas > lines.check_sigmas)) {
    for (EdgeMatch& match : matches) match.excluded = false;
    return verdict;
  }
  hold_marks(matches);
  // The 6 x 6 normal equations' LM: lmder's poses within the golden tolerances
  // (test_normal_equations.cxx) in fewer instructions; a check needs no more.
  PoseParams second = pose_params;
  second.solver = PoseSolver::kNormalEquations;
  verdict.second = solve_pose(matches, camera, start, second, workspace);
  if (verdict.second.solved) {
    verdict.checked = true;
    verdict.parted_px = largest_overlay_distance_px(model, camera, solved.camera_from_model,
                                                    verdict.second.camera_from_model);
    const real sigma = std::max(verdict.second.residual_scale, sigma_floor);
    verdict.allowed_px = lines.check_sigmas * pose_uncertainty_px(matches, model, camera, verdict.second.camera_from_model,
                                                                  sigma, pose_params.tukey_c, pose_params.tukey_floor);
    verdict.drifted = verdict.parted_px > verdict.allowed_px;
  }
  give_back_marks(matches);
  return verdict;
}

}  // namespace edgetrack
