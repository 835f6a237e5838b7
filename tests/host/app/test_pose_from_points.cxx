// SPDX-License-Identifier: BSD-3-Clause
// Initialisation from points: the 4 points of ViSP's mbt/cube.init, projected with cube.0.pos,
// give back that pose (exactly without noise, within a few millimetres with 0.5 px of noise);
// points in one plane and too few points are refused.
#include <cmath>

#include "configuration.h"
#include "edgetrack/pose_io.h"
#include "pose_from_points.h"
#include "testlib/testlib_test.h"

using namespace edgetrack_app;
using edgetrack::PinholeCamera;
using edgetrack::Se3;
using edgetrack::Vec2;
using edgetrack::Vec3;

static double distance_mm(const Se3& a, const Se3& b) {
  const Vec3 d = a.translation() - b.translation();
  return 1000 * static_cast<double>(edgetrack::norm(d));
}

static double angle_deg(const Se3& a, const Se3& b) {
  return static_cast<double>(edgetrack::norm(edgetrack::rotation_log(a.rotation() * b.rotation().transpose()))) * 57.29578;
}

static void test_pose_from_points() {
  const std::string mbt = std::string(EDGETRACK_VISP_IMAGES) + "/mbt";
  auto points = read_init_points(mbt + "/cube.init");
  TEST("cube.init reads", points.ok(), true);
  auto truth = edgetrack::read_pos(mbt + "/cube.0.pos");
  auto camera = edgetrack_app::read_camera(mbt + "/cube.xml", 640, 480);
  if (!points.ok() || !truth.ok() || !camera.ok()) return;
  TEST_EQUAL("cube.init has 4 points", points.value().size(), size_t(4));
  std::vector<Vec2> pixels;
  for (const Vec3& p : points.value()) pixels.push_back(camera.value().project(truth.value() * p));
  auto exact = pose_from_points(points.value(), pixels, camera.value(), "clicks");
  TEST("a pose is found from exact points", exact.ok(), true);
  if (exact.ok()) {
    TEST_NEAR("exact points: translation within 0.05 mm", distance_mm(exact.value().camera_from_model, truth.value()), 0, 0.05);
    TEST_NEAR("exact points: rotation within 0.01 deg", angle_deg(exact.value().camera_from_model, truth.value()), 0, 0.01);
    TEST_NEAR("exact points: reprojection error below 0.01 px", exact.value().rms_px, 0, 0.01);
  }
  const double noise[4][2] = {{0.5, -0.3}, {-0.4, 0.5}, {0.2, 0.4}, {-0.5, -0.2}};
  std::vector<Vec2> clicked = pixels;
  for (int i = 0; i < 4; ++i) clicked[i] = clicked[i] + Vec2{real(noise[i][0]), real(noise[i][1])};
  auto noisy = pose_from_points(points.value(), clicked, camera.value(), "clicks");
  TEST("a pose is found from clicked points", noisy.ok(), true);
  if (noisy.ok()) {
    TEST_NEAR("clicked points (0.5 px): translation within 5 mm", distance_mm(noisy.value().camera_from_model, truth.value()), 0, 5);
    TEST_NEAR("clicked points: rotation within 2 deg", angle_deg(noisy.value().camera_from_model, truth.value()), 0, 2);
  }
  std::vector<Vec3> flat = {{real(0), real(0), real(0)}, {real(0.05), real(0), real(0)}, {real(0), real(0.05), real(0)},
                            {real(0.05), real(0.05), real(0)}};
  auto planar = pose_from_points(flat, pixels, camera.value(), "clicks");
  TEST("points in one plane are refused", planar.ok(), false);
  TEST("the message says why", planar.error().message.find("one plane") != std::string::npos, true);
  std::vector<Vec2> three(pixels.begin(), pixels.begin() + 3);
  TEST("a count mismatch is refused", pose_from_points(points.value(), three, camera.value(), "clicks").ok(), false);
}

TESTMAIN(test_pose_from_points)
