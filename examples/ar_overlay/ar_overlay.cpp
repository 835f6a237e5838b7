// SPDX-License-Identifier: BSD-3-Clause
/// Augmented reality on the installed edgetrack package: tracks a model in a camera, a video
/// or an image sequence read by OpenCV, and draws the model's edges and, as in the paper's
/// figures, a cone standing on the face that looks most upwards at the start.
/// usage: ar_overlay MODEL CAMERA.xml INIT.pos SOURCE [OUT]
///   SOURCE: a camera number (0), a video file, or an image pattern (frames/image%04d.pgm).
///   OUT: a video (overlay.avi) or an image pattern (overlay%04d.png); without it the frames
///   are shown in a window (Esc quits).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/highgui.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "edgetrack/edgetrack.h"

namespace {

cv::Vec3d to_cv(const edgetrack::Vec3& v) { return {double(v.x), double(v.y), double(v.z)}; }

/// A pose and a camera in doubles: drawing needs no `real`.
struct View {
  cv::Matx33d rotation;
  cv::Vec3d translation;
  double px, py, u0, v0;

  View(const edgetrack::Se3& pose, const edgetrack::PinholeCamera& c)
      : translation(to_cv(pose.translation())), px(double(c.px)), py(double(c.py)), u0(double(c.u0)), v0(double(c.v0)) {
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) rotation(r, k) = double(pose.rotation().m[r][k]);
  }
  cv::Vec3d in_camera(const cv::Vec3d& p) const { return rotation * p + translation; }
  cv::Point2d pixel(const cv::Vec3d& p) const {
    const cv::Vec3d c = in_camera(p);
    return {u0 + px * c[0] / c[2], v0 + py * c[1] / c[2]};
  }
};

/// The paper's cone: on the face whose normal points most upwards in the image at `start`.
struct Cone {
  cv::Vec3d base, axis, u, v;
  double radius = 0, height = 0;
};

Cone cone_on_top_face(const edgetrack::EdgeModel& model, const View& start) {
  const auto up = [&](const edgetrack::Face& f) { return -(start.rotation * to_cv(f.normal))[1]; };
  const edgetrack::Face& face = *std::max_element(model.faces.begin(), model.faces.end(),
                                                  [&](const auto& a, const auto& b) { return up(a) < up(b); });
  Cone cone;
  for (int i : face.vertices) cone.base += to_cv(model.vertices[i]) / double(face.vertices.size());
  double nearest = 1e30;
  for (int i : face.vertices) nearest = std::min(nearest, cv::norm(to_cv(model.vertices[i]) - cone.base));
  cone.axis = to_cv(face.normal);
  cone.u = cv::normalize(to_cv(model.vertices[face.vertices[0]]) - cone.base);
  cone.v = cone.axis.cross(cone.u);
  cone.radius = 0.4 * nearest;
  cone.height = 2.2 * cone.radius;
  return cone;
}

/// Side triangles far to near, each shaded by how much it faces the camera.
void draw_cone(cv::Mat& image, const Cone& cone, const View& view) {
  constexpr int kSides = 24;
  const cv::Vec3d apex = cone.base + cone.height * cone.axis;
  struct Side { double depth, light; cv::Point corners[3]; };
  std::vector<Side> sides;
  for (int i = 0; i < kSides; ++i) {
    const double a = 2 * CV_PI * i / kSides, b = 2 * CV_PI * (i + 1) / kSides;
    const cv::Vec3d p = cone.base + cone.radius * (std::cos(a) * cone.u + std::sin(a) * cone.v);
    const cv::Vec3d q = cone.base + cone.radius * (std::cos(b) * cone.u + std::sin(b) * cone.v);
    const cv::Vec3d normal = view.rotation * cv::normalize((q - p).cross(apex - p));
    const cv::Vec3d centre = view.in_camera((p + q + apex) / 3.0);
    sides.push_back({centre[2], std::max(0.0, -normal.dot(cv::normalize(centre))),
                     {cv::Point(view.pixel(p)), cv::Point(view.pixel(q)), cv::Point(view.pixel(apex))}});
  }
  std::sort(sides.begin(), sides.end(), [](const Side& s, const Side& t) { return s.depth > t.depth; });
  for (const Side& s : sides) cv::fillConvexPoly(image, s.corners, 3, cv::Scalar(0, 60 + 150 * s.light, 255), cv::LINE_AA);
}

int fail(const std::string& message) {
  std::fprintf(stderr, "ar_overlay: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) return fail("usage: ar_overlay MODEL CAMERA.xml INIT.pos SOURCE [OUT]");
  const std::string source = argv[4];
  cv::VideoCapture capture;
  if (source.find_first_not_of("0123456789") == std::string::npos) capture.open(std::stoi(source));
  else capture.open(source);
  cv::Mat bgr;
  if (!capture.isOpened() || !capture.read(bgr) || bgr.type() != CV_8UC3) return fail(source + ": no colour frame to read");

  auto model = edgetrack::load_model(argv[1]);
  edgetrack::TrackerConfig config;  // the camera and settings of a ViSP XML, as loadConfigFile reads it
  auto read = edgetrack::apply_visp_config(argv[2], config);
  auto initial = edgetrack::read_pos(argv[3]);
  for (const edgetrack::Error* e : {&model.error(), &read.error(), &initial.error()})
    if (!e->message.empty()) return fail(e->text());
  if (config.camera.width == 0) config.camera.width = bgr.cols;
  if (config.camera.height == 0) config.camera.height = bgr.rows;
  const edgetrack::PinholeCamera& camera = config.camera;
  auto tracker = edgetrack::Tracker::create(model.value(), camera, initial.value(), config.params);
  if (!tracker.ok()) return fail(tracker.error().text());
  const Cone cone = cone_on_top_face(model.value(), View(initial.value(), camera));
  cv::VideoWriter video;
  const bool images = argc > 5 && std::string(argv[5]).find('%') != std::string::npos;
  if (argc > 5 && !(images ? video.open(argv[5], cv::CAP_IMAGES, 0, 15, bgr.size())
                            : video.open(argv[5], cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 15, bgr.size())))
    return fail(std::string(argv[5]) + ": cannot write the video");

  std::printf("%s\n", edgetrack::kPosesCsvHeader);  // the poses CSV, as minimal prints it
  for (int index = 0; !bgr.empty(); ++index, capture.read(bgr)) {
    // OpenCV's BGR frame, read in place with its row stride.
    auto tracked = tracker.value().track({bgr.data, bgr.cols, bgr.rows, int(bgr.step), edgetrack::PixelLayout::kBgr24});
    if (!tracked.ok()) return fail(tracked.error().text());
    const edgetrack::FrameResult& r = tracked.value();
    const View view(r.camera_from_model, camera);
    for (const edgetrack::Edge& e : model.value().edges)
      cv::line(bgr, view.pixel(to_cv(model.value().vertices[e.a])), view.pixel(to_cv(model.value().vertices[e.b])),
               cv::Scalar(0, 255, 0), 1, cv::LINE_AA);
    draw_cone(bgr, cone, view);
    std::printf("%s\n", edgetrack::poses_csv_line(edgetrack::poses_csv_row(index, r)).c_str());
    if (video.isOpened()) {
      video.write(bgr);
    } else {
      cv::imshow("edgetrack ar_overlay", bgr);
      if (cv::waitKey(1) == 27) break;
    }
  }
  return 0;
}
