// SPDX-License-Identifier: BSD-3-Clause
/// Templates linked as constant data (`edgetrack templates --cxx`, built into this test from the
/// tree's own edgetrack) are the templates of the file written with them, read in place: the
/// same header, templates and features, bit for bit, with no copy on the heap, and a detector
/// keeps them there. Another camera's constant templates are refused as its file would be.
#include <cstring>

#include "edgetrack/detector/detector.h"
#include "edgetrack/detector/template_io.h"
#include "edgetrack/model_io.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

extern const edgetrack::ConstantTemplates edgetrack_constant_templates;

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

bool same_bits(const real& a, const real& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_template(const Template& a, const Template& b) {
  return same_bits(a.theta_u.x, b.theta_u.x) && same_bits(a.theta_u.y, b.theta_u.y) &&
         same_bits(a.theta_u.z, b.theta_u.z) && same_bits(a.distance, b.distance) &&
         a.distance_index == b.distance_index && same_bits(a.anchor.x, b.anchor.x) &&
         same_bits(a.anchor.y, b.anchor.y) && a.width == b.width && a.height == b.height && a.first == b.first &&
         a.count == b.count;
}

}  // namespace

static void test_constant_templates() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const Result<TemplateSet> file = read_templates(EDGETRACK_CONSTANT_TEMPLATES_FILE, model.value(), camera);
  const Result<TemplateSet> constant =
      constant_template_set(edgetrack_constant_templates, model.value(), camera, "constant templates");
  TEST("the template file reads", file.ok(), true);
  TEST("the constant templates read", constant.ok(), true);
  if (!file.ok() || !constant.ok()) return;
  const TemplateSet& a = file.value();
  const TemplateSet& b = constant.value();
  TEST("they are read in place", b.templates.read_in_place() && b.features.read_in_place(), true);
  TEST("from the linked arrays themselves", b.templates.begin() == edgetrack_constant_templates.templates &&
                                                b.features.begin() == edgetrack_constant_templates.features,
       true);
  TEST_EQUAL("the same camera", camera_description(b.camera), camera_description(a.camera));
  TEST("the same view range and feature settings",
       a.params.views.subdivisions == b.params.views.subdivisions &&
           a.params.views.in_plane_steps == b.params.views.in_plane_steps &&
           same_bits(a.params.views.distance_min, b.params.views.distance_min) &&
           same_bits(a.params.views.distance_max, b.params.views.distance_max) &&
           same_bits(a.params.views.max_angle, b.params.views.max_angle) && a.params.downscale == b.params.downscale &&
           a.params.features == b.params.features && same_bits(a.params.sample_step, b.params.sample_step),
       true);
  TEST("the same extent and distances", same_bits(a.extent.radius, b.extent.radius) &&
                                            a.distance_count == b.distance_count,
       true);
  TEST_EQUAL("the same number of templates", b.templates.size(), a.templates.size());
  TEST_EQUAL("and of features", b.features.size(), a.features.size());
  int templates_differ = 0, features_differ = 0;
  for (size_t i = 0; i < a.templates.size() && i < b.templates.size(); ++i)
    templates_differ += !same_template(a.templates[i], b.templates[i]);
  for (size_t i = 0; i < a.features.size() && i < b.features.size(); ++i)
    features_differ += a.features[i].x != b.features[i].x || a.features[i].y != b.features[i].y ||
                       a.features[i].bin != b.features[i].bin;
  TEST_EQUAL("every template the same, bit for bit", templates_differ, 0);
  TEST_EQUAL("every feature the same", features_differ, 0);

  const Result<Detector> detector =
      Detector::create(model.value(), camera, constant.value(), DetectorParams{}, TrackerParams{});
  TEST("a detector takes them", detector.ok(), true);
  if (detector.ok())
    TEST("and reads them in place", detector.value().templates().templates.begin() == edgetrack_constant_templates.templates,
         true);

  PinholeCamera other = camera;
  other.px = real(300);
  TEST("constant templates for another camera are refused",
       constant_template_set(edgetrack_constant_templates, model.value(), other, "constant templates").ok(), false);
}

TESTMAIN(test_constant_templates)
