// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's face rules: a face turning edge-on disappears past angle_disappear and comes back under
/// angle_appear (hysteresis), an edge is tracked while one of its faces is visible, edges are
/// clipped to [near, far] and to the field of view before sampling, and level of detail drops
/// small faces and short free lines.
#include <cmath>
#include <string>

#include "edgetrack/control_points.h"
#include "edgetrack/face_visibility.h"
#include "edgetrack/model_io.h"
#include "face_angle.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

const double kPi = 3.14159265358979323846;

Se3 turned_about_y(double degrees, double distance) {
  const double a = degrees * kPi / 180;
  Mat33 r = Mat33::identity();
  r.m[0][0] = real(std::cos(a));
  r.m[0][2] = real(std::sin(a));
  r.m[2][0] = real(-std::sin(a));
  r.m[2][2] = real(std::cos(a));
  return Se3(r, {real(0), real(0), real(distance)});
}

void hysteresis(const EdgeModel& model, const PinholeCamera& camera) {
  FaceVisibilityParams params;
  params.angle_appear = real(65 * kPi / 180);
  params.angle_disappear = real(75 * kPi / 180);
  FaceVisibility faces(model);
  const int front = 0;  // z-: faces the camera at 0 degrees
  bool expected = false;
  int mismatches = 0, near_limit = 0;
  double disappeared_at = -1, reappeared_at = -1;
  // Turning 0 -> 88 -> 0 degrees in 0.5 degree steps.
  for (int k = 0; k <= 352; ++k) {
    const double turn = k <= 176 ? k * 0.5 : (352 - k) * 0.5;
    const Se3 pose = turned_about_y(turn, 0.15);
    faces.update(model, camera, pose, params);
    const double angle = edgetrack_test::face_angle_degrees(model, front, pose);
    const bool was = expected;
    expected = was ? angle < 75 : angle < 65;
    if (std::fabs(angle - 75) < 0.05 || std::fabs(angle - 65) < 0.05) {
      ++near_limit;  // on the limit itself rounding may decide either way
      expected = faces.face_visible(front);
    }
    if (faces.face_visible(front) != expected) ++mismatches;
    if (was && !expected && disappeared_at < 0) disappeared_at = angle;
    if (!was && expected && k > 176 && reappeared_at < 0) reappeared_at = angle;
    for (size_t e = 0; e < model.edges.size(); ++e) {
      const Edge& edge = model.edges[e];
      const bool any = (edge.faces[0] >= 0 && faces.face_visible(edge.faces[0])) ||
                       (edge.faces[1] >= 0 && faces.face_visible(edge.faces[1]));
      if (faces.edge_tracked(static_cast<int>(e)) != any) ++mismatches;
    }
  }
  TEST_EQUAL("the face follows the appear/disappear rule and each edge its faces", mismatches, 0);
  TEST("the limits are met at most twice", near_limit <= 4, true);
  TEST_NEAR("the turning face disappears at angle_disappear (75 degrees)", disappeared_at, 75, 0.6);
  TEST_NEAR("and reappears at angle_appear (65 degrees) on the way back", reappeared_at, 65, 0.6);

  FaceVisibility fresh(model);
  fresh.update(model, camera, turned_about_y(70, 0.15), params);
  TEST("a face first seen at 70 degrees is hidden: every face starts hidden (angle_appear applies)",
       fresh.face_visible(front), false);
  const FaceVisibilityParams defaults;
  fresh.update(model, camera, turned_about_y(70, 0.15), defaults);
  TEST("with ViSP's default 89 degrees it is visible", fresh.face_visible(front), true);
  fresh.update(model, camera, turned_about_y(0, 0.15), defaults);
  TEST("a back face is never visible (orientation counts, as ViSP's modulo = false)", fresh.face_visible(1), false);
}

void clipping(const EdgeModel& cube, const PinholeCamera& camera) {
  const double tol = std::string(real_name()) == "s47_16" ? 1e-3 : 1e-5;
  ViewClipping depth;
  depth.near_distance = real(0.1);
  depth.far_clipping = true;
  depth.far_distance = real(0.3);
  real t0, t1;
  const bool kept = clip_to_view({real(0), real(0), real(0.05)}, {real(0), real(0), real(0.5)}, camera, depth, t0, t1);
  TEST("a segment through both planes keeps a part", kept, true);
  TEST_NEAR("from the near plane", t0, 0.05 / 0.45, tol);
  TEST_NEAR("to the far plane", t1, 0.25 / 0.45, tol);
  TEST("a segment behind the near plane keeps nothing",
       clip_to_view({real(0), real(0), real(0.01)}, {real(0.1), real(0), real(0.09)}, camera, depth, t0, t1), false);
  ViewClipping fov;
  fov.fov_clipping = true;
  TEST("a segment across the view is cut at the image borders",
       clip_to_view({real(-10), real(0), real(1)}, {real(10), real(0), real(1)}, camera, fov, t0, t1), true);
  TEST_NEAR("at u = 0", t0, (10 - 160.0 / 220) / 20, tol);
  TEST_NEAR("at u = width", t1, (10 + 160.0 / 220) / 20, tol);
  TEST("a segment outside the view keeps nothing",
       clip_to_view({real(2), real(0), real(1)}, {real(3), real(0), real(1)}, camera, fov, t0, t1), false);

  // The cube turned 40 degrees, its centre 150 mm away: depths run from about 0.11 to 0.19 m.
  const Se3 pose = turned_about_y(40, 0.15);
  SamplingParams all, cut;
  cut.clipping.near_distance = real(0.135);
  cut.clipping.far_clipping = true;
  cut.clipping.far_distance = real(0.165);
  const auto every = sample_control_points(cube, camera, pose, all);
  const auto within = sample_control_points(cube, camera, pose, cut);
  int outside = 0;
  for (const ControlPoint& p : within) {
    const real z = (pose * p.point_in_model).z;
    if (z < real(0.135) - real(1e-4) || z > real(0.165) + real(1e-4)) ++outside;
  }
  TEST("near and far clipping leave fewer control points", within.size() < every.size() && !within.empty(), true);
  TEST_EQUAL("and none outside [near, far]", outside, 0);
}

