// SPDX-License-Identifier: BSD-3-Clause
// Motion blur and rolling shutter on a scene whose image motion is known exactly: a bright
// rectangle whose right edge moves 12 px per frame interval, whose lower edge stays still.
#include <algorithm>
#include <cmath>

#include "camera_timing.h"
#include "testlib/testlib_test.h"

using namespace edgetrack_app;

namespace {

constexpr int kWidth = 64, kHeight = 48;
constexpr double kSpeedPx = 12, kEdgeAtFrameTime = 30, kLowerEdge = 24;

/// Pixel x covers [x - 0.5, x + 0.5): its share left of the moving edge, and above the still one.
RgbImage rectangle_at(double offset) {
  RgbImage image = make_image(kWidth, kHeight);
  const double edge = kEdgeAtFrameTime + kSpeedPx * offset;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const double share = std::clamp(edge - (x - 0.5), 0.0, 1.0) * (y < kLowerEdge ? 1 : 0);
      std::fill_n(image.pixel(x, y), 3, static_cast<uint8_t>(std::lround(255 * share)));
    }
  return image;
}

/// The integral of a pixel's coverage clamp(u, 0, 1) from u = 0, u being how far the edge has
/// passed the pixel's left side.
double coverage_area(double u) { return u <= 0 ? 0 : u < 1 ? u * u / 2 : u - 0.5; }

/// Where row y's moving edge lies: the row's bright share, as a column position.
double edge_position(const RgbImage& image, int y) {
  double bright = 0;
  for (int x = 0; x < kWidth; ++x) bright += image.pixel(x, y)[0] / 255.0;
  return bright - 0.5;
}

/// The columns of row y neither dark nor bright: the length of the edge's smear.
int smeared_columns(const RgbImage& image, int y) {
  int count = 0;
  for (int x = 0; x < kWidth; ++x) count += image.pixel(x, y)[0] > 5 && image.pixel(x, y)[0] < 250;
  return count;
}

int renders_asked = 0;
RgbImage counted_rectangle_at(double offset) {
  ++renders_asked;
  return rectangle_at(offset);
}

}  // namespace

static void test_camera_timing() {
  const ExposurePlan still = plan_exposure({}, kHeight, kSpeedPx);
  TEST("no shutter time and no readout: one render at the frame's time", still.times.size() == 1 && still.times[0] == 0, true);
  TEST("that render is the frame as it is", expose(still, rectangle_at).rgb == rectangle_at(0).rgb, true);

  const ExposurePlan open = plan_exposure({1.0, 0.0}, kHeight, kSpeedPx);
  TEST("a shutter open a whole frame interval at 12 px per interval: renders 1 px apart",
       open.times.size() == 13 && std::fabs((open.times[1] - open.times[0]) * kSpeedPx - 1) < 1e-12, true);
  bool rows_sum_to_one = true;
  for (int y = 0; y < kHeight; ++y) {
    double sum = 0;
    for (size_t j = 0; j < open.times.size(); ++j) sum += open.weight(y, j);
    rows_sum_to_one = rows_sum_to_one && std::fabs(sum - 1) < 1e-12;
  }
  TEST("every row's weights sum to 1", rows_sum_to_one, true);
  renders_asked = 0;
  const RgbImage blurred = expose(open, counted_rectangle_at);
  TEST_EQUAL("each render is asked for once", renders_asked, 13);
  const int smear = smeared_columns(blurred, 10);
  TEST("the moving edge is smeared over the 12 px it moves while the shutter is open", smear >= 11 && smear <= 13, true);
  TEST_NEAR("the smear is centred on the edge at the frame's time", edge_position(blurred, 10), kEdgeAtFrameTime, 0.05);
  double worst_ramp = 0;
  for (int x = 0; x < kWidth; ++x) {  // the pixel's coverage averaged over the edge's 12 px, 24 to 36
    const double first = kEdgeAtFrameTime - kSpeedPx / 2, last = kEdgeAtFrameTime + kSpeedPx / 2;
    const double expected = 255 * (coverage_area(last - x + 0.5) - coverage_area(first - x + 0.5)) / kSpeedPx;
    worst_ramp = std::max(worst_ramp, std::fabs(blurred.pixel(x, 10)[0] - expected));
  }
  TEST("the smear is the linear ramp of an edge moving steadily (within 3 grey levels)", worst_ramp <= 3, true);
  bool still_edge_sharp = true;
  for (int x = 0; x < 20; ++x)
    still_edge_sharp = still_edge_sharp && blurred.pixel(x, kLowerEdge - 1)[0] == 255 && blurred.pixel(x, kLowerEdge)[0] == 0;
  TEST("the edge along the motion stays sharp", still_edge_sharp, true);
  TEST("a global shutter smears every row alike", edge_position(blurred, 0) == edge_position(blurred, kLowerEdge - 1), true);

  const ExposurePlan rolling = plan_exposure({0.0, 1.0}, kHeight, kSpeedPx);
  const RgbImage sheared = expose(rolling, rectangle_at);
  double worst_row = 0;
  for (int y = 0; y < kLowerEdge; ++y) {
    const double read = (y + 0.5) / kHeight - 0.5;
    worst_row = std::max(worst_row, std::fabs(edge_position(sheared, y) - (kEdgeAtFrameTime + kSpeedPx * read)));
  }
  TEST("rolling shutter: each row shows the edge where it was at the row's read time (within 0.05 px)", worst_row < 0.05, true);
  TEST_NEAR("the top and bottom rows of the object are 12 px x 23/48 apart",
            edge_position(sheared, kLowerEdge - 1) - edge_position(sheared, 0), kSpeedPx * 23 / kHeight, 0.05);
  TEST("with no shutter time a rolling-shutter row is sharp", smeared_columns(sheared, 10) <= 2, true);

  const RgbImage both = expose(plan_exposure({0.5, 1.0}, kHeight, kSpeedPx), rectangle_at);
  const int both_smear = smeared_columns(both, 0);
  TEST("rolling shutter with half a frame's exposure: rows shifted as before", std::fabs(edge_position(both, 0) - edge_position(sheared, 0)) < 0.05, true);
  TEST("and each smeared over 6 px", both_smear >= 5 && both_smear <= 7, true);

  std::vector<edgetrack::Se3> poses = {edgetrack::Se3(), edgetrack::Se3::from_theta_u({real(0.01), real(0), real(0.2)}, {real(0), real(0.1), real(0)})};
  TEST("pose_at_time on a whole frame is that frame's pose, as it is",
       pose_at_time(poses, 1).translation().x == poses[1].translation().x && pose_at_time(poses, 1).rotation().m[0][2] == poses[1].rotation().m[0][2], true);
  const edgetrack::Se3 half = pose_at_time(poses, 0.5);
  TEST_NEAR("half way, half the rotation", static_cast<double>(half.theta_u().y), 0.05, 1e-4);
  const edgetrack::Se3 beyond = pose_at_time(poses, 1.5);
  TEST_NEAR("past the last frame the last step carries on", static_cast<double>(beyond.theta_u().y), 0.15, 1e-4);
}

TESTMAIN(test_camera_timing);
