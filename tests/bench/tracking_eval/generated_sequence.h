// SPDX-License-Identifier: BSD-3-Clause
/// A sequence written by `edgetrack synth`, as the tracking_eval tools read it: the model, the
/// camera-only XML applied as `track --camera` applies it, the true poses and the frames.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/tracker.h"
#include "edgetrack/visp_config.h"
#include "image_io.h"
#include "pose_table.h"

struct GeneratedSequence {
  std::string directory;
  edgetrack::EdgeModel model;
  edgetrack::TrackerConfig config;
  std::vector<edgetrack::Se3> truth;  ///< camera_from_model per frame, in frame order

  /// Reads MODEL.cao and the sequence's camera.xml and truth.csv; false (and a message naming
  /// `tool`) when any of them cannot be read.
  bool load(const char* tool, const std::string& model_path, const std::string& sequence) {
    using namespace edgetrack;
    directory = sequence;
    const Result<EdgeModel> loaded = load_model(model_path);
    const auto notes = apply_visp_config(sequence + "/camera.xml", config);
    const auto rows = edgetrack_app::read_pose_table(sequence + "/truth.csv", edgetrack_app::kTruthHeader);
    if (!loaded.ok() || !notes.ok() || !rows.ok() || rows.value().empty()) {
      std::fprintf(stderr, "%s: cannot read the model, camera.xml or truth.csv\n", tool);
      return false;
    }
    model = loaded.value();
    truth.clear();
    for (const edgetrack_app::PoseRow& row : rows.value())
      truth.emplace_back(rotation_exp(Vec3{real(row.tu[0]), real(row.tu[1]), real(row.tu[2])}),
                         Vec3{real(row.t[0]), real(row.t[1]), real(row.t[2])});
    return true;
  }

  /// Frame k's pixels (frames/frameNNNN.ppm).
  edgetrack::Result<edgetrack_app::FramePixels> frame(size_t k) const {
    char name[64];
    std::snprintf(name, sizeof name, "/frames/frame%04zu.ppm", k);
    return edgetrack_app::read_netpbm_pixels(directory + name);
  }
};
