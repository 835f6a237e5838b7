// SPDX-License-Identifier: BSD-3-Clause
// `edgetrack calibrate` on frames of calibration targets rendered (ray cast, exact lens) through
// known cameras and lenses: what it writes, read back by the reader `--intrinsics` uses, must
// give the camera back. Tolerances: px and py within 1 %, u0 and v0 within 1.5 px, and the
// recovered camera's image of every ray within 0.5 px of the true camera's where the target was seen.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "commands.h"
#include "edgetrack/calibration_target.h"
#include "edgetrack/camera_file.h"
#include "image_io.h"
#include "testlib/testlib_test.h"
#include "visp_lens_fit.h"

using namespace edgetrack_app;
using edgetrack::CalibrationTarget;
using edgetrack::LensModel;
using edgetrack::PinholeCamera;
using edgetrack::Se3;
using edgetrack::TargetKind;
using edgetrack::Vec2;
using edgetrack::Vec3;

namespace {

/// Whether the camera sees `point` (camera frame) inside its image, `margin` pixels in, on the
/// near side of its lens's fold (where the lens still has an inverse).
bool seen_inside(const PinholeCamera& camera, const Vec3& point, double margin) {
  if (point.z <= real(0)) return false;
  const Vec2 n{point.x / point.z, point.y / point.z};
  const edgetrack::LensJacobian j = camera.lens_jacobian(n);
  if (!(j.xx * j.yy - j.xy * j.yx > real(0))) return false;
  const Vec2 p = camera.to_pixel(camera.distort(n));
  return p.x >= real(margin) && p.y >= real(margin) && p.x <= real(camera.width - 1 - margin) &&
         p.y <= real(camera.height - 1 - margin);
}

/// Whether the pattern, out to a spacing beyond its outermost points (a chessboard's outer
/// squares), is in the image at `camera_from_target`: its outline checked every eighth of a side.
bool pattern_in_view(const CalibrationTarget& target, const PinholeCamera& camera, const Se3& camera_from_target) {
  const std::vector<Vec3> points = target.points();
  real x0 = points[0].x, x1 = points[0].x, y0 = points[0].y, y1 = points[0].y;
  for (const Vec3& p : points) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  x0 = x0 - target.spacing, y0 = y0 - target.spacing, x1 = x1 + target.spacing, y1 = y1 + target.spacing;
  for (int k = 0; k <= 8; ++k) {
    const real a = real(k / 8.0);
    for (const Vec3& p : {Vec3{x0 + a * (x1 - x0), y0, real(0)}, Vec3{x0 + a * (x1 - x0), y1, real(0)},
                          Vec3{x0, y0 + a * (y1 - y0), real(0)}, Vec3{x1, y0 + a * (y1 - y0), real(0)}})
      if (!seen_inside(camera, camera_from_target * p, 3)) return false;
  }
  return true;
}

/// Views of the target over the whole image, as one calibrates a camera: the pattern about 45 %
/// of the image wide at nine places (the centre, the middles of the sides, the corners), tilted
/// by 0.3 rad one way and, a little nearer, the other, and nearer views tilted by 0.6 rad about
/// each axis. A view whose pattern would
/// leave the image is moved back until it fits.
std::vector<Se3> calibration_views(const CalibrationTarget& target, const PinholeCamera& camera) {
  const std::vector<Vec3> points = target.points();
  Vec3 centre{real(0), real(0), real(0)};
  for (const Vec3& p : points) centre = centre + p;
  centre = real(1.0 / points.size()) * centre;
  const double width = 2 * static_cast<double>(centre.x + target.spacing);  // the pattern's, outer squares included
  const double far = static_cast<double>(camera.px) * width / (0.45 * camera.width);
  // {place across, place down (halves of the image), tilt about x, about y, about z, distance}
  std::vector<std::array<double, 6>> plan;
  for (const double turn : {1.0, -1.0})
    for (int b = -1; b <= 1; ++b)
      for (int a = -1; a <= 1; ++a)
        plan.push_back({0.55 * a, 0.5 * b, turn * (0.3 * b + 0.1 * a), turn * (-0.3 * a + 0.1 * b), 0.1 * (a - b) * turn,
                        turn > 0 ? far : 0.9 * far});
  for (const auto& tilt : {std::array<double, 3>{0.6, 0, 0.1}, {-0.6, 0, -0.1}, {0, 0.6, 0.2}, {0, -0.6, -0.2},
                           {0.4, 0.4, 0}, {-0.4, 0.4, 0.3}})
    plan.push_back({0, 0, tilt[0], tilt[1], tilt[2], 0.75 * far});
  std::vector<Se3> views;
  for (const auto& p : plan) {
    const Se3 turned(edgetrack::rotation_exp(Vec3{real(p[2]), real(p[3]), real(p[4])}), Vec3{});
    for (double distance = p[5]; distance < 3 * far; distance *= 1.1) {
      const Vec3 wanted{real(p[0] * camera.width / 2 / static_cast<double>(camera.px) * distance),
                        real(p[1] * camera.height / 2 / static_cast<double>(camera.py) * distance), real(distance)};
      const Se3 view(turned.rotation(), wanted - turned.rotation() * centre);
      if (!pattern_in_view(target, camera, view)) continue;
      views.push_back(view);
      break;
    }
  }
  return views;
}

/// Where the target's points fell in the image, over all views: cells of 16 x 16 pixels. A
/// calibration knows the lens where it saw points; beyond them it extrapolates.
struct Coverage {
  static constexpr int kCell = 16;
  int columns = 0;
  std::vector<bool> seen;

