// SPDX-License-Identifier: BSD-3-Clause
/// The tracker's testlib driver: `tracker_test_all <test>` runs one test.
#include "testlib/testlib_register.h"

DECLARE(test_se3);
DECLARE(test_model_io);
DECLARE(test_camera_and_pos);
DECLARE(test_edge_id);
DECLARE(test_edge_id_buffer);
DECLARE(test_control_points);
DECLARE(test_scene_renderer);
DECLARE(test_scene_extras);
DECLARE(test_pose_solver);
DECLARE(test_status_rule);
DECLARE(test_motion_model);
DECLARE(test_cao_format);
DECLARE(test_contours);
DECLARE(test_rolling_shutter);
DECLARE(test_row_times_match_indices);
DECLARE(test_input_checks);
DECLARE(test_face_visibility);
DECLARE(test_cylinder_windows);
DECLARE(test_line_in_triangle);
DECLARE(test_detector_core);
DECLARE(test_template_files);
DECLARE(test_order_statistic);
DECLARE(test_xml_document);
DECLARE(test_template_bounds);
DECLARE(test_status_statistics);
DECLARE(test_edge_support);
DECLARE(test_pose_files);
DECLARE(test_lens);
DECLARE(test_lens_chord_pieces);
DECLARE(test_camera_file);
DECLARE(test_model_text);
DECLARE(test_netpbm_header);

void register_tests() {
  REGISTER(test_se3);
  REGISTER(test_model_io);
  REGISTER(test_camera_and_pos);
  REGISTER(test_edge_id);
  REGISTER(test_edge_id_buffer);
  REGISTER(test_control_points);
  REGISTER(test_scene_renderer);
  REGISTER(test_scene_extras);
  REGISTER(test_pose_solver);
  REGISTER(test_status_rule);
  REGISTER(test_motion_model);
  REGISTER(test_cao_format);
  REGISTER(test_contours);
  REGISTER(test_rolling_shutter);
  REGISTER(test_row_times_match_indices);
  REGISTER(test_input_checks);
  REGISTER(test_face_visibility);
  REGISTER(test_cylinder_windows);
  REGISTER(test_line_in_triangle);
  REGISTER(test_detector_core);
  REGISTER(test_template_files);
  REGISTER(test_order_statistic);
  REGISTER(test_xml_document);
  REGISTER(test_template_bounds);
  REGISTER(test_status_statistics);
  REGISTER(test_edge_support);
  REGISTER(test_pose_files);
  REGISTER(test_lens);
  REGISTER(test_lens_chord_pieces);
  REGISTER(test_camera_file);
  REGISTER(test_model_text);
  REGISTER(test_netpbm_header);
}

DEFINE_MAIN
