// SPDX-License-Identifier: BSD-3-Clause
/// Control point sampling: n = length / step points per edge (equation (1)), evenly spaced,
/// lying on the projected edge and on the 3D edge, none within the border margin.
#include <cmath>
#include <string>

#include "edgetrack/control_points.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

static void test_control_points() {
  const double tol = std::string(real_name()) == "s47_16" ? 2e-3 : 1e-6;
  const PinholeCamera camera{real(300), real(300), real(160), real(120), 320, 240};
  // One free edge, 100 mm long, slanted in depth: from (-50, 0, 150) mm to (50, 0, 250) mm.
  Polygons line;
  line.vertices = {{real(-0.05), real(0), real(0.15)}, {real(0.05), real(0), real(0.25)}};
  line.lines = {{0, 1}};
  const Result<EdgeModel> built = build_edge_model(line, EdgeRules{}, "line");
  TEST("a one-line model builds", built.ok(), true);
  if (!built.ok()) return;
  const EdgeModel& model = built.value();
  const Se3 identity;
  // Projected from u = 160 - 100 = 60 to u = 160 + 60 = 220: 160 pixels long.
  SamplingParams params;
  std::vector<ControlPoint> points = sample_control_points(model, camera, identity, params);
  TEST_EQUAL("a 160 pixel edge with step 10 gets 16 points", points.size(), size_t(16));
  if (points.size() == 16) {
    TEST_NEAR("the first point is half a step from the start", points[0].pixel.x, 65.0, tol * 100);
    TEST_NEAR("points are one step apart", points[1].pixel.x - points[0].pixel.x, 10.0, tol * 100);
    TEST_NEAR("the normal is perpendicular to the edge", dot(points[3].normal, points[3].direction), 0.0, tol);
    double worst = 0;
    for (const ControlPoint& p : points) {
      const Vec2 reprojected = camera.project(p.point_in_model);
      worst = std::fmax(worst, std::fabs(static_cast<double>(reprojected.x - p.pixel.x)));
      worst = std::fmax(worst, std::fabs(static_cast<double>(p.point_in_model.y)));
    }
    TEST_NEAR("each 3D point projects onto its pixel (perspective-correct lifting)", worst, 0.0, tol * 1000);
    TEST("the 3D points are not evenly spaced in depth: the far half is sparser in 3D",
         points[1].point_in_model.x - points[0].point_in_model.x <
             points[15].point_in_model.x - points[14].point_in_model.x,
         true);
  }
  params.step = real(7);
  TEST_EQUAL("with step 7 the same edge gets floor(160 / 7) = 22 points",
             sample_control_points(model, camera, identity, params).size(), size_t(22));
  params.step = real(10);
  params.border = 70;  // drops u < 70 and u > 249: the points at 65
  points = sample_control_points(model, camera, identity, params);
  bool inside = true;
  for (const ControlPoint& p : points) inside &= p.pixel.x >= real(70) && p.pixel.x <= real(249);
  TEST_EQUAL("a 70 pixel border drops the one point at u = 65", points.size(), size_t(15));
  TEST("no point lies within the border", inside, true);
  // An edge shorter than one step gets no point (n = 0).
  line.vertices[1] = {real(-0.047), real(0), real(0.15)};
  const Result<EdgeModel> short_edge = build_edge_model(line, EdgeRules{}, "short");
  TEST("an edge of 6 pixels gets no control point",
       short_edge.ok() && sample_control_points(short_edge.value(), camera, identity, SamplingParams{}).empty(), true);
}

TESTMAIN(test_control_points)