  Coverage(const CalibrationTarget& target, const PinholeCamera& camera, const std::vector<Se3>& views)
      : columns(camera.width / kCell + 1), seen(static_cast<size_t>(columns) * (camera.height / kCell + 1), false) {
    for (const Se3& view : views)
      for (const Vec3& p : target.points()) {
        const Vec2 pixel = camera.project(view * p);
        seen[cell(pixel)] = true;
      }
  }
  size_t cell(const Vec2& pixel) const {
    return static_cast<size_t>(static_cast<int>(pixel.y) / kCell) * columns + static_cast<int>(pixel.x) / kCell;
  }
  bool covers(const Vec2& pixel) const { return seen[cell(pixel)]; }
};

/// The largest of `distance(pixel, ray)` over a 33 x 25 grid of the image's pixels, each with
/// the ray the true camera sees there: where `coverage` saw the target, or anywhere a ray
/// reaches (not beyond a wide lens's fold) when it is null.
template <class Distance>
double largest_over_image(const PinholeCamera& truth, const Coverage* coverage, const Distance& distance) {
  double largest = 0;
  for (int j = 0; j <= 24; ++j)
    for (int i = 0; i <= 32; ++i) {
      const Vec2 pixel{real((truth.width - 1) * i / 32.0), real((truth.height - 1) * j / 24.0)};
      const Vec2 ray = truth.invert_distortion(truth.to_normalised(pixel));
      const Vec2 back = truth.distort(ray);
      const bool reached = std::fabs(static_cast<double>(back.x - truth.to_normalised(pixel).x)) +
                               std::fabs(static_cast<double>(back.y - truth.to_normalised(pixel).y)) < 1e-9 &&
                           seen_inside(truth, {ray.x, ray.y, real(1)}, -1);
      if (!reached || (coverage && !coverage->covers(pixel))) continue;
      largest = std::max(largest, distance(pixel, ray));
    }
  return largest;
}

/// How far `recovered` shows each ray from where `truth` does, at most (pixels).
double largest_displacement(const PinholeCamera& truth, const PinholeCamera& recovered, const Coverage* coverage) {
  return largest_over_image(truth, coverage, [&](const Vec2& pixel, const Vec2& ray) {
    const Vec2 seen = recovered.to_pixel(recovered.distort(ray));
    return std::hypot(static_cast<double>(seen.x - pixel.x), static_cast<double>(seen.y - pixel.y));
  });
}

/// How far the ray of ViSP's back model (kdu) at each pixel is from the true ray, at most, in
/// pixels of the true camera.
double largest_back_displacement(const PinholeCamera& truth, const PinholeCamera& recovered, const Coverage* coverage) {
  return largest_over_image(truth, coverage, [&](const Vec2& pixel, const Vec2& ray) {
    const Vec2 back = recovered.undistort(recovered.to_normalised(pixel));
    return std::hypot(static_cast<double>((back.x - ray.x) * truth.px), static_cast<double>((back.y - ray.y) * truth.py));
  });
}

/// Renders the views into DIR/frameNN.pgm, then a frame with no target, the last.
std::string render_frames(const std::string& dir, const CalibrationTarget& target, const PinholeCamera& camera,
                          const std::vector<Se3>& views) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  TEST("the pattern fits the image in every planned view", views.size(), 24u);
  const edgetrack::TargetRenderer renderer(camera, 4);
  char name[32];
  for (size_t k = 0; k <= views.size(); ++k) {
    const std::vector<uint8_t> grey =
        k < views.size() ? renderer.render(target, views[k])
                         : std::vector<uint8_t>(static_cast<size_t>(camera.width) * camera.height, 128);
    RgbImage image = make_image(camera.width, camera.height);
    for (size_t i = 0; i < grey.size(); ++i) std::fill_n(&image.rgb[3 * i], 3, grey[i]);
    std::snprintf(name, sizeof name, "/frame%02zu.pgm", k);
    write_pgm(dir + name, image);
  }
  return dir + "/frame%02d.pgm";
}

