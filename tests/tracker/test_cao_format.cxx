// SPDX-License-Identifier: BSD-3-Clause
/// The .cao format as ViSP reads it: every primitive and its parameters, comments and Windows
/// line ends, load() includes (nested, relative to the including file, placed by t= and tu=,
/// indices local to each file), and bad includes (a missing file, a cycle) reported with the
/// chain of load() lines; includes within their limits (a chain of thousands of files read
/// without recursion, files known by identity through symbolic links).
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "edgetrack/model_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

std::string output_path(const std::string& name) { return std::string(EDGETRACK_TEST_OUTPUT) + "/" + name; }

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = output_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// `base`, or `steps` steps of the real's resolution where that is coarser (S47.16: 2^-16).
double tolerance(double base, double steps) {
  return std::max(base, steps * static_cast<double>(std::numeric_limits<real>::epsilon()));
}

/// Points 0-3 a unit square at z = 0, 4 above its centre, 5-6 on the plane z = 0.5 (V1).
const char* kEveryPrimitive =
    "V1\n"
    "# a comment line\n"
    "7 # points\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.5\n1 0.5 0.5\n0.5 1 0.5\n"
    "5\n"
    "0 1 name=bottom\n1 2\n2 3\n3 0\n"
    "0 4 name=mast useLod=true minLineLengthThreshold=12.5\n"
    "1\n"
    "4 0 1 2 3 name=\"square face\" minPolygonAreaThreshold=300 useLod=false\n"
    "1\n"
    "3 0 1 4 name=fin\n"
    "1\n"
    "0 4 0.25 name=post minLineLengthThreshold=7 useLod=1\n"
    "1\n"
    "0.2 4 5 6 name=ring minPolygonAreaThreshold=40.5\n";

void test_every_primitive() {
  const Result<EdgeModel> model = load_model(write_file("every_primitive.cao", kEveryPrimitive));
  TEST("a .cao with every primitive loads", model.ok(), true);
  if (!model.ok()) {
    std::printf("%s\n", model.error().text().c_str());
    return;
  }
  const EdgeModel& m = model.value();
  TEST_EQUAL("7 points", m.vertices.size(), size_t(7));
  TEST_EQUAL("two faces: one from lines, one from points", m.faces.size(), size_t(2));
  TEST_EQUAL("a face from lines keeps its quoted name", m.faces[0].attributes.name, std::string("square face"));
  TEST("a face's minPolygonAreaThreshold is stored",
       m.faces[0].attributes.min_polygon_area.has_value() && *m.faces[0].attributes.min_polygon_area == real(300), true);
  TEST("a face's useLod=false is stored", m.faces[0].attributes.use_lod.has_value() && !*m.faces[0].attributes.use_lod,
       true);
  TEST_EQUAL("a face from points keeps its name", m.faces[1].attributes.name, std::string("fin"));
  TEST("a face without useLod leaves it to the general setting", m.faces[1].attributes.use_lod.has_value(), false);
  const Edge* mast = nullptr;
  for (const Edge& e : m.edges)
    if ((e.a == 0 && e.b == 4) || (e.a == 4 && e.b == 0)) mast = &e;
  TEST("the free line 0-4 is tracked", mast != nullptr, true);
  if (mast) {
    TEST_EQUAL("a line keeps its name", mast->attributes.name, std::string("mast"));
    TEST("a line's useLod=true and minLineLengthThreshold are stored",
         mast->attributes.use_lod.value_or(false) && mast->attributes.min_line_length.value_or(real(0)) == real(12.5),
         true);
  }
  TEST_EQUAL("one cylinder", m.cylinders.size(), size_t(1));
  if (m.cylinders.size() == 1) {
    const Cylinder& c = m.cylinders[0];
    TEST_NEAR("the cylinder's radius", c.radius, 0.25, 1e-6);
    TEST_NEAR("the cylinder's second axis point is point 4", c.axis_b.z, 0.5, 1e-6);
    TEST_EQUAL("the cylinder keeps its name", c.attributes.name, std::string("post"));
    TEST("the cylinder's useLod=1 and minLineLengthThreshold are stored",
         c.attributes.use_lod.value_or(false) && c.attributes.min_line_length.value_or(real(0)) == real(7), true);
    TEST_EQUAL("its side is tessellated", m.cylinder_surface.size(), size_t(2 * kCylinderSides));
    TEST_EQUAL("its rims' points, each once", m.cylinder_points.size(), size_t(2 * (kCylinderSides + 1)));
    int named = 0, facets_closing = 0;
    for (const SurfaceTriangle& t : m.cylinder_surface) {
      for (int i = 0; i < 3; ++i) {
        const size_t p = static_cast<size_t>(t.points[i]);
        const Vec3& corner = t.corners[i];
        if (p < m.cylinder_points.size() && m.cylinder_points[p].x == corner.x && m.cylinder_points[p].y == corner.y &&
            m.cylinder_points[p].z == corner.z)
          ++named;
      }
      facets_closing += t.points[1] == kCylinderSides ? 1 : 0;  // the base rim's last point, at 2 pi
    }
    TEST_EQUAL("every facet corner is the rim point it names", named, 3 * 2 * kCylinderSides);
    TEST_EQUAL("the last facet closes on the rim's last point", facets_closing, 1);
  }
  TEST_EQUAL("one circle", m.circles.size(), size_t(1));
  if (m.circles.size() == 1) {
    const Circle& c = m.circles[0];
    // A number read from text rounds to the nearest step: within one step.
    TEST_NEAR("the circle's radius comes first on its line", c.radius, 0.2, tolerance(1e-6, 1));
    TEST_NEAR("the circle's centre is point 4", c.centre.z, 0.5, 1e-6);
    TEST_NEAR("its plane through points 4, 5, 6 is z = 0.5: normal along z", std::fabs(double(c.normal.z)), 1, 1e-6);
    TEST_EQUAL("the circle keeps its name", c.attributes.name, std::string("ring"));
    TEST("the circle's minPolygonAreaThreshold is stored",
         c.attributes.min_polygon_area.value_or(real(0)) == real(40.5), true);
    TEST_EQUAL("its rim has kCircleSides + 1 points", c.rim.size(), size_t(kCircleSides + 1));
    TEST_EQUAL("it closes no cylinder (radius 0.2, not 0.25)", c.cap_of, -1);
  }
  TEST_EQUAL("primitives: edges, 2 per cylinder, 1 per circle", primitive_count(m),
             static_cast<int>(m.edges.size()) + 3);
}

