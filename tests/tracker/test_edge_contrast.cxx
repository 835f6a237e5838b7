// SPDX-License-Identifier: BSD-3-Clause
/// The contrast test between frames, on a drawn image: a bright face's vertical edge with a dark
/// line 4 pixels outside it, far stronger than the edge. Without a reference the site takes the
/// line's stronger side; with the edge's own contrast as reference it refuses both sides of the
/// line (one has the other polarity, the other three times the contrast) and finds the edge; a
/// reference no edge matches falls back to the strongest edge, unless it is strict (borrowed),
/// which leaves the point unmatched. The memory gives a control point the contrast of the
/// nearest kept match of its own primitive within a sample step, and nothing for another
/// primitive; of an outlier, a match off the solved projection or a match much weaker than its
/// primitive's others nothing is remembered, and a point with nothing of its own within reach
/// borrows its primitive's mean contrast when that primitive's are all of one polarity.
#include <cmath>
#include <vector>

#include "edgetrack/contrast_memory.h"
#include "edgetrack/moving_edges.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

constexpr int kEdgeColumn = 60;  ///< first column of the bright face
constexpr int kLineColumn = 55;  ///< the dark line covers columns 55 and 56

/// Background 120, the face (columns >= 60) 160, the dark line 10, 128 x 48 pixels.
vpImage<unsigned char> drawn_image() {
  vpImage<unsigned char> image(48, 128, 120);
  for (unsigned i = 0; i < 48; ++i)
    for (unsigned j = 0; j < 128; ++j) {
      if (j >= kEdgeColumn) image[i][j] = 160;
      if (j == kLineColumn || j == kLineColumn + 1) image[i][j] = 10;
    }
  return image;
}

ControlPoint point_on_edge(int edge, real x, real y) {
  ControlPoint p;
  p.edge = edge;
  p.pixel = {x, y};
  p.direction = {real(0), real(1)};
  p.normal = {real(-1), real(0)};  // direction turned by +90 degrees
  p.point_in_model = {x / real(1000), y / real(1000), real(0)};
  return p;
}

/// Where the match lies along the image row (pixels): the edge sits between columns 59 and 60.
double found_column(const std::vector<EdgeMatch>& matches) {
  return matches.empty() ? -1 : static_cast<double>(matches[0].found.x);
}

}  // namespace

