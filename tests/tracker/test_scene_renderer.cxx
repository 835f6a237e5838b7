// SPDX-License-Identifier: BSD-3-Clause
/// The test-image renderer draws the model bright over a darker textured background, the same
/// way for the same seeds; its ray-cast ground truth agrees with Edge-ID visibility.
#include <string>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

int grey_at(const Rgb565Frame& frame, int x, int y) {
  const uint16_t p = frame.pixels[static_cast<size_t>(y) * frame.width + x];
  return ((p >> 5) & 63) << 2;  // the green channel carries the grey level best
}

}  // namespace

static void test_scene_renderer() {
  const Result<EdgeModel> loaded = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("the cube loads", loaded.ok(), true);
  if (!loaded.ok()) return;
  const EdgeModel& cube = loaded.value();
  const PinholeCamera camera{real(300), real(300), real(160), real(120), 320, 240};
  SceneStyle style;
  SceneRenderer renderer(camera, style);
  const Se3 turned(rotation_exp({real(0.45), real(0.6), real(0.1)}), {real(0.005), real(-0.004), real(0.16)});
  Rgb565Frame a, b, c;
  renderer.render(cube, turned, 7, a);
  renderer.render(cube, turned, 7, b);
  renderer.render(cube, turned, 8, c);
  TEST_EQUAL("the frame has the camera's size", a.pixels.size(), size_t(320 * 240));
  TEST("the same seeds give the same frame", a.pixels == b.pixels, true);
  TEST("another noise seed gives another frame", a.pixels != c.pixels, true);
  const int centre = grey_at(a, 165, 117), corner = grey_at(a, 5, 5);
  TEST("the cube's centre is drawn in the face range", centre >= style.face_low - style.noise - 8, true);
  TEST("the image corner shows the darker background", corner <= style.background_high + style.noise + 4, true);

  // Ground truth against Edge-ID on every sampled point of the turned cube.
  EdgeIdBuffer ids(camera);
  ids.render(cube, turned);
  SamplingParams params;
  params.step = real(4);
  int agree = 0, total = 0, hidden_but_shown = 0;
  for (const ControlPoint& p : sample_control_points(cube, camera, turned, params)) {
    const bool truth = point_visible(cube, turned, p.point_in_model, real(0.02));
    const bool shown = ids.shows(p.edge, p.pixel, p.direction);
    agree += truth == shown;
    hidden_but_shown += !truth && shown;
    ++total;
  }
  TEST("there are points to compare", total > 100, true);
  TEST("Edge-ID agrees with ray casting on at least 95 % of the points", agree >= total * 95 / 100, true);
  TEST_EQUAL("Edge-ID never shows a point that ray casting finds hidden", hidden_but_shown, 0);
  const Se3 face_on(Mat33::identity(), {real(0), real(0), real(0.15)});
  TEST("ray casting: the front face's centre is visible",
       point_visible(cube, face_on, {real(0), real(0), real(-0.03)}, real(0.02)), true);
  TEST("ray casting: a back corner is hidden",
       point_visible(cube, face_on, {real(0.03), real(0.03), real(0.03)}, real(0.02)), false);
}

TESTMAIN(test_scene_renderer)
