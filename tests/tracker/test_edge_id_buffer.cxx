// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID rendering with hidden-line removal: a cube seen face-on shows only its front square;
/// turned, it hides exactly the three edges at its farthest corner; the same buffer reused for
/// another pose forgets the previous one.
#include <string>
#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/model_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// Share of each edge's sampled points that the buffer shows.
std::vector<double> shown_share(const EdgeModel& model, const PinholeCamera& camera, const Se3& pose,
                                const EdgeIdBuffer& ids) {
  std::vector<int> total(model.edges.size(), 0), shown(model.edges.size(), 0);
  SamplingParams params;
  params.step = real(3);
  for (const ControlPoint& p : sample_control_points(model, camera, pose, params)) {
    ++total[p.edge];
    shown[p.edge] += ids.shows(p.edge, p.pixel, p.direction);
  }
  std::vector<double> share(model.edges.size(), 0.0);
  for (size_t e = 0; e < share.size(); ++e) share[e] = total[e] ? double(shown[e]) / total[e] : -1.0;
  return share;
}

/// The edge at every pixel, row by row.
std::vector<int> edge_image(const EdgeIdBuffer& ids) {
  std::vector<int> edges;
  for (int y = 0; y < ids.height(); ++y)
    for (int x = 0; x < ids.width(); ++x) edges.push_back(ids.edge_at(x, y));
  return edges;
}

}  // namespace

static void test_edge_id_buffer() {
  const Result<EdgeModel> loaded = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("the cube loads", loaded.ok(), true);
  if (!loaded.ok()) return;
  const EdgeModel& cube = loaded.value();
  const PinholeCamera camera{real(300), real(300), real(160), real(120), 320, 240};
  EdgeIdBuffer ids(camera);

  // Face-on from 150 mm: the face z = -30 mm is in front; all other edges lie behind it.
  const Se3 face_on(Mat33::identity(), {real(0), real(0), real(0.15)});
  ids.render(cube, face_on);
  std::vector<double> share = shown_share(cube, camera, face_on, ids);
  bool front_shown = true, others_hidden = true;
  for (size_t e = 0; e < cube.edges.size(); ++e) {
    const bool front = cube.edges[e].a < 4 && cube.edges[e].b < 4;
    if (front) front_shown &= share[e] >= 0.9;
    if (!front && share[e] >= 0) others_hidden &= share[e] == 0.0;
  }
  TEST("face-on, the 4 front edges are shown at 90 % or more of their points", front_shown, true);
  TEST("face-on, no point of the 8 other edges is shown", others_hidden, true);
  TEST_EQUAL("the centre of the front face is no edge", ids.edge_at(160, 120), -1);
  std::vector<int32_t> depth;
  ids.surface_depth(depth);
  TEST("the front face is in the depth buffer at the centre", depth[120 * 320 + 160] > 0, true);
  TEST_EQUAL("outside the image there is no edge", ids.edge_at(-1, 5), -1);

  // Turned: three faces visible, the farthest corner's three edges hidden.
  const Se3 turned(rotation_exp({real(0.45), real(0.6), real(0.1)}), {real(0.005), real(-0.004), real(0.16)});
  ids.render(cube, turned);
  share = shown_share(cube, camera, turned, ids);
  int farthest = 0;
  for (int v = 1; v < 8; ++v)
    if ((turned * cube.vertices[v]).z > (turned * cube.vertices[farthest]).z) farthest = v;
  int hidden_edges = 0, shown_edges = 0;
  bool hidden_are_at_far_corner = true;
  for (size_t e = 0; e < cube.edges.size(); ++e) {
    const bool at_far = cube.edges[e].a == farthest || cube.edges[e].b == farthest;
    if (share[e] >= 0.9) ++shown_edges;
    if (share[e] == 0.0) {
      ++hidden_edges;
      hidden_are_at_far_corner &= at_far;
    }
  }
  TEST_EQUAL("turned, 9 edges are shown", shown_edges, 9);
  TEST_EQUAL("turned, 3 edges are hidden", hidden_edges, 3);
  TEST("the hidden edges are those of the farthest corner", hidden_are_at_far_corner, true);

  // Reusing the buffer: the face-on frame again gives the same colours as a fresh buffer.
  ids.render(cube, face_on);
  EdgeIdBuffer fresh(camera);
  fresh.render(cube, face_on);
  std::vector<int32_t> fresh_depth;
  ids.surface_depth(depth);
  fresh.surface_depth(fresh_depth);
  TEST("a reused buffer equals a fresh one", edge_image(ids) == edge_image(fresh) && depth == fresh_depth, true);

  // Half a byte per pixel for a model of up to 15 primitives, a byte up to 255, RGB565 for any:
  // the same edges everywhere.
  EdgeIdBuffer nibbles(camera, primitive_count(cube)), bytes(camera, EdgeIdBuffer::kNarrowPrimitives), wide(camera);
  nibbles.render(cube, turned);
  bytes.render(cube, turned);
  wide.render(cube, turned);
  TEST_EQUAL("the cube's Edge-ID image takes half a byte per pixel", nibbles.image_bytes(), size_t(320 * 240 / 2));
  TEST_EQUAL("a byte for up to 255 primitives", bytes.image_bytes(), size_t(320 * 240));
  TEST_EQUAL("or two as RGB565", wide.image_bytes(), size_t(2 * 320 * 240));
  TEST("all show the same edge at every pixel",
       edge_image(nibbles) == edge_image(wide) && edge_image(bytes) == edge_image(wide), true);
  // Drawn again from another pose, each image's last lines are cleared, not left behind.
  nibbles.render(cube, face_on);
  wide.render(cube, face_on);
  TEST("a redrawn half-byte image equals the RGB565 one", edge_image(nibbles) == edge_image(wide), true);

  // Partly outside the image and partly behind the camera: no crash, nothing drawn off-image.
  const Se3 close(Mat33::identity(), {real(0.02), real(0), real(0.0)});
  ids.render(cube, close);
  TEST_EQUAL("a cube around the camera renders without leaving the buffers", edge_image(ids).size(), size_t(320 * 240));
}

TESTMAIN(test_edge_id_buffer)
