// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack calibrate` (host): a camera's intrinsics and lens from frames of a chessboard or a
/// circle grid (calibration.h, OpenCV), written as ViSP's camera file and OpenCV's calibration
/// file, the two formats `--intrinsics` reads.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "args.h"
#include "atomic_output.h"
#include "calibration.h"
#include "commands.h"
#include "edgetrack/calibration_target.h"
#include "edgetrack/grey_conversion.h"
#include "frame_source.h"
#include "host_io.h"

using edgetrack::CalibrationTarget;
using edgetrack::Error;
using edgetrack::Result;
using edgetrack::TargetKind;

namespace edgetrack_app {
namespace {

CommandLine calibrate_command_line() {
  return {
      "calibrate",
      "--images PATTERN|DIR|VIDEO --count COLUMNSxROWS --spacing M --visp FILE --opencv FILE "
      "[--target chessboard|circles|asymmetric-circles] [--first N] [--last N] [--step N] [--name NAME] [--k3] [--overlay DIR]",
      {
          {"--images", "PATTERN|DIR|VIDEO", "the frames: printf pattern, directory or video file", ""},
          {"--first", "N", "first frame number", ""},
          {"--last", "N", "last frame number", ""},
          {"--step", "N", "use every Nth frame from the first (a video's neighbouring frames show the same view)", "1"},
          {"--target", "chessboard|circles|asymmetric-circles", "the calibration target", "chessboard"},
          {"--count", "COLUMNSxROWS", "inner corners (chessboard) or circles along a row x along a column", ""},
          {"--spacing", "M", "metres: a square's side, or between neighbouring circles (asymmetric: between rows)", ""},
          {"--visp", "FILE", "write ViSP's camera file (vpXmlParserCamera: both models) here", ""},
          {"--opencv", "FILE", "write OpenCV's calibration file (cv::FileStorage YAML) here", ""},
          {"--name", "NAME", "the camera's <name> in the ViSP file", "Camera"},
          {"--k3", "", "OpenCV's model also gets k3 (the sixth-order radial term; wide lenses, many views)", ""},
          {"--overlay", "DIR", "write each frame with the target's points drawn (overlayNNNN.png) here", ""},
      },
      {"--images", "--count", "--spacing", "--visp", "--opencv"},
      {},
      {},
  };
}

/// --target, --count and --spacing as the target, or an Error naming the option.
Result<CalibrationTarget> read_target(const Args& a) {
  CalibrationTarget target;
  const std::string kind = a.text("--target");
  if (kind == "chessboard") target.kind = TargetKind::kChessboard;
  else if (kind == "circles") target.kind = TargetKind::kCircles;
  else if (kind == "asymmetric-circles") target.kind = TargetKind::kAsymmetricCircles;
  else return Error{"", 0, "--target '" + kind + "': expected chessboard, circles or asymmetric-circles"};
  const std::string count = a.text("--count");
  char end = 0;
  // At least 3 x 2 points make a target whose grid the detectors can orient; 100 a side is more
  // than any printed target holds.
  if (std::sscanf(count.c_str(), "%dx%d%c", &target.columns, &target.rows, &end) != 2 || target.columns < 2 ||
      target.rows < 2 || target.columns * target.rows < 6 || target.columns > 100 || target.rows > 100)
    return Error{"", 0, "--count '" + count + "': expected COLUMNSxROWS, each 2..100, 6 points or more"};
  auto spacing = a.number("--spacing");
  if (!spacing.ok()) return spacing.error();
  if (spacing.value() < 1e-4 || spacing.value() > 10)
    return Error{"", 0, "--spacing must be 0.0001..10 metres"};
  target.spacing = real(spacing.value());
  return target;
}

/// The frames read: the target's points in each frame that shows it, the names of the others.
struct Detections {
  std::vector<std::vector<PixelPoint>> views;
  std::vector<std::string> found, rejected;
  int width = 0, height = 0;
};

/// Reads every frame, finds the target in it, and draws it into `overlay_dir` when given.
Result<Detections> detect_in_frames(const SourceOptions& source, int step, const CalibrationTarget& target,
                                    const std::string& overlay_dir) {
  auto frames = open_frame_source(source);
  if (!frames.ok()) return frames.error();
  Detections d;
  Frame frame;
  for (int read = 0;; ++read) {
    auto next = frames.value()->next(frame);
    if (!next.ok()) return next.error();
    if (!next.value()) break;
    if (read % step != 0) continue;
    if (d.width == 0) d.width = frame.pixels.width, d.height = frame.pixels.height;
    if (frame.pixels.width != d.width || frame.pixels.height != d.height)
      return Error{frame.name, 0, "is " + std::to_string(frame.pixels.width) + "x" + std::to_string(frame.pixels.height) +
                                      ", the first frame " + std::to_string(d.width) + "x" + std::to_string(d.height)};
    // The grey the tracker reads (vpImageConvert's rule), so the target is found in what tracks.
    vpImage<unsigned char> grey(static_cast<unsigned>(d.height), static_cast<unsigned>(d.width));
    edgetrack::convert_to_grey(frame.pixels.view(), {0, 0, d.height, d.width}, grey);
    std::vector<PixelPoint> points = find_target(target, grey.bitmap, d.width, d.height);
    if (!overlay_dir.empty()) {
      RgbImage image = to_rgb_image(frame.pixels.view());
      if (!points.empty()) draw_target_points(image, target, points);
      char name[32];
      std::snprintf(name, sizeof name, "/overlay%04d.png", frame.index);
      auto written = write_image(overlay_dir + name, image);
      if (!written.ok()) return written.error();
    }
    if (points.empty()) {
      d.rejected.push_back(frame.name);
      continue;
    }
    d.views.push_back(std::move(points));
    d.found.push_back(frame.name);
  }
  return d;
}

void print_model(const char* what, const CalibratedModel& m) {
  const edgetrack::PinholeCamera& c = m.camera;
  std::printf("calibrate: %s: px %.4f py %.4f u0 %.4f v0 %.4f", what, static_cast<double>(c.px),
              static_cast<double>(c.py), static_cast<double>(c.u0), static_cast<double>(c.v0));
  if (c.lens.model == edgetrack::LensModel::kOpenCv)
    std::printf(" k1 %.6f k2 %.6f p1 %.6f p2 %.6f k3 %.6f", static_cast<double>(c.lens.k1),
                static_cast<double>(c.lens.k2), static_cast<double>(c.lens.p1), static_cast<double>(c.lens.p2),
                static_cast<double>(c.lens.k3));
  if (c.lens.model == edgetrack::LensModel::kVisp)
    std::printf(" kud %.6f kdu %.6f", static_cast<double>(c.lens.kud), static_cast<double>(c.lens.kdu));
  std::printf("; reprojection error %.4f px RMS\n", m.rms_px);
}

void print_results(const Detections& d, const Calibration& c) {
  std::printf("calibrate: the target in %zu of %zu frames (%dx%d)\n", d.views.size(), d.views.size() + d.rejected.size(),
              d.width, d.height);
  for (const std::string& name : d.rejected) std::printf("calibrate: rejected %s: target not found\n", name.c_str());
  print_model("OpenCV", c.opencv);
  print_model("ViSP perspectiveProjWithDistortion", c.visp);
  print_model("ViSP perspectiveProjWithoutDistortion", c.visp_pinhole);
  for (size_t i = 0; i < d.found.size() && i < c.opencv.view_rms_px.size(); ++i)
    std::printf("calibrate: %s: %.4f px RMS (OpenCV's model)\n", d.found[i].c_str(), c.opencv.view_rms_px[i]);
  std::printf("calibrate: frames=%zu rejected=%zu rms_opencv=%.6f rms_visp=%.6f rms_pinhole=%.6f\n", d.views.size(),
              d.rejected.size(), c.opencv.rms_px, c.visp.rms_px, c.visp_pinhole.rms_px);
}

int calibrate_main(int argc, char** argv) {
  Args a;
  if (auto stop = parse_command_line(calibrate_command_line(), argc, argv, a)) return *stop;
  std::vector<std::pair<std::string, std::string>> outputs;
  for (const char* option : {"--visp", "--opencv", "--overlay"})
    if (a.has(option)) outputs.emplace_back(option, a.text(option));
  if (auto clash = check_output_names(outputs)) return report("calibrate", *clash) + 1;
  auto target = read_target(a);
  if (!target.ok()) return report("calibrate", target.error()) + 1;
  const std::string name = a.text("--name");
  if (name.empty() || name.find_first_of("<>&") != std::string::npos)
    return report("calibrate", {"", 0, "--name '" + name + "': give a name without <, > or &"}) + 1;
  SourceOptions source;
  source.images = a.text("--images");
  auto first = a.frame_number("--first"), last = a.frame_number("--last");
  auto step = a.integer("--step");
  for (const Error* bad : {&first.error(), &last.error(), &step.error()})
    if (!bad->message.empty()) return report("calibrate", *bad) + 1;
  if (step.value() < 1) return report("calibrate", {"", 0, "--step must be 1 or more"}) + 1;
  source.first = first.value(), source.last = last.value();

  const std::string overlay_dir = a.text("--overlay");
  if (!overlay_dir.empty()) {
    if (auto refused = prepare_overlay_directory(overlay_dir, kIncompleteMarker)) return report("calibrate", *refused);
    auto marked = write_text_file(overlay_dir + "/" + kIncompleteMarker, "calibrate has not finished\n");
    if (!marked.ok()) return report("calibrate", marked.error());
  }
  auto detections = detect_in_frames(source, step.value(), target.value(), overlay_dir);
  if (!detections.ok()) return report("calibrate", detections.error());
  const Detections& d = detections.value();
  if (d.views.size() < 3) {
    std::string rejected;
    for (const std::string& n : d.rejected) rejected += " " + n;
    return report("calibrate", {source.images, 0, "the target is in " + std::to_string(d.views.size()) +
                                                      " frames, 3 or more are needed (not found in:" + rejected + ")"});
  }
  auto calibration = calibrate_views(target.value(), d.views, d.width, d.height, a.has("--k3"));
  if (!calibration.ok()) return report("calibrate", calibration.error());
  const Calibration& c = calibration.value();
  print_results(d, c);
  auto visp = write_atomically(a.text("--visp"), [&](const std::string& path) {
    return write_visp_camera_file(path, name, c.visp_pinhole.camera, c.visp.camera);
  });
  if (!visp.ok()) return report("calibrate", visp.error());
  auto opencv = write_atomically(a.text("--opencv"), [&](const std::string& path) {
    return write_opencv_calibration(path, c.opencv, static_cast<int>(d.views.size()));
  });
  if (!opencv.ok()) {
    std::remove(a.text("--visp").c_str());  // both files or neither: one calibration
    return report("calibrate", opencv.error());
  }
  if (!overlay_dir.empty()) std::remove((overlay_dir + "/" + kIncompleteMarker).c_str());
  std::printf("calibrate: ViSP camera file %s, OpenCV calibration file %s\n", a.text("--visp").c_str(),
              a.text("--opencv").c_str());
  return 0;
}

}  // namespace

std::vector<Command> calibration_commands() {
  return {{"calibrate", "a camera's intrinsics and lens from frames of a chessboard or circle grid (ViSP and OpenCV files)",
           calibrate_main}};
}

}  // namespace edgetrack_app
