// SPDX-License-Identifier: BSD-3-Clause
/// The face angle rule inside the tracker, on generated frames of the cube, seen from above,
/// turning a face towards edge-on and back (0 -> 66 -> 45 degrees about its axis, 1.5 degrees a
/// frame; the face's own angle runs from 36 to 79 degrees and back to 57):
/// with cube.xml's 65/75 degrees the face disappears past 75 degrees and comes back under 65,
/// no control point is sampled on an edge whose faces are all hidden, and the cube is tracked
/// throughout.
#include <cmath>
#include <cstdio>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "face_angle.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

const double kPi = 3.14159265358979323846;

/// The cube (centre 150 mm away) seen from 30 degrees above and turned about its vertical axis.
Se3 turned(double degrees) {
  const double a = degrees * kPi / 180, tilt = 30 * kPi / 180;
  Mat33 yaw = Mat33::identity(), pitch = Mat33::identity();
  yaw.m[0][0] = real(std::cos(a));
  yaw.m[0][2] = real(std::sin(a));
  yaw.m[2][0] = real(-std::sin(a));
  yaw.m[2][2] = real(std::cos(a));
  pitch.m[1][1] = real(std::cos(tilt));
  pitch.m[1][2] = real(-std::sin(tilt));
  pitch.m[2][1] = real(std::sin(tilt));
  pitch.m[2][2] = real(std::cos(tilt));
  return Se3(pitch * yaw, {real(0.003), real(-0.002), real(0.15)});
}

}  // namespace

static void test_tracker_faces() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  std::vector<double> angles;
  for (int k = 0; k <= 44; ++k) angles.push_back(1.5 * k);
  for (int k = 43; k >= 30; --k) angles.push_back(1.5 * k);
  TrackerParams params;
  params.faces.angle_appear = real(65 * kPi / 180);
  params.faces.angle_disappear = real(75 * kPi / 180);
  Result<Tracker> tracker = Tracker::create(model.value(), camera, turned(0), params);
  TEST("the tracker starts", tracker.ok(), true);
  if (!tracker.ok()) return;
  SceneStyle style;  // faces turned differently differ more in grey than in the default style
  style.face_low = 120;
  style.face_high = 255;
  SceneRenderer renderer(camera, style);
  Rgb565Frame image;
  const int front = 0;  // z-, facing the camera at 0 degrees
  double gone_at = -1, back_at = -1, worst_mm = 0;
  bool was_visible = false;
  int on_hidden_edges = 0, wrong_state = 0;
  for (size_t k = 0; k < angles.size(); ++k) {
    renderer.render(model.value(), turned(angles[k]), static_cast<uint32_t>(500 + k), image);
    // The rule runs at the frame's starting pose, the previous frame's.
    const double seen_at = face_angle_degrees(model.value(), front, tracker.value().camera_from_model());
    tracker.value().track(rgb565_view(image)).value();
    const FaceVisibility& faces = tracker.value().face_visibility();
    const bool visible = faces.face_visible(front);
    const bool expected = was_visible ? seen_at < 75 : seen_at < 65;
    if (visible != expected && std::fabs(seen_at - 75) > 0.05 && std::fabs(seen_at - 65) > 0.05) ++wrong_state;
    if (was_visible && !visible && gone_at < 0) gone_at = seen_at;
    if (!was_visible && visible && k > 41 && back_at < 0) back_at = seen_at;
    was_visible = visible;
    for (const ControlPoint& p : tracker.value().control_points()) on_hidden_edges += !faces.edge_tracked(p.edge);
    const Vec3 d = camera_position(tracker.value().camera_from_model()) - camera_position(turned(angles[k]));
    worst_mm = std::fmax(worst_mm, 1000 * static_cast<double>(norm(d)));
  }
  std::printf("%s: front face gone at %.1f degrees, back at %.1f, largest position error %.2f mm\n", real_name(),
              gone_at, back_at, worst_mm);
  TEST("the front face is visible at first (0 degrees < angle_appear)", gone_at >= 0, true);
  TEST_EQUAL("in every frame the face follows the rule at the frame's starting pose", wrong_state, 0);
  TEST_NEAR("it disappears past angle_disappear (75 degrees, within a frame's turn)", gone_at, 76, 1.5);
  TEST_NEAR("and comes back under angle_appear (65 degrees) on the way back", back_at, 64, 1.5);
  TEST_EQUAL("no control point on an edge whose faces are all hidden", on_hidden_edges, 0);
  TEST("the cube is tracked throughout (within 2 mm)", worst_mm < 2.0, true);
}

TESTMAIN(test_tracker_faces)
