// SPDX-License-Identifier: BSD-3-Clause
/// The drift check (drift_check.h; issue #27, drift in clutter), on by default: the generated
/// cube with dark lines 8 mm beside every edge, tracked from its true first pose with the
/// default settings, must lose no frame and stay within 1.5 times the mean error of each frame
/// solved alone from its true pose (the target); with the check off the same run walks
/// onto the lines. Also the exclusion mask, the gate (and that it bounds what the check does),
/// the overlay distance the check compares poses by, the second solve's start from the gate's
/// step, and its settings by name and in the XML.
/// The real scene: test_drift_check_real_scene.cxx.
#include <algorithm>
#include <cstdio>
#include <string>

#include "edgetrack/control_points.h"
#include "edgetrack/drift_check.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_uncertainty.h"
#include "edgetrack/tracker_params.h"
#include "edgetrack/visp_config.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

static void test_overlay_distance() {
  EdgeModel model;
  model.vertices = {Vec3{real(0), real(0), real(0)}, Vec3{real(0.01), real(0), real(0)}};
  PinholeCamera camera;
  camera.px = camera.py = real(200);
  camera.u0 = real(160);
  camera.v0 = real(120);
  const Se3 at(Mat33::identity(), Vec3{real(0), real(0), real(0.2)});
  const Se3 moved(Mat33::identity(), Vec3{real(0.001), real(0), real(0.2)});  // 1 mm across at 200 mm: 1 px
  TEST_NEAR("the same pose parts by nothing", static_cast<double>(largest_overlay_distance_px(model, camera, at, at)),
            0.0, 1e-9);
  // S47.16 keeps a projection of about 160 px to some 2^-16 relative: its 1 px is within 0.01.
  TEST_NEAR("1 mm across at 200 mm is 1 px at px = 200",
            static_cast<double>(largest_overlay_distance_px(model, camera, at, moved)), 1.0, 1e-2);
  const Se3 behind(Mat33::identity(), Vec3{real(0), real(0), real(-0.2)});
  TEST_NEAR("points behind the camera are passed over",
            static_cast<double>(largest_overlay_distance_px(model, camera, at, behind)), 0.0, 1e-9);
}

/// The generated cube's matches at its first true pose, each at its control point's projection
/// moved along the normal by a deterministic noise of up to `noise_px` (0 to 1 in thirteenths,
/// either sign), those of `shifted_edge` moved `shift_px` more: an edge pulled aside.
static std::vector<EdgeMatch> cube_matches(const EdgeModel& model, const PinholeCamera& camera, const Se3& pose,
                                           int shifted_edge, const real& shift_px, const real& noise_px = real(0)) {
  std::vector<EdgeMatch> matches;
  int k = 0;
  for (const ControlPoint& point : sample_control_points(model, camera, pose, SamplingParams{})) {
    const real noise = noise_px * real((k++ * 7919) % 13 - 6) / real(6);
    EdgeMatch m;
    m.point = point;
    m.found = point.pixel + (point.edge == shifted_edge ? shift_px + noise : noise) * point.normal;
    matches.push_back(m);
  }
  return matches;
}

static int edge_count(const std::vector<EdgeMatch>& matches, int edge) {
  int count = 0;
  for (const EdgeMatch& m : matches) count += m.point.edge == edge;
  return count;
}

/// The exclusion mask solve_pose honours: the masked matches count nowhere, as if absent.
static void test_exclusion_mask() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the cube loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const Se3 pose = true_poses(Scene::kCube, 1)[0];
  std::vector<EdgeMatch> all = cube_matches(model.value(), camera, pose, -1, real(0));
  const int pulled = all[all.size() / 2].point.edge;
  all = cube_matches(model.value(), camera, pose, pulled, real(4));
  std::vector<EdgeMatch> without;
  for (const EdgeMatch& m : all)
    if (m.point.edge != pulled) without.push_back(m);
  for (EdgeMatch& m : all) m.excluded = m.point.edge == pulled;
  const PoseParams params;
  const PoseSolution masked = solve_pose(all, camera, pose, params);
  const PoseSolution absent = solve_pose(without, camera, pose, params);
  TEST("both solve", masked.solved && absent.solved, true);
  const double apart =
      static_cast<double>(largest_overlay_distance_px(model.value(), camera, masked.camera_from_model, absent.camera_from_model));
  std::printf("%s: %d of %zu matches masked, pose %.2e px from the solve without them\n", real_name(),
              edge_count(all, pulled), all.size(), apart);
  TEST("the masked matches' solve is the solve without them", apart < 1e-3, true);
  TEST_EQUAL("with as many outliers", masked.outliers, absent.outliers);
  TEST_NEAR("and the same residual scale", static_cast<double>(masked.residual_scale),
            static_cast<double>(absent.residual_scale), 1e-4);
  int masked_outliers = 0;
  for (const EdgeMatch& m : all) masked_outliers += m.excluded && m.outlier;
  TEST_EQUAL("a masked match is no outlier", masked_outliers, 0);
  for (EdgeMatch& m : all) m.excluded = true;
  TEST("every match masked: nothing to solve", solve_pose(all, camera, pose, params).solved, false);
}

