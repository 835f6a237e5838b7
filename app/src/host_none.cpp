// SPDX-License-Identifier: BSD-3-Clause
/// What the host-only parts become in builds without OpenCV and OSMesa (the ARM target): PPM is
/// written with our own writer; other formats, video, plots and the OSMesa commands are refused
/// with a message naming the file.
#include "click_init.h"
#include "commands.h"
#include "host_io.h"
#include "overlay.h"
#include "plots.h"
#include "visibility.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

bool host_io_available() { return false; }

Result<RgbImage> read_image_any(const std::string& path) {
  return Error{path, 0, "this build reads PGM, PPM and raw RGB565 only (other formats need the host build)"};
}

Result<bool> write_image(const std::string& path, const RgbImage& image) {
  const std::string ext = extension_of(path);
  if (ext == "ppm" || ext == "pnm") return write_ppm(path, image);
  return Error{path, 0, "this build writes PPM only (PNG needs the host build)"};
}

Result<std::unique_ptr<VideoInput>> open_video_file(const std::string& path) {
  return Error{path, 0, "video input needs the host build (OpenCV)"};
}

Result<std::unique_ptr<VideoInput>> open_camera_device(int device) {
  return Error{"camera " + std::to_string(device), 0, "camera input needs the host build (OpenCV)"};
}

Result<std::unique_ptr<VideoOutput>> open_video_output(const std::string& path, int, int, double) {
  return Error{path, 0, "video output needs the host build (OpenCV)"};
}

Result<bool> write_plots(const std::string& dir, const Evaluation&) {
  return Error{dir, 0, "plots need the host build (OpenCV)"};
}

std::vector<Command> host_commands() { return {}; }

Result<std::unique_ptr<Overlay>> make_overlay(const edgetrack::PinholeCamera& camera) { return make_soft_overlay(camera); }

Result<std::unique_ptr<edgetrack::EdgeIdSource>> make_gl_edge_id_source(const edgetrack::PinholeCamera&) {
  return Error{"", 0, "--visibility gl needs the host build (OSMesa); this build has --visibility soft only"};
}

Result<edgetrack::Se3> click_initial_pose(const ClickInitOptions& options, const RgbImage&, const edgetrack::PinholeCamera&,
                                          const edgetrack::EdgeModel&) {
  return Error{options.init_path, 0,
               "--init-click needs the host build (a window); give the points' image positions with --init I.init "
               "--init-points P.txt instead"};
}

}  // namespace edgetrack_app
