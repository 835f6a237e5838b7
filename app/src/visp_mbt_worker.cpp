// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack-visp-mbt` (host, ViSP API only): runs Debian's ViSP vpMbGenericTracker in edge
/// mode for `edgetrack compare`, one frame per request (visp_worker_protocol.h). Its settings are
/// ViSP's own: loadConfigFile on the XML, loadModel on the .cao, initFromPose on the first frame.
#include <visp3/core/vpException.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/mbt/vpMbGenericTracker.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "visp_worker_protocol.h"

namespace {

using edgetrack_app::VispFrameHeader;
using edgetrack_app::VispFrameReply;

/// A frame `factor` times smaller, as `edgetrack track --downscale` sees it: the camera's rays
/// keep their pixels ((u + 0.5) / factor - 0.5), the sample step and the range shrink with it.
void downscale_settings(vpMbGenericTracker& tracker, int factor) {
  if (factor <= 1) return;
  vpCameraParameters camera;
  tracker.getCameraParameters(camera);
  camera.initPersProjWithoutDistortion(camera.get_px() / factor, camera.get_py() / factor,
                                       (camera.get_u0() + 0.5) / factor - 0.5, (camera.get_v0() + 0.5) / factor - 0.5);
  tracker.setCameraParameters(camera);
  vpMe me = tracker.getMovingEdge();
  me.setSampleStep(me.getSampleStep() / factor);
  me.setRange(std::max(1u, me.getRange() / static_cast<unsigned>(factor)));
  tracker.setMovingEdge(me);
}

bool read_all(void* data, size_t bytes) { return std::fread(data, 1, bytes, stdin) == bytes; }

/// The replies' stream: the original standard output. ViSP's own messages (std::cout) go to
/// standard error instead, so that they cannot be read as a reply.
std::FILE* reply_stream() {
  const int replies = dup(1);
  if (replies < 0 || dup2(2, 1) < 0) return nullptr;
  return fdopen(replies, "wb");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 10) {
    std::fprintf(stderr, "usage: edgetrack-visp-mbt CONFIG.xml MODEL.cao tx ty tz tux tuy tuz DOWNSCALE\n");
    return 2;
  }
  vpPoseVector initial;
  for (int i = 0; i < 6; ++i) initial[i] = std::atof(argv[3 + i]);
  const int factor = std::atoi(argv[9]);
  std::FILE* replies = reply_stream();
  if (!replies) {
    std::perror("edgetrack-visp-mbt: standard output");
    return 1;
  }
  vpMbGenericTracker tracker(1, vpMbGenericTracker::EDGE_TRACKER);
  try {
    tracker.loadConfigFile(argv[1], false);
    tracker.loadModel(argv[2]);
    downscale_settings(tracker, factor);
  } catch (const vpException& e) {
    std::fprintf(stderr, "ViSP refused %s / %s: %s\n", argv[1], argv[2], e.getMessage());
    return 1;
  }
  vpImage<unsigned char> grey;
  bool started = false;
  VispFrameHeader header;
  while (read_all(&header, sizeof header) && header.width > 0 && header.height > 0) {
    grey.resize(static_cast<unsigned>(header.height), static_cast<unsigned>(header.width));
    if (!read_all(grey.bitmap, static_cast<size_t>(header.width) * header.height)) return 1;
    VispFrameReply reply;
    try {
      if (!started) tracker.initFromPose(grey, vpHomogeneousMatrix(initial));
      started = true;
      const auto begin = std::chrono::steady_clock::now();
      try {
        tracker.track(grey);
      } catch (const vpException&) {
        reply.lost = 1;
      }
      reply.track_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    } catch (const vpException& e) {
      std::fprintf(stderr, "ViSP could not start from the initial pose: %s\n", e.getMessage());
      return 1;
    }
    reply.features = static_cast<int32_t>(tracker.getNbFeaturesEdge());
    const vpPoseVector pose(tracker.getPose());
    for (int i = 0; i < 6; ++i) reply.pose[i] = pose[i];
    if (std::fwrite(&reply, sizeof reply, 1, replies) != 1 || std::fflush(replies) != 0) return 1;
  }
  return 0;
}
