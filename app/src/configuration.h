// SPDX-License-Identifier: BSD-3-Clause
/// The command line's ViSP configuration files: `--camera C.xml` read as ViSP's loadConfigFile
/// reads it, `--config X.xml` over it, and the notes printed once.
#pragma once

#include <string>
#include <vector>

#include "args.h"
#include "edgetrack/result.h"
#include "edgetrack/visp_config.h"

namespace edgetrack_app {

/// The configuration and the notes to print about it.
struct Configuration {
  edgetrack::TrackerConfig config;
  /// One line each: the elements read and not applied (once, whichever file they came from),
  /// and ViSP's default camera when neither file has a <camera> block.
  std::vector<std::string> notes;
};

/// Reads `camera_path`, then `config_path` (when not empty) over it: a value in the second file
/// replaces the first's, element by element.
edgetrack::Result<Configuration> read_configuration(const std::string& camera_path, const std::string& config_path);

/// Prints each note on stderr as "note: ...".
void print_notes(const std::vector<std::string>& notes);

/// The camera of one file, its image size from the file or else width x height.
edgetrack::Result<edgetrack::PinholeCamera> read_camera(const std::string& path, int width, int height);

/// `--intrinsics FILE` and `--intrinsics-name NAME`, for every command that reads a camera.
const std::vector<OptionSpec>& intrinsics_specs();
/// `camera` (from the ViSP XML) replaced, when --intrinsics is given, by the calibration file's
/// camera (camera_file.h), which takes precedence: the file's camera named --intrinsics-name and
/// of camera's image size when that is known (width and height not 0).
edgetrack::Result<edgetrack::PinholeCamera> apply_intrinsics(const Args& a, const edgetrack::PinholeCamera& camera);

}  // namespace edgetrack_app
