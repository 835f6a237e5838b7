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

DriftVerdict DriftCheck::check(const vpImage<unsigned char>& grey, const std::vector<EdgeMatch>& matches,
                               const Se3& solved, const EdgeModel& model, const PinholeCamera& camera, const Se3& start,
                               const PoseParams& pose_params, const ThinLineParams& lines, const real& sigma_floor,
                               PoseWorkspace& workspace) {
  DriftVerdict verdict;
  matches_ = matches;
  // The first solve's outlier marks are its own; the second solve sets its own.
  for (EdgeMatch& match : matches_) match.outlier = false;
  // Lines beside the edges are a sizeable share of the matches where they can pull the pose; a
  // few matches of noise or texture called lines are not.
  const int changed = reject_thin_line_matches(grey, matches_, lines);
  if (changed == 0 || real(changed) < lines.check_share * real(matches.size())) return verdict;
  // The 6 x 6 normal equations' LM: lmder's poses within the golden tolerances
  // (test_normal_equations.cxx) in fewer instructions; a check needs no more.
  PoseParams second = pose_params;
  second.solver = PoseSolver::kNormalEquations;
  solution_ = solve_pose(matches_, camera, start, second, workspace);
  if (!solution_.solved) return verdict;
  verdict.checked = true;
  verdict.parted_px = largest_overlay_distance_px(model, camera, solved, solution_.camera_from_model);
  const real sigma = std::max(solution_.residual_scale, sigma_floor);
  verdict.allowed_px = lines.check_sigmas * pose_uncertainty_px(matches_, model, camera, solution_.camera_from_model,
                                                                sigma, pose_params.tukey_c, pose_params.tukey_floor);
  verdict.drifted = verdict.parted_px > verdict.allowed_px;
  return verdict;
}

}  // namespace edgetrack