static void test_edge_contrast() {
  const vpImage<unsigned char> image = drawn_image();
  const vpMe me;
  const unsigned range = 6;
  const std::vector<ControlPoint> points = {point_on_edge(0, real(59.5), real(24))};

  const std::vector<EdgeMatch> strongest = search_moving_edges(image, points, me, range);
  TEST_EQUAL("without a reference the site matches", strongest.size(), size_t(1));
  TEST("and takes the dark line's stronger side, 3 pixels off the edge",
       std::fabs(found_column(strongest) - (kLineColumn + 2 - 0.5)) < 1.0, true);

  std::vector<real> reference;
  contrasts_at_points(image, points, me, reference);
  TEST("the edge's own contrast is the reference", reference.size() == 1 && reference[0] != real(0), true);
  const std::vector<EdgeMatch> tested = search_moving_edges(image, points, me, range, 1, &reference);
  TEST_EQUAL("with it the site matches", tested.size(), size_t(1));
  TEST_NEAR("and finds the edge", found_column(tested), kEdgeColumn - 0.5, 0.5);
  TEST("the match carries the edge's contrast and polarity",
       !tested.empty() && (tested[0].contrast > real(0)) == (reference[0] > real(0)), true);

  std::vector<real> unmatched = {real(-10) * reference[0]};
  const std::vector<EdgeMatch> fallback = search_moving_edges(image, points, me, range, 1, &unmatched);
  TEST_EQUAL("a reference no edge passes: the site still matches", fallback.size(), size_t(1));
  TEST_NEAR("the strongest edge, as without one", found_column(fallback), found_column(strongest), 1e-9);
  const std::vector<unsigned char> strict = {1};
  TEST_EQUAL("a strict (borrowed) reference no edge passes: no match",
             search_moving_edges(image, points, me, range, 1, &unmatched, &strict).size(), size_t(0));
  TEST_EQUAL("a strict one an edge passes: matched as by its own",
             search_moving_edges(image, points, me, range, 1, &reference, &strict).size(), size_t(1));
  // The same point twice, the first held to a reference no edge passes: the one match is the
  // second's, though its point compares equal to the first's.
  const std::vector<ControlPoint> twice = {points[0], points[0]};
  const std::vector<real> first_unmatched = {unmatched[0], reference[0]};
  const std::vector<unsigned char> first_strict = {1, 0};
  const std::vector<EdgeMatch> second_only = search_moving_edges(image, twice, me, range, 1, &first_unmatched, &first_strict);
  TEST("a match names the point it was searched for (its index), past one that found none",
       second_only.size() == 1 && second_only[0].point_index == 1, true);

  // The memory: matches at the identity pose, a camera whose pixels are millimetres at 1 m.
  const PinholeCamera camera{real(1000), real(1000), real(0), real(0), 128, 48};
  const Se3 pose(Mat33::identity(), {real(0), real(0), real(1)});
  std::vector<EdgeMatch> kept;
  for (int k = 0; k < 4; ++k) {
    EdgeMatch m;
    m.point = point_on_edge(0, real(10 + 10 * k), real(20));
    m.found = camera.project(pose * m.point.point_in_model);
    m.contrast = real(1000 + 10 * k);
    kept.push_back(m);
  }
  kept[1].outlier = true;
  kept[2].found.x = kept[2].found.x + real(3);  // off the solved projection
  EdgeMatch weak = kept[0];
  weak.point = point_on_edge(0, real(90), real(20));
  weak.found = camera.project(pose * weak.point.point_in_model);
  weak.contrast = real(100);  // a tenth of its edge's others: matched to noise under an occluder
  kept.push_back(weak);
  ContrastMemory memory;
  memory.remember(kept, camera, pose, real(1));
  const std::vector<ControlPoint> asked = {point_on_edge(0, real(12), real(21)), point_on_edge(1, real(12), real(21)),
                                           point_on_edge(0, real(30), real(200)), point_on_edge(0, real(21), real(20)),
                                           point_on_edge(0, real(29), real(20)), point_on_edge(0, real(90), real(20))};
  std::vector<real> found;
  std::vector<unsigned char> borrowed;
  memory.references(asked, camera, pose, real(10), found, borrowed);
  TEST_EQUAL("one reference per point", found.size(), asked.size());
  TEST_EQUAL("and one mark", borrowed.size(), asked.size());
  TEST_NEAR("a point near a kept match gets its contrast", found[0], 1000, 1e-9);
  TEST("its own", borrowed[0] == 0, true);
  TEST_NEAR("a point of another primitive gets none", found[1], 0, 1e-9);
  TEST("nor a mark", borrowed[1] == 0, true);
  // Remembered of primitive 0: the matches at 10 (1000) and 40 (1030) mm.
  TEST_NEAR("a point farther than the reach gets its primitive's mean", found[2], 1015, 1e-9);
  TEST("borrowed", borrowed[2] != 0, true);
  TEST_NEAR("nothing is remembered of an outlier: the nearest kept match is farther", found[3], 1000, 1e-9);
  TEST_NEAR("nor of a match off the solved projection", found[4], 1030, 1e-9);
  TEST_NEAR("nor of a match far weaker than its primitive's others: the primitive's mean", found[5], 1015, 1e-9);
  TEST("borrowed", borrowed[5] != 0, true);
  // The same memory from projections made once (the tracker shares its status's, a match's at
  // its point_index): the same references; a match whose point is marked behind the camera is
  // not remembered.
  std::vector<ControlPoint> kept_points;
  for (EdgeMatch& m : kept) {
    m.point_index = static_cast<int>(kept_points.size());
    kept_points.push_back(m.point);
  }
  ProjectedPoints projected;
  project_points(kept_points, camera, pose, projected);
  ContrastMemory shared;
  shared.remember(kept, camera, pose, real(1), &projected);
  std::vector<real> shared_found;
  std::vector<unsigned char> shared_borrowed;
  shared.references(asked, camera, pose, real(10), shared_found, shared_borrowed);
  TEST("projections given: the same references", shared_found == found && shared_borrowed == borrowed, true);
  projected.in_front[0] = 0;
  shared.remember(kept, camera, pose, real(1), &projected);
  shared.references(asked, camera, pose, real(10), shared_found, shared_borrowed);
  TEST_NEAR("a match marked behind the camera is not remembered: its primitive's other", shared_found[0], 1030, 1e-9);
  TEST("borrowed", shared_borrowed[0] != 0, true);
  std::vector<EdgeMatch> mixed = kept;
  mixed[3].contrast = real(-1030);  // a silhouette whose background changes side
  memory.remember(mixed, camera, pose, real(1));
  memory.references(asked, camera, pose, real(10), found, borrowed);
  TEST("a primitive of both polarities lends nothing", found[2] == real(0) && borrowed[2] == 0, true);
  memory.clear();
  memory.references(asked, camera, pose, real(10), found, borrowed);
  TEST_NEAR("after clear nothing is remembered", found[0], 0, 1e-9);
}

TESTMAIN(test_edge_contrast)
