// SPDX-License-Identifier: BSD-3-Clause
/// The image's support of a pose along its projected edges (edge_support.h): the angle between
/// gradient and normal without a libm arctangent, full support and a small angle on the edge,
/// none over flat image beside it, and a gradient across the normal measured but not supporting.
#include <algorithm>
#include <cmath>
#include <vector>

#include "edgetrack/angles.h"
#include "edgetrack/edge_support.h"
#include "edgetrack/me_search_box.h"
#include "edgetrack/moving_edges.h"
#include "edgetrack/tracker_params.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

constexpr int kSide = 100;
const PinholeCamera kCamera(real(100), real(100), real(50), real(50), kSide, kSide);

/// A grey image of `dark` left of the line through (50, 50) at `tilt_deg` from the vertical and
/// `bright` right of it.
vpImage<unsigned char> step_image(double tilt_deg, int dark, int bright) {
  vpImage<unsigned char> image(kSide, kSide);
  const double c = std::cos(tilt_deg * kRadiansPerDegree), s = std::sin(tilt_deg * kRadiansPerDegree);
  for (int r = 0; r < kSide; ++r)
    for (int col = 0; col < kSide; ++col) {
      const double across = c * (col - 50 + 0.5) + s * (r - 50);  // the edge between columns 49 and 50 at 0 tilt
      image[r][col] = static_cast<unsigned char>(across < 0 ? dark : bright);
    }
  return image;
}

/// Control points on the vertical line x = 49.5 at depth 1, every 5 rows, their normal +x turned
/// by `normal_deg`.
std::vector<ControlPoint> vertical_points(double normal_deg = 0) {
  std::vector<ControlPoint> points;
  for (int r = 20; r <= 80; r += 5) {
    ControlPoint p;
    p.pixel = Vec2{real(49.5), real(r)};
    p.point_in_model = kCamera.unproject(p.pixel, real(1));
    p.direction = Vec2{real(0), real(1)};
    p.normal = Vec2{real(std::cos(normal_deg * kRadiansPerDegree)), real(std::sin(normal_deg * kRadiansPerDegree))};
    points.push_back(p);
  }
  return points;
}

void test_angle() {
  double worst = 0;
  for (int k = 0; k < 360; k += 7) {
    const double a = (k + 0.3) * kRadiansPerDegree;
    const real gx = real(100 * std::cos(a)), gy = real(100 * std::sin(a));
    for (double normal_deg : {0.0, 33.0, 90.0, 147.0}) {
      const double n = normal_deg * kRadiansPerDegree;
      const Vec2 normal{real(std::cos(n)), real(std::sin(n))};
      double expected = std::fabs(std::remainder(a - n, kPi)) / kRadiansPerDegree;  // folded into [0, 90]
      worst = std::fmax(worst, std::fabs(static_cast<double>(gradient_normal_angle_deg(gx, gy, normal)) - expected));
    }
  }
  TEST("the angle between gradient and normal is within 0.1 degree of the arctangent's", worst < 0.1, true);
  TEST_NEAR("a gradient along the normal is at 0 degrees",
            gradient_normal_angle_deg(real(-40), real(0), Vec2{real(1), real(0)}), 0.0, 1e-3);
  TEST_NEAR("one across it at 90", gradient_normal_angle_deg(real(0), real(40), Vec2{real(1), real(0)}), 90.0, 1e-3);
  TEST_NEAR("no gradient at 0", gradient_normal_angle_deg(real(0), real(0), Vec2{real(1), real(0)}), 0.0, 1e-9);
}