void test_line_ends_and_visp_files() {
  std::string crlf;
  for (const char* c = kEveryPrimitive; *c; ++c) crlf += *c == '\n' ? std::string("\r\n") : std::string(1, *c);
  const Result<EdgeModel> windows = load_model(write_file("windows.cao", crlf));
  TEST("Windows line ends read as Unix ones", windows.ok() && windows.value().circles.size() == 1 &&
                                                  windows.value().faces[0].attributes.name == "square face",
       true);
  const std::string visp = EDGETRACK_VISP_IMAGES;
  const Result<EdgeModel> both = load_model(visp + "/mbt/cube_and_cylinder.cao");
  TEST("ViSP's mbt/cube_and_cylinder.cao loads", both.ok(), true);
  if (both.ok()) {
    TEST_EQUAL("its cube has 12 edges", both.value().edges.size(), size_t(12));
    TEST_EQUAL("and one cylinder", both.value().cylinders.size(), size_t(1));
    TEST_NEAR("of radius 0.04", both.value().cylinders[0].radius, 0.04, tolerance(1e-6, 1));
  }
  for (const char* name : {"linux", "windows"}) {
    const Result<EdgeModel> m = load_model(visp + "/mbt-cao/cylinder_cao_model_" + name + "_line_ending.cao");
    TEST((std::string("ViSP's mbt-cao cylinder model with ") + name + " line ends loads").c_str(),
         m.ok() && m.value().cylinders.size() == 1 && m.value().circles.size() == 1, true);
    if (m.ok() && m.value().circles.size() == 1)
      TEST_EQUAL("its circle closes its cylinder", m.value().circles[0].cap_of, 0);
  }
}

void test_v2_and_trailing_text() {
  // V2 points carry two image coordinates; text after a record's numbers (ViSP's "// comment")
  // is ignored, and parameters stop at the first word that is not one.
  const Result<EdgeModel> v2 = load_model(write_file(
      "v2.cao", "V2\n3\n0 0 0 10 20\n1 0 0 11 21 // a note\n0 1 0 12 22\n0\n0\n1\n3 0 1 2 // face name=ignored\n"));
  TEST("a V2 file with trailing text loads", v2.ok(), true);
  if (v2.ok()) {
    TEST_NEAR("V2 points keep X Y Z", v2.value().vertices[1].x, 1, 1e-9);
    TEST_EQUAL("a name= after other text is not a parameter (as ViSP)", v2.value().faces[0].attributes.name,
               std::string());
  }
  const Result<EdgeModel> short_v2 = load_model(write_file("short_v2.cao", "V2\n1\n0 0 0\n0\n0\n0\n"));
  TEST("a V2 point without its image coordinates is reported at its line",
       !short_v2.ok() && short_v2.error().line == 3, true);
}

