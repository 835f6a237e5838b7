// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID fills a cylinder's back facets only inside its rims' boxes (cylinder_windows.h): from
/// poses all around the cube with its post, the inside of the open end in view included, the
/// inverse-depth buffer equals the one of every front face and every facet filled, pixel for pixel.
#include <algorithm>
#include <string>
#include <vector>

#include "edgetrack/contours.h"
#include "edgetrack/cylinder_windows.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/model_io.h"
#include "edgetrack/raster.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// The nearest surface at each pixel with every cylinder facet filled.
std::vector<int32_t> every_facet_filled(const EdgeModel& model, const PinholeCamera& camera, const Se3& pose) {
  std::vector<int32_t> depth(static_cast<size_t>(camera.width) * camera.height, 0);
  auto fill = [&](const Vec3 (&corners)[3]) {
    ScreenVertex polygon[kMaxClippedVertices];
    const int n = clip_and_project_triangle(camera, corners, polygon);
    for (int i = 1; i + 1 < n; ++i)
      fill_triangle(polygon[0], polygon[i], polygon[i + 1], camera.width, camera.height, [&](int x, int y, int32_t w) {
        int32_t& d = depth[static_cast<size_t>(y) * camera.width + x];
        d = std::max(d, w);
      });
  };
  for (const Triangle& t : model.triangles) {
    const Vec3 a = pose * model.vertices[t.a];
    if (model.closed && !(dot(pose.rotation() * model.faces[t.face].normal, a) < real(0))) continue;
    const Vec3 corners[3] = {a, pose * model.vertices[t.b], pose * model.vertices[t.c]};
    fill(corners);
  }
  for (const SurfaceTriangle& t : model.cylinder_surface) {
    const Vec3 corners[3] = {pose * t.corners[0], pose * t.corners[1], pose * t.corners[2]};
    fill(corners);
  }
  return depth;
}

}  // namespace

static void test_cylinder_windows() {
  const Result<EdgeModel> loaded = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60_cylinder.cao");
  TEST("the cube with its post loads", loaded.ok(), true);
  if (!loaded.ok()) return;
  const EdgeModel& model = loaded.value();
  const PinholeCamera camera{real(300), real(300), real(160), real(120), 320, 240};
  EdgeIdBuffer ids(camera);
  int poses = 0, same = 0, windowed = 0, narrower = 0;
  for (int k = 0; k < 48; ++k) {
    // Around the vertical axis, and tipped up to look down the post's open end (+z, last poses).
    const real yaw = real(0.27) * k, tip = k < 36 ? real(0.25) * (k % 4) : real(2.5) + real(0.05) * (k - 36);
    const Se3 pose = Se3::from_theta_u({real(0.01), real(0), real(0.2)}, {tip, yaw, real(0.1)});
    ids.render(model, pose);
    ++poses;
    const std::vector<int32_t> expected = every_facet_filled(model, camera, pose);
    std::vector<int32_t> depth;
    ids.surface_depth(depth);
    same += depth == expected;
    PixelRect boxes[2];
    if (cylinder_rim_boxes(model, 0, camera, pose, boxes)) {
      ++windowed;
      int rows = 0;
      for (const PixelRect& b : boxes) rows += std::max(0, b.y1 - b.y0 + 1);
      narrower += rows < camera.height;
    }
  }
  TEST_EQUAL("the same depth buffer at every pose", same, poses);
  TEST("the rim boxes apply at most poses (the comparison is not vacuous)", windowed >= 36, true);
  TEST("and leave rows of the facets out", narrower >= 36, true);

  // A camera on the post's axis, within its radius, sees its inside: every facet is filled.
  const Cylinder& post = model.cylinders[0];
  const Vec3 above = post.axis_b + real(4) * (post.axis_b - post.axis_a);
  const Se3 down_the_axis(Mat33::identity(), -above);
  PixelRect boxes[2];
  TEST("no rim boxes from inside the radius", cylinder_rim_boxes(model, 0, camera, down_the_axis, boxes), false);
}

TESTMAIN(test_cylinder_windows);
