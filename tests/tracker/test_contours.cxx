// SPDX-License-Identifier: BSD-3-Clause
/// Cylinders and circles at a pose: the silhouette generator lines are tangent to the side
/// (checked against the analytic case), sampled where the limbs project, and a cylinder in
/// front of a cube hides the cube's edges behind it in Edge-ID; circles are sampled evenly on
/// their projected ellipse with its normal, and faces hide them.
#include <cmath>
#include <cstdio>

#include "edgetrack/contours.h"
#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

const PinholeCamera kCamera{real(220), real(220), real(160), real(120), 320, 240};

/// A 60 mm cube centred at (0, 0, 0.2), seen from the origin, plus, when asked, a cylinder of
/// radius 10 mm standing along y at (0, 0, 0.12), in front of the cube, and circles.
Polygons cube_scene(bool with_cylinder) {
  Polygons p;
  const real h = real(0.03), z = real(0.2);
  for (int k = 0; k < 8; ++k)
    p.vertices.push_back({(k & 1) ? h : -h, (k & 2) ? h : -h, z + ((k & 4) ? h : -h)});
  // Counter-clockwise seen from outside.
  p.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  if (with_cylinder) {
    p.vertices.push_back({real(0), real(-0.05), real(0.12)});
    p.vertices.push_back({real(0), real(0.05), real(0.12)});
    CylinderRecord c;
    c.axis_a = 8;
    c.axis_b = 9;
    c.radius = real(0.01);
    p.cylinders.push_back(c);
  }
  return p;
}

/// Circles of radius 15 mm centred on the cube's front face (z = 0.17) and on its back face.
void add_face_circles(Polygons& p) {
  const int base = static_cast<int>(p.vertices.size());
  for (const real z : {real(0.17), real(0.23)}) {
    p.vertices.push_back({real(0), real(0), z});
    p.vertices.push_back({real(0.01), real(0), z});
    p.vertices.push_back({real(0), real(0.01), z});
  }
  for (int k = 0; k < 2; ++k) {
    CircleRecord c;
    c.centre = base + 3 * k;
    c.plane_a = base + 3 * k + 1;
    c.plane_b = base + 3 * k + 2;
    c.radius = real(0.015);
    p.circles.push_back(c);
  }
}

void test_generators_analytic() {
  // Axis along z through the origin, r = 20 mm, camera centre at D = 100 mm on x: the planes
  // through the camera touch the side at x = r^2 / D, y = +-r sqrt(1 - r^2 / D^2).
  Cylinder c;
  c.axis_a = {real(0), real(0), real(-0.05)};
  c.axis_b = {real(0), real(0), real(0.05)};
  c.radius = real(0.02);
  const Vec3 camera{real(0.1), real(0), real(0)};
  Vec3 lines[2][2];
  TEST("a camera outside the cylinder sees two generators", cylinder_generators(c, camera, lines), true);
  const double x = 0.02 * 0.02 / 0.1, y = 0.02 * std::sqrt(1 - 0.04);
  for (int k = 0; k < 2; ++k) {
    TEST_NEAR("the generator touches the rim at x = r^2/D", lines[k][0].x, x, 1e-6);
    TEST_NEAR("at |y| = r sqrt(1 - r^2/D^2)", std::fabs(double(lines[k][0].y)), y, 1e-6);
    TEST_NEAR("it runs from one axis end", lines[k][0].z, -0.05, 1e-6);
    TEST_NEAR("to the other", lines[k][1].z, 0.05, 1e-6);
    // Tangency: the radius at the touching point is perpendicular to the viewing ray.
    const Vec3 radial{lines[k][0].x, lines[k][0].y, real(0)};
    TEST_NEAR("the viewing ray is perpendicular to the radius there (tangent)",
              dot(radial, lines[k][0] - camera), 0, 1e-8);
  }
  TEST("the two generators lie on opposite sides", double(lines[0][0].y) * double(lines[1][0].y) < 0, true);
  TEST("a camera inside the cylinder sees no silhouette",
       cylinder_generators(c, Vec3{real(0.01), real(0), real(0)}, lines), false);
}