void test_includes() {
  // main.cao includes parts/wheel.cao twice over (once through parts/axle.cao, so the second
  // load is skipped as ViSP skips a file already in the model) and places it with t and tu.
  const std::string dir = output_path("");
  mkdir(output_path("parts").c_str(), 0755);
  write_file("parts/wheel.cao", "V1\n3\n0 0 0\n0.1 0 0\n0 0.1 0\n0\n0\n1\n3 0 1 2 name=wheel\n0\n0\n");
  write_file("parts/axle.cao",
             "V1\nload(\"wheel.cao\", t=[0; 0; 1], tu=[0; 0; 90deg])\n2\n0 0 0\n0 0 1\n1\n0 1 name=axle\n0\n0\n0\n0\n");
  const std::string main_path = write_file(
      "main.cao", "V1\nload(\"parts/axle.cao\")\nload(\"./parts/../parts/wheel.cao\")\n"
                  "4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0\n0\n1\n4 0 1 2 3 name=base\n");
  const Result<Polygons> parts = read_cao(main_path);
  TEST("nested includes load", parts.ok(), true);
  if (parts.ok()) {
    const Polygons& p = parts.value();
    TEST_EQUAL("3 wheel + 2 axle + 4 base points, the wheel once", p.vertices.size(), size_t(9));
    TEST_EQUAL("the wheel's face, then the base's", p.faces.size(), size_t(2));
    TEST_EQUAL("included parts come first", p.face_attributes[0].name, std::string("wheel"));
    TEST("the base's indices are moved past the included points",
         p.faces.size() == 2 && p.faces[1][0] == 5 && p.faces[1][3] == 8, true);
    TEST("the axle's line uses the axle's own points 3 and 4",
         p.lines.size() == 1 && p.lines[0].first == 3 && p.lines[0].second == 4, true);
    TEST_NEAR("t places the wheel: its point 0 at z = 1", p.vertices[0].z, 1, 1e-6);
    // The point rounds once as read and once through the rotation (sin, cos of 90 deg): 2 steps.
    TEST_NEAR("tu=[0;0;90deg] turns its point 1 (0.1, 0, 0) to (0, 0.1, 1): y", p.vertices[1].y, 0.1, tolerance(1e-6, 2));
    TEST_NEAR("x", p.vertices[1].x, 0, tolerance(1e-6, 2));
  }

  const std::string missing = write_file("missing_top.cao", "V1\nload(\"missing_mid.cao\")\n0\n0\n0\n0\n");
  write_file("missing_mid.cao", "V1\n# the part\nload(\"nowhere/gone.cao\")\n0\n0\n0\n0\n");
  const Result<Polygons> gone = read_cao(missing);
  TEST("a missing include is an error", gone.ok(), false);
  if (!gone.ok()) {
    std::printf("%s\n", gone.error().text().c_str());
    TEST("it is reported at the load() line that names it", contains(gone.error().text(), "missing_mid.cao:3:"), true);
    TEST("with the include chain, file:line of each load()",
         contains(gone.error().message, "missing_top.cao:2 -> " + dir + "missing_mid.cao:3 -> " + dir +
                                            "nowhere/gone.cao"),
         true);
  }

  write_file("cycle_a.cao", "V1\nload(\"cycle_b.cao\")\n1\n0 0 0\n0\n0\n0\n");
  write_file("cycle_b.cao", "V1\n\nload(\"cycle_a.cao\")\n1\n0 0 0\n0\n0\n0\n");
  const Result<Polygons> cycle = read_cao(output_path("cycle_a.cao"));
  TEST("a cycle of includes is an error", cycle.ok(), false);
  if (!cycle.ok()) {
    std::printf("%s\n", cycle.error().text().c_str());
    TEST("it says so", contains(cycle.error().message, "cycle"), true);
    TEST("and shows the chain back to the first file",
         contains(cycle.error().message, "cycle_a.cao:2 -> " + dir + "cycle_b.cao:3 -> " + dir + "cycle_a.cao"), true);
  }
  const std::string bad_load = write_file("bad_load.cao", "V1\nload(parts/wheel.cao)\n0\n0\n0\n0\n");
  const Result<Polygons> unquoted = read_cao(bad_load);
  TEST("an unquoted load() path is reported at its line", !unquoted.ok() && unquoted.error().line == 2, true);
}

