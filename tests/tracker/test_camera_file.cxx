// SPDX-License-Identifier: BSD-3-Clause
/// Calibration files as users have them: ViSP's camera XML (vpXmlParserCamera's layout, several
/// cameras and models, chosen by name and image size, the distorted model preferred) and
/// OpenCV's calibration sample output in YAML and XML; and their bad forms, each refused at the
/// file and line.
#include <fstream>
#include <string>

#include "edgetrack/camera_file.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = std::string(EDGETRACK_TEST_OUTPUT) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

const char* const kVisp = R"(<?xml version="1.0"?>
<root>
  <!--This file stores intrinsic camera parameters used
   in the vpCameraParameters Class of ViSP.-->
  <camera>
    <!--Name of the camera-->
    <name>Camera</name>
    <!--Size of the image on which camera calibration was performed-->
    <image_width>640</image_width>
    <image_height>480</image_height>
    <model>
      <type>perspectiveProjWithoutDistortion</type>
      <px>600.5</px>
      <py>601.25</py>
      <u0>320.5</u0>
      <v0>240.25</v0>
    </model>
    <model>
      <type>perspectiveProjWithDistortion</type>
      <px>598</px>
      <py>599</py>
      <u0>321</u0>
      <v0>239</v0>
      <kud>-0.25</kud>
      <kdu>0.28</kdu>
    </model>
  </camera>
  <camera>
    <name>Camera</name>
    <image_width>320</image_width>
    <image_height>240</image_height>
    <model>
      <type>perspectiveProjWithoutDistortion</type>
      <px>300</px>
      <py>300</py>
      <u0>160</u0>
      <v0>120</v0>
    </model>
  </camera>
  <camera>
    <name>wide</name>
    <image_width>640</image_width>
    <image_height>480</image_height>
    <model>
      <type>perspectiveProjWithDistortion</type>
      <px>400</px>
      <py>400</py>
      <u0>320</u0>
      <v0>240</v0>
      <kud>0.12</kud>
      <kdu>-0.11</kdu>
    </model>
  </camera>
</root>
)";

const char* const kOpenCvYaml = R"(%YAML:1.0
---
calibration_time: "Sun 06 Dec 2026 12:00:00 UTC"
nr_of_frames: 12
image_width: 640
image_height: 480
board_width: 9
board_height: 6
square_size: 25.
flags: 0
camera_matrix: !!opencv-matrix
   rows: 3
   cols: 3
   dt: d
   data: [ 6.5746697944293521e+02, 0., 3.1950000000000000e+02, 0.,
       6.5846697944293521e+02, 2.3950000000000000e+02, 0., 0., 1. ]
distortion_coefficients: !!opencv-matrix
   rows: 5
   cols: 1
   dt: d
   data: [ -4.1802327176423804e-01, 5.0715244063187526e-01, 1.5e-03,
       -2.5e-03, -5.7843597214487474e-01 ]
avg_reprojection_error: 3.9e-01
per_view_reprojection_errors: !!opencv-matrix
   rows: 2
   cols: 1
   dt: f
   data: [ 0.4, 0.38 ]
)";

const char* const kOpenCvXml = R"(<?xml version="1.0"?>
<opencv_storage>
<calibration_time>"Sun 06 Dec 2026"</calibration_time>
<image_width>320</image_width>
<image_height>240</image_height>
<camera_matrix type_id="opencv-matrix">
  <rows>3</rows>
  <cols>3</cols>
  <dt>d</dt>
  <data>
    2.2e+02 0. 1.6e+02 0. 2.21e+02 1.2e+02 0. 0. 1.</data></camera_matrix>
<distortion_coefficients type_id="opencv-matrix">
  <rows>1</rows>
  <cols>8</cols>
  <dt>d</dt>
  <data>
    -0.2 0.05 0. 0. 0.01 0. 0. 0.</data></distortion_coefficients>
</opencv_storage>
)";

/// The error's "file:line: message", or "" when the file was read.
std::string refusal(const std::string& name, const std::string& text, const CameraChoice& choice = CameraChoice{}) {
  const Result<PinholeCamera> got = read_camera_file(write(name, text), choice);
  return got.ok() ? "" : got.error().text();
}

