// SPDX-License-Identifier: BSD-3-Clause
/// Models read from memory: a .cao or .obj text gives the very model its file gives; a load()
/// line resolves against the base directory the caller passes and is refused at its line when
/// none is given; errors name the text by the name it was given.
#include <fstream>
#include <string>

#include "edgetrack/input_file.h"
#include "edgetrack/model_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool same_points(const EdgeModel& a, const EdgeModel& b) {
  if (a.vertices.size() != b.vertices.size() || a.edges.size() != b.edges.size()) return false;
  for (size_t i = 0; i < a.vertices.size(); ++i)
    if (a.vertices[i].x != b.vertices[i].x || a.vertices[i].y != b.vertices[i].y || a.vertices[i].z != b.vertices[i].z)
      return false;
  for (size_t i = 0; i < a.edges.size(); ++i)
    if (a.edges[i].a != b.edges[i].a || a.edges[i].b != b.edges[i].b) return false;
  return true;
}

void same_model_as_the_file(const std::string& path) {
  const Result<std::string> text = read_input_text(path);
  const Result<EdgeModel> from_file = load_model(path), from_text = load_model_text(text.value(), path);
  TEST((path + ": read from memory").c_str(), from_text.ok(), true);
  TEST((path + ": the same points and edges as from the file").c_str(),
       from_file.ok() && from_text.ok() && same_points(from_file.value(), from_text.value()), true);
}

}  // namespace

static void test_model_text() {
  const std::string data = EDGETRACK_DATA_DIR, visp = EDGETRACK_VISP_IMAGES, out = EDGETRACK_TEST_OUTPUT;
  same_model_as_the_file(visp + "/mbt/cube.cao");
  same_model_as_the_file(data + "/models/cube60.cao");
  const std::string obj = out + "/text_square.obj";
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  same_model_as_the_file(obj);

  std::ofstream(out + "/text_part.cao") << "V1\n4\n0 0 0\n0.1 0 0\n0.1 0.1 0\n0 0.1 0\n0\n0\n1\n4 0 1 2 3\n";
  const std::string includer = "V1\nload(\"text_part.cao\", t=[0; 0; 1])\n0\n0\n0\n0\n";
  const Result<EdgeModel> with_base = load_model_text(includer, "scene.cao", out);
  TEST("a load() line resolves against the base directory given", with_base.ok(), true);
  TEST("and places the part",
       with_base.ok() && with_base.value().vertices.size() == 4 && with_base.value().vertices[0].z == real(1), true);
  const Result<EdgeModel> with_slash = load_model_text(includer, "scene.cao", out + "/");
  TEST("the base directory may end with a slash", with_slash.ok(), true);

  const Result<EdgeModel> no_base = load_model_text(includer, "scene.cao");
  TEST("a relative load() with no base directory is refused", no_base.ok(), false);
  if (!no_base.ok())
    TEST("at its line, in one sentence naming the text",
         contains(no_base.error().text(), "scene.cao:2: load(\"text_part.cao\") in a model given as text needs a base directory"),
         true);
  const Result<EdgeModel> absolute = load_model_text("V1\nload(\"" + out + "/text_part.cao\")\n0\n0\n0\n0\n", "abs.cao");
  TEST("an absolute load() needs no base directory", absolute.ok() && absolute.value().vertices.size() == 4, true);

  const Result<EdgeModel> bad = load_model_text("V1\n2\n0 0 0\n0 zero 0\n", "bad.cao");
  TEST("a bad record is refused with the name and line given", !bad.ok() && contains(bad.error().text(), "bad.cao:4:"), true);
  const Result<EdgeModel> bad_obj = load_model_text("v 0 0 0\nf 1 2 9\n", "bad.obj");
  TEST("so is an .obj's", !bad_obj.ok() && contains(bad_obj.error().text(), "bad.obj:2:"), true);
  const Result<EdgeModel> unnamed = load_model_text("V1\n", "model");
  TEST("a name without .cao or .obj is refused, saying so", !unnamed.ok() && contains(unnamed.error().message, ".cao or .obj"),
       true);
}

TESTMAIN(test_model_text)