/// Writes chain_0.cao .. chain_{n-1}.cao in `dir`, each loading the next and holding one point.
std::string write_chain(const std::string& dir, int n) {
  mkdir(output_path(dir).c_str(), 0755);
  for (int i = 0; i < n; ++i) {
    const std::string load = i + 1 < n ? "load(\"chain_" + std::to_string(i + 1) + ".cao\")\n" : "";
    write_file(dir + "/chain_" + std::to_string(i) + ".cao", "V1\n" + load + "1\n0 0 " + std::to_string(i) + "\n0\n0\n0\n");
  }
  return output_path(dir + "/chain_0.cao");
}

void test_include_limits() {
  // A chain of thousands of files is read without recursion (it overflowed the stack).
  const std::string chain = write_chain("long_chain", 3000);
  const Result<Polygons> long_chain = read_cao(chain);
  TEST("a chain of 3000 load()ed files loads", long_chain.ok(), true);
  TEST("with a point from each", long_chain.ok() && long_chain.value().vertices.size() == 3000, true);

  CaoIncludeLimits shallow;
  shallow.max_depth = 100;
  const Result<Polygons> deep = read_cao(chain, shallow);
  TEST("a chain deeper than the limit is refused", deep.ok(), false);
  if (!deep.ok()) {
    const std::string text = deep.error().text();
    std::printf("%s\n", text.c_str());
    TEST("naming the limit", contains(text, "deeper than 100 files"), true);
    TEST("at the load() line of the last file read", contains(text, "chain_99.cao:2:"), true);
    TEST("the chain abbreviated: first links, the count between, last links",
         contains(text, "chain_0.cao:2 -> ") && contains(text, "(94 more) -> ") &&
             contains(text, "chain_99.cao:2 -> " + output_path("long_chain/chain_100.cao")),
         true);
    TEST("on one short line", text.find('\n') == std::string::npos && text.size() < 1000, true);
  }

  // The same part reached through a symbolic link to its directory is one file: read once,
  // and a link back to a directory on the chain is a cycle (names differ, the file does not).
  mkdir(output_path("linked").c_str(), 0755);
  mkdir(output_path("linked/parts").c_str(), 0755);
  symlink("parts", output_path("linked/alias").c_str());
  symlink("..", output_path("linked/parts/up").c_str());
  write_file("linked/parts/wheel.cao", "V1\n1\n0 0 0\n0\n0\n0\n");
  const Result<Polygons> once =
      read_cao(write_file("linked/main.cao", "V1\nload(\"parts/wheel.cao\")\nload(\"alias/wheel.cao\")\n"
                                             "load(\"alias/up/alias/wheel.cao\")\n1\n0 0 1\n0\n0\n0\n"));
  TEST("a part reached through links to its directory is loaded once",
       once.ok() && once.value().vertices.size() == 2, true);
  write_file("linked/parts/back.cao", "V1\nload(\"up/alias/back.cao\")\n1\n0 0 0\n0\n0\n0\n");
  const Result<Polygons> cycle = read_cao(output_path("linked/parts/back.cao"));
  TEST("a cycle through a link is recognised", !cycle.ok() && contains(cycle.error().message, "cycle"), true);

  // A fan of ten parts against limits on the number of files and on their bytes.
  std::string fan = "V1\n";
  for (int i = 0; i < 10; ++i) {
    write_file("fan_" + std::to_string(i) + ".cao", "V1\n1\n0 0 " + std::to_string(i) + "\n0\n0\n0\n");
    fan += "load(\"fan_" + std::to_string(i) + ".cao\")\n";
  }
  const std::string fan_path = write_file("fan.cao", fan + "0\n0\n0\n0\n");
  TEST("the fan of ten parts loads", read_cao(fan_path).ok(), true);
  CaoIncludeLimits few_files;
  few_files.max_files = 5;
  const Result<Polygons> many = read_cao(fan_path, few_files);
  TEST("more files than the limit are refused at the load() that passes it",
       !many.ok() && contains(many.error().message, "more than 5 files") && many.error().line == 6, true);
  CaoIncludeLimits few_bytes;
  few_bytes.max_bytes = fan.size() + 60;
  const Result<Polygons> big = read_cao(fan_path, few_bytes);
  TEST("more bytes than the limit are refused before reading",
       !big.ok() && contains(big.error().message, "more than " + std::to_string(few_bytes.max_bytes) + " bytes"), true);
}