/// The gate: how far the pose of the matches off the lines lies from the frame's, in its
/// standard deviations. With matches off their edges by a noise of sigma, an edge pulled 2 px
/// aside moves a least-squares pose: without it the rest's pose from the start lies many standard
/// deviations from the pulled one, and the overlays part by at most the bound times the
/// uncertainty (Cauchy-Schwarz, to first order); without an edge that is not pulled, the rest's
/// pose lies within the noise of the frame's.
static void test_pull_gate() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const Se3 start = true_poses(Scene::kCube, 1)[0];
  const real sigma(0.3), wide(100), c(4.685);  // a cut far beyond every distance: least squares
  std::vector<EdgeMatch> all = cube_matches(model.value(), camera, start, -1, real(0));
  const int pulled = all[all.size() / 2].point.edge, kept = all.front().point.edge;
  all = cube_matches(model.value(), camera, start, pulled, real(2), sigma);
  PoseParams plain;  // least squares: every match pulls
  plain.tukey_c = real(0);
  StartRows rows;  // the first solve's rows at the start, which the gate sums
  PoseWorkspace workspace;
  workspace.start_rows = &rows;
  const PoseSolution solved = solve_pose(all, camera, start, plain, workspace);
  TEST("the pulled pose solves", solved.solved, true);
  TEST("and keeps its rows at the start", rows.kept && rows.residuals.size() == all.size(), true);
  if (!solved.solved) return;
  const Se3& pose = solved.camera_from_model;
  const StartRows all_rows = rows;
  PoseWorkspace plain_workspace;  // keeping the rows is a copy: the pose is the same, bit for bit
  std::vector<EdgeMatch> again = all;
  TEST("the rows kept or not, the same pose",
       same_bits(solve_pose(again, camera, start, plain, plain_workspace).camera_from_model, pose), true);
  PoseParams robust;  // and with the robust rounds, whose first solve is weighted
  std::vector<EdgeMatch> weighed = all;
  const Se3 robust_pose = solve_pose(weighed, camera, start, robust, plain_workspace).camera_from_model;
  StartRows robust_rows;
  plain_workspace.start_rows = &robust_rows;
  TEST("and with robust rounds",
       same_bits(solve_pose(weighed, camera, start, robust, plain_workspace).camera_from_model, robust_pose) &&
           robust_rows.kept,
       true);
  for (EdgeMatch& m : all) m.excluded = m.point.edge == pulled;
  const real pulled_out = excluded_pull_sigmas(all, rows, model.value(), start, pose, sigma);
  workspace.start_rows = nullptr;
  const PoseSolution back = solve_pose(all, camera, start, plain, workspace);
  const real uncertainty = pose_uncertainty_px(all, model.value(), camera, back.camera_from_model, sigma, c, wide);
  const real parted = largest_overlay_distance_px(model.value(), camera, pose, back.camera_from_model);
  for (EdgeMatch& m : all) m.excluded = false;
  rows = all_rows;
  const real none_out = excluded_pull_sigmas(all, rows, model.value(), start, pose, sigma);
  std::vector<EdgeMatch> unpulled = cube_matches(model.value(), camera, start, -1, real(0), sigma);
  workspace.start_rows = &rows;
  const PoseSolution noisy = solve_pose(unpulled, camera, start, plain, workspace);
  for (EdgeMatch& m : unpulled) m.excluded = m.point.edge == kept;
  const real true_out = excluded_pull_sigmas(unpulled, rows, model.value(), start, noisy.camera_from_model, sigma);
  rows.kept = false;
  TEST("without the first solve's rows the gate sends every frame to the second solve",
       excluded_pull_sigmas(unpulled, rows, model.value(), start, noisy.camera_from_model, sigma) ==
           real(kUnconstrainedPx),
       true);
  std::printf("%s: pull without the pulled edge %.2f sigmas (overlay parted %.3f px, uncertainty %.3f px), with every "
              "match %.3f; without an edge of a frame with none pulled %.2f\n",
              real_name(), static_cast<double>(pulled_out), static_cast<double>(parted),
              static_cast<double>(uncertainty), static_cast<double>(none_out), static_cast<double>(true_out));
  TEST("leaving the pulled edge out moves the pose beyond 3 sigmas", pulled_out > real(3), true);
  TEST("the overlay parts by at most the bound times the uncertainty, to first order",
       static_cast<double>(parted) <= 1.05 * static_cast<double>(pulled_out * uncertainty), true);
  // Within a deviation, not 0: S47.16's LM ends where its resolution does, short of the optimum.
  TEST("leaving nothing out moves it by less than a deviation (the pose is their optimum)", none_out < real(1), true);
  TEST("leaving a true edge out moves it by less than 3 sigmas", noisy.solved && true_out < real(3), true);
  // A model that fits loosely (every match off its edge by a noise of 1 px, a scale well over the
  // floor): the rest fit their own pose no closer than all of them did, and the gate is taken at
  // the scale they are predicted to have there, near the first solve's, not at the floor.
  std::vector<EdgeMatch> loose = cube_matches(model.value(), camera, start, -1, real(0), real(1));
  const PoseSolution fitted = solve_pose(loose, camera, start, plain, workspace);
  for (EdgeMatch& m : loose) m.excluded = m.point.edge == kept;
  real gate_scale(0);
  const real loose_out = excluded_pull_sigmas(loose, rows, model.value(), start, fitted.camera_from_model, sigma, &gate_scale);
  std::printf("%s: loose fit, first scale %.3f px, gate's predicted scale %.3f px, %.2f sigmas\n", real_name(),
              static_cast<double>(fitted.residual_scale), static_cast<double>(gate_scale), static_cast<double>(loose_out));
  TEST("on a loose fit the gate's scale is the one the rest are predicted to fit at, near the first's",
       fitted.solved && gate_scale > real(0.7) * fitted.residual_scale && gate_scale < real(1.4) * fitted.residual_scale,
       true);
}

