// SPDX-License-Identifier: BSD-3-Clause
/// The host extras as one table of functions: image formats, video and camera I/O through OpenCV
/// (host_io.h), the plots (plots.h), the OSMesa overlay and Edge-ID (overlay.h, visibility.h),
/// the --init-click window (click_init.h) and the OSMesa commands. In the host build they live
/// in a plugin, libexec/edgetrack/edgetrack-host.so, that `edgetrack` loads only when an option
/// needs one of them (host_extras_loader.cpp): on image files the command starts without OpenCV,
/// Qt, GDAL and LLVM.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "click_init.h"
#include "commands.h"
#include "evaluation.h"
#include "host_io.h"
#include "overlay.h"
#include "visibility.h"

namespace edgetrack_app {

struct HostExtras {
  /// The plugin's build: the `real` and the version must be the command's own.
  const char* real_name;
  const char* version;
  edgetrack::Result<RgbImage> (*read_image_any)(const std::string& path);
  edgetrack::Result<bool> (*write_image)(const std::string& path, const RgbImage& image);
  edgetrack::Result<std::unique_ptr<VideoInput>> (*open_video_file)(const std::string& path);
  edgetrack::Result<std::unique_ptr<VideoInput>> (*open_camera_device)(int device);
  edgetrack::Result<std::unique_ptr<VideoOutput>> (*open_video_output)(const std::string& path, int width,
                                                                        int height, double fps);
  edgetrack::Result<bool> (*write_plots)(const std::string& dir, const Evaluation& evaluation);
  edgetrack::Result<std::unique_ptr<Overlay>> (*make_overlay)(const edgetrack::PinholeCamera& camera);
  edgetrack::Result<std::unique_ptr<edgetrack::EdgeIdSource>> (*make_gl_edge_id_source)(
      const edgetrack::PinholeCamera& camera);
  edgetrack::Result<edgetrack::Se3> (*click_initial_pose)(const ClickInitOptions& options, const RgbImage& frame,
                                                          const edgetrack::PinholeCamera& camera,
                                                          const edgetrack::EdgeModel& model);
  std::vector<Command> (*host_commands)();
};

}  // namespace edgetrack_app

/// The plugin's one exported symbol.
extern "C" const edgetrack_app::HostExtras* edgetrack_host_extras();