void test_visp_readings() {
  // ViSP lowercases useLod's value, and loads a face of two points as one line.
  const Result<Polygons> p = read_cao(write_file(
      "visp_readings.cao", "V1\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0\n0\n3\n3 0 1 2 useLod=True\n"
                           "3 0 2 3 useLod=FALSE\n2 1 3 name=diagonal useLod=TRUE minLineLengthThreshold=5\n"));
  TEST("useLod=True, FALSE and TRUE are read", p.ok(), true);
  if (!p.ok()) return;
  const Polygons& m = p.value();
  TEST("True is true", m.face_attributes.size() == 2 && m.face_attributes[0].use_lod == true, true);
  TEST("FALSE is false", m.face_attributes.size() == 2 && m.face_attributes[1].use_lod == false, true);
  TEST("the face of two points is a line, not a face", m.faces.size() == 2 && m.lines.size() == 1, true);
  TEST("from point 1 to point 3 with its parameters",
       m.lines.size() == 1 && m.lines[0].first == 1 && m.lines[0].second == 3 &&
           m.line_attributes[0].name == "diagonal" && m.line_attributes[0].use_lod == true,
       true);
  TEST("but the general line length: ViSP reads no minLineLengthThreshold on a face",
       m.line_attributes.size() == 1 && !m.line_attributes[0].min_line_length.has_value(), true);
}

void test_bad_records() {
  const struct {
    const char* text;
    int line;
    const char* what;
  } cases[] = {
      {"V1\n2\n0 0 0\n1 0 0\n0\n0\n0\n1\n0 1 -0.5\n", 9, "a cylinder with a negative radius"},
      {"V1\n2\n0 0 0\n1 0 0\n0\n0\n0\n1\n0 5 0.5\n", 9, "a cylinder axis point out of range"},
      {"V1\n3\n0 0 0\n1 0 0\n0 1 0\n0\n0\n0\n0\n1\n0.5 0 1 9\n", 11, "a circle point out of range"},
      {"V1\n3\n0 0 0\n1 0 0\n0 1 0\n0\n0\n1\n3 0 1 2 useLod=maybe\n", 9, "a useLod= that is not a boolean"},
      {"V1\n0\n0\n0\n0\n", 2, "a file without points or includes"},
  };
  for (const auto& c : cases) {
    const Result<EdgeModel> m = load_model(write_file("bad_record.cao", c.text));
    TEST((std::string(c.what) + " is reported at its line").c_str(), !m.ok() && m.error().line == c.line, true);
  }
  // A circle whose plane points are on one line with its centre has no plane.
  const Result<EdgeModel> flat = load_model(write_file("flat_circle.cao", "V1\n3\n0 0 0\n1 0 0\n2 0 0\n0\n0\n0\n0\n1\n0.5 0 1 2\n"));
  TEST("a circle without a plane is refused", !flat.ok() && contains(flat.error().message, "circle 0"), true);
}

void test_primitive_limit() {
  // Edge-ID names at most 32767 primitives, and a cylinder counts twice: 32765 lines and a
  // cylinder fit, one more circle does not.
  Polygons p;
  for (int i = 0; i <= 32766; ++i) p.vertices.push_back({real(i % 100), real(i / 100), real(0)});
  for (int i = 0; i < 32765; ++i) p.lines.emplace_back(i, i + 1);
  CylinderRecord cylinder;
  cylinder.axis_a = 0;
  cylinder.axis_b = 1;
  cylinder.radius = real(0.1);
  p.cylinders.push_back(cylinder);
  TEST("32765 lines and a cylinder (32767 primitives) are accepted", build_edge_model(p, EdgeRules{}, "p").ok(), true);
  CircleRecord circle;
  circle.centre = 0;
  circle.plane_a = 1;
  circle.plane_b = 100;
  circle.radius = real(0.1);
  p.circles.push_back(circle);
  const Result<EdgeModel> too_many = build_edge_model(p, EdgeRules{}, "p");
  TEST("one circle more is refused, naming the limit", !too_many.ok() && contains(too_many.error().message, "32767"),
       true);
}

}  // namespace

static void test_cao_format() {
  test_every_primitive();
  test_line_ends_and_visp_files();
  test_v2_and_trailing_text();
  test_includes();
  test_include_limits();
  test_visp_readings();
  test_bad_records();
  test_primitive_limit();
}

TESTMAIN(test_cao_format)