void test_silhouettes_sampled_where_limbs_project() {
  // The scene's cylinder seen from the origin: its limbs project to u = u0 +- px r / sqrt(Z^2 - r^2).
  const Result<EdgeModel> model = build_edge_model(cube_scene(true), EdgeRules{}, "scene");
  TEST("the cube and cylinder scene builds", model.ok(), true);
  if (!model.ok()) return;
  const std::vector<ControlPoint> points = sample_control_points(model.value(), kCamera, Se3(), SamplingParams{});
  const double limb = 220 * 0.01 / std::sqrt(0.12 * 0.12 - 0.01 * 0.01);
  int on_limbs[2] = {0, 0}, off = 0;
  for (const ControlPoint& p : points) {
    const int side = p.edge - cylinder_primitive(model.value(), 0, 0);
    if (side < 0 || side > 1) continue;
    const double u = double(p.pixel.x) - 160;
    ++on_limbs[side];
    off += std::fabs(std::fabs(u) - limb) > 1e-3 || std::fabs(double(p.normal.x)) < 0.999999;
  }
  std::printf("silhouette points: %d and %d, limbs at +-%.3f px\n", on_limbs[0], on_limbs[1], limb);
  TEST("both silhouettes are sampled every 10 px over their 0.1 m (about 180 px)",
       on_limbs[0] >= 15 && on_limbs[1] >= 15, true);
  TEST_EQUAL("every silhouette point sits on the analytic limb, with the normal across it", off, 0);
}

void test_cylinder_hides_cube() {
  const Result<EdgeModel> cube = build_edge_model(cube_scene(false), EdgeRules{}, "cube");
  const Result<EdgeModel> both = build_edge_model(cube_scene(true), EdgeRules{}, "both");
  if (!cube.ok() || !both.ok()) return;
  EdgeIdBuffer cube_ids(kCamera), both_ids(kCamera);
  cube_ids.render(cube.value(), Se3());
  both_ids.render(both.value(), Se3());
  const std::vector<ControlPoint> points = sample_control_points(both.value(), kCamera, Se3(), SamplingParams{});
  const double limb = 220 * 0.01 / std::sqrt(0.12 * 0.12 - 0.01 * 0.01);
  int behind = 0, behind_shown = 0, beside = 0, beside_changed = 0, silhouettes = 0, silhouettes_shown = 0;
  for (const ControlPoint& p : points) {
    const bool shown = both_ids.shows(p.edge, p.pixel, p.direction);
    if (p.edge >= static_cast<int>(both.value().edges.size())) {
      ++silhouettes;
      silhouettes_shown += shown;
      continue;
    }
    const double u = std::fabs(double(p.pixel.x) - 160);
    if (u < limb - 2) {
      ++behind;
      behind_shown += shown;
    } else if (u > limb + 2) {
      ++beside;
      beside_changed += shown != cube_ids.shows(p.edge, p.pixel, p.direction);
    }
  }
  std::printf("cube points behind the cylinder: %d (%d shown), beside it: %d, silhouette points %d (%d shown)\n",
              behind, behind_shown, beside, silhouettes, silhouettes_shown);
  TEST("some cube edges cross behind the cylinder", behind >= 4, true);
  TEST_EQUAL("the cylinder hides every cube point behind it", behind_shown, 0);
  TEST_EQUAL("cube points clear of the cylinder are shown as without it", beside_changed, 0);
  TEST_EQUAL("the cylinder's own side never hides its silhouettes", silhouettes_shown, silhouettes);
}