/// A flat grey image with, beside each of `matches` whose edge is in `lined`, the profile of a
/// thin dark line along its normal (the image darkening along it, as a match of positive
/// contrast reads it): bright before the match, dark for two pixels, back beyond.
static vpImage<unsigned char> lines_beside(const std::vector<EdgeMatch>& matches, const std::vector<int>& lined,
                                           const PinholeCamera& camera) {
  vpImage<unsigned char> grey(static_cast<unsigned>(camera.height), static_cast<unsigned>(camera.width), 230);
  for (const EdgeMatch& m : matches) {
    if (std::find(lined.begin(), lined.end(), m.point.edge) == lined.end()) continue;
    for (int k = 1; k <= 4; ++k) {
      const Vec2 at = m.found + real(k) * m.point.normal;
      if (at.x >= real(0) && at.y >= real(0) && at.x < real(camera.width) && at.y < real(camera.height))
        grey[static_cast<unsigned>(static_cast<int>(at.y))][static_cast<unsigned>(static_cast<int>(at.x))] =
            k <= 2 ? 40 : 200;
    }
  }
  return grey;
}

/// The gate bounds what the check can do. The check allows the second pose's deviations at its
/// own residual scale, which the matches off the lines set; where many matches sat on lines the
/// first solve's scale is many times it. Every other visible edge of the cube is matched on
/// lines, 4.5 and -0.5 px aside by turns (2 px on average: a pull, and a spread the pose cannot
/// take up), the rest within 0.05 px, solved by least squares from the true pose: the frame
/// the check corrects when it solves every frame again (no first-solve rows: the gate passes
/// everything) is corrected with the gate too.
static void test_gate_bounds_the_check() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const Se3 start = true_poses(Scene::kCube, 1)[0];
  std::vector<EdgeMatch> matches = cube_matches(model.value(), camera, start, -1, real(0), real(0.05));
  std::vector<int> edges;
  for (const EdgeMatch& m : matches)
    if (std::find(edges.begin(), edges.end(), m.point.edge) == edges.end()) edges.push_back(m.point.edge);
  std::vector<int> lined;
  for (size_t e = 0; e < edges.size(); e += 2) lined.push_back(edges[e]);
  int k = 0;
  for (EdgeMatch& m : matches)
    if (std::find(lined.begin(), lined.end(), m.point.edge) != lined.end())
      m.found = m.found + (real(2) + real(k++ % 2 ? 2.5 : -2.5)) * m.point.normal;
  const vpImage<unsigned char> grey = lines_beside(matches, lined, camera);
  PoseParams plain;  // least squares: every match pulls
  plain.tukey_c = real(0);
  const ThinLineParams lines;
  const real floor(0.3);  // StatusParams::edge_location_px
  DriftWorkspace drift;
  PoseWorkspace workspace;
  workspace.start_rows = &drift.start_rows;
  const PoseSolution solved = solve_pose(matches, camera, start, plain, workspace);
  TEST("the frame with lines solves", solved.solved, true);
  if (!solved.solved) return;
  const DriftVerdict gated = check_drift(grey, matches, solved, model.value(), camera, start, plain, lines, floor,
                                         workspace, drift);
  drift.start_rows.kept = false;
  const DriftVerdict every = check_drift(grey, matches, solved, model.value(), camera, start, plain, lines, floor,
                                         workspace, drift);
  std::printf("%s: %d of %zu matches on lines; first scale %.3f px, second %.3f; parted %.3f px, allowed %.3f; "
              "gate %.2f sigmas\n",
              real_name(), gated.lines, matches.size(), static_cast<double>(solved.residual_scale),
              static_cast<double>(every.second.residual_scale), static_cast<double>(every.parted_px),
              static_cast<double>(every.allowed_px), static_cast<double>(gated.pull_sigmas));
  TEST("the lines' matches, and only they, are called lines", gated.lines == every.lines && gated.lines > 0, true);
  TEST("the lines spread the first solve's residuals far beyond the rest's",
       solved.residual_scale > real(3) * every.second.residual_scale, true);
  TEST("solving every frame again, the check corrects this one (the case is one of drift)", every.drifted, true);
  TEST("the gate passes it to the second solve, which corrects it", gated.checked && gated.drifted, true);
}