/// Runs `edgetrack calibrate` on the frames (every `step`th); its exit status.
int run_calibrate(const std::string& pattern, const std::string& dir, const char* kind, const char* count,
                  const char* spacing, const char* step = "1") {
  const std::string visp = dir + "/camera.xml", opencv = dir + "/camera.yaml", overlay = dir + "/overlay";
  std::vector<std::string> args = {"calibrate", "--images", pattern,       "--target", kind,     "--count",
                                   count,       "--spacing", spacing,      "--visp",   visp,     "--opencv",
                                   opencv,      "--overlay", overlay,      "--step",   step};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return calibration_commands()[0].run(static_cast<int>(args.size()), argv.data());
}

/// Both written files read back by `--intrinsics`'s reader, checked against `truth`.
void check_files(const std::string& dir, const PinholeCamera& truth, const Coverage& coverage, const char* what,
                 bool visp_lens_exact) {
  const std::string label = std::string(what) + ": ";
  auto opencv = edgetrack::read_camera_file(dir + "/camera.yaml", {"", truth.width, truth.height});
  auto visp = edgetrack::read_camera_file(dir + "/camera.xml", {"Camera", truth.width, truth.height});
  TEST((label + "--intrinsics reads the OpenCV file").c_str(), opencv.ok(), true);
  TEST((label + "--intrinsics reads the ViSP file").c_str(), visp.ok(), true);
  if (!opencv.ok() || !visp.ok()) {
    std::printf("%s\n", (opencv.ok() ? visp : opencv).error().text().c_str());
    return;
  }
  const PinholeCamera& o = opencv.value();
  const PinholeCamera& v = visp.value();
  std::printf("%s true px %.3f py %.3f u0 %.3f v0 %.3f; OpenCV file px %.3f py %.3f u0 %.3f v0 %.3f k1 %.5f k2 %.5f "
              "p1 %.5f p2 %.5f; ViSP file px %.3f py %.3f u0 %.3f v0 %.3f kud %.5f kdu %.5f\n",
              what, static_cast<double>(truth.px), static_cast<double>(truth.py), static_cast<double>(truth.u0),
              static_cast<double>(truth.v0), static_cast<double>(o.px), static_cast<double>(o.py),
              static_cast<double>(o.u0), static_cast<double>(o.v0), static_cast<double>(o.lens.k1),
              static_cast<double>(o.lens.k2), static_cast<double>(o.lens.p1), static_cast<double>(o.lens.p2),
              static_cast<double>(v.px), static_cast<double>(v.py), static_cast<double>(v.u0),
              static_cast<double>(v.v0), static_cast<double>(v.lens.kud), static_cast<double>(v.lens.kdu));
  TEST((label + "the OpenCV file holds OpenCV's lens").c_str(), o.lens.model == LensModel::kOpenCv, true);
  TEST((label + "the ViSP file's distorted model is the one read").c_str(), v.lens.model == LensModel::kVisp, true);
  const std::vector<std::pair<const char*, const PinholeCamera*>> files = {{"OpenCV", &o}, {"ViSP", &v}};
  for (const auto& [name, c] : files) {
    if (std::string(name) == "ViSP" && !visp_lens_exact) continue;
    const std::string l = label + name + " file: ";
    TEST_NEAR_REL((l + "px within 1 %").c_str(), static_cast<double>(c->px), static_cast<double>(truth.px), 0.01);
    TEST_NEAR_REL((l + "py within 1 %").c_str(), static_cast<double>(c->py), static_cast<double>(truth.py), 0.01);
    TEST_NEAR((l + "u0 within 1.5 px").c_str(), static_cast<double>(c->u0), static_cast<double>(truth.u0), 1.5);
    TEST_NEAR((l + "v0 within 1.5 px").c_str(), static_cast<double>(c->v0), static_cast<double>(truth.v0), 1.5);
    const double moved = largest_displacement(truth, *c, &coverage), anywhere = largest_displacement(truth, *c, nullptr);
    std::printf("%s%s file: largest displacement of a ray's pixel %.4f px where the target was seen, %.4f px over "
                "the whole image\n", label.c_str(), name, moved, anywhere);
    TEST((l + "every ray's pixel within 0.5 px where the target was seen").c_str(), moved < 0.5, true);
  }
  if (visp_lens_exact) {
    // kdu is itself a fit to kud's inverse: compared with the true lens's own fitted kdu.
    PinholeCamera true_visp = truth;
    true_visp.lens.kdu = real(fitted_kdu(truth));
    const double back = largest_back_displacement(truth, v, &coverage);
    const double true_back = largest_back_displacement(truth, true_visp, &coverage);
    std::printf("%sViSP file: kdu's ray off the true ray by %.4f px at most (the true kud's fitted kdu: %.4f px)\n",
                label.c_str(), back, true_back);
    TEST((label + "ViSP file: kdu's rays within 0.5 px of the true kdu's").c_str(), back < true_back + 0.5, true);
  }
}

