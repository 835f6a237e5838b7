// SPDX-License-Identifier: BSD-3-Clause
/// Reading --camera and --config.
#include "configuration.h"

#include <algorithm>
#include <cstdio>

#include "edgetrack/camera_file.h"

using edgetrack::Result;
using edgetrack::TrackerConfig;

namespace edgetrack_app {
namespace {

std::string not_applied_note(const std::string& element) { return element + " is read but not applied"; }

std::string default_camera_note(const edgetrack::PinholeCamera& camera) {
  char text[160];
  std::snprintf(text, sizeof text, "no <camera> block: ViSP's default camera px = %g, py = %g, u0 = %g, v0 = %g",
                static_cast<double>(camera.px), static_cast<double>(camera.py), static_cast<double>(camera.u0),
                static_cast<double>(camera.v0));
  return text;
}

}  // namespace

void print_notes(const std::vector<std::string>& notes) {
  for (const std::string& note : notes) std::fprintf(stderr, "note: %s\n", note.c_str());
}

Result<Configuration> read_configuration(const std::string& camera_path, const std::string& config_path) {
  Configuration read;
  auto first = edgetrack::apply_visp_config(camera_path, read.config);
  if (!first.ok()) return first.error();
  std::vector<std::string> not_applied = first.value().not_applied;
  read.notes = first.value().cut_to_whole;
  bool camera_block = first.value().camera_block;
  if (!config_path.empty()) {
    auto second = edgetrack::apply_visp_config(config_path, read.config);
    if (!second.ok()) return second.error();
    for (const std::string& cut : second.value().cut_to_whole) read.notes.push_back(cut);
    for (const std::string& element : second.value().not_applied)
      if (std::find(not_applied.begin(), not_applied.end(), element) == not_applied.end()) not_applied.push_back(element);
    camera_block = camera_block || second.value().camera_block;
  }
  for (const std::string& element : not_applied) read.notes.push_back(not_applied_note(element));
  if (!camera_block) read.notes.push_back(default_camera_note(read.config.camera));
  return read;
}

Result<edgetrack::PinholeCamera> read_camera(const std::string& path, int width, int height) {
  TrackerConfig config;
  auto read = edgetrack::apply_visp_config(path, config);
  if (!read.ok()) return read.error();
  print_notes(read.value().cut_to_whole);
  if (!read.value().camera_block) print_notes({default_camera_note(config.camera)});
  edgetrack::PinholeCamera camera = config.camera;
  if (camera.width == 0) camera.width = width;
  if (camera.height == 0) camera.height = height;
  if (camera.width <= 0 || camera.height <= 0) return edgetrack::Error{path, 0, "the camera has no image size (give --size)"};
  return camera;
}

const std::vector<OptionSpec>& intrinsics_specs() {
  static const std::vector<OptionSpec> specs = {
      {"--intrinsics", "FILE",
       "calibration file, ViSP's camera XML or OpenCV's YAML/XML, with the lens distortion; it replaces the camera of "
       "the ViSP XML (docs/FORMATS.md)", ""},
      {"--intrinsics-name", "NAME",
       "with --intrinsics: the ViSP camera <name> to take (default: the file's first camera of the image's size)", ""},
  };
  return specs;
}

Result<edgetrack::PinholeCamera> apply_intrinsics(const Args& a, const edgetrack::PinholeCamera& camera) {
  if (!a.has("--intrinsics")) {
    if (a.has("--intrinsics-name")) return edgetrack::Error{"", 0, "--intrinsics-name needs --intrinsics"};
    return camera;
  }
  return edgetrack::read_camera_file(a.text("--intrinsics"),
                                     edgetrack::CameraChoice{a.text("--intrinsics-name"), camera.width, camera.height});
}

}  // namespace edgetrack_app
