// SPDX-License-Identifier: BSD-3-Clause
/// The pose step: from matches that lie exactly on the true projected edges, LM with the
/// analytic Jacobian recovers the true pose from a start 1 degree and 3 mm off; with 10 % of the
/// matches moved 3 pixels off, the Tukey-weighted robust solves flag them and still recovers the
/// pose, which the paper's plain solve does not; robust rounds of one LM step each land where
/// rounds run to convergence do, and ending them once settled (rounds_settled_px) where all
/// of them do; given the true edge as a second hypothesis, the robust rounds
/// choose it.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_solver.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// |v| in double: squares of sub-millimetre values would underflow in fixed point.
double length(const Vec3& v) {
  return std::hypot(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

double position_error_mm(const Se3& a, const Se3& b) {
  return 1000 * length(a.inverse().translation() - b.inverse().translation());
}

double rotation_error_deg(const Se3& a, const Se3& b) {
  return length(rotation_log(a.rotation() * b.rotation().transpose())) * 57.29577951308232;
}

}  // namespace

static void test_pose_solver() {
  const std::string name = real_name();
  const double tol_mm = name == "s47_16" ? 1.0 : name == "double" ? 1e-4 : 0.02;
  const Result<EdgeModel> loaded = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("the cube loads", loaded.ok(), true);
  if (!loaded.ok()) return;
  const EdgeModel& cube = loaded.value();
  const PinholeCamera camera{real(300), real(300), real(160), real(120), 320, 240};
  const Se3 truth(rotation_exp({real(0.5), real(-0.6), real(0.15)}), {real(0.002), real(0.005), real(0.15)});
  const Se3 start(rotation_exp({real(0.012), real(-0.01), real(0.008)}) * truth.rotation(),
                  truth.translation() + Vec3{real(0.002), real(-0.001), real(0.002)});

  // Control points sampled at the start pose, matched to where their edges really are: the
  // true projection of the same 3D point slid along its edge changes nothing, so use it.
  EdgeIdBuffer ids(camera);
  ids.render(cube, start);
  const std::vector<ControlPoint> points = keep_visible(sample_control_points(cube, camera, start, {}), ids);
  std::vector<EdgeMatch> matches;
  for (const ControlPoint& p : points) {
    EdgeMatch m;
    m.point = p;
    m.found = camera.project(truth * p.point_in_model);
    matches.push_back(m);
  }
  TEST("there are about 80 visible control points", matches.size() >= 60 && matches.size() <= 100, true);
  const PoseParams params;
  std::vector<EdgeMatch> clean = matches;
  const PoseSolution exact = solve_pose(clean, camera, start, params);
  TEST("the pose is solved", exact.solved, true);
  TEST_NEAR("exact matches: the camera position comes back (mm)", position_error_mm(exact.camera_from_model, truth),
            0, tol_mm);
  TEST_NEAR("exact matches: the rotation comes back (degrees)", rotation_error_deg(exact.camera_from_model, truth), 0,
            tol_mm / 10);
  const double rms_tol = name == "s47_16" ? 0.05 : 0.01;  // S47.16 resolves 1.5e-5 m: about 0.03 px here
  TEST_NEAR("exact matches: the final RMS distance is near 0 px", exact.end_rms, 0, rms_tol);
  TEST("the start was off by more than 1 px RMS", exact.start_rms > real(1), true);
  std::printf("LM iterations over the first and the %d robust solves: %d\n", params.robust_rounds, exact.iterations);
  TEST("the analytic Jacobian converges within 12 LM iterations plus 1 per robust solve (one step each)",
       exact.iterations <= 12 + params.robust_rounds, true);
  TEST_EQUAL("exact matches: no outlier is flagged", exact.outliers, 0);

  // Every tenth match moved 3 pixels along its normal: a wrong edge found by the search.
  std::vector<EdgeMatch> spoiled = matches;
  int moved = 0;
  for (size_t i = 0; i < spoiled.size(); i += 10, ++moved)
    spoiled[i].found = spoiled[i].found + real(3) * spoiled[i].point.normal;
  const PoseSolution robust = solve_pose(spoiled, camera, start, params);
  int flagged_moved = 0, flagged_other = 0;
  for (size_t i = 0; i < spoiled.size(); ++i) {
    if (!spoiled[i].outlier) continue;
    if (i % 10 == 0) ++flagged_moved;
    else ++flagged_other;
  }
  TEST_EQUAL("the Tukey solve flags every moved match", flagged_moved, moved);
  TEST_EQUAL("and no other", flagged_other, 0);
  TEST_NEAR("with 10 % outliers the robust pose is still right (mm)",
            position_error_mm(robust.camera_from_model, truth), 0, 10 * tol_mm);
  // Robust rounds run to convergence land where the one-step rounds do.
  PoseParams converged = params;
  converged.robust_evaluations = params.max_evaluations;
  std::vector<EdgeMatch> spoiled_converged = spoiled;
  const PoseSolution full = solve_pose(spoiled_converged, camera, start, converged);
  std::printf("robust rounds of one step: %d evaluations, %d iterations; run to convergence: %d, %d\n",
              robust.evaluations, robust.iterations, full.evaluations, full.iterations);
  TEST("one-step robust rounds take fewer LM iterations than converged ones", robust.iterations < full.iterations,
       true);
  TEST_NEAR("and give the same pose (mm)", position_error_mm(robust.camera_from_model, full.camera_from_model), 0,
            tol_mm);
  // Many robust rounds reach the weighted optimum before the last: ending them once a round
  // moved no match more than a hundredth of a pixel takes fewer steps to the same pose.
  PoseParams many = params;
  many.robust_rounds = 8;
  PoseParams settling = many;
  settling.rounds_settled_px = real(0.01);
  std::vector<EdgeMatch> spoiled_many = spoiled, spoiled_settling = spoiled;
  const PoseSolution all_rounds = solve_pose(spoiled_many, camera, start, many);
  const PoseSolution settled = solve_pose(spoiled_settling, camera, start, settling);
  std::printf("8 robust rounds: %d iterations; ending once settled to 0.01 px: %d\n", all_rounds.iterations,
              settled.iterations);
  TEST("robust rounds ending once settled take fewer LM iterations", settled.iterations < all_rounds.iterations, true);
  TEST_NEAR("and give the same pose (mm)", position_error_mm(settled.camera_from_model, all_rounds.camera_from_model),
            0, tol_mm);
  // The same moved matches keeping the true edge as a second hypothesis: the robust rounds
  // choose it, so no match is left out and the pose comes back.
  std::vector<EdgeMatch> two_hypotheses = spoiled;
  for (size_t i = 0; i < two_hypotheses.size(); i += 10) {
    two_hypotheses[i].alternatives[0] = matches[i].found;
    two_hypotheses[i].alternative_count = 1;
  }
  const PoseSolution chosen = solve_pose(two_hypotheses, camera, start, params);
  int chose_true = 0, chose_other = 0;
  for (size_t i = 0; i < two_hypotheses.size(); ++i) {
    if (i % 10 == 0) chose_true += two_hypotheses[i].chosen == 1;
    else chose_other += two_hypotheses[i].chosen != 0;
  }
  TEST_EQUAL("with the true edge as a second hypothesis, every moved match uses it", chose_true, moved);
  TEST_EQUAL("and every other match keeps its only one", chose_other, 0);
  TEST_EQUAL("no match is left out", chosen.outliers, 0);
  TEST_NEAR("the pose from the nearest hypotheses is right (mm)", position_error_mm(chosen.camera_from_model, truth),
            0, 10 * tol_mm);
  // A caller's matches may claim more alternatives than a match holds, or fewer than none: the
  // pose step reads the array only (under UBSan an index past it stops the test).
  std::vector<EdgeMatch> overclaimed = two_hypotheses, underclaimed = spoiled;
  for (size_t i = 0; i < overclaimed.size(); i += 10) {
    overclaimed[i].alternative_count = 1000;
    for (int a = 1; a < kMaxHypotheses - 1; ++a) overclaimed[i].alternatives[a] = spoiled[i].found;
    underclaimed[i].alternative_count = -3;
  }
  const PoseSolution over = solve_pose(overclaimed, camera, start, params);
  TEST_NEAR("a count over the array's reads the alternatives it holds (mm)",
            position_error_mm(over.camera_from_model, chosen.camera_from_model), 0, 10 * tol_mm);
  const PoseSolution under = solve_pose(underclaimed, camera, start, params);
  TEST_NEAR("a negative count is none (mm)", position_error_mm(under.camera_from_model, robust.camera_from_model), 0,
            tol_mm);
  underclaimed[0].chosen = 7;
  TEST("and a chosen hypothesis it does not hold is its strongest edge", &underclaimed[0].used() == &underclaimed[0].found,
       true);
  PoseParams plain = params;
  plain.tukey_c = real(0);
  std::vector<EdgeMatch> spoiled_again = spoiled;
  const PoseSolution paper = solve_pose(spoiled_again, camera, start, plain);
  std::printf("camera position error with 10 %% outliers: plain solve %.4f mm, robust %.4f mm\n",
              position_error_mm(paper.camera_from_model, truth), position_error_mm(robust.camera_from_model, truth));
  TEST("the paper's plain solve is pulled off by the outliers (more than 0.1 mm)",
       position_error_mm(paper.camera_from_model, truth) > 0.1, true);

  std::vector<EdgeMatch> few(matches.begin(), matches.begin() + 5);
  const PoseSolution none = solve_pose(few, camera, start, params);
  TEST("five matches are too few: nothing is solved", none.solved, false);
  TEST_NEAR("and the start pose is kept", position_error_mm(none.camera_from_model, start), 0, 1e-9);
}

TESTMAIN(test_pose_solver)