void calibrate_and_check(const char* what, const CalibrationTarget& target, const PinholeCamera& truth,
                         const char* kind, const char* count, const char* spacing, bool visp_lens_exact) {
  const std::string dir = std::string(APP_TEST_TMP) + "/calibrate_" + what;
  const std::vector<Se3> views = calibration_views(target, truth);
  const std::string pattern = render_frames(dir, target, truth, views);
  const int status = run_calibrate(pattern, dir, kind, count, spacing);
  TEST((std::string(what) + ": calibrate succeeds").c_str(), status, 0);
  TEST((std::string(what) + ": one overlay per frame, the run complete").c_str(),
       std::filesystem::exists(dir + "/overlay/overlay0024.png") && !std::filesystem::exists(dir + "/overlay/INCOMPLETE"),
       true);
  if (status == 0) check_files(dir, truth, Coverage(target, truth, views), what, visp_lens_exact);
}

/// The frames of `frames_dir` (frame00.pgm ... frameNN.pgm), each written twice as a video holds
/// a still view over neighbouring frames, into an MJPG .avi through OpenCV's VideoWriter; its path.
std::string write_video(const std::string& frames_dir, size_t frames, const std::string& dir) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/views.avi";
  cv::VideoWriter writer;
  char name[32];
  for (size_t k = 0; k < frames; ++k) {
    std::snprintf(name, sizeof name, "/frame%02zu.pgm", k);
    const cv::Mat grey = cv::imread(frames_dir + name, cv::IMREAD_GRAYSCALE);
    TEST("a rendered frame reads back", grey.empty(), false);
    if (grey.empty()) return path;
    if (!writer.isOpened()) {
      writer.open(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10, grey.size(), false);
      TEST("OpenCV opens an MJPG .avi for writing", writer.isOpened(), true);
      if (!writer.isOpened()) return path;
    }
    writer.write(grey);
    writer.write(grey);
  }
  writer.release();
  cv::VideoCapture reader(path);
  TEST("OpenCV reads the video back, two frames a view",
       static_cast<size_t>(reader.get(cv::CAP_PROP_FRAME_COUNT)), 2 * frames);
  return path;
}

