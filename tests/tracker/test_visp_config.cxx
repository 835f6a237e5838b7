// SPDX-License-Identifier: BSD-3-Clause
/// One ViSP configuration file read as ViSP's loadConfigFile reads it for the edge tracker:
/// <camera> with and without an image size, <ecm> with <sample> inside it or beside it, <face>,
/// <lod>, ViSP's defaults for missing blocks, a second file overriding element by element,
/// unknown elements and other trackers' blocks passed over, and bad values refused at their line.
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "edgetrack/visp_config.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

const double kDegree = 3.14159265358979323846 / 180;

std::string write(const std::string& name, const std::string& text) {
  const std::string path = std::string(EDGETRACK_TEST_OUTPUT) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

void cube_xml() {
  TrackerConfig config;
  auto read = apply_visp_config(std::string(EDGETRACK_VISP_IMAGES) + "/mbt/cube.xml", config);
  TEST("mbt/cube.xml reads", read.ok(), true);
  if (!read.ok()) return;
  const TrackerParams& p = config.params;
  TEST_NEAR("<camera><px>", config.camera.px, 547.7367575, 1e-4);
  TEST_NEAR("<camera><v0>", config.camera.v0, 234.5083345, 1e-4);
  TEST_EQUAL("no image size in cube.xml", config.camera.width, 0);
  TEST_EQUAL("<ecm><mask><size>", p.me.mask_size, 5u);
  TEST_EQUAL("<ecm><mask><nb_mask>", p.me.mask_number, 180u);
  TEST_EQUAL("<ecm><range><tracking> 7", p.me.range, 7u);
  TEST_NEAR("<ecm><contrast><edge_threshold> 5000", p.me.threshold, 5000, 0);
  TEST_NEAR("<ecm><sample><step> 4 spaces the control points", p.me.sample_step, 4, 0);
  TEST_NEAR("<face><angle_appear> 65 degrees", p.faces.angle_appear, 65 * kDegree, 1e-5);
  TEST_NEAR("<face><angle_disappear> 75 degrees", p.faces.angle_disappear, 75 * kDegree, 1e-5);
  TEST("<face><near_clipping> 0.1 m", p.faces.near_clipping && std::abs(static_cast<double>(p.faces.near_distance) - 0.1) < 1e-5, true);
  TEST("<face><far_clipping> 0.9 m", p.faces.far_clipping && std::abs(static_cast<double>(p.faces.far_distance) - 0.9) < 1e-5, true);
  TEST("<face><fov_clipping> 1", p.faces.fov_clipping, true);
  TEST("no <lod>: level of detail off, as ViSP", p.faces.use_lod, false);
  TEST_NEAR("<ecm><contrast><mu1> 0.5", p.me.mu1, 0.5, 1e-6);
  TEST_NEAR("<ecm><contrast><mu2> 0.5", p.me.mu2, 0.5, 1e-6);
  TEST_EQUAL("nothing is named as not applied: <klt> is another tracker's, passed over as ViSP's edge tracker does",
             read.value().not_applied.size(), size_t(0));
}

void blocks() {
  TrackerConfig sized;
  auto read = apply_visp_config(write("sized.xml", "<conf><camera><px>300</px><py>301</py><u0>160</u0><v0>120</v0>"
                                                   "<width>320</width><height>240</height></camera></conf>"), sized);
  TEST("a camera with <width>/<height> gives its size", read.ok() && sized.camera.width == 320 && sized.camera.height == 240, true);
  TrackerConfig written;
  read = apply_visp_config(write("written.xml", "<?xml version=\"1.0\"?>\n<conf>\n<camera><px>300</px><py>300</py>"
                                                "<u0>1</u0><v0>2</v0><image_width>160</image_width>"
                                                "<image_height>120</image_height></camera></conf>\n"), written);
  TEST("<image_width>/<image_height> (vpXmlParserCamera's names) too", read.ok() && written.camera.width == 160, true);
  TrackerConfig bare_root;
  read = apply_visp_config(write("camera_root.xml", "<camera><px>310</px><py>300</py><u0>1</u0><v0>2</v0></camera>"),
                           bare_root);
  TEST("a file whose root is <camera> is read as the camera block",
       read.ok() && read.value().camera_block && bare_root.camera.px == real(310), true);

  const TrackerConfig defaults;
  TrackerConfig outside;
  read = apply_visp_config(write("old_sample.xml", "<conf>\n<!-- older files -->\n<sample><step>6</step></sample>\n"
                                                   "<ecm><range><tracking>5</tracking></range></ecm></conf>"), outside);
  TEST("<sample> beside <ecm> (older files) sets the step", read.ok() && outside.params.me.sample_step == real(6), true);
  TrackerConfig both;
  read = apply_visp_config(write("both_samples.xml", "<conf><ecm><sample><step>3</step></sample></ecm>"
                                                     "<sample><step>8</step></sample></conf>"), both);
  TEST("with both, the later in the file wins (ViSP reads in order)", read.ok() && both.params.me.sample_step == real(8), true);

  TrackerConfig cut;
  read = apply_visp_config(write("fraction.xml", "<conf><ecm><sample><step>4.5</step></sample>"
                                                 "<range><tracking>7.9</tracking></range></ecm></conf>"), cut);
  TEST("a decimal fraction where ViSP reads an integer is cut to its whole part, as ViSP does",
       read.ok() && cut.params.me.sample_step == real(4) && cut.params.me.range == 7u, true);
  TEST("and each is named in the notes", read.ok() && read.value().cut_to_whole.size() == 2 &&
                                             read.value().cut_to_whole[0].find("<ecm><sample><step> '4.5' is read as 4") == 0,
       true);
  for (const char* text : {"4abc", ".5", "4.5e1", "x", "4,5"}) {
    TrackerConfig refused;
    read = apply_visp_config(write("not_whole.xml", std::string("<conf><ecm><sample><step>") + text +
                                                        "</step></sample></ecm></conf>"), refused);
    TEST("other text where ViSP reads an integer is refused", !read.ok() &&
             read.error().message.find("is not a whole number") != std::string::npos, true);
  }
  read = apply_visp_config(write("half.xml", "<conf><ecm><sample><step>0.5</step></sample></ecm></conf>"), cut);
  TEST("a fraction cut to 0 meets the step's limit", !read.ok(), true);

  TrackerConfig lod;
  read = apply_visp_config(write("lod.xml", "<conf><lod><use_lod>1</use_lod><min_line_length_threshold>30"
                                            "</min_line_length_threshold><min_polygon_area_threshold>900"
                                            "</min_polygon_area_threshold></lod></conf>"), lod);
  TEST("<lod> applies", read.ok() && lod.params.faces.use_lod && lod.params.faces.min_line_length == real(30) &&
                            lod.params.faces.min_polygon_area == real(900), true);

  TrackerConfig bare;
  read = apply_visp_config(write("camera_only.xml", "<conf><camera><px>300</px><py>300</py><u0>160</u0><v0>120</v0>"
                                                    "</camera><unknown><x>1</x></unknown><ecm><bogus>2</bogus></ecm></conf>"), bare);
  TEST("a camera-only file (with unknown elements) reads", read.ok(), true);
  TEST_EQUAL("missing <ecm>: ViSP's range 4", bare.params.me.range, defaults.params.me.range);
  TEST_NEAR("ViSP's threshold 1500", bare.params.me.threshold, 1500, 0);
  TEST_NEAR("ViSP's sample step 10", bare.params.me.sample_step, 10, 0);
  TEST_NEAR("missing <face>: vpMbTracker's 89 degrees", bare.params.faces.angle_appear, 89 * kDegree, 1e-5);
  TEST("and no clipping", !bare.params.faces.near_clipping && !bare.params.faces.far_clipping && !bare.params.faces.fov_clipping, true);
  TEST("nothing to note", read.ok() && read.value().not_applied.empty() && read.value().camera_block, true);
  TrackerConfig none;
  read = apply_visp_config(write("no_camera.xml", "<conf><ecm><range><tracking>5</tracking></range></ecm></conf>"), none);
  TEST("a file without <camera> keeps ViSP's default camera (600, 600, 192, 144)",
       read.ok() && !read.value().camera_block && none.camera.px == real(600) && none.camera.u0 == real(192), true);
  read = apply_visp_config(write("projection.xml", "<conf><projection_error><sample_step>2</sample_step>"
                                                   "</projection_error></conf>"), none);
  TEST("<projection_error> is named as not applied", read.ok() && read.value().not_applied.size() == 1, true);
}

void precedence() {
  TrackerConfig config;
  auto first = apply_visp_config(std::string(EDGETRACK_VISP_IMAGES) + "/mbt/cube.xml", config);
  auto second = apply_visp_config(write("override.xml", "<conf><ecm><range><tracking>3</tracking></range></ecm>"
                                                        "<face><fov_clipping>0</fov_clipping></face></conf>"), config);
  TEST("a second file applies over the first", first.ok() && second.ok(), true);
  TEST_EQUAL("its range replaces cube.xml's", config.params.me.range, 3u);
  TEST_NEAR("cube.xml's step stays", config.params.me.sample_step, 4, 0);
  TEST_NEAR("cube.xml's camera stays", config.camera.px, 547.7367575, 1e-4);
  TEST("its fov_clipping 0 replaces cube.xml's 1", config.params.faces.fov_clipping, false);
  TEST("cube.xml's near clipping stays", config.params.faces.near_clipping, true);
}

/// edgetrack's status settings, in a block ViSP passes over, beside ViSP's own.
void status_block() {
  TrackerConfig config;
  auto read = apply_visp_config(write("status.xml", "<conf><ecm><range><tracking>6</tracking></range></ecm>"
                                                    "<edgetrack><status><tracked_scale_px>1.5</tracked_scale_px>"
                                                    "<learn_frames>8</learn_frames></status></edgetrack>"
                                                    "<status><least_inlier_share>0.3</least_inlier_share></status></conf>"),
                                config);
  TEST("a file with <edgetrack><status> and <status> is read", read.ok(), true);
  TEST_NEAR("  the tracked scale", config.params.status.tracked_scale_px, 1.5, 1e-6);
  TEST_EQUAL("  the learning frames", config.params.status.learn_frames, 8);
  TEST_NEAR("  the least inlier share", config.params.status.least_inlier_share, 0.3, 1e-4);  // S47.16: 1.5e-5 steps
  TEST_EQUAL("  and ViSP's range beside them", config.params.me.range, 6u);
}

/// The camera's rolling-shutter readout, in edgetrack's block beside ViSP's <camera>.
void readout_block() {
  TrackerConfig config;
  TEST("a global shutter by default", config.params.readout == real(0), true);
  auto read = apply_visp_config(write("readout.xml", "<conf><camera><px>300</px></camera>"
                                                     "<edgetrack><camera><readout>0.75</readout></camera></edgetrack></conf>"),
                                config);
  TEST("a file with <edgetrack><camera><readout> is read", read.ok(), true);
  TEST_NEAR("  the readout", config.params.readout, 0.75, 1e-6);
  TEST_NEAR("  and ViSP's camera beside it", config.camera.px, 300, 1e-6);
}

/// The detector's work budget, in edgetrack's block; none by default.
void detector_block() {
  TrackerConfig config;
  TEST_EQUAL("the detection budget by default", config.detector.max_points_searched, DetectorParams{}.max_points_searched);
  TEST("  which is a limit", config.detector.max_points_searched > 0, true);
  auto read = apply_visp_config(
      write("detector.xml", "<conf><edgetrack><detector><max_points_searched>5000</max_points_searched></detector>"
                            "</edgetrack></conf>"),
      config);
  TEST("a file with <edgetrack><detector><max_points_searched> is read", read.ok(), true);
  TEST_EQUAL("  the budget", config.detector.max_points_searched, 5000);
}

void refused(const std::string& name, const std::string& xml, int line, const std::string& element) {
  TrackerConfig config;
  const TrackerConfig before = config;
  const std::string path = write(name, xml);
  auto read = apply_visp_config(path, config);
  TEST(("refused: " + name).c_str(), read.ok(), false);
  if (read.ok()) return;
  TEST_EQUAL(("  at line " + std::to_string(line)).c_str(), read.error().line, line);
  TEST(("  naming the file and " + element).c_str(),
       read.error().file == path && read.error().message.find(element) != std::string::npos, true);
  TEST("  nothing applied", config.params.me.range == before.params.me.range, true);
}

void bad_values() {
  refused("nan_range.xml", "<conf>\n<ecm>\n<range>\n<tracking>seven</tracking>\n</range>\n</ecm>\n</conf>\n", 4,
          "<ecm><range><tracking>");
  refused("zero_range.xml", "<conf>\n<ecm><range><tracking>0</tracking></range></ecm>\n</conf>\n", 2, "<ecm><range><tracking>");
  refused("negative_range.xml", "<conf>\n<ecm><range>\n<tracking>-2</tracking></range></ecm>\n</conf>\n", 3,
          "<ecm><range><tracking>");
  refused("mask.xml", "<conf>\n<ecm>\n<mask>\n<size>1</size>\n</mask>\n</ecm>\n</conf>\n", 4, "<ecm><mask><size>");
  refused("step.xml", "<conf>\n<ecm>\n<range><tracking>5</tracking></range>\n<sample><step>0</step></sample>\n</ecm>\n</conf>\n",
          4, "<ecm><sample><step>");
  refused("half_step.xml", "<conf>\n<sample>\n<step>2.5px</step>\n</sample>\n</conf>\n", 3, "<sample><step>");
  refused("threshold.xml", "<conf><ecm><contrast>\n<edge_threshold>-1</edge_threshold>\n</contrast></ecm></conf>", 2,
          "<ecm><contrast><edge_threshold>");
  refused("mu.xml", "<conf><ecm><contrast>\n\n<mu1>1.5</mu1></contrast></ecm></conf>", 3, "<ecm><contrast><mu1>");
  refused("px.xml", "<conf>\n<camera>\n<px>0</px>\n</camera>\n</conf>\n", 3, "<camera><px>");
  refused("huge_px.xml", "<conf>\n<camera>\n<px>1e308</px>\n</camera>\n</conf>\n", 3, "<camera><px>");
  refused("far_u0.xml", "<conf>\n<camera>\n<u0>-2e6</u0>\n</camera>\n</conf>\n", 3, "<camera><u0>");
  refused("width.xml", "<conf>\n<camera>\n<width>wide</width>\n</camera>\n</conf>\n", 3, "<camera><width>");
  // A calibration file (vpXmlParserCamera) given as the tracker's configuration: its intrinsics
  // are in <model>, so it is refused with the option that reads it rather than tracked with none.
  refused("calibration.xml",
          "<root>\n<camera>\n<name>Camera</name>\n<image_width>640</image_width>\n<image_height>480</image_height>\n"
          "<model>\n<type>perspectiveProjWithoutDistortion</type>\n<px>600</px>\n</model>\n</camera>\n</root>\n",
          6, "--intrinsics");
  // Intrinsics and sizes inside the bounds every other input has: a focal length or principal
  // point beyond a million pixels, a side beyond an image file's 16384, more than 64 M pixels.
  refused("huge_px.xml", "<conf>\n<camera>\n<px>1e308</px>\n</camera>\n</conf>\n", 3, "<camera><px>");
  refused("huge_py.xml", "<conf>\n<camera>\n<py>2e6</py>\n</camera>\n</conf>\n", 3, "<camera><py>");
  refused("huge_u0.xml", "<conf>\n<camera>\n<u0>1e300</u0>\n</camera>\n</conf>\n", 3, "<camera><u0>");
  refused("far_v0.xml", "<conf>\n<camera>\n<v0>-2e6</v0>\n</camera>\n</conf>\n", 3, "<camera><v0>");
  refused("wide.xml", "<conf>\n<camera>\n<width>100000</width>\n</camera>\n</conf>\n", 3, "<camera><width>");
  refused("many_pixels.xml", "<conf>\n<camera>\n<width>16384</width>\n<height>16384</height>\n</camera>\n</conf>\n", 4,
          "<camera><height>");
  refused("angle.xml", "<conf>\n<face>\n<angle_appear>200</angle_appear>\n</face>\n</conf>\n", 3, "<face><angle_appear>");
  refused("far.xml", "<conf>\n<face>\n<near_clipping>0.5</near_clipping>\n<far_clipping>0.2</far_clipping>\n</face>\n</conf>\n",
          4, "<face><far_clipping>");
  refused("fov.xml", "<conf>\n<face><fov_clipping>yes</fov_clipping></face>\n</conf>\n", 2, "<face><fov_clipping>");
  refused("lod.xml", "<conf>\n<lod>\n<min_polygon_area_threshold>-4</min_polygon_area_threshold>\n</lod>\n</conf>\n", 3,
          "<lod><min_polygon_area_threshold>");
  refused("readout.xml", "<conf>\n<edgetrack>\n<camera>\n<readout>1.5</readout>\n</camera>\n</edgetrack>\n</conf>\n", 4,
          "<edgetrack><camera><readout>");
  refused("readout_text.xml", "<conf><edgetrack><camera>\n<readout>fast</readout></camera></edgetrack></conf>", 2,
          "<edgetrack><camera><readout>");
  refused("readout_name.xml", "<conf><edgetrack><camera>\n\n<read_out>0.5</read_out></camera></edgetrack></conf>", 3,
          "<edgetrack><camera><read_out>");
  refused("status.xml", "<conf>\n<edgetrack>\n<status>\n<learning_rate>0</learning_rate>\n</status>\n</edgetrack>\n</conf>\n",
          4, "<edgetrack><status><learning_rate>");
  refused("status_share.xml", "<conf>\n<status><min_inlier_share>1.5</min_inlier_share></status>\n</conf>\n", 2,
          "<status><min_inlier_share>");
  refused("status_name.xml", "<conf>\n<status>\n<tracked_scale>2</tracked_scale>\n</status>\n</conf>\n", 3,
          "<status><tracked_scale>");
  refused("status_frames.xml", "<conf>\n<status>\n<learn_frames>2.5</learn_frames>\n</status>\n</conf>\n", 3,
          "<status><learn_frames>");
  refused("budget.xml", "<conf>\n<edgetrack><detector>\n<max_points_searched>-5</max_points_searched>\n</detector></edgetrack>\n</conf>\n",
          3, "<edgetrack><detector><max_points_searched>");
  refused("budget_part.xml", "<conf><edgetrack><detector>\n<max_points_searched>2.5</max_points_searched></detector></edgetrack></conf>",
          2, "<edgetrack><detector><max_points_searched>");
  refused("budget_name.xml", "<conf><edgetrack><detector>\n\n<points>500</points></detector></edgetrack></conf>", 3,
          "<edgetrack><detector><points>");
  refused("unclosed.xml", "<conf>\n<ecm>\n<range><tracking>5</tracking>\n</ecm>\n</conf>\n", 4, "</ecm> does not close <range>");
  TrackerConfig config;
  auto missing = apply_visp_config(std::string(EDGETRACK_TEST_OUTPUT) + "/no_such.xml", config);
  TEST("a missing file is an error naming it",
       !missing.ok() && missing.error().file == std::string(EDGETRACK_TEST_OUTPUT) + "/no_such.xml", true);
}

/// apply_visp_config_text reads a configuration held in memory as the file reader reads it.
void from_memory() {
  const std::string path = std::string(EDGETRACK_VISP_IMAGES) + "/mbt/cube.xml";
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  TrackerConfig from_file, from_text;
  auto file = apply_visp_config(path, from_file);
  auto memory = apply_visp_config_text(text, "cube.xml in memory", from_text);
  TEST("cube.xml reads from memory", file.ok() && memory.ok(), true);
  TEST("with the file's settings", from_text.params.me.range == from_file.params.me.range &&
                                       from_text.params.me.sample_step == from_file.params.me.sample_step &&
                                       from_text.camera.px == from_file.camera.px &&
                                       from_text.params.faces.angle_appear == from_file.params.faces.angle_appear, true);
  TrackerConfig bad;
  auto refused_text = apply_visp_config_text("<conf>\n<ecm><range><tracking>0</tracking></range></ecm></conf>", "buffer", bad);
  TEST("a bad value in memory is refused naming the buffer's name and line",
       !refused_text.ok() && refused_text.error().file == "buffer" && refused_text.error().line == 2, true);
}

}  // namespace

static void test_visp_config() {
  from_memory();
  cube_xml();
  blocks();
  precedence();
  status_block();
  readout_block();
  detector_block();
  bad_values();
}

TESTMAIN(test_visp_config)