bool says(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace

static void test_camera_file() {
  const double tol = std::string(real_name()) == "s47_16" ? 2e-4 : 1e-6;
  const std::string visp = write("visp_camera.xml", kVisp);
  {
    const Result<PinholeCamera> c = read_camera_file(visp, CameraChoice{"", 640, 480});
    TEST("ViSP: the first 640x480 camera reads", c.ok(), true);
    if (c.ok()) {
      TEST("its distorted model is preferred", c.value().lens.model == LensModel::kVisp, true);
      TEST_NEAR("px", c.value().px, 598, tol);
      TEST_NEAR("v0", c.value().v0, 239, tol);
      TEST_NEAR("kud", c.value().lens.kud, -0.25, tol);
      TEST_NEAR("kdu", c.value().lens.kdu, 0.28, tol);
      TEST("the image size", c.value().width == 640 && c.value().height == 480, true);
    }
  }
  {
    const Result<PinholeCamera> c = read_camera_file(visp, CameraChoice{"", 320, 240});
    TEST("ViSP: the 320x240 camera is chosen by image size", c.ok() && c.value().width == 320, true);
    if (c.ok()) {
      TEST("with its only model, the pinhole", c.value().distorted(), false);
      TEST_NEAR("px", c.value().px, 300, tol);
    }
  }
  {
    const Result<PinholeCamera> c = read_camera_file(visp, CameraChoice{"wide", 0, 0});
    TEST("ViSP: a camera is chosen by name", c.ok(), true);
    if (c.ok()) TEST_NEAR("its kud", c.value().lens.kud, 0.12, tol);
  }
  {
    const Result<PinholeCamera> c = read_camera_file(visp, CameraChoice{"wide", 320, 240});
    TEST("ViSP: no camera of that name and size is an error", c.ok(), false);
    if (!c.ok()) {
      TEST("naming the file and the root's line", says(c.error().text(), "visp_camera.xml:2:"), true);
      TEST("and listing what the file holds", says(c.error().text(), "'wide' 640x480"), true);
    }
  }
  {
    const Result<PinholeCamera> c = read_camera_file(write("opencv.yml", kOpenCvYaml));
    TEST("OpenCV YAML reads", c.ok(), true);
    if (c.ok()) {
      TEST("as OpenCV's model", c.value().lens.model == LensModel::kOpenCv, true);
      TEST_NEAR("fx", c.value().px, 657.46697944293521, 1e3 * tol);
      TEST_NEAR("fy", c.value().py, 658.46697944293521, 1e3 * tol);
      TEST_NEAR("cx", c.value().u0, 319.5, tol);
      TEST_NEAR("cy", c.value().v0, 239.5, tol);
      TEST_NEAR("k1", c.value().lens.k1, -0.41802327176423804, tol);
      TEST_NEAR("p1", c.value().lens.p1, 1.5e-3, tol);
      TEST_NEAR("p2", c.value().lens.p2, -2.5e-3, tol);
      TEST_NEAR("k3", c.value().lens.k3, -0.57843597214487474, tol);
      TEST("the image size", c.value().width == 640 && c.value().height == 480, true);
    }
  }
  {
    const Result<PinholeCamera> c = read_camera_file(write("opencv.xml", kOpenCvXml));
    TEST("OpenCV XML with 8 coefficients, the rational ones 0, reads", c.ok(), true);
    if (c.ok()) {
      TEST_NEAR("fy", c.value().py, 221, tol);
      TEST_NEAR("k2", c.value().lens.k2, 0.05, tol);
      TEST_NEAR("k3", c.value().lens.k3, 0.01, tol);
    }
  }

  // Bad files: one line each, naming the file and the line.
  const std::string rational = refusal("rational.xml", replaced(kOpenCvXml, "0.01 0. 0. 0.", "0.01 0.3 0. 0."));
  TEST("OpenCV: a rational term is refused at the coefficients' line",
       says(rational, "rational.xml:12:") && says(rational, "rational"), true);
  const std::string short_data = refusal("short.yml", replaced(kOpenCvYaml, "0., 0., 1. ]", "0., 0. ]"));
  TEST("OpenCV: a matrix with too few entries is refused at its line",
       says(short_data, "short.yml:11:") && says(short_data, "8 entries"), true);
  const std::string word = refusal("word.yml", replaced(kOpenCvYaml, "-2.5e-03", "-2.5e-0x"));
  TEST("OpenCV: a number that is not one is refused at its own line", says(word, "word.yml:22:"), true);
  const std::string no_matrix = refusal("no_matrix.yml", replaced(kOpenCvYaml, "camera_matrix:", "camera_matrx:"));
  TEST("OpenCV: a missing camera_matrix is refused", says(no_matrix, "no_matrix.yml:1: has no camera_matrix"), true);
  const std::string skew = refusal("skew.yml", replaced(kOpenCvYaml, "data: [ 6.5746697944293521e+02, 0.,",
                                                        "data: [ 6.5746697944293521e+02, 2.,"));
  TEST("OpenCV: a skewed camera matrix is refused", says(skew, "skew.yml:11:") && says(skew, "skew"), true);
  const std::string size = refusal("size.yml", kOpenCvYaml, CameraChoice{"", 320, 240});
  TEST("OpenCV: a calibration of another image size is refused", says(size, "of 640x480 images, not 320x240"), true);
  const std::string negative = refusal("negative.xml", replaced(kVisp, "<px>598</px>", "<px>-598</px>"));
  TEST("ViSP: a negative focal length is refused at its line", says(negative, "negative.xml:20:"), true);
  const std::string missing = refusal("missing.xml", replaced(kVisp, "<kdu>0.28</kdu>", ""));
  TEST("ViSP: a distorted model without kdu is refused at the model's line",
       says(missing, "missing.xml:18:") && says(missing, "<kdu>"), true);
  const std::string kannala = refusal("kb.xml", replaced(kVisp, "<type>perspectiveProjWithDistortion</type>",
                                                         "<type>ProjWithKannalaBrandtDistortion</type>"));
  TEST("ViSP: the Kannala-Brandt model is refused by name", says(kannala, "kb.xml:19:") && says(kannala, "Kannala"),
       true);
  const std::string unclosed = refusal("unclosed.xml", replaced(kVisp, "</model>", ""));
  TEST("ViSP: malformed XML is refused with its line", says(unclosed, "unclosed.xml:"), true);
  TEST("neither format is refused", says(refusal("neither.txt", "px 600\n"), "neither.txt:1: is neither"), true);
}

TESTMAIN(test_camera_file)