/// `calibrate --images VIDEO --step 2` on the frames calibrate_and_check rendered for `rendered`,
/// in a video: the same camera back from the same views.
void calibrate_video_and_check(const char* rendered, const CalibrationTarget& target, const PinholeCamera& truth,
                               const char* kind, const char* count, const char* spacing, bool visp_lens_exact) {
  const std::string what = std::string(rendered) + "_video";
  const std::string dir = std::string(APP_TEST_TMP) + "/calibrate_" + what;
  const std::vector<Se3> views = calibration_views(target, truth);
  const std::string video =
      write_video(std::string(APP_TEST_TMP) + "/calibrate_" + rendered, views.size() + 1, dir);
  const int status = run_calibrate(video, dir, kind, count, spacing, "2");
  TEST((what + ": calibrate succeeds on the video").c_str(), status, 0);
  // Frames 0, 2, ..., 2 x views read (the last the empty view), the odd ones stepped over.
  char last[64];
  std::snprintf(last, sizeof last, "/overlay/overlay%04zu.png", 2 * views.size());
  TEST((what + ": one overlay per frame read, every second frame").c_str(),
       std::filesystem::exists(dir + last) && !std::filesystem::exists(dir + "/overlay/overlay0001.png") &&
           !std::filesystem::exists(dir + "/overlay/INCOMPLETE"),
       true);
  if (status == 0) check_files(dir, truth, Coverage(target, truth, views), what.c_str(), visp_lens_exact);
}

}  // namespace

static void test_calibrate() {
  CalibrationTarget chessboard;  // 9 x 6 inner corners of 20 mm squares
  // A wide lens through ViSP's model (the kud = -0.25), synth's QVGA camera.
  PinholeCamera wide(real(220), real(220), real(160), real(120), 320, 240);
  wide.lens.model = LensModel::kVisp;
  wide.lens.kud = real(-0.25);
  calibrate_and_check("chessboard_visp_lens", chessboard, wide, "chessboard", "9x6", "0.02", true);
  calibrate_video_and_check("chessboard_visp_lens", chessboard, wide, "chessboard", "9x6", "0.02", true);

  // OpenCV's model with a fourth-order term and tangential distortion, non-square pixels and an
  // off-centre principal point: ViSP's one-coefficient lens cannot hold it, OpenCV's file must.
  PinholeCamera tangential(real(300), real(294), real(163.5), real(117.2), 320, 240);
  tangential.lens.model = LensModel::kOpenCv;
  tangential.lens.k1 = real(-0.2);
  tangential.lens.k2 = real(0.08);
  tangential.lens.p1 = real(0.0015);
  tangential.lens.p2 = real(-0.001);
  calibrate_and_check("chessboard_opencv_lens", chessboard, tangential, "chessboard", "9x6", "0.02", false);

  // Circle grids: 6 x 6 circles 20 mm apart (ViSP's grid2d layout) through the wide lens, and
  // OpenCV's asymmetric 4 x 11 grid through the tangential one.
  CalibrationTarget circles;
  circles.kind = TargetKind::kCircles;
  circles.columns = 6;
  circles.rows = 6;
  calibrate_and_check("circles_visp_lens", circles, wide, "circles", "6x6", "0.02", true);
  CalibrationTarget asymmetric;
  asymmetric.kind = TargetKind::kAsymmetricCircles;
  asymmetric.columns = 4;
  asymmetric.rows = 11;
  asymmetric.spacing = real(0.01);
  calibrate_and_check("asymmetric_circles_opencv_lens", asymmetric, tangential, "asymmetric-circles", "4x11", "0.01",
                      false);
}
TESTMAIN(test_calibrate);
