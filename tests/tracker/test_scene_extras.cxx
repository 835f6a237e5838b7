// SPDX-License-Identifier: BSD-3-Clause
/// The evaluation scenes' additions: faster motion follows the slow path, the occluder band
/// covers the share asked for and the renderer draws it there, clutter lines run parallel to
/// their edges at the offset asked for and show beside the edges in the image.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_extras.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/synthetic_trajectory.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

int grey_at(const Rgb565Frame& frame, int x, int y) {
  const uint16_t p = frame.pixels[static_cast<size_t>(y) * frame.width + x];
  return ((p >> 5) & 63) << 2;
}

double distance(const Vec3& a, const Vec3& b) { return static_cast<double>(norm(a - b)); }

/// `base`, or `steps` steps of the real's resolution where that is coarser (S47.16: 2^-16).
double tolerance(double base, double steps) {
  return std::max(base, steps * static_cast<double>(std::numeric_limits<real>::epsilon()));
}

void check_faster_poses() {
  const std::vector<Se3> slow = cube_trajectory(121);
  const std::vector<Se3> twice = faster_poses(slow, real(2), 60);
  TEST("speed 2 gives the 60 poses asked for", twice.size(), size_t(60));
  TEST_NEAR("speed 2: pose 10 is slow pose 20", distance(twice[10].translation(), slow[20].translation()), 0, 1e-6);
  const std::vector<Se3> half = faster_poses(slow, real(1.5), 80);
  TEST("speed 1.5 gives 80 poses", half.size(), size_t(80));
  const Vec3 midpoint = real(0.5) * (slow[1].translation() + slow[2].translation());
  // The midpoint rounds once; the interpolated pose's translation rounds in the inverse, the
  // product, log, exp and the product again, about half a step each: 4 steps.
  TEST_NEAR("speed 1.5: pose 1 lies halfway between slow poses 1 and 2 (within 0.01 mm)",
            distance(half[1].translation(), midpoint), 0, tolerance(1e-5, 4));
  TEST("a path too short ends early", faster_poses(slow, real(4), 60).size(), size_t(31));
}

void check_there_and_back() {
  const std::vector<Se3> forward = cube_trajectory(4);
  const std::vector<Se3> poses = there_and_back(forward);
  TEST("4 poses there and back are 7", poses.size(), size_t(7));
  const auto same = [](const Se3& a, const Se3& b) {
    return distance(a.translation(), b.translation()) == 0 && distance(a * Vec3{real(1), real(1), real(1)},
                                                                          b * Vec3{real(1), real(1), real(1)}) == 0;
  };
  TEST("the turn is the last forward pose, shown once", same(poses[3], forward[3]) && !same(poses[4], forward[3]), true);
  TEST("then the way back", same(poses[4], forward[2]) && same(poses[6], forward[0]), true);
  TEST("one pose stays one", there_and_back({forward[0]}).size(), size_t(1));
}

void check_occluder(const EdgeModel& cube, const PinholeCamera& camera, const Se3& pose) {
  std::vector<uint8_t> mask;
  std::vector<int> columns;
  silhouette_columns(cube, camera, pose, mask, columns);
  int total = 0, widest = 0;
  for (int c : columns) total += c, widest = c > widest ? c : widest;
  TEST("the cube covers some thousands of pixels", total > 2000 && total < 40000, true);
  const OccluderBand band = occluder_band(columns, sweeping_centre(columns, 0, 10), real(0.3));
  const double share = static_cast<double>(band.covered_share);
  TEST("the band covers at least 30 % of the cube's image", share >= 0.3, true);
  TEST("and not more than one column more", share <= 0.3 + static_cast<double>(widest) / total, true);
  int covered = 0;
  for (int x = band.x_begin; x < band.x_end; ++x) covered += columns[static_cast<size_t>(x)];
  // covered_share is one quotient of two counts: one rounding, at most one step.
  TEST_NEAR("its share is the share of the silhouette's pixels in its columns", share,
            static_cast<double>(covered) / total, tolerance(1e-6, 1));
  TEST("the band moves left to right over the sequence",
       sweeping_centre(columns, 0, 10) < sweeping_centre(columns, 9, 10), true);

  SceneStyle style;
  style.noise = 0;
  SceneRenderer renderer(camera, style);
  SceneAdditions additions;
  additions.band = band;
  Rgb565Frame frame;
  renderer.render(cube, pose, 1, additions, frame);
  int flat = 0, inside = 0;
  for (int y = 0; y < camera.height; ++y)
    for (int x = band.x_begin; x < band.x_end; ++x, ++inside) flat += std::abs(grey_at(frame, x, y) - 45) <= 4;
  TEST("every pixel of the band's columns is the occluder's grey", flat, inside);
}

void check_clutter(const EdgeModel& cube, const PinholeCamera& camera, const Se3& pose) {
  const std::vector<Segment3> clutter = parallel_clutter(cube, real(0.003));
  TEST("one clutter line per edge", clutter.size(), cube.edges.size());
  double worst_angle = 0, worst_offset = 0;
  for (size_t i = 0; i < clutter.size(); ++i) {
    const Vec3 a = cube.vertices[cube.edges[i].a], b = cube.vertices[cube.edges[i].b];
    const Vec3 along = normalized(b - a), line = normalized(clutter[i].b - clutter[i].a);
    worst_angle = std::fmax(worst_angle, static_cast<double>(norm(cross(along, line))));
    const Vec3 off = clutter[i].a - a;
    worst_offset = std::fmax(worst_offset, std::fabs(static_cast<double>(norm(off - dot(off, along) * along)) - 0.003));
  }
  // Within 0.01 mm and 1e-5 rad: S40.23 resolves 2^-23 m, and the offset takes a square root.
  TEST_NEAR("each line is parallel to its edge", worst_angle, 0, 1e-5);
  TEST_NEAR("and 3 mm from it", worst_offset, 0, 1e-5);
  const double offset_px = static_cast<double>(clutter_image_offset(cube, clutter, camera, pose));
  TEST("3 mm at about 150 mm looks a few pixels off the edges", offset_px > 1 && offset_px < 8, true);

  SceneStyle style;
  style.noise = 0;
  SceneRenderer renderer(camera, style);
  SceneAdditions additions;
  additions.clutter = &clutter;
  Rgb565Frame plain, cluttered;
  renderer.render(cube, pose, 1, plain);
  renderer.render(cube, pose, 1, additions, cluttered);
  int dark = 0, changed = 0;
  for (size_t k = 0; k < plain.pixels.size(); ++k) {
    const int x = static_cast<int>(k) % camera.width, y = static_cast<int>(k) / camera.width;
    if (plain.pixels[k] != cluttered.pixels[k]) ++changed, dark += grey_at(cluttered, x, y) < 40;
  }
  TEST("the lines change some hundreds of pixels", changed > 200 && changed < 5000, true);
  TEST("most of them to the lines' dark grey", 2 * dark > changed, true);
}

}  // namespace

static void test_scene_extras() {
  const Result<EdgeModel> loaded = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("the cube loads", loaded.ok(), true);
  if (!loaded.ok()) return;
  const PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  const Se3 pose = cube_trajectory(1)[0];
  check_faster_poses();
  check_there_and_back();
  check_occluder(loaded.value(), camera, pose);
  check_clutter(loaded.value(), camera, pose);
}

TESTMAIN(test_scene_extras);