/// The second solve starts from the gate's Gauss-Newton step (excluded_pull_sigmas' `stepped`):
/// the same rows, weights and optimum as from the frame's start, so it must end where the solve
/// from the start ends, within what LM's stopping rule (a step that reduces the sum of squares by
/// at most 1 %) leaves, here a twentieth of a pixel on the overlay (a sixth of the 0.3 px edge
/// location floor the check's scales start from), and in no more evaluations. The generated cube
/// with one edge pulled 2 px aside and the rest off by a noise of 0.3 px, the pulled edge excluded,
/// solved from a start 1.5 mm and 0.4 degrees off the pose the matches were made at (a frame's
/// motion), with the default robust rounds and the check's normal-equations LM.
static void test_warm_start() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const Se3 truth = true_poses(Scene::kCube, 1)[0];
  const Se3 start = truth.retract(Vec3{real(0.001), real(-0.001), real(0.0005)}, Vec3{real(0.005), real(0), real(-0.005)});
  std::vector<EdgeMatch> matches = cube_matches(model.value(), camera, truth, -1, real(0));
  const int pulled = matches[matches.size() / 2].point.edge;
  matches = cube_matches(model.value(), camera, truth, pulled, real(2), real(0.3));
  StartRows rows;
  PoseWorkspace workspace;
  workspace.start_rows = &rows;
  const PoseSolution first = solve_pose(matches, camera, start, PoseParams{}, workspace);
  TEST("the pulled frame solves", first.solved, true);
  if (!first.solved) return;
  for (EdgeMatch& m : matches) m.excluded = m.point.edge == pulled;
  Se3 stepped = start;
  excluded_pull_sigmas(matches, rows, model.value(), start, first.camera_from_model, real(0.3), nullptr, real(0),
                       &stepped);
  workspace.start_rows = nullptr;
  PoseParams second;
  second.solver = PoseSolver::kNormalEquations;
  std::vector<EdgeMatch> cold_matches = matches;
  const PoseSolution cold = solve_pose(cold_matches, camera, start, second, workspace);
  const PoseSolution warm = solve_pose(matches, camera, stepped, second, workspace);
  TEST("both solve", cold.solved && warm.solved, true);
  const double step_px = static_cast<double>(largest_overlay_distance_px(model.value(), camera, start, stepped));
  const double to_cold_px = static_cast<double>(
      largest_overlay_distance_px(model.value(), camera, stepped, cold.camera_from_model));
  const double apart_px = static_cast<double>(
      largest_overlay_distance_px(model.value(), camera, cold.camera_from_model, warm.camera_from_model));
  std::printf("%s: the gate's step moves the overlay %.3f px, %.3f px short of the solve from the start; from it "
              "the solve ends %.2e px from that one's, in %d evaluations against %d\n",
              real_name(), step_px, to_cold_px, apart_px, warm.evaluations, cold.evaluations);
  TEST("the gate's step is the most of the way from the start", to_cold_px < 0.25 * step_px, true);
  TEST("from it the second solve ends within 0.05 px of the solve from the start", apart_px < 0.05, true);
  TEST("in no more evaluations", warm.evaluations <= cold.evaluations, true);
  TEST_NEAR("with the same residual scale", static_cast<double>(warm.residual_scale),
            static_cast<double>(cold.residual_scale), 0.01);
}