/// Through a lens, the projections the frame's status makes once (project_points) give
/// edge_support's own verdict; points behind the camera are marked so and not measured.
void test_shared_projections(const vpImage<unsigned char>& edge, const std::vector<ControlPoint>& points,
                             const std::vector<PixelBox>& boxes, const real& floor, const real& angle) {
  LensDistortion lens;
  lens.model = LensModel::kVisp;
  lens.kud = real(-0.25);
  const PinholeCamera camera(real(100), real(100), real(50), real(50), kSide, kSide, lens);
  int measured = 0;
  for (const double shift : {0.0, 0.004, 0.03}) {
    const Se3 pose(Mat33::identity(), Vec3{real(shift), real(0), real(0)});
    ProjectedPoints projected;
    project_points(points, camera, pose, projected);
    const EdgeSupport own = edge_support(edge, points, boxes, camera, pose, floor, support_bound(angle));
    const EdgeSupport shared = edge_support(edge, points, boxes, camera, pose, floor, support_bound(angle), &projected);
    TEST("projections given: the same points measured and supported",
         own.measured == shared.measured && own.supported == shared.supported, true);
    TEST("at the same mean angle", own.mean_angle_deg == shared.mean_angle_deg, true);
    measured += own.measured;
  }
  TEST("points were measured", measured > 0, true);
  const Se3 behind(Mat33::identity(), Vec3{real(0), real(0), real(-2)});
  ProjectedPoints projected;
  project_points(points, camera, behind, projected);
  TEST("behind the camera no point is in front", std::count(projected.in_front.begin(), projected.in_front.end(), 1), 0);
  TEST_EQUAL("nor measured",
             edge_support(edge, points, boxes, camera, behind, floor, support_bound(angle), &projected).measured, 0);
}

}  // namespace

static void test_edge_support() {
  test_angle();
  const vpMe me = moving_edge_masks(MovingEdgeParams{});
  const std::vector<ControlPoint> points = vertical_points();
  const real floor(40), angle(30);
  const unsigned range = 4;
  std::vector<PixelBox> boxes;
  for (const ControlPoint& point : points) boxes.push_back(me_search_box(point, me, range));
  // A 30-level step: Sobel 120 across it.
  const vpImage<unsigned char> edge = step_image(0, 80, 110);
  const EdgeSupport on = edge_support(edge, points, boxes, kCamera, Se3(), floor, support_bound(angle));
  TEST_EQUAL("every point looked at", on.visible, static_cast<int>(points.size()));
  TEST_EQUAL("the pose on the edge: every point supported", on.supported, on.visible);
  TEST("at a small angle", on.mean_angle_deg < real(1), true);
  // The same pose 3 px right of the edge (within the range searched): flat image.
  const Se3 beside(Mat33::identity(), Vec3{real(0.03), real(0), real(0)});
  const EdgeSupport off = edge_support(edge, points, boxes, kCamera, beside, floor, support_bound(angle));
  TEST_EQUAL("3 px beside the edge over flat image nothing is measured", off.measured, 0);
  TEST_EQUAL("nor supported", off.supported, 0);
  // Beyond the range searched the grey image is not the frame's: not read.
  const Se3 far(Mat33::identity(), Vec3{real(-0.2), real(0), real(0)});
  TEST_EQUAL("beyond the range searched nothing is read",
             edge_support(edge, points, boxes, kCamera, far, floor, support_bound(angle)).measured, 0);
  test_shared_projections(edge, points, boxes, floor, angle);
  // A weak step (5 levels, Sobel 20) is under the floor.
  TEST_EQUAL("a step under the gradient floor is not measured",
             edge_support(step_image(0, 80, 85), points, boxes, kCamera, Se3(), floor, support_bound(angle)).measured, 0);
  // An edge turned 60 degrees from the model's: measured, not supported.
  const EdgeSupport turned = edge_support(step_image(60, 80, 140), points, boxes, kCamera, Se3(), floor, support_bound(angle));
  TEST("an edge turned 60 degrees is measured", turned.measured > 0, true);
  TEST_EQUAL("but supports nothing", turned.supported, 0);
  TEST_NEAR("at about 60 degrees", turned.mean_angle_deg, 60.0, 5.0);
  // Points on the edge whose normals are turned against its gradient: supported up to the
  // support angle (the tangent test), past it not, on either side of 45 degrees.
  for (const double turn : {29.0, 31.0, 55.0, 65.0}) {
    const std::vector<ControlPoint> turned_points = vertical_points(turn);
    std::vector<PixelBox> turned_boxes;
    for (const ControlPoint& point : turned_points) turned_boxes.push_back(me_search_box(point, me, range));
    const real limit = turn < 45 ? angle : real(60);
    const EdgeSupport s = edge_support(edge, turned_points, turned_boxes, kCamera, Se3(), floor, support_bound(limit));
    TEST_EQUAL("normals turned from the gradient: every point measured", s.measured, s.visible);
    TEST_NEAR("at the turn", s.mean_angle_deg, turn, 0.1);
    TEST_EQUAL("supported within the support angle, none past it", s.supported, turn < static_cast<double>(limit) ? s.visible : 0);
  }
}

TESTMAIN(test_edge_support)
