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
  // One free edge, 100 mm long, slanted in depth: from (-50, 0, 150) mm to (55, 0, 250) mm.
  Polygons line;
  line.vertices = {{real(-0.05), real(0), real(0.15)}, {real(0.055), real(0), real(0.25)}};
  line.lines = {{0, 1}};
  const Result<EdgeModel> built = build_edge_model(line, EdgeRules{}, "line");
  TEST("a one-line model builds", built.ok(), true);
  if (!built.ok()) return;
  const EdgeModel& model = built.value();
  const Se3 identity;
  // Projected from u = 160 - 100 = 60 to u = 160 + 66 = 226: 166 pixels long.
  SamplingParams params;
  std::vector<ControlPoint> points = sample_control_points(model, camera, identity, params);
  TEST_EQUAL("a 166 pixel edge with step 10 gets floor(16.6) = 16 points", points.size(), size_t(16));
  if (points.size() == 16) {
    TEST_NEAR("the first point is half a part from the start", points[0].pixel.x, 60 + 166.0 / 32, tol * 100);
    TEST_NEAR("points split the edge into 16 equal parts", points[1].pixel.x - points[0].pixel.x, 166.0 / 16, tol * 100);
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
  TEST_EQUAL("with step 7 the same edge gets floor(166 / 7) = 23 points",
             sample_control_points(model, camera, identity, params).size(), size_t(23));
  params.step = real(10);
  params.border = 66;  // drops u < 66 and u > 253: the point at 65.2
  points = sample_control_points(model, camera, identity, params);
  bool inside = true;
  for (const ControlPoint& p : points) inside &= p.pixel.x >= real(66) && p.pixel.x <= real(253);
  TEST_EQUAL("a 66 pixel border drops the one point at u = 65.2", points.size(), size_t(15));
  TEST("no point lies within the border", inside, true);
  // An edge shorter than one step gets no point (n = 0).
  line.vertices[1] = {real(-0.047), real(0), real(0.15)};
  const Result<EdgeModel> short_edge = build_edge_model(line, EdgeRules{}, "short");
  TEST("an edge of 6 pixels gets no control point",
       short_edge.ok() && sample_control_points(short_edge.value(), camera, identity, SamplingParams{}).empty(), true);
}

TESTMAIN(test_control_points)
