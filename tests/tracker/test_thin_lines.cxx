// SPDX-License-Identifier: BSD-3-Clause
/// The thin-line test (thin_lines.h; issue #27, drift in clutter): a profile with a dark line
/// beside a step against the step alone, a match moved to its alternative or dropped, its
/// settings by name, and the generated cube with dark lines 8 mm beside every edge, where the
/// tracker with the defaults walks onto the lines and with the test stays on the cube.
#include <cstdio>
#include <string>

#include "edgetrack/thin_lines.h"
#include "edgetrack/tracker_params.h"
#include "edgetrack/visp_config.h"
#include "run_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// A 20 x 20 image whose columns follow `profile` (one grey level per column).
vpImage<unsigned char> columns(const int (&profile)[20]) {
  vpImage<unsigned char> image(20, 20);
  for (unsigned i = 0; i < 20; ++i)
    for (unsigned j = 0; j < 20; ++j) image[i][j] = static_cast<unsigned char>(profile[j]);
  return image;
}

/// A match at column 8.5 (between the face and what lies right of it), normal along +x, whose
/// mask response says the image darkens along the normal.
EdgeMatch match_at(real x) {
  EdgeMatch m;
  m.point.normal = Vec2{real(1), real(0)};
  m.point.pixel = Vec2{real(8.5), real(10)};
  m.found = Vec2{x, real(10)};
  m.contrast = real(5000);
  return m;
}

// A bright face up to column 8, then: a background that goes on (a step edge); a dark line
// two pixels wide and the background again (a thin line right at the edge).
const int kStep[20] = {230, 230, 230, 230, 230, 230, 230, 230, 230, 110, 112, 108, 111, 109, 110, 112, 110, 111, 110, 109};
const int kLine[20] = {230, 230, 230, 230, 230, 230, 230, 230, 230, 60, 65, 118, 120, 119, 118, 120, 119, 121, 118, 120};
// The same, with a darker surface from column 15 on (a step at 14.5).
const int kLineThenStep[20] = {230, 230, 230, 230, 230, 230, 230, 230, 230, 60, 65, 118, 120, 119, 118, 40, 41, 40, 42, 40};

}  // namespace

static void test_thin_line_profiles() {
  const ThinLineParams params;
  const vpImage<unsigned char> step = columns(kStep), line = columns(kLine);
  const Vec2 at{real(8.5), real(10)}, normal{real(1), real(0)};
  TEST("a step edge is no thin line", on_thin_line(step, at, normal, false, params), false);
  TEST("a dark line two pixels wide beside the face is one", on_thin_line(line, at, normal, false, params), true);
  TEST("seen from the other side (brighter along the normal) the line's profile is no line",
       on_thin_line(line, at, normal, true, params), false);
  TEST("a profile leaving the image is no line", on_thin_line(line, Vec2{real(18.5), real(10)}, normal, false, params),
       false);
  ThinLineParams strict = params;
  strict.return_share = real(0.9);  // (118 - 60) / (230 - 60) = 0.34 comes back
  TEST("a return under return_share is no line", on_thin_line(line, at, normal, false, strict), false);

  // On the line: the alternative on the step beyond is taken, or the match goes.
  const vpImage<unsigned char> line_then_step = columns(kLineThenStep);
  std::vector<EdgeMatch> matches{match_at(real(8.5)), match_at(real(8.5))};
  matches[0].alternatives[0] = Vec2{real(8.5), real(10)};
  matches[0].alternatives[1] = Vec2{real(14.5), real(10)};
  matches[0].alternative_count = 2;
  TEST_EQUAL("both matches on the line are counted", reject_thin_line_matches(line_then_step, matches, params), 2);
  TEST_EQUAL("the one without an alternative off the line goes", matches.size(), size_t(1));
  TEST_NEAR("the other takes its first alternative off the line", static_cast<double>(matches[0].found.x), 14.5, 1e-9);
  TEST_EQUAL("and keeps none of those before it", matches[0].alternative_count, 0);
  std::vector<EdgeMatch> overclaimed{match_at(real(8.5))};
  overclaimed[0].alternatives[0] = Vec2{real(8.5), real(10)};
  overclaimed[0].alternatives[1] = Vec2{real(8.5), real(10)};
  overclaimed[0].alternatives[2] = Vec2{real(14.5), real(10)};
  overclaimed[0].alternative_count = 1000;  // a caller's count past the array: only the three held are read
  reject_thin_line_matches(line_then_step, overclaimed, params);
  TEST("a match claiming more alternatives than it holds takes the last one held",
       overclaimed.size() == 1 && overclaimed[0].found.x == real(14.5) && overclaimed[0].alternative_count == 0, true);
  std::vector<EdgeMatch> on_step{match_at(real(8.5))};
  TEST_EQUAL("a match on a step edge stays", reject_thin_line_matches(step, on_step, params), 0);
  TEST_EQUAL("unchanged", on_step.size(), size_t(1));
}

