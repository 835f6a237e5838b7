// SPDX-License-Identifier: BSD-3-Clause
/// The tracking-sequence tests' driver (they need the whole tracker, moving edges and LM).
#include "testlib/testlib_register.h"

DECLARE(test_tracking_cube);
DECLARE(test_normal_equations_keep_lmder_poses);
DECLARE(test_tracking_wood_toy);
DECLARE(test_tracking_cube_cylinder);
DECLARE(test_tracker_grey);
DECLARE(test_tracker_reset);
DECLARE(test_fast_motion_cube);
DECLARE(test_fast_motion_wood_toy);
DECLARE(test_status_noise_and_flat);
DECLARE(test_status_covered);
DECLARE(test_status_leaving_view);
DECLARE(test_visp_config);
DECLARE(test_tracker_faces);
DECLARE(test_hypotheses);
DECLARE(test_frame_layouts);
DECLARE(test_detection_cube);
DECLARE(test_detection_wood_toy);
DECLARE(test_detection_refine_from_truth);
DECLARE(test_detection_restarts);
DECLARE(test_auto_init_recovery);
DECLARE(test_detection_large_frames);
DECLARE(test_pose_uncertainty_measure);
DECLARE(test_pose_unconstrained_leaving_view);
DECLARE(test_back_and_forth);
DECLARE(test_wrong_pose);
DECLARE(test_field_conditions);
DECLARE(test_edge_contrast);
DECLARE(test_normal_mask);
DECLARE(test_api_door);
DECLARE(test_lens_tracking_cube);
DECLARE(test_lens_tracking_wood_toy);
DECLARE(test_lens_tracking_wood_toy_barrel);
DECLARE(test_android_frames);
DECLARE(test_visp_cube_poses);

void register_tests() {
  REGISTER(test_tracking_cube);
  REGISTER(test_normal_equations_keep_lmder_poses);
  REGISTER(test_tracking_wood_toy);
  REGISTER(test_tracking_cube_cylinder);
  REGISTER(test_tracker_grey);
  REGISTER(test_tracker_reset);
  REGISTER(test_fast_motion_cube);
  REGISTER(test_fast_motion_wood_toy);
  REGISTER(test_status_noise_and_flat);
  REGISTER(test_status_covered);
  REGISTER(test_status_leaving_view);
  REGISTER(test_visp_config);
  REGISTER(test_tracker_faces);
  REGISTER(test_hypotheses);
  REGISTER(test_frame_layouts);
  REGISTER(test_detection_cube);
  REGISTER(test_detection_wood_toy);
  REGISTER(test_detection_refine_from_truth);
  REGISTER(test_detection_restarts);
  REGISTER(test_auto_init_recovery);
  REGISTER(test_detection_large_frames);
  REGISTER(test_pose_uncertainty_measure);
  REGISTER(test_pose_unconstrained_leaving_view);
  REGISTER(test_back_and_forth);
  REGISTER(test_wrong_pose);
  REGISTER(test_field_conditions);
  REGISTER(test_edge_contrast);
  REGISTER(test_normal_mask);
  REGISTER(test_api_door);
  REGISTER(test_lens_tracking_cube);
  REGISTER(test_lens_tracking_wood_toy);
  REGISTER(test_lens_tracking_wood_toy_barrel);
  REGISTER(test_android_frames);
  REGISTER(test_visp_cube_poses);
}

DEFINE_MAIN
