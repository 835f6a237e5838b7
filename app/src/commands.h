// SPDX-License-Identifier: BSD-3-Clause
/// The subcommands of the `edgetrack` executable.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack_app {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);  ///< argv[0] is the subcommand's name
};

/// Commands every build has (the ARM build included).
int eval_main(int argc, char** argv);
/// `track`, when the tracker's frame loop is in the checkout (else empty).
std::vector<Command> tracking_commands();
/// `detect` and `templates` (cmd_detect.cpp, cmd_templates.cpp), when the tracker's frame loop
/// is in the checkout.
std::vector<Command> detection_commands();
int detect_main(int argc, char** argv);
int templates_main(int argc, char** argv);
/// Commands that need host libraries (OSMesa, OpenCV); empty in the ARM build.
std::vector<Command> host_commands();
int edgeid_main(int argc, char** argv);
/// `calibrate` (cmd_calibrate.cpp, host): one of the host commands.
std::vector<Command> calibration_commands();
/// `compare`, when ViSP's mbt module was found at configure time (else empty).
std::vector<Command> comparison_commands();

/// Prints "edgetrack <command>: <error>" to stderr and returns the exit status for a failure.
int report(const std::string& command, const edgetrack::Error& error);

/// The file `track --overlay DIR` keeps in DIR while the run is not complete.
constexpr const char* kIncompleteMarker = "INCOMPLETE";
/// Writes `text` to `path`, or an Error naming it.
edgetrack::Result<bool> write_text_file(const std::string& path, const std::string& text);

/// The data folder of the source tree (data/), for default models.
std::string data_dir();

/// `relative` (a path from the installed bin/ folder, as libexec/edgetrack/...) from where the
/// running executable is: the build tree mirrors the install, so one rule serves both.
edgetrack::Result<std::string> path_from_executable(const std::string& relative);

/// An Error naming `source` when a model vertex is not in front of the camera (Z <= 1 mm).
edgetrack::Result<bool> check_in_front(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model,
                                       const std::string& source);

/// Writes the camera as a ViSP-style XML file with its image size (read_camera in configuration.h reads it).
edgetrack::Result<bool> write_camera_xml(const std::string& path, const edgetrack::PinholeCamera& camera);
/// `camera` (ViSP's lens or none) as ViSP's vpXmlParserCamera writes a camera file: the model
/// without distortion, and with it when the camera has ViSP's lens.
edgetrack::Result<bool> write_visp_camera_file(const std::string& path, const edgetrack::PinholeCamera& camera);
/// A ViSP camera file named `name` with the model `without_distortion` and, when
/// `with_distortion` has ViSP's lens, that model too (a calibration estimates each on its own).
edgetrack::Result<bool> write_visp_camera_file(const std::string& path, const std::string& name,
                                               const edgetrack::PinholeCamera& without_distortion,
                                               const edgetrack::PinholeCamera& with_distortion);

}  // namespace edgetrack_app