static void test_thin_line_settings() {
  ThinLineParams p;
  TEST("off by default", p.enabled, false);
  TEST("enabled=1 is taken", set_thin_line_param(p, "enabled", 1).empty() && p.enabled, true);
  TEST("return_share=0.3 is taken", set_thin_line_param(p, "return_share", 0.3).empty(), true);
  TEST_NEAR("to its value", static_cast<double>(p.return_share), 0.3, 1e-4);  // S47.16 holds 0.3 within 2^-17
  TEST("dark_px=3 is taken", set_thin_line_param(p, "dark_px", 3).empty() && p.dark_px == 3, true);
  TEST("enabled=2 is refused", set_thin_line_param(p, "enabled", 2).empty(), false);
  TEST("return_share=0 is refused", set_thin_line_param(p, "return_share", 0).empty(), false);
  TEST("beyond_px=1.5 is refused", set_thin_line_param(p, "beyond_px", 1.5).empty(), false);
  TEST("beyond_px=9 is refused", set_thin_line_param(p, "beyond_px", 9).empty(), false);
  TEST("an unknown name is refused, and named",
       set_thin_line_param(p, "width", 1).find("'width'") != std::string::npos, true);
  TrackerConfig config;
  const Result<ConfigNotes> read = apply_visp_config_text(
      "<conf>\n<edgetrack><thin_lines><enabled>1</enabled><return_share>0.4</return_share></thin_lines></edgetrack>\n</conf>",
      "lines.xml", config);
  TEST("the XML block is read", read.ok() && config.params.thin_lines.enabled, true);
  TEST_NEAR("with its return share", static_cast<double>(config.params.thin_lines.return_share), 0.4, 1e-4);
  const Result<ConfigNotes> refused = apply_visp_config_text(
      "<conf>\n<edgetrack><thin_lines><beyond_px>0</beyond_px></thin_lines></edgetrack>\n</conf>", "lines.xml", config);
  TEST("a value outside its limits is refused at its line, naming the element",
       !refused.ok() && refused.error().text().find("lines.xml:2") != std::string::npos &&
           refused.error().text().find("<edgetrack><thin_lines><beyond_px>") != std::string::npos,
       true);
  TrackerParams params;
  params.thin_lines.return_share = real(1.5);
  TEST("check_tracker_params refuses a return share above 1", check_tracker_params(params).has_value(), true);
}

static void test_thin_lines_drift() {
  // Lines 8 mm beside every edge of the cube: without the test (nor its drift check,
  // test_drift_check.cxx) the tracker walks onto them within the first frames (docs/ME.md,
  // "From frame to frame"); with the test the cube's edges hold.
  constexpr int kFrames = 12;
  SequenceSpec spec;
  spec.clutter = 0.008;
  TrackerParams without;
  without.thin_lines.check = DriftAction::kNone;
  TrackerParams with_test;
  with_test.thin_lines.enabled = true;
  const SequenceRun plain = run_sequence(Scene::kCube, kFrames, false, without, spec);
  const SequenceRun tested = run_sequence(Scene::kCube, kFrames, false, with_test, spec);
  TEST("both runs load", plain.loaded && tested.loaded, true);
  if (!plain.loaded || !tested.loaded) return;
  double worst_plain = 0, worst_tested = 0;
  for (double e : plain.position_error_mm) worst_plain = e > worst_plain ? e : worst_plain;
  for (double e : tested.position_error_mm) worst_tested = e > worst_tested ? e : worst_tested;
  std::printf("%s cube, lines 8 mm beside the edges, %d frames: without the test mean %.3f mm (largest %.3f), "
              "thin-line test mean %.3f mm (largest %.3f)\n",
              real_name(), kFrames, plain.mean_position_error_mm, worst_plain, tested.mean_position_error_mm,
              worst_tested);
  TEST_EQUAL("with the test no frame is lost", count_status(tested, TrackingStatus::kLost), 0);
  TEST("with the test the mean error is under half the defaults'",
       tested.mean_position_error_mm < 0.5 * plain.mean_position_error_mm, true);
  TEST("with the test every frame stays within 2 mm", worst_tested < 2.0, true);
}

static void test_thin_lines() {
  test_thin_line_profiles();
  test_thin_line_settings();
  test_thin_lines_drift();
}

TESTMAIN(test_thin_lines)
