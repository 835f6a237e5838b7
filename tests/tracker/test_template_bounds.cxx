// SPDX-License-Identifier: BSD-3-Clause
/// A template range is checked before any template is made: the camera outside the model at the
/// nearest distance, the model at least a few pixels wide at the farthest, and at most
/// kMaxTemplateViews views, few enough that the file `templates` writes is one `detect
/// --templates` reads (each template line under 900 bytes).
#include <fstream>
#include <string>

#include "edgetrack/detector/template_io.h"
#include "edgetrack/detector/viewpoints.h"
#include "edgetrack/input_file.h"
#include "edgetrack/model_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

bool refused_with(const Result<long long>& count, const std::string& words) {
  if (count.ok()) return false;
  std::printf("  refused: %s\n", count.error().message.c_str());
  return count.error().message.find(words) != std::string::npos;
}

}  // namespace

static void test_template_bounds() {
  const Result<EdgeModel> cube = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("cube60.cao loads", cube.ok(), true);
  if (!cube.ok()) return;
  const PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  const ModelExtent extent = model_extent(cube.value());  // radius 0.052 m

  ViewRange range;
  const Result<long long> defaults = checked_view_count(range, camera, extent);
  TEST("the default range: 162 directions x 18 in-plane steps per distance",
       defaults.ok() && defaults.value() % (162 * 18) == 0 && defaults.value() <= kMaxTemplateViews, true);
  range.distance_min = real(1e-3);
  range.distance_max = real(100);
  TEST("a nearest distance inside the model is refused", refused_with(checked_view_count(range, camera, extent), "inside the model"),
       true);
  range.distance_min = real(0.2);
  TEST("a farthest distance where the model spans under 16 pixels is refused",
       refused_with(checked_view_count(range, camera, extent), "under 16 pixels"), true);
  range.distance_max = real(1.4);  // 220 x 0.104 / 1.4 = 16.3 pixels
  range.subdivisions = 1;
  TEST("16 pixels at the farthest is enough", checked_view_count(range, camera, extent).ok(), true);
  range.distance_max = real(0.3);
  range.subdivisions = 4;
  range.in_plane_steps = 360;
  TEST("options inside their own ranges asking for millions of views are refused",
       refused_with(checked_view_count(range, camera, extent), "more than the 74560"), true);
  range.in_plane_steps = 4;
  const Result<long long> fits = checked_view_count(range, camera, extent);
  TEST_EQUAL("2562 directions x 4 in-plane steps x 5 distances fit", fits.ok() ? fits.value() : 0, 2562LL * 4 * 5);

  // The file bound: the longest template line, 63 features each, stays under 900 bytes.
  TemplateParams params;
  params.views.subdivisions = 0;
  params.views.in_plane_steps = 2;
  params.features = 63;
  params.min_features = 4;
  const Result<TemplateSet> made = make_template_set(cube.value(), camera, params);
  TEST("templates of 63 features are made", made.ok(), true);
  if (!made.ok()) return;
  const std::string path = std::string(EDGETRACK_TEST_OUTPUT) + "/bound_templates.txt";
  TEST("and written", write_templates(path, made.value()).ok(), true);
  std::ifstream in(path);
  std::string line;
  size_t longest = 0;
  while (std::getline(in, line))
    if (line.compare(0, 2, "t ") == 0 && line.size() + 1 > longest) longest = line.size() + 1;
  std::printf("  longest template line: %zu bytes\n", longest);
  TEST("the longest template line is under kMaxTemplateFileLineBytes",
       longest > 0 && static_cast<long long>(longest) < kMaxTemplateFileLineBytes, true);
  TEST("so the most views make a file detect --templates reads",
       static_cast<unsigned long long>(kMaxTemplateViews) * kMaxTemplateFileLineBytes + 4096 <= kMaxTextFileBytes, true);
}

TESTMAIN(test_template_bounds)
