// SPDX-License-Identifier: BSD-3-Clause
/// The host functions of `edgetrack` (host build): each one loads the host extras plugin
/// (libexec/edgetrack/edgetrack-host.so, found from the running executable) the first time an
/// option needs it and calls the plugin's own. A missing or mismatched plugin is one Error
/// naming it and what needed it.
#include <dlfcn.h>
#include <unistd.h>

#include "host_extras.h"
#include "plots.h"
#include "real/real_config.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

Result<const HostExtras*> load_host_extras() {
  auto found = path_from_executable(EDGETRACK_HOST_EXTRAS_FROM_BINDIR);
  if (!found.ok()) return found.error();
  const std::string& path = found.value();
  if (access(path.c_str(), R_OK) != 0)
    return Error{path, 0, "is missing (edgetrack installs it in libexec/edgetrack)"};
  void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // never closed: its objects live until exit
  if (library == nullptr) return Error{path, 0, std::string("cannot be loaded: ") + dlerror()};
  using Entry = const HostExtras* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(library, "edgetrack_host_extras"));
  if (entry == nullptr) return Error{path, 0, "is not edgetrack's (no edgetrack_host_extras)"};
  const HostExtras* extras = entry();
  if (std::string(extras->real_name) != EDGETRACK_REAL_NAME || std::string(extras->version) != EDGETRACK_VERSION)
    return Error{path, 0, std::string("is edgetrack ") + extras->version + " (real = " + extras->real_name +
                              "), this command " + EDGETRACK_VERSION + " (real = " + EDGETRACK_REAL_NAME + ")"};
  return extras;
}

/// The plugin, loaded once; `what` names the option that needs it in the error.
Result<const HostExtras*> host_extras(const std::string& what) {
  static const Result<const HostExtras*> loaded = load_host_extras();
  if (loaded.ok()) return loaded;
  return Error{loaded.error().file, 0, what + " needs the host extras plugin, which " + loaded.error().message};
}

/// `synth`, `edgeid` and `calibrate` run the plugin's command of the same name.
int run_host_command(int argc, char** argv) {
  auto extras = host_extras(argv[0]);
  if (!extras.ok()) return report(argv[0], extras.error());
  for (const Command& c : extras.value()->host_commands())
    if (c.name == std::string(argv[0])) return c.run(argc, argv);
  return report(argv[0], Error{"", 0, "the host extras plugin has no such command"});
}

}  // namespace

bool host_io_available() { return true; }

Result<RgbImage> read_image_any(const std::string& path) {
  auto extras = host_extras("reading " + path);
  if (!extras.ok()) return extras.error();
  return extras.value()->read_image_any(path);
}

Result<bool> write_image(const std::string& path, const RgbImage& image) {
  auto extras = host_extras("writing " + path);
  if (!extras.ok()) return extras.error();
  return extras.value()->write_image(path, image);
}

Result<std::unique_ptr<VideoInput>> open_video_file(const std::string& path) {
  auto extras = host_extras("the video " + path);
  if (!extras.ok()) return extras.error();
  return extras.value()->open_video_file(path);
}

Result<std::unique_ptr<VideoInput>> open_camera_device(int device) {
  auto extras = host_extras("--camera-device");
  if (!extras.ok()) return extras.error();
  return extras.value()->open_camera_device(device);
}

Result<std::unique_ptr<VideoOutput>> open_video_output(const std::string& path, int width, int height, double fps) {
  auto extras = host_extras("--video");
  if (!extras.ok()) return extras.error();
  return extras.value()->open_video_output(path, width, height, fps);
}

Result<bool> write_plots(const std::string& dir, const Evaluation& evaluation) {
  auto extras = host_extras("--plots");
  if (!extras.ok()) return extras.error();
  return extras.value()->write_plots(dir, evaluation);
}

Result<std::unique_ptr<Overlay>> make_overlay(const edgetrack::PinholeCamera& camera) {
  auto extras = host_extras("drawing the overlay (--overlay, --video)");
  if (!extras.ok()) return extras.error();
  return extras.value()->make_overlay(camera);
}

Result<std::unique_ptr<edgetrack::EdgeIdSource>> make_gl_edge_id_source(const edgetrack::PinholeCamera& camera) {
  auto extras = host_extras("--visibility gl");
  if (!extras.ok()) return extras.error();
  return extras.value()->make_gl_edge_id_source(camera);
}

Result<edgetrack::Se3> click_initial_pose(const ClickInitOptions& options, const RgbImage& frame,
                                          const edgetrack::PinholeCamera& camera, const edgetrack::EdgeModel& model) {
  auto extras = host_extras("--init-click");
  if (!extras.ok()) return extras.error();
  return extras.value()->click_initial_pose(options, frame, camera, model);
}

// The summaries are listed here so that `edgetrack --help` does not load the plugin.
std::vector<Command> host_commands() {
  return {{"synth", "render a ground-truth sequence with OSMesa (frames, truth.csv, first pose, camera)", run_host_command},
          {"edgeid", "portable Edge-ID against Edge-ID through GL; colour-code approximation in RGB565", run_host_command},
          {"calibrate", "a camera's intrinsics and lens from frames of a chessboard or circle grid (ViSP and OpenCV files)",
           run_host_command}};
}

}  // namespace edgetrack_app
