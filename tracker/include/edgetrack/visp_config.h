// SPDX-License-Identifier: BSD-3-Clause
/// One ViSP model-based tracker configuration file (as mbt/cube.xml), read the way ViSP 3.5's
/// vpMbGenericTracker::loadConfigFile reads it for the edge tracker: <camera>, <ecm> (and the
/// older <sample> beside it), <face> and <lod>. Values the file does not give keep what the
/// configuration held before, so a second file overrides the first element by element.
/// edgetrack's own status settings (StatusParams, each element named as its field) come from a
/// <status> block, or <edgetrack><status>, which ViSP passes over; the camera's rolling-shutter
/// readout (TrackerParams::readout) from <edgetrack><camera><readout>; the detector's work budget
/// (DetectorParams::max_points_searched) from <edgetrack><detector><max_points_searched>.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/detector/detector.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/tracker_params.h"

namespace edgetrack {

/// The camera and the tracker settings a configuration describes.
struct TrackerConfig {
  /// ViSP's default camera (vpCameraParameters: px = py = 600, u0 = 192, v0 = 144); the image
  /// size is 0 until a file gives one (<width>/<height> or <image_width>/<image_height>).
  PinholeCamera camera{real(600), real(600), real(192), real(144), 0, 0};
  TrackerParams params;  ///< ViSP's defaults for the edge tracker (vpMe, vpMbTracker)
  DetectorParams detector;  ///< for --init-auto and detect: the defaults but what <edgetrack><detector> sets
};

/// What a file held beyond the values it set.
struct ConfigNotes {
  bool camera_block = false;  ///< it had a <camera> block
  /// Elements read and not applied, as "<ecm><contrast><mu1>", each once.
  std::vector<std::string> not_applied;
  /// Decimal fractions where ViSP reads a whole number, each as "<ecm><sample><step> '4.5' is
  /// read as 4, ...": ViSP cuts them to their whole part, and so does this reader.
  std::vector<std::string> cut_to_whole;
};

/// Applies the file at `path` onto `config`. A value that is not a number (or, where ViSP reads
/// an integer, neither a whole number nor a decimal fraction) or outside check_tracker_params'
/// limits is an Error naming the file, the line and the element; nothing is applied then. Unknown elements and blocks for
/// ViSP's other trackers (<klt>, <depth_normal>, <depth_dense>) are passed over, as ViSP's edge
/// tracker does.
Result<ConfigNotes> apply_visp_config(const std::string& path, TrackerConfig& config);
/// The same for a configuration held in memory (`xml`, the file's text); `name` stands for the
/// file in errors.
Result<ConfigNotes> apply_visp_config_text(const std::string& xml, const std::string& name, TrackerConfig& config);

}  // namespace edgetrack
