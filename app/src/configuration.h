// SPDX-License-Identifier: BSD-3-Clause
/// The command line's ViSP configuration files: `--camera C.xml` read as ViSP's loadConfigFile
/// reads it, `--config X.xml` over it, and the notes printed once.
#pragma once

#include <string>
#include <vector>

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

}  // namespace edgetrack_app