void test_circles() {
  Polygons scene = cube_scene(false);
  add_face_circles(scene);
  const Result<EdgeModel> model = build_edge_model(scene, EdgeRules{}, "circles");
  TEST("the cube with two circles builds", model.ok(), true);
  if (!model.ok()) return;
  const EdgeModel& m = model.value();
  const std::vector<ControlPoint> points = sample_control_points(m, kCamera, Se3(), SamplingParams{});
  EdgeIdBuffer ids(kCamera);
  ids.render(m, Se3());
  // The front circle faces the camera on its axis: its image is a circle of f r / Z = 19.41 px.
  const double radius_px = 220 * 0.015 / 0.17;
  int front = 0, front_shown = 0, back = 0, back_shown = 0;
  double worst_px = 0, worst_cos = 1, worst_m = 0;
  for (const ControlPoint& p : points) {
    const bool shown = ids.shows(p.edge, p.pixel, p.direction);
    if (p.edge == circle_primitive(m, 0)) {
      ++front;
      front_shown += shown;
      const double dx = double(p.pixel.x) - 160, dy = double(p.pixel.y) - 120, d = std::sqrt(dx * dx + dy * dy);
      const double radial = std::fabs((dx * double(p.normal.x) + dy * double(p.normal.y)) / d);
      const Vec3 from_centre = p.point_in_model - m.circles[0].centre;
      worst_px = std::fmax(worst_px, std::fabs(d - radius_px));
      worst_cos = std::fmin(worst_cos, radial);
      worst_m = std::fmax(worst_m, std::fabs(double(norm(from_centre)) - 0.015));
    } else if (p.edge == circle_primitive(m, 1)) {
      ++back;
      back_shown += shown;
    }
  }
  std::printf("front circle: %d points (%d shown), back circle: %d (%d shown)\n", front, front_shown, back, back_shown);
  TEST_EQUAL("the front circle is sampled every 10 px: floor(2 pi 19.41 / 10) points", front,
             static_cast<int>(2 * 3.14159265358979 * radius_px / 10));
  // Tolerances: the fixed-point builds round unit vectors and products at about 1e-6.
  std::printf("largest deviations: %.2g px from the image circle, %.2g m from the 3D circle, normal cosine %.8f\n",
              worst_px, worst_m, worst_cos);
  TEST_NEAR("each point lies on the image circle (px)", worst_px, 0, 1e-3);
  TEST_NEAR("and on the 3D circle (m)", worst_m, 0, 1e-5);
  TEST_NEAR("with the ellipse's normal, here radial (cosine)", worst_cos, 1, 1e-6);
  TEST_EQUAL("the circle on the front face is visible", front_shown, front);
  TEST("the circle on the back face is sampled", back > 0, true);
  TEST_EQUAL("and hidden by the cube's faces", back_shown, 0);
}

void test_cap_circles() {
  // A cylinder standing along y, 60 mm long, r = 20 mm, 150 mm in front of the camera, with a
  // circle closing each end. The camera is level with its middle, so both caps face away: the
  // near half of each rim (z < 0.15) is in view, the far half lies behind the side.
  Polygons p;
  p.vertices = {{real(0), real(-0.03), real(0.15)}, {real(0), real(0.03), real(0.15)},
                {real(0.02), real(-0.03), real(0.15)}, {real(0), real(-0.03), real(0.17)},
                {real(0.02), real(0.03), real(0.15)}, {real(0), real(0.03), real(0.17)}};
  CylinderRecord c;
  c.axis_a = 0;
  c.axis_b = 1;
  c.radius = real(0.02);
  p.cylinders.push_back(c);
  for (int k = 0; k < 2; ++k) {
    CircleRecord circle;
    circle.centre = k;
    circle.plane_a = 2 + 2 * k;
    circle.plane_b = 3 + 2 * k;
    circle.radius = real(0.02);
    p.circles.push_back(circle);
  }
  const Result<EdgeModel> model = build_edge_model(p, EdgeRules{}, "caps");
  TEST("the capped cylinder builds", model.ok(), true);
  if (!model.ok()) return;
  TEST("both circles are found to close the cylinder", model.value().circles[0].cap_of == 0 &&
                                                             model.value().circles[1].cap_of == 0,
       true);
  EdgeIdBuffer ids(kCamera);
  ids.render(model.value(), Se3());
  int near = 0, near_shown = 0, far = 0, far_shown = 0;
  for (const ControlPoint& point : sample_control_points(model.value(), kCamera, Se3(), SamplingParams{})) {
    if (point.edge < circle_primitive(model.value(), 0)) continue;
    const bool shown = ids.shows(point.edge, point.pixel, point.direction);
    const double z = double(point.point_in_model.z);
    if (z < 0.15 - 0.005) {
      ++near;
      near_shown += shown;
    } else if (z > 0.15 + 0.005) {
      ++far;
      far_shown += shown;
    }
  }
  std::printf("cap rims: near halves %d points (%d shown), far halves %d (%d shown)\n", near, near_shown, far,
              far_shown);
  TEST("the near halves are sampled", near >= 6, true);
  TEST_EQUAL("and shown: the cylinder's own side does not hide them", near_shown, near);
  TEST("the far halves are sampled", far >= 4, true);
  TEST_EQUAL("and hidden by the side in front of them", far_shown, 0);
}

}  // namespace

static void test_contours() {
  test_generators_analytic();
  test_silhouettes_sampled_where_limbs_project();
  test_cylinder_hides_cube();
  test_circles();
  test_cap_circles();
}

TESTMAIN(test_contours)
