// SPDX-License-Identifier: BSD-3-Clause
/// Template files: what is written reads back the same (features exactly, poses to the nine
/// digits written), and a file that is not a template file, of another format version, made for
/// another model or camera, cut short, or with a value out of its range is refused with its file
/// and line.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "edgetrack/detector/template_io.h"
#include "edgetrack/input_file.h"
#include "edgetrack/model_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

std::string output(const char* name) { return std::string(EDGETRACK_TEST_OUTPUT) + "/" + name; }

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

/// `text` with the first occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Reads `text` as a template file: true when it is refused at `line` with `words` in the message.
bool refused(const std::string& text, const EdgeModel& model, const PinholeCamera& camera, int line,
             const std::string& words) {
  const std::string path = output("refused_templates.txt");
  write_text(path, text);
  const Result<TemplateSet> read = read_templates(path, model, camera);
  if (read.ok()) return false;
  std::printf("  refused: %s\n", read.error().text().c_str());
  return read.error().file == path && read.error().line == line && read.error().message.find(words) != std::string::npos;
}

}  // namespace

static void test_template_files() {
  const Result<EdgeModel> cube = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  const Result<EdgeModel> toy = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/wood_toy.cao");
  TEST("the models load", cube.ok() && toy.ok(), true);
  if (!cube.ok() || !toy.ok()) return;
  const PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  TemplateParams params;
  params.views.subdivisions = 0;
  params.views.in_plane_steps = 2;
  const Result<TemplateSet> made = make_template_set(cube.value(), camera, params);
  TEST("templates are made", made.ok(), true);
  if (!made.ok()) return;
  const std::string path = output("cube_templates.txt");
  TEST("they are written", write_templates(path, made.value()).ok(), true);
  const Result<TemplateSet> read = read_templates(path, cube.value(), camera);
  TEST("and read back", read.ok(), true);
  if (!read.ok()) return;
  const TemplateSet& a = made.value();
  const TemplateSet& b = read.value();
  TEST_EQUAL("the same number of templates", b.templates.size(), a.templates.size());
  TEST_EQUAL("and distances", b.distance_count, a.distance_count);
  int features_differ = 0;
  double pose_difference = 0;
  for (size_t i = 0; i < a.features.size() && i < b.features.size(); ++i)
    features_differ += a.features[i].x != b.features[i].x || a.features[i].y != b.features[i].y ||
                       a.features[i].bin != b.features[i].bin;
  for (size_t i = 0; i < a.templates.size() && i < b.templates.size(); ++i) {
    const Se3 pa = template_pose(a.templates[i], a.extent), pb = template_pose(b.templates[i], b.extent);
    const Vec3 d = pa.translation() - pb.translation();
    const Vec2 anchor = a.templates[i].anchor - b.templates[i].anchor;
    pose_difference = std::fmax(pose_difference, std::fabs(static_cast<double>(d.x)) + std::fabs(static_cast<double>(d.y)) +
                                                     std::fabs(static_cast<double>(d.z)) +
                                                     std::fabs(static_cast<double>(anchor.x)) +
                                                     std::fabs(static_cast<double>(anchor.y)));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        pose_difference =
            std::fmax(pose_difference, std::fabs(static_cast<double>(pa.rotation().m[r][c] - pb.rotation().m[r][c])));
  }
  TEST_EQUAL("every feature reads back exactly", features_differ, 0);
  TEST_NEAR("poses and anchors read back to the digits written", pose_difference, 0.0, 1e-5);

  const Result<std::string> text = read_input_text(path);
  TEST("the file reads as text", text.ok(), true);
  if (!text.ok()) return;
  const std::string& good = text.value();
  TEST("another model is refused at the model line", refused(good, toy.value(), camera, 2, "another model"), true);
  PinholeCamera other = camera;
  other.px = real(221);
  TEST("another camera is refused at the camera line", refused(good, cube.value(), other, 3, "another camera"), true);
  TEST("a file that is not a template file is refused",
       refused("V1\n# a model\n8\n", cube.value(), camera, 1, "not an edgetrack template file"), true);
  const std::string header = "edgetrack-templates " + std::to_string(kTemplateFormatVersion);
  TEST("another format version is refused",
       refused(replaced(good, header, "edgetrack-templates 7"), cube.value(), camera, 1, "format version 7"), true);
  const std::string version_1 = output("version_1_templates.txt");
  write_text(version_1, replaced(good, header, "edgetrack-templates 1"));
  const Result<TemplateSet> read_1 = read_templates(version_1, cube.value(), camera);
  TEST("a version 1 file for a camera detection does not reduce is read",
       read_1.ok() && read_1.value().features.size() == a.features.size(), true);
  const std::string cut = good.substr(0, good.find("\nt ", good.find("\nt ") + 1));
  TEST("a file cut short is refused at its end",
       refused(cut, cube.value(), camera, 9, "the file ends"), true);
  std::istringstream lines(good);
  std::string line;
  for (int k = 0; k < 9; ++k) std::getline(lines, line);
  std::string bad_line = line;
  bad_line.replace(bad_line.size() - 1, 1, "9");  // the last feature's bin
  TEST("an orientation bin out of range is refused at its line",
       refused(replaced(good, line, bad_line), cube.value(), camera, 9, "orientation bin"), true);
  TEST("a value that is not a number is refused",
       refused(replaced(good, "features 2 32", "features two 32"), cube.value(), camera, 5, "downscale"), true);
  TEST("more templates than the header states are refused",
       refused(good + line + "\n", cube.value(), camera, static_cast<int>(9 + a.templates.size()), "more than"), true);

  // A camera above the detector's side: the file records it, and holds the templates made for
  // the camera detection reduces its frames to; a version 1 file (made at full size) is refused.
  const PinholeCamera large = camera.scaled(4);
  const Result<TemplateSet> made_large = make_template_set(cube.value(), large, params);
  const Result<TemplateSet> made_reduced = make_template_set(cube.value(), detection_camera(large), params);
  TEST("templates are made for a 1280x960 camera and for the camera it is detected at",
       made_large.ok() && made_reduced.ok(), true);
  if (!made_large.ok() || !made_reduced.ok()) return;
  TEST_EQUAL("1280x960 is detected at 640x480", detection_camera(large).width, 640);
  int large_differ = made_large.value().features.size() != made_reduced.value().features.size();
  for (size_t i = 0; !large_differ && i < made_large.value().features.size(); ++i)
    large_differ += made_large.value().features[i].x != made_reduced.value().features[i].x ||
                    made_large.value().features[i].y != made_reduced.value().features[i].y ||
                    made_large.value().features[i].bin != made_reduced.value().features[i].bin;
  TEST_EQUAL("they are the reduced camera's templates", large_differ, 0);
  const std::string large_path = output("large_templates.txt");
  TEST("they are written", write_templates(large_path, made_large.value()).ok(), true);
  const Result<TemplateSet> read_large = read_templates(large_path, cube.value(), large);
  TEST("and read back for the 1280x960 camera",
       read_large.ok() && camera_description(read_large.value().camera) == camera_description(large), true);
  const Result<std::string> large_text = read_input_text(large_path);
  if (!large_text.ok()) return;
  TEST("a version 1 file for a camera detection reduces is refused at its version",
       refused(replaced(large_text.value(), header, "edgetrack-templates 1"), cube.value(), large, 1,
               "version 1 for frames above 480 px"), true);
}

TESTMAIN(test_template_files)
