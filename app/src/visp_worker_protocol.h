// SPDX-License-Identifier: BSD-3-Clause
/// The pipe between `edgetrack compare` and `edgetrack-visp-mbt`, the child process that runs
/// ViSP's own edge tracker. Upstream ViSP and our ports/visp define the same class names
/// (vpMeSite, vpImage), so the two cannot share one process; the frames travel through a pipe,
/// one at a time, so the two trackers alternate on the same grey frames.
///
/// The child's arguments: CONFIG.xml MODEL.cao tx ty tz tux tuy tuz DOWNSCALE (the initial
/// camera_from_model as a ViSP pose vector). Then, per frame, on its standard input a
/// VispFrameHeader and width * height grey bytes (the grey frame our tracker gets too); it
/// answers a VispFrameReply on its standard output. A header with width 0 ends it. Plain C++, no header of ours or of ViSP.
#pragma once

#include <cstdint>

namespace edgetrack_app {

struct VispFrameHeader {
  int32_t width = 0;
  int32_t height = 0;
};

struct VispFrameReply {
  double track_ms = 0;      ///< the tracker's track() call, steady clock
  int32_t features = 0;     ///< moving-edge sites in the last pose estimation (getNbFeaturesEdge)
  int32_t lost = 0;         ///< 1 when track() threw (too few sites, a failed estimation)
  double pose[6] = {0, 0, 0, 0, 0, 0};  ///< camera_from_model after the frame: tx ty tz tux tuy tuz
};

}  // namespace edgetrack_app
