// SPDX-License-Identifier: BSD-3-Clause
/// The motion model between frames: no velocity from the start pose, constant velocity once the
/// motion exceeds twice the range and none within the range, a search range that follows the
/// motion and doubles after a start or a loss, a retry from the last trusted pose whose range
/// reaches a frame's motion back, dead reckoning that fades while lost, and a reset
/// that starts again at rest.
#include <algorithm>
#include <cmath>
#include <limits>

#include "edgetrack/motion_model.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// A unit cube's corners 150 mm in front of a QVGA camera (px = py = 220).
EdgeModel corners() {
  EdgeModel model;
  for (int i = 0; i < 8; ++i)
    model.vertices.push_back({real(0.03 * (i & 1)), real(0.03 * ((i >> 1) & 1)), real(0.03 * ((i >> 2) & 1))});
  return model;
}

Se3 at_x(double x_m) { return Se3(Mat33::identity(), Vec3{real(x_m), real(0), real(0.15)}); }

double x_of(const Se3& pose) { return static_cast<double>(pose.translation().x); }

/// `base`, or `steps` steps of the real's resolution where that is coarser (S47.16: 2^-16 m).
/// Every pose here rounds its x once (half a step), and each velocity, exp and product applied
/// to it adds about half a step more.
double tolerance(double base, double steps) {
  return std::max(base, steps * static_cast<double>(std::numeric_limits<real>::epsilon()));
}

}  // namespace

static void test_motion_model() {
  const PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  const EdgeModel model = corners();
  const unsigned range = 4;
  const MotionParams params;
  // 1 mm at 150 mm is 1.47 px: 10 mm per frame moves the image by ~15 px, 1 mm by ~1.5 px.
  MotionModel fast(at_x(0), params);
  TEST_EQUAL("after the start the range is doubled (no velocity yet)", fast.search_range(range), 2 * range);
  fast.trust(at_x(0), model, camera, range);
  TEST_NEAR("the start pose gives no velocity", x_of(fast.prediction()), 0, 1e-6);
  fast.trust(at_x(0.010), model, camera, range);
  TEST_NEAR("15 px per frame: constant velocity", x_of(fast.prediction()), 0.020, tolerance(1e-5, 2));
  const unsigned wide = fast.search_range(range);
  TEST("the range follows the motion (4 + half of the ~11 px beyond it)", wide >= 9 && wide <= 10, true);
  TEST_NEAR("the last trusted pose is kept for a retry", x_of(fast.trusted()), 0.010, tolerance(1e-6, 1));
  TEST_EQUAL("the retry's range reaches a frame's motion back, ~15 px, at most 4 times the range",
             fast.retry_range(range), 4 * range);

  MotionModel medium(at_x(0), params);
  medium.trust(at_x(0), model, camera, range);
  medium.trust(at_x(0.005), model, camera, range);
  TEST_EQUAL("7.3 px per frame: the retry searches the range plus 8 px", medium.retry_range(range), range + 8);

  MotionModel slow(at_x(0), params);
  slow.trust(at_x(0), model, camera, range);
  slow.trust(at_x(0.001), model, camera, range);
  TEST_NEAR("1.5 px per frame, within the range: no prediction", x_of(slow.prediction()), 0.001, tolerance(1e-6, 1));
  TEST_EQUAL("and the range as configured", slow.search_range(range), range);
  TEST("the prediction is the trusted pose: no other start to retry from", slow.predicts_motion(), false);
  TEST("a fast one predicts motion", fast.predicts_motion(), true);

  fast.lose(model, camera);
  TEST_NEAR("a lost frame moves on by 0.8 of the velocity", x_of(fast.prediction()), 0.028, tolerance(1e-5, 2));
  TEST_EQUAL("a lost frame doubles the search", fast.search_range(range) >= 2 * range, true);
  TEST("and says so", fast.lost_last_frame(), true);
  TEST_NEAR("the retry still starts from the last trusted pose", x_of(fast.trusted()), 0.010, tolerance(1e-6, 1));
  TEST("which the prediction has left", fast.predicts_motion(), true);
  fast.lose(model, camera);
  TEST_NEAR("the next by 0.64", x_of(fast.prediction()), 0.0344, tolerance(1e-5, 3));
  fast.trust(at_x(0.040), model, camera, range);
  TEST_NEAR("found again: the velocity is the mean motion since the last trusted frame", x_of(fast.prediction()),
            0.050, tolerance(1e-5, 2));
  TEST("still searching wider", fast.search_range(range) >= 2 * range, true);

  fast.reset(at_x(0.1));
  TEST_NEAR("a reset starts again from the pose", x_of(fast.prediction()), 0.1, tolerance(1e-6, 1));
  fast.trust(at_x(0.1), model, camera, range);
  TEST_NEAR("at rest", x_of(fast.prediction()), 0.1, tolerance(1e-6, 1));
  // 1 m of x at 150 mm is 220 / 0.15 px: one step of the 10 mm there moves the shift by that much.
  TEST_NEAR("largest_image_shift: 10 mm at 150-180 mm moves a corner by ~14.7 px",
            static_cast<double>(largest_image_shift(model, camera, at_x(0), at_x(0.01))), 14.67,
            tolerance(0.01, 220 / 0.15));
}

TESTMAIN(test_motion_model)
