// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack detect`: finds the model in one image with no pose given (tracker/.../detector.h)
/// and prints the pose, its score and the time; `--out` writes the pose as a .pos file. Exit
/// status 0 when found, 3 when not found, 1 or 2 on errors.
#include <chrono>
#include <cstdio>

#include "args.h"
#include "commands.h"
#include "configuration.h"
#include "count_markers.h"
#include "detection_options.h"
#include "edgetrack/detector/detector.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "frame_source.h"
#include "image_io.h"

using edgetrack::Error;

namespace edgetrack_app {

namespace {

constexpr int kNotFound = 3;

void print_detection(const edgetrack::Detection& d, double ms) {
  const edgetrack::Vec3 t = d.camera_from_model.translation(), tu = d.camera_from_model.theta_u();
  if (d.found)
    std::printf("pose (tx ty tz m, tux tuy tuz rad): %.6f %.6f %.6f %.6f %.6f %.6f\n", static_cast<double>(t.x),
                static_cast<double>(t.y), static_cast<double>(t.z), static_cast<double>(tu.x),
                static_cast<double>(tu.y), static_cast<double>(tu.z));
  std::printf("detect: found=%d score=%.3f match_share=%.3f candidates=%zu points=%d cut_short=%d ms=%.1f\n",
              d.found ? 1 : 0, static_cast<double>(d.score), static_cast<double>(d.match_share), d.refined.size(),
              d.points_searched, d.cut_short ? 1 : 0, ms);
}

}  // namespace

int detect_main(int argc, char** argv) {
  CommandLine line = {
      "detect",
      "--model FILE --camera FILE --image FILE [--out FILE] [--templates FILE | range options]",
      {
          {"--model", "FILE", "model, .cao or .obj", ""},
          {"--camera", "FILE", "ViSP camera XML", ""},
          {"--config", "FILE", "a second ViSP XML whose values override those of --camera (the refining tracker's settings)", ""},
          {"--image", "FILE", "the image: PGM/PPM, raw RGB565 with --raw-size, or any format OpenCV reads (host)", ""},
          {"--raw-size", "WIDTHxHEIGHT", "size of a raw RGB565 image", ""},
          {"--templates", "FILE", "templates made by `edgetrack templates` for this model and camera", ""},
          {"--out", "FILE", "write the pose found as a .pos file", ""},
          detector_option_spec(),
      },
      {"--model", "--camera", "--image"},
      {},
      {},
  };
  for (const OptionSpec& spec : template_range_specs()) line.options.push_back(spec);
  for (const OptionSpec& spec : intrinsics_specs()) line.options.push_back(spec);
  Args a;
  if (auto stop = parse_command_line(line, argc, argv, a)) return *stop;
  int raw_width = 0, raw_height = 0;
  auto raw = a.size("--raw-size", raw_width, raw_height);
  if (!raw.ok()) return report("detect", raw.error()) + 1;
  auto model = edgetrack::load_model(a.text("--model"));
  if (!model.ok()) return report("detect", model.error());
  auto config = read_configuration(a.text("--camera"), a.text("--config"));
  if (!config.ok()) return report("detect", config.error());
  auto image = read_frame_file(a.text("--image"), raw_width, raw_height);
  if (!image.ok()) return report("detect", image.error());
  edgetrack::PinholeCamera camera = config.value().config.camera;
  if (camera.width == 0) camera.width = image.value().width;
  if (camera.height == 0) camera.height = image.value().height;
  auto calibrated = apply_intrinsics(a, camera);
  if (!calibrated.ok()) return report("detect", calibrated.error());
  camera = calibrated.value();
  if (camera.width != image.value().width || camera.height != image.value().height)
    return report("detect", {a.text("--image"), 0,
                             "image size " + std::to_string(image.value().width) + "x" +
                                 std::to_string(image.value().height) + " does not match the camera's " +
                                 std::to_string(camera.width) + "x" + std::to_string(camera.height)});
  print_detection_reduction(camera, "detect");
  auto templates = templates_for(a, model.value(), camera);
  if (!templates.ok()) {
    edgetrack::Error error = templates.error();
    // An image too small to downscale for matching is the image's fault: name it.
    if (error.file.empty() && error.message.find("image") != std::string::npos) error.file = a.text("--image");
    return report("detect", error);
  }
  auto detection_params = detector_params_from(a, config.value().config.detector);
  if (!detection_params.ok()) return report("detect", detection_params.error()) + 1;
  auto detector = edgetrack::Detector::create(model.value(), camera, std::move(templates).value(),
                                              detection_params.value(), config.value().config.params);
  if (!detector.ok()) return report("detect", detector.error());
  const auto start = std::chrono::steady_clock::now();
  edgetrack_count_begin();  // the detector's own share (QEMU counter, tests/bench/mcu)
  const auto detected = detector.value().detect(image.value().view());
  edgetrack_count_end();
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!detected.ok()) return report("detect", {a.text("--image"), 0, detected.error().message});
  const edgetrack::Detection& detection = detected.value();
  print_detection(detection, ms);
  print_notes(config.value().notes);
  if (!detection.found) return kNotFound;
  if (a.has("--out")) {
    auto written = edgetrack::write_pos(a.text("--out"), detection.camera_from_model);
    if (!written.ok()) return report("detect", written.error());
  }
  return 0;
}

std::vector<Command> detection_commands() {
  return {{"detect", "find the model in one image with no pose given (templates from the model, refined by the tracker)",
           detect_main},
          {"templates", "make the detector's templates for a model and a camera, for detect --templates", templates_main}};
}

}  // namespace edgetrack_app