void level_of_detail(const EdgeModel& cube, const PinholeCamera& camera) {
  // The front face, 60 mm at 120 mm with px = 220: 110 pixels wide, about 12100 square pixels.
  FaceVisibilityParams params;
  params.use_lod = true;
  params.min_polygon_area = real(12500);
  FaceVisibility faces(cube);
  faces.update(cube, camera, turned_about_y(0, 0.15), params);
  TEST("a face smaller than min_polygon_area is not visible with use_lod", faces.face_visible(0), false);
  params.min_polygon_area = real(11500);
  faces.update(cube, camera, turned_about_y(0, 0.15), params);
  TEST("one larger is", faces.face_visible(0), true);

  Polygons line;  // a free line 40 mm long at 200 mm: 44 pixels
  line.vertices = {{real(-0.02), real(0), real(0.2)}, {real(0.02), real(0), real(0.2)}};
  line.lines = {{0, 1}};
  const Result<EdgeModel> free_line = build_edge_model(line, EdgeRules{}, "line");
  if (!free_line.ok()) return;
  FaceVisibility lines(free_line.value());
  FaceVisibilityParams lod;
  lines.update(free_line.value(), camera, Se3(), lod);
  TEST("a free line is tracked without level of detail", lines.edge_tracked(0), true);
  lod.use_lod = true;
  lod.min_line_length = real(50);
  lines.update(free_line.value(), camera, Se3(), lod);
  TEST("a 44 pixel free line is not tracked with min_line_length 50", lines.edge_tracked(0), false);
  lod.min_line_length = real(40);
  lines.update(free_line.value(), camera, Se3(), lod);
  TEST("it is with 40", lines.edge_tracked(0), true);
  std::vector<ControlPoint> points;
  sample_control_points(free_line.value(), camera, Se3(), SamplingParams{}, lines, points);
  TEST("the tracked line is sampled", points.empty(), false);
  lod.min_line_length = real(50);
  lines.update(free_line.value(), camera, Se3(), lod);
  sample_control_points(free_line.value(), camera, Se3(), SamplingParams{}, lines, points);
  TEST("an untracked edge is not sampled", points.empty(), true);

  // A primitive's own .cao parameters override the general setting, in both directions.
  EdgeModel own_face = cube;
  own_face.faces[0].attributes.use_lod = true;
  own_face.faces[0].attributes.min_polygon_area = real(12500);
  FaceVisibility by_face(own_face);
  by_face.update(own_face, camera, turned_about_y(0, 0.15), FaceVisibilityParams{});
  TEST("a face's useLod=1 minPolygonAreaThreshold=12500 hides it without the general use_lod",
       by_face.face_visible(0), false);
  own_face.faces[0].attributes.use_lod = false;
  params.min_polygon_area = real(100000);
  by_face.update(own_face, camera, turned_about_y(0, 0.15), params);
  TEST("a face's useLod=0 keeps it under the general use_lod", by_face.face_visible(0), true);
  own_face.faces[0].attributes.use_lod.reset();
  by_face.update(own_face, camera, turned_about_y(0, 0.15), params);
  TEST("its own threshold 12500 replaces the general 100000 (the face stays hidden, 12100 < 12500)",
       by_face.face_visible(0), false);
  own_face.faces[0].attributes.min_polygon_area = real(11500);
  by_face.update(own_face, camera, turned_about_y(0, 0.15), params);
  TEST("and 11500 shows it", by_face.face_visible(0), true);

  EdgeModel own_line = free_line.value();
  own_line.edges[0].attributes.use_lod = true;
  own_line.edges[0].attributes.min_line_length = real(50);
  FaceVisibility by_line(own_line);
  by_line.update(own_line, camera, Se3(), FaceVisibilityParams{});
  TEST("a line's useLod=1 minLineLengthThreshold=50 drops the 44 pixel line", by_line.edge_tracked(0), false);
  own_line.edges[0].attributes.min_line_length = real(40);
  by_line.update(own_line, camera, Se3(), FaceVisibilityParams{});
  TEST("its threshold 40 keeps it", by_line.edge_tracked(0), true);
}

}  // namespace

static void test_face_visibility() {
  const PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  const Result<EdgeModel> cube = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("cube60.cao loads", cube.ok(), true);
  if (!cube.ok()) return;
  hysteresis(cube.value(), camera);
  clipping(cube.value(), camera);
  level_of_detail(cube.value(), camera);
}

TESTMAIN(test_face_visibility)