static void test_drift_settings() {
  ThinLineParams p;
  TEST("the check corrects by default", p.check == DriftAction::kCorrect, true);
  TEST("check=0 switches it off", set_thin_line_param(p, "check", 0).empty() && p.check == DriftAction::kNone, true);
  TEST("check=2 corrects", set_thin_line_param(p, "check", 2).empty() && p.check == DriftAction::kCorrect, true);
  TEST("check=1 reports", set_thin_line_param(p, "check", 1).empty() && p.check == DriftAction::kReport, true);
  TEST("check=3 is refused", set_thin_line_param(p, "check", 3).empty(), false);
  TEST("check_sigmas=4 is taken", set_thin_line_param(p, "check_sigmas", 4).empty(), true);
  TEST_NEAR("to its value", static_cast<double>(p.check_sigmas), 4.0, 1e-4);
  TEST("check_sigmas=0 is refused", set_thin_line_param(p, "check_sigmas", 0).empty(), false);
  TEST("check_share is no setting (the pull gate needs none)", set_thin_line_param(p, "check_share", 0.3).empty(), false);
  TrackerConfig config;
  const Result<ConfigNotes> read = apply_visp_config_text(
      "<conf>\n<edgetrack><thin_lines><check>0</check></thin_lines></edgetrack>\n</conf>", "drift.xml", config);
  TEST("the XML block switches the check off", read.ok() && config.params.thin_lines.check == DriftAction::kNone, true);
  TrackerParams params;
  params.thin_lines.check_sigmas = real(-1);
  TEST("check_tracker_params refuses a negative check_sigmas", check_tracker_params(params).has_value(), true);
}

static void test_drift_in_clutter() {
  constexpr int kFrames = 24;
  SequenceSpec spec;
  spec.clutter = 0.008;
  const TrackerParams defaults;
  TrackerParams unchecked;
  unchecked.thin_lines.check = DriftAction::kNone;
  const SequenceRun checked = run_sequence(Scene::kCube, kFrames, false, defaults, spec);
  const SequenceRun plain = run_sequence(Scene::kCube, kFrames, false, unchecked, spec);
  TEST("both runs load", checked.loaded && plain.loaded, true);
  if (!checked.loaded || !plain.loaded) return;
  // Each frame alone: its true pose as a one-frame sequence, solved from that pose by the pose
  // step alone (tracking_eval_clutter_dynamics' "alone").
  double alone = 0;
  for (int k = 0; k < kFrames; ++k) {
    SequenceSpec one = spec;
    one.poses = {checked.truth[static_cast<size_t>(k)]};
    const SequenceRun single = run_sequence(Scene::kCube, 1, false, unchecked, one);
    if (!single.loaded) return;
    alone += single.position_error_mm[0] / kFrames;
  }
  std::printf("%s cube, lines 8 mm beside the edges, %d frames: the defaults (check on) mean %.3f mm, check off "
              "%.3f mm, each frame alone %.3f mm\n",
              real_name(), kFrames, checked.mean_position_error_mm, plain.mean_position_error_mm, alone);
  TEST_EQUAL("with the defaults no frame is lost", count_status(checked, TrackingStatus::kLost), 0);
  TEST("with the defaults the mean error is at most 1.5 times alone's",
       checked.mean_position_error_mm <= 1.5 * alone, true);
  TEST("with the check off the run drifts beyond it (the case is one of drift)",
       plain.mean_position_error_mm > 1.5 * alone, true);
}

static void test_drift_check() {
  test_overlay_distance();
  test_exclusion_mask();
  test_pull_gate();
  test_gate_bounds_the_check();
  test_warm_start();
  test_drift_settings();
  test_drift_in_clutter();
}

TESTMAIN(test_drift_check)
