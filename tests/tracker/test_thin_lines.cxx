// SPDX-License-Identifier: BSD-3-Clause
/// Dark lines beside the edges. On a drawn image, a bright face's edge with a dark line 3 pixels
/// outside it whose inner side has the edge's polarity and more contrast: both pass the contrast
/// test against the edge's own contrast, and the site takes the edge, not the line's side (a step
/// with an opposite one within two pixels). On the generated wood toy with a dark line 4 mm
/// beside every edge (`edgetrack synth --clutter 4`), tracked with the defaults from the true
/// first pose: no frame lost, and the mean camera position error within the paper's 2 mm for
/// the toy (test_tracking.cxx), which the strongest passing maximum alone misses (docs/ME.md);
/// S47.16 within the loose agreement it claims.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "edgetrack/moving_edges.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

constexpr int kEdgeColumn = 60;  ///< first column of the bright face
constexpr int kLineColumn = 55;  ///< the dark line covers columns 55 and 56

/// Background 120, the face (columns >= 60) 200, the dark line 30, 128 x 48 pixels: the line's
/// inner side (120 to 30) is a larger step than the edge (200 to 120), of the same polarity.
vpImage<unsigned char> drawn_image() {
  vpImage<unsigned char> image(48, 128, 120);
  for (unsigned i = 0; i < 48; ++i)
    for (unsigned j = 0; j < 128; ++j) {
      if (j >= kEdgeColumn) image[i][j] = 200;
      if (j == kLineColumn || j == kLineColumn + 1) image[i][j] = 30;
    }
  return image;
}

void edge_not_line_side() {
  const vpImage<unsigned char> image = drawn_image();
  vpMe me;
  me.setRange(6);
  ControlPoint point;
  point.pixel = {real(59.5), real(24)};
  point.direction = {real(0), real(1)};
  point.normal = {real(-1), real(0)};  // direction turned by +90 degrees
  const std::vector<ControlPoint> points = {point};
  std::vector<real> reference;
  contrasts_at_points(image, points, me, reference);
  const std::vector<EdgeMatch> matches = search_moving_edges(image, points, me, 1, &reference);
  TEST_EQUAL("next to a dark line the site matches", matches.size(), size_t(1));
  TEST_NEAR("the edge, not the line's inner side 3 pixels out", matches.empty() ? -1.0 : static_cast<double>(matches[0].found.x),
            kEdgeColumn - 0.5, 0.5);
}

/// Frames of the line sequence: as test_hypotheses.cxx's, enough to settle on lines.
constexpr int kLineFrames = 15;

void wood_toy_beside_lines() {
  SequenceSpec spec;
  spec.clutter = 0.004;
  const SequenceRun run = run_sequence(Scene::kWoodToy, kLineFrames, false, TrackerParams{}, spec);
  TEST("the wood toy line sequence runs", run.loaded, true);
  if (!run.loaded) return;
  std::printf("wood toy, %s, lines 4 mm beside each edge, %d frames: mean %.3f mm\n", real_name(), kLineFrames,
              run.mean_position_error_mm);
  TEST_EQUAL("lines beside the wood toy's edges: no frame lost", count_status(run, TrackingStatus::kLost), 0);
  // Float and S47.16 only claim a loose agreement with double (golden_check.cxx: a mean within 1 mm).
  const std::string real = real_name();
  const double bound_mm = real == "s47_16" || real == "float" ? 3.0 : 2.0;
  TEST_NEAR(("lines beside the wood toy's edges: mean camera position error within 2 mm (" + std::to_string(bound_mm) + " mm)").c_str(),
            run.mean_position_error_mm, 0, bound_mm);
}

}  // namespace

static void test_thin_lines() {
  edge_not_line_side();
  wood_toy_beside_lines();
}

TESTMAIN(test_thin_lines)
