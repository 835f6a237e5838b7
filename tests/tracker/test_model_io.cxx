// SPDX-License-Identifier: BSD-3-Clause
/// Model loading: .cao and .obj files give the contour edges the crease rule promises, and bad
/// files give errors naming the file and the line.
#include <cstdio>
#include <fstream>
#include <string>

#include "edgetrack/model_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = std::string(EDGETRACK_TEST_OUTPUT) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

int count_edges_between(const EdgeModel& model, int a, int b) {
  int n = 0;
  for (const Edge& e : model.edges) n += (e.a == a && e.b == b) || (e.a == b && e.b == a);
  return n;
}

}  // namespace

static void test_model_io() {
  const std::string data = EDGETRACK_DATA_DIR;
  const std::string visp = EDGETRACK_VISP_IMAGES;

  const Result<EdgeModel> visp_cube = load_model(visp + "/mbt/cube.cao");
  TEST("ViSP's mbt/cube.cao loads", visp_cube.ok(), true);
  if (visp_cube.ok()) {
    TEST_EQUAL("ViSP's 84 mm cube has 12 contour edges", visp_cube.value().edges.size(), size_t(12));
    TEST_EQUAL("ViSP's cube has 6 faces, 12 triangles", visp_cube.value().triangles.size(), size_t(12));
    TEST_NEAR("ViSP's cube point 1 is at x = -0.084", visp_cube.value().vertices[1].x, -0.084, 1e-4);
  }

  const Result<EdgeModel> cube = load_model(data + "/models/cube60.cao");
  TEST("data/models/cube60.cao loads", cube.ok(), true);
  if (cube.ok()) {
    TEST_EQUAL("the 60 mm cube has 12 contour edges", cube.value().edges.size(), size_t(12));
    bool every_edge_has_two_faces = true;
    for (const Edge& e : cube.value().edges) every_edge_has_two_faces &= e.faces[0] >= 0 && e.faces[1] >= 0;
    TEST("every cube edge borders two faces", every_edge_has_two_faces, true);
    TEST_NEAR("face normals point outwards (face x+ has normal +x)", cube.value().faces[5].normal.x, 1.0, 1e-3);
    TEST_EQUAL("face names come from name=", cube.value().faces[5].attributes.name, std::string("x+"));
  }

  const Result<EdgeModel> cube_obj = load_model(data + "/models/cube60.obj");
  TEST("data/models/cube60.obj loads", cube_obj.ok(), true);
  if (cube_obj.ok()) {
    TEST_EQUAL("the triangulated cube still has 12 contour edges: diagonals are not tracked",
               cube_obj.value().edges.size(), size_t(12));
    TEST_EQUAL("the diagonal 0-2 of the bottom face is not an edge", count_edges_between(cube_obj.value(), 0, 2), 0);
  }

  const Result<EdgeModel> toy = load_model(data + "/models/wood_toy.cao");
  TEST("data/models/wood_toy.cao loads", toy.ok(), true);
  if (toy.ok()) {
    TEST_EQUAL("the wood toy has 30 contour edges", toy.value().edges.size(), size_t(30));
    // The L-shaped top (6 corners) and bottom need 4 triangles each; 11 quads need 2 each.
    TEST_EQUAL("the non-convex L faces triangulate into 4 triangles each", toy.value().triangles.size(),
               size_t(4 + 4 + 11 * 2));
    TEST_EQUAL("the tower's lower edge 12-13 (a crease on the base) is tracked",
               count_edges_between(toy.value(), 12, 13), 1);
  }

  // A looser crease rule: a shallow roof (10 degrees) is tracked at 5 degrees and not at 30.
  Polygons roof;
  roof.vertices = {{real(0), real(0), real(0)}, {real(1), real(0), real(0)}, {real(1), real(1), real(0.0882)},
                   {real(0), real(1), real(0.0882)}, {real(1), real(2), real(0)}, {real(0), real(2), real(0)}};
  roof.faces = {{0, 1, 2, 3}, {3, 2, 4, 5}};
  EdgeRules strict;
  const Result<EdgeModel> roof_30 = build_edge_model(roof, strict, "roof");
  EdgeRules loose;
  loose.crease_angle = real(0.0872664626);  // 5 degrees
  const Result<EdgeModel> roof_5 = build_edge_model(roof, loose, "roof");
  TEST("a 10 degree ridge is not tracked with a 30 degree crease angle",
       roof_30.ok() && count_edges_between(roof_30.value(), 2, 3) == 0, true);
  TEST("a 10 degree ridge is tracked with a 5 degree crease angle",
       roof_5.ok() && count_edges_between(roof_5.value(), 2, 3) == 1, true);

  const std::string bad_point = write_file("bad_point.cao", "V1\n# points\n3\n0 0 0\n1 0 zero\n0 1 0\n");
  const Result<EdgeModel> bad = load_model(bad_point);
  TEST("a malformed point is reported at its line", !bad.ok() && bad.error().line == 5, true);
  const std::string bad_index = write_file("bad_index.cao", "V1\n3\n0 0 0\n1 0 0\n0 1 0\n0\n0\n1\n3 0 1 7\n");
  const Result<EdgeModel> bad_face = load_model(bad_index);
  TEST("a face using a missing point is reported at its line", !bad_face.ok() && bad_face.error().line == 9, true);
  const std::string bad_obj = write_file("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  const Result<EdgeModel> obj = load_model(bad_obj);
  TEST("an .obj face with a missing vertex is reported at its line", !obj.ok() && obj.error().line == 4, true);
  const Result<EdgeModel> missing = load_model(data + "/models/no_such_model.cao");
  TEST("a missing file is an error, not an exit", !missing.ok() && contains(missing.error().text(), "no_such_model"),
       true);

  // Edge-ID names at most 32767 edges: a model of 32768 free lines is refused, 32767 accepted.
  Polygons lines;
  for (int i = 0; i <= 32768; ++i) lines.vertices.push_back({real(i % 100), real(i / 100), real(0)});
  for (int i = 0; i < 32767; ++i) lines.lines.emplace_back(i, i + 1);
  TEST("32767 edges are accepted", build_edge_model(lines, EdgeRules{}, "lines").ok(), true);
  lines.lines.emplace_back(32767, 32768);
  const Result<EdgeModel> too_many = build_edge_model(lines, EdgeRules{}, "lines");
  TEST("32768 edges are refused with a message about Edge-ID",
       !too_many.ok() && contains(too_many.error().message, "32767"), true);
}

TESTMAIN(test_model_io)
